//! Webhooks: when a job ends, the service POSTs the job (as `GET /v1/jobs/{id}` answers it) to
//! the job's `webhook` URL (or the server's `--webhook`). Deliveries are durable: the job's row
//! records when the next attempt is due, how many were made and how the last went, and every
//! process runs [`spawn_sender`], which takes due deliveries one at a time under a short lease
//! (so replicas never send the same one at once, and one whose process died is sent by another),
//! retrying with exponential backoff (1 s, 2 s, 4 s, … up to 5 minutes apart, 12 attempts).
//!
//! Each request is signed: `Phygap-Signature: t=UNIX_SECONDS,v1=HEX`, where HEX is
//! HMAC-SHA256 under the server's `--webhook-secret` of `t` and the body joined by a dot
//! (`"{t}.{body}"`). A receiver recomputes it, compares in constant time, and refuses stale
//! timestamps (replays). Only `http` and `https` URLs are accepted, and with `--webhook-hosts`
//! only those hosts (anything else is refused at submit): the service calls out from inside its
//! network, so an operator should list the hosts it may call.

use std::time::Duration;

use hmac::{Hmac, KeyInit, Mac};
use sha2::Sha256;
use tokio::task::JoinHandle;

use crate::error::ApiError;
use crate::routes::jobs::JobView;
use crate::store::{now_ms, WebhookDelivery};
use crate::AppState;

/// The header carrying the signature.
pub const SIGNATURE_HEADER: &str = "phygap-signature";

/// Attempts before a delivery is given up.
pub const MAX_ATTEMPTS: u32 = 12;

/// The longest wait between attempts.
const MAX_BACKOFF: Duration = Duration::from_secs(300);

/// How long a process owns a delivery it took (it is sent again by anyone after this).
const DELIVERY_LEASE: Duration = Duration::from_secs(30);

/// How long one attempt may take.
const REQUEST_TIMEOUT: Duration = Duration::from_secs(10);

/// How often an idle sender looks for due deliveries.
const POLL: Duration = Duration::from_millis(200);

/// The operator's webhook settings.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct WebhookSettings {
    /// The URL jobs without their own are reported to.
    pub default_url: Option<String>,
    /// The HMAC key of the signatures (empty: the requests carry an unkeyed signature, which
    /// proves nothing; set one).
    pub secret: String,
    /// Hosts webhooks may target; empty: any.
    pub allowed_hosts: Vec<String>,
}

impl WebhookSettings {
    /// The URL a job submitted with `requested` reports to, checked; `Ok(None)`: none.
    pub fn target(&self, requested: Option<&str>) -> Result<Option<String>, ApiError> {
        let Some(url) = requested.or(self.default_url.as_deref()) else {
            return Ok(None);
        };
        let invalid = |why: String| ApiError::unprocessable("invalid_webhook", why);
        let (scheme, rest) = url
            .split_once("://")
            .ok_or_else(|| invalid(format!("`{url}` is not an http(s) URL")))?;
        if !scheme.eq_ignore_ascii_case("http") && !scheme.eq_ignore_ascii_case("https") {
            return Err(invalid(format!("`{url}`: webhooks are http or https")));
        }
        let authority = rest.split(['/', '?', '#']).next().unwrap_or("");
        let host_port = authority.rsplit('@').next().unwrap_or("");
        let host = match host_port.strip_prefix('[') {
            Some(v6) => v6.split(']').next().unwrap_or(""),
            None => host_port.split(':').next().unwrap_or(""),
        };
        if host.is_empty() || url.len() > 2048 || url.chars().any(char::is_whitespace) {
            return Err(invalid(format!("`{url}` is not a usable URL")));
        }
        if !self.allowed_hosts.is_empty()
            && !self
                .allowed_hosts
                .iter()
                .any(|allowed| allowed.eq_ignore_ascii_case(host))
        {
            return Err(invalid(format!(
                "webhooks may call {} only (--webhook-hosts), not `{host}`",
                self.allowed_hosts.join(", ")
            )));
        }
        Ok(Some(url.to_owned()))
    }
}

/// The signature header's value for `body` sent at `timestamp` (unix seconds).
pub fn signature(secret: &str, timestamp: i64, body: &[u8]) -> String {
    let mut mac =
        Hmac::<Sha256>::new_from_slice(secret.as_bytes()).expect("HMAC takes keys of any length");
    mac.update(timestamp.to_string().as_bytes());
    mac.update(b".");
    mac.update(body);
    let digest = mac.finalize().into_bytes();
    let hex: String = digest.iter().map(|b| format!("{b:02x}")).collect();
    format!("t={timestamp},v1={hex}")
}

/// The wait before attempt `attempt + 1` (attempt counts from 1).
pub fn backoff(attempt: u32) -> Duration {
    let seconds = 1u64 << attempt.saturating_sub(1).min(16);
    Duration::from_secs(seconds).min(MAX_BACKOFF)
}

/// Starts the task that sends this process's share of due deliveries.
pub fn spawn_sender(state: &AppState) -> JoinHandle<()> {
    let state = state.clone();
    tokio::spawn(async move {
        let client = match reqwest::Client::builder()
            .timeout(REQUEST_TIMEOUT)
            .redirect(reqwest::redirect::Policy::none())
            .build()
        {
            Ok(client) => client,
            Err(e) => {
                tracing::error!(error = %e, "webhooks disabled: no HTTP client");
                return;
            }
        };
        loop {
            let lease_until = now_ms() + DELIVERY_LEASE.as_millis() as i64;
            let delivery = match state.store.take_webhook(now_ms(), lease_until).await {
                Ok(delivery) => delivery,
                Err(e) => {
                    tracing::warn!(error = %e, "looking for due webhooks failed");
                    None
                }
            };
            match delivery {
                Some(delivery) => deliver(&state, &client, delivery).await,
                None => {
                    tokio::select! {
                        _ = state.shutdown.cancelled() => break,
                        _ = tokio::time::sleep(POLL) => {}
                    }
                }
            }
        }
    })
}

/// One attempt at a delivery, and its record.
async fn deliver(state: &AppState, client: &reqwest::Client, delivery: WebhookDelivery) {
    let attempt = delivery.attempts + 1;
    let body = match serde_json::to_vec(&JobView::from(delivery.job.clone())) {
        Ok(body) => body,
        Err(e) => {
            tracing::error!(error = %e, "webhook body");
            return;
        }
    };
    let timestamp = now_ms() / 1000;
    let sent = client
        .post(&delivery.url)
        .header("content-type", "application/json")
        .header(
            SIGNATURE_HEADER,
            signature(&state.config.webhooks.secret, timestamp, &body),
        )
        .header("phygap-event", "job.ended")
        .body(body)
        .send()
        .await;
    let (delivered, status) = match sent {
        Ok(response) if response.status().is_success() => {
            (true, format!("delivered: {}", response.status().as_u16()))
        }
        Ok(response) => (false, format!("answered {}", response.status().as_u16())),
        Err(e) => (false, format!("not delivered: {}", without_url(&e))),
    };
    let next = (!delivered && attempt < MAX_ATTEMPTS)
        .then(|| now_ms() + backoff(attempt).as_millis() as i64);
    let status = if !delivered && next.is_none() {
        format!("{status}; given up after {attempt} attempts")
    } else {
        status
    };
    tracing::info!(job_id = %delivery.job.id, attempt, %status, "webhook");
    if let Err(e) = state
        .store
        .record_webhook(&delivery.job.id, attempt, &status, next)
        .await
    {
        tracing::warn!(error = %e, "recording a webhook attempt failed");
    }
    state.runtime.changed(&delivery.job.id);
}

/// A client error's description without its URL (which can hold credentials).
fn without_url(e: &reqwest::Error) -> String {
    let kind = if e.is_timeout() {
        "timed out"
    } else if e.is_connect() {
        "cannot connect"
    } else {
        "request failed"
    };
    kind.to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signatures_are_hmac_sha256_of_the_timestamp_and_body() {
        // RFC 4231 test case 2's key and data, as "t.body" = "what do ya want for nothing?".
        let signed = signature("Jefe", 0, b"what do ya want for nothing?");
        assert!(signed.starts_with("t=0,v1="));
        let mut mac = Hmac::<Sha256>::new_from_slice(b"Jefe").unwrap();
        mac.update(b"0.what do ya want for nothing?");
        let expected: String = mac
            .finalize()
            .into_bytes()
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        assert_eq!(signed, format!("t=0,v1={expected}"));
        assert_ne!(signature("other", 0, b"x"), signature("Jefe", 0, b"x"));
        assert_ne!(signature("Jefe", 1, b"x"), signature("Jefe", 0, b"x"));
    }

    #[test]
    fn targets_are_http_and_within_the_allowed_hosts() {
        let open = WebhookSettings::default();
        assert_eq!(open.target(None).unwrap(), None);
        let ok = open
            .target(Some("https://hooks.example.com/phygap?x=1"))
            .unwrap();
        assert_eq!(ok.as_deref(), Some("https://hooks.example.com/phygap?x=1"));
        for bad in [
            "ftp://x/y",
            "file:///etc/passwd",
            "localhost:80",
            "http:///x",
            "http://a b",
        ] {
            assert!(open.target(Some(bad)).is_err(), "{bad}");
        }
        let closed = WebhookSettings {
            allowed_hosts: vec!["127.0.0.1".into(), "hooks.example.com".into()],
            default_url: Some("http://127.0.0.1:9/default".into()),
            ..WebhookSettings::default()
        };
        assert!(closed.target(Some("http://127.0.0.1:8123/hook")).is_ok());
        assert!(closed
            .target(Some("http://user:pw@HOOKS.example.com/x"))
            .is_ok());
        assert!(closed
            .target(Some("http://169.254.169.254/latest"))
            .is_err());
        assert!(closed.target(Some("http://[::1]:80/")).is_err());
        assert_eq!(
            closed.target(None).unwrap().as_deref(),
            Some("http://127.0.0.1:9/default")
        );
    }

    #[test]
    fn backoff_doubles_up_to_five_minutes() {
        let waits: Vec<u64> = (1..=12).map(|a| backoff(a).as_secs()).collect();
        assert_eq!(waits, [1, 2, 4, 8, 16, 32, 64, 128, 256, 300, 300, 300]);
    }
}

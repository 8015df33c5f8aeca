//! Webhooks: when a job ends, the service POSTs the job (as `GET /v1/jobs/{id}` answers it) to
//! the job's `webhook` URL (or the server's `--webhook`). Deliveries are durable: the job's row
//! records when the next attempt is due, how many were made and how the last went, and every
//! process runs [`spawn_sender`], which takes due deliveries under a short lease (so replicas
//! never send the same one at once, and one whose process died is sent by another), several at
//! once but only a few of any one account (a receiver that hangs delays its own account alone),
//! retrying with exponential backoff (1 s, 2 s, 4 s, … up to 5 minutes apart, 12 attempts).
//!
//! Each request is signed: `Phygap-Signature: t=UNIX_SECONDS,v1=HEX`, where HEX is
//! HMAC-SHA256 under the server's `--webhook-secret` of `t` and the body joined by a dot
//! (`"{t}.{body}"`). A receiver recomputes it, compares in constant time, and refuses stale
//! timestamps (replays).
//!
//! The service calls out from inside its network, so a URL is checked before it is accepted and
//! again when it is called: parsed once by the parser the HTTP client uses (the host checked is
//! the host called), `http` or `https`, no credentials, a host of `--webhook-hosts` when that is
//! set, and every address it names or resolves to outside the network unless
//! `--webhook-allow-cidr` admits it ([`crate::outbound`]); the client connects only to addresses
//! that passed, follows no redirect and uses no proxy.

use std::collections::HashMap;
use std::net::IpAddr;
use std::time::Duration;

use hmac::{Hmac, KeyInit, Mac};
use sha2::Sha256;
use tokio::task::{JoinHandle, JoinSet};

use crate::error::ApiError;
use crate::outbound::{AddressPolicy, CheckedResolver};
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
    /// The addresses webhooks may reach: public ones, and the internal ranges the operator
    /// allows (`--webhook-allow-cidr`).
    pub addresses: AddressPolicy,
}

/// Longest webhook URL, bytes.
const MAX_URL_BYTES: usize = 2048;

/// Characters of a refused URL quoted back in the error.
const QUOTED_CHARS: usize = 120;

impl WebhookSettings {
    /// The URL a job submitted with `requested` reports to, checked as far as it can be without
    /// the network (see [`Self::parse`]), its name resolved and every address it resolves to
    /// checked; `Ok(None)`: none.
    pub async fn target(&self, requested: Option<&str>) -> Result<Option<String>, ApiError> {
        let Some(url) = requested.or(self.default_url.as_deref()) else {
            return Ok(None);
        };
        let parsed = self.parse(url)?;
        if let Some(url::Host::Domain(name)) = parsed.host() {
            let port = parsed.port_or_known_default().unwrap_or(80);
            self.addresses
                .resolve(name, port)
                .await
                .map_err(|e| invalid_webhook(format!("`{}`: {e}", quoted(url))))?;
        }
        Ok(Some(parsed.into()))
    }

    /// `url` parsed by the parser the HTTP client uses (so the host checked is the host called),
    /// and checked: http(s), no credentials, a host in `--webhook-hosts` when that is set, an
    /// address literal outside the network unless allowed. The name of a host is checked where
    /// it is resolved.
    pub fn parse(&self, url: &str) -> Result<url::Url, ApiError> {
        let shown = quoted(url);
        if url.len() > MAX_URL_BYTES {
            return Err(invalid_webhook(format!(
                "`{shown}` is longer than {MAX_URL_BYTES} bytes"
            )));
        }
        let parsed = url::Url::parse(url)
            .map_err(|e| invalid_webhook(format!("`{shown}` is not a usable URL: {e}")))?;
        if !matches!(parsed.scheme(), "http" | "https") {
            return Err(invalid_webhook(format!(
                "`{shown}`: webhooks are http or https"
            )));
        }
        if !parsed.username().is_empty() || parsed.password().is_some() {
            return Err(invalid_webhook(format!(
                "`{}`: webhook URLs may not carry credentials (the signature authenticates \
                 the service to the receiver)",
                quoted(&without_userinfo(&parsed))
            )));
        }
        let host = parsed
            .host()
            .ok_or_else(|| invalid_webhook(format!("`{shown}` has no host")))?;
        if !self.allowed_hosts.is_empty() && !self.allowed_hosts.iter().any(|a| same_host(a, &host))
        {
            return Err(invalid_webhook(format!(
                "webhooks may call {} only (--webhook-hosts), not `{}`",
                self.allowed_hosts.join(", "),
                quoted(&host.to_string())
            )));
        }
        let literal = match host {
            url::Host::Ipv4(v4) => Some(IpAddr::V4(v4)),
            url::Host::Ipv6(v6) => Some(IpAddr::V6(v6)),
            url::Host::Domain(_) => None,
        };
        if let Some(address) = literal {
            self.addresses
                .check(address)
                .map_err(|e| invalid_webhook(format!("`{shown}`: {e}")))?;
        }
        Ok(parsed)
    }
}

fn invalid_webhook(why: String) -> ApiError {
    ApiError::unprocessable("invalid_webhook", why)
}

/// The start of `text`, for an error message (an input is never echoed whole).
fn quoted(text: &str) -> String {
    crate::error::quoted_prefix(text, QUOTED_CHARS)
}

/// `url` with its credentials removed (never shown back).
fn without_userinfo(url: &url::Url) -> String {
    let mut shown = url.clone();
    let _ = shown.set_username("");
    let _ = shown.set_password(None);
    shown.to_string()
}

/// Whether `allowed` (an entry of `--webhook-hosts`) names `host`: the same address, or the same
/// name once both are normalised as URL hosts (case, IDN).
fn same_host(allowed: &str, host: &url::Host<&str>) -> bool {
    let allowed = allowed.trim().trim_start_matches('[').trim_end_matches(']');
    if let Ok(address) = allowed.parse::<IpAddr>() {
        return match host {
            url::Host::Ipv4(v4) => IpAddr::V4(*v4) == address.to_canonical(),
            url::Host::Ipv6(v6) => IpAddr::V6(*v6).to_canonical() == address.to_canonical(),
            url::Host::Domain(_) => false,
        };
    }
    match (url::Host::parse(allowed), host) {
        (Ok(url::Host::Domain(name)), url::Host::Domain(host)) => name == *host,
        _ => false,
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

/// Deliveries in flight at once in one process.
const MAX_IN_FLIGHT: usize = 32;

/// Deliveries of one account in flight at once in one process: a receiver that hangs holds at
/// most this many, and delays only its own account's deliveries.
const MAX_IN_FLIGHT_PER_ACCOUNT: usize = 2;

/// The HTTP client of deliveries: no redirects, no proxy from the environment, the attempt's
/// timeout, and a resolver that admits only the addresses the policy allows.
fn delivery_client(settings: &WebhookSettings) -> reqwest::Result<reqwest::Client> {
    reqwest::Client::builder()
        .timeout(REQUEST_TIMEOUT)
        .redirect(reqwest::redirect::Policy::none())
        .no_proxy()
        .dns_resolver(CheckedResolver {
            policy: settings.addresses.clone(),
        })
        .build()
}

/// Starts the task that sends this process's share of due deliveries: up to [`MAX_IN_FLIGHT`]
/// at once, and at most [`MAX_IN_FLIGHT_PER_ACCOUNT`] of any one account.
pub fn spawn_sender(state: &AppState) -> JoinHandle<()> {
    let state = state.clone();
    tokio::spawn(async move {
        let client = match delivery_client(&state.config.webhooks) {
            Ok(client) => client,
            Err(e) => {
                tracing::error!(error = %e, "webhooks disabled: no HTTP client");
                return;
            }
        };
        let mut in_flight: JoinSet<String> = JoinSet::new();
        let mut per_account: HashMap<String, usize> = HashMap::new();
        loop {
            let mut delivery = None;
            if in_flight.len() < MAX_IN_FLIGHT {
                let busy: Vec<String> = per_account
                    .iter()
                    .filter(|(_, &n)| n >= MAX_IN_FLIGHT_PER_ACCOUNT)
                    .map(|(account, _)| account.clone())
                    .collect();
                let lease_until = now_ms() + DELIVERY_LEASE.as_millis() as i64;
                delivery = match state.store.take_webhook(now_ms(), lease_until, &busy).await {
                    Ok(delivery) => delivery,
                    Err(e) => {
                        tracing::warn!(error = %e, "looking for due webhooks failed");
                        None
                    }
                };
            }
            match delivery {
                Some(delivery) => {
                    let account = delivery.job.account.clone().unwrap_or_default();
                    *per_account.entry(account.clone()).or_default() += 1;
                    let (state, client) = (state.clone(), client.clone());
                    in_flight.spawn(async move {
                        deliver(&state, &client, delivery).await;
                        account
                    });
                }
                None => {
                    tokio::select! {
                        _ = state.shutdown.cancelled() => break,
                        Some(done) = in_flight.join_next() => {
                            if let Ok(account) = done {
                                if let Some(n) = per_account.get_mut(&account) {
                                    *n -= 1;
                                    if *n == 0 {
                                        per_account.remove(&account);
                                    }
                                }
                            }
                        }
                        _ = tokio::time::sleep(POLL) => {}
                    }
                }
            }
        }
        in_flight.shutdown().await;
    })
}

/// One attempt at a delivery, and its record.
async fn deliver(state: &AppState, client: &reqwest::Client, delivery: WebhookDelivery) {
    let attempt = delivery.attempts + 1;
    let (delivered, status, retry) = match state.config.webhooks.parse(&delivery.url) {
        // A URL recorded before the policy changed, now refused: not sent, not retried.
        Err(refused) => (false, format!("refused: {}", refused.message), false),
        Ok(url) => send(state, client, url, &delivery).await,
    };
    let next = (!delivered && retry && attempt < MAX_ATTEMPTS)
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

/// Sends the signed request: whether it was delivered, the status to record, and whether a
/// failure may be retried.
async fn send(
    state: &AppState,
    client: &reqwest::Client,
    url: url::Url,
    delivery: &WebhookDelivery,
) -> (bool, String, bool) {
    let body = match serde_json::to_vec(&JobView::from(delivery.job.clone())) {
        Ok(body) => body,
        Err(e) => return (false, format!("the body cannot be written: {e}"), false),
    };
    let timestamp = now_ms() / 1000;
    let sent = client
        .post(url)
        .header("content-type", "application/json")
        .header(
            SIGNATURE_HEADER,
            signature(&state.config.webhooks.secret, timestamp, &body),
        )
        .header("phygap-event", "job.ended")
        .body(body)
        .send()
        .await;
    match sent {
        Ok(response) if response.status().is_success() => (
            true,
            format!("delivered: {}", response.status().as_u16()),
            false,
        ),
        Ok(response) => (
            false,
            format!("answered {}", response.status().as_u16()),
            true,
        ),
        Err(e) => match crate::outbound::refusal_in(&e) {
            // The name now resolves inside the network: retried, as DNS answers change.
            Some(refused) => (false, format!("refused: {refused}"), true),
            None => (false, format!("not delivered: {}", without_url(&e)), true),
        },
    }
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

    /// Settings that admit loopback (as tests and private deployments do) and `hosts`.
    fn loopback_settings(hosts: &[&str]) -> WebhookSettings {
        WebhookSettings {
            allowed_hosts: hosts.iter().map(|h| h.to_string()).collect(),
            addresses: AddressPolicy::allowing(["127.0.0.0/8", "::1"]).unwrap(),
            ..WebhookSettings::default()
        }
    }

    #[test]
    fn urls_are_http_without_credentials_and_outside_the_network() {
        let open = WebhookSettings::default();
        let ok = open.parse("https://hooks.example.com/phygap?x=1").unwrap();
        assert_eq!(ok.as_str(), "https://hooks.example.com/phygap?x=1");
        for bad in [
            "ftp://x/y",
            "file:///etc/passwd",
            "localhost:80",
            "http://",
            "http://a b",
            "http://user:pw@hooks.example.com/x",
            "http://user@hooks.example.com/x",
            // Address literals inside the network, however they are written.
            "http://127.0.0.1/",
            "http://2130706433/",
            "http://0x7f000001/",
            "http://0177.0.0.1/",
            "http://127.1/",
            "http://0.0.0.0/",
            "http://[::1]/",
            "http://[::ffff:127.0.0.1]/",
            "http://[::ffff:7f00:1]/",
            "http://169.254.169.254/latest/meta-data",
            "http://10.0.0.1/",
            "http://[fd00::1]/",
            "http://100.64.0.1/",
        ] {
            assert!(open.parse(bad).is_err(), "{bad}");
        }
        let long = format!("https://hooks.example.com/{}", "a".repeat(3000));
        let refused = open.parse(&long).unwrap_err();
        assert!(refused.message.len() < 400, "{}", refused.message);
    }

    #[test]
    fn credentials_are_never_shown_back() {
        let refused = WebhookSettings::default()
            .parse("https://alice:s3cret@hooks.example.com/x")
            .unwrap_err();
        assert!(!refused.message.contains("s3cret"), "{}", refused.message);
        assert!(!refused.message.contains("alice"), "{}", refused.message);
    }

    #[test]
    fn the_host_checked_is_the_host_the_client_calls() {
        let settings = loopback_settings(&["localhost"]);
        // The client reads `\` as `/`: the host is 127.0.0.1, not `localhost`.
        let backslash = r"http://127.0.0.1:9\@localhost:8/x";
        assert!(settings.parse(backslash).is_err());
        assert_eq!(
            settings.parse("http://LOCALHOST:8/x").unwrap().host_str(),
            Some("localhost")
        );
        // IDN: fullwidth letters are the same name once normalised.
        assert!(settings.parse("http://ｌｏｃａｌｈｏｓｔ:8/x").is_ok());
        let by_address = loopback_settings(&["127.0.0.1", "::1"]);
        assert!(by_address.parse("http://127.0.0.1:8123/hook").is_ok());
        assert!(by_address.parse("http://2130706433:8123/hook").is_ok());
        assert!(by_address.parse("http://[::1]:80/").is_ok());
        assert!(by_address.parse("http://127.0.0.2/").is_err());
        assert!(by_address.parse("http://localhost/").is_err());
    }

    #[tokio::test]
    async fn names_are_resolved_and_checked_at_submit() {
        let strict = WebhookSettings::default();
        let inside = strict
            .target(Some("http://localhost:8/x"))
            .await
            .unwrap_err();
        assert_eq!(inside.code, "invalid_webhook");
        assert!(inside.message.contains("loopback"), "{}", inside.message);
        assert!(strict
            .target(Some("http://no-such-host.invalid/x"))
            .await
            .is_err());
        let allowed = loopback_settings(&[]);
        assert_eq!(
            allowed.target(Some("http://localhost:8/x")).await.unwrap(),
            Some("http://localhost:8/x".to_owned())
        );
        let with_default = WebhookSettings {
            default_url: Some("http://127.0.0.1:9/default".into()),
            ..loopback_settings(&[])
        };
        assert_eq!(
            with_default.target(None).await.unwrap().as_deref(),
            Some("http://127.0.0.1:9/default")
        );
        assert_eq!(strict.target(None).await.unwrap(), None);
    }

    #[test]
    fn backoff_doubles_up_to_five_minutes() {
        let waits: Vec<u64> = (1..=12).map(|a| backoff(a).as_secs()).collect();
        assert_eq!(waits, [1, 2, 4, 8, 16, 32, 64, 128, 256, 300, 300, 300]);
    }
}

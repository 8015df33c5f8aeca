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
//! again when it is called ([`crate::jobs::webhook_targets`]); the client connects only to
//! addresses that passed, follows no redirect and uses no proxy.
//!
//! The body is the job as the API shows it, which the HTTP layer renders: [`spawn_sender`] takes
//! that rendering as a [`JobBody`].

use std::collections::HashMap;
use std::time::Duration;

use hmac::{Hmac, KeyInit, Mac};
use sha2::Sha256;
use tokio::task::{JoinHandle, JoinSet};

use crate::jobs::outbound::CheckedResolver;
use crate::jobs::state::AppState;
use crate::jobs::webhook_targets::WebhookSettings;
use crate::storage::store::{now_ms, JobRecord, WebhookDelivery};

/// How a delivery's body is written: the job as `GET /v1/jobs/{id}` answers it (the HTTP
/// layer's rendering, handed to [`spawn_sender`]).
pub type JobBody = fn(JobRecord) -> serde_json::Result<Vec<u8>>;

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
pub fn spawn_sender(state: &AppState, job_body: JobBody) -> JoinHandle<()> {
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
                        deliver(&state, &client, job_body, delivery).await;
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
async fn deliver(
    state: &AppState,
    client: &reqwest::Client,
    job_body: JobBody,
    delivery: WebhookDelivery,
) {
    let attempt = delivery.attempts + 1;
    let (delivered, status, retry) = match state.config.webhooks.parse(&delivery.url) {
        // A URL recorded before the policy changed, now refused: not sent, not retried.
        Err(refused) => (false, format!("refused: {}", refused.message), false),
        Ok(url) => send(state, client, job_body, url, &delivery).await,
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
    job_body: JobBody,
    url: url::Url,
    delivery: &WebhookDelivery,
) -> (bool, String, bool) {
    let body = match job_body(delivery.job.clone()) {
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
        Err(e) => match crate::jobs::outbound::refusal_in(&e) {
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

    #[test]
    fn backoff_doubles_up_to_five_minutes() {
        let waits: Vec<u64> = (1..=12).map(|a| backoff(a).as_secs()).collect();
        assert_eq!(waits, [1, 2, 4, 8, 16, 32, 64, 128, 256, 300, 300, 300]);
    }
}

//! Webhooks against a receiver on loopback: a job's end is POSTed within two seconds, signed so
//! that the receiver can check it; a receiver that is down for ten seconds still gets it from a
//! retry; URLs that are not http(s), or not of an allowed host, are refused at submit.

mod common;

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use axum::body::Bytes;
use axum::http::HeaderMap;
use common::*;
use hmac::{Hmac, KeyInit, Mac};
use phygap_api::jobs::outbound::AddressPolicy;
use serde_json::{json, Value};
use sha2::Sha256;

const SECRET: &str = "webhook-test-secret";

/// One request the receiver got: when, its signature header, its body.
#[derive(Clone, Debug)]
struct Received {
    at: Instant,
    signature: String,
    body: Bytes,
}

/// An HTTP receiver on `port` recording what it is sent.
async fn receiver(port: u16) -> (Arc<Mutex<Vec<Received>>>, tokio::task::JoinHandle<()>) {
    let got: Arc<Mutex<Vec<Received>>> = Arc::default();
    let record = got.clone();
    let app = axum::Router::new().route(
        "/hook",
        axum::routing::post(move |headers: HeaderMap, body: Bytes| {
            let record = record.clone();
            async move {
                let signature = headers
                    .get("phygap-signature")
                    .map(|v| v.to_str().unwrap().to_owned())
                    .unwrap_or_default();
                record.lock().unwrap().push(Received {
                    at: Instant::now(),
                    signature,
                    body,
                });
                "ok"
            }
        }),
    );
    let listener = tokio::net::TcpListener::bind(("127.0.0.1", port))
        .await
        .unwrap();
    let task = tokio::spawn(async move {
        axum::serve(listener, app).await.unwrap();
    });
    (got, task)
}

/// Checks `Phygap-Signature: t=…,v1=…` against the body as a receiver would.
fn verify(received: &Received) {
    let (t, v1) = received
        .signature
        .strip_prefix("t=")
        .and_then(|rest| rest.split_once(",v1="))
        .unwrap_or_else(|| panic!("signature {:?}", received.signature));
    let mut mac = Hmac::<Sha256>::new_from_slice(SECRET.as_bytes()).unwrap();
    mac.update(format!("{t}.").as_bytes());
    mac.update(&received.body);
    let expected: String = mac
        .finalize()
        .into_bytes()
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    assert_eq!(v1, expected, "the signature does not match the body");
    let age = common::now_seconds() - t.parse::<i64>().unwrap();
    assert!((0..=60).contains(&age), "a stale timestamp: {age} s");
}

async fn server() -> (tempfile::TempDir, TestServer) {
    TestServer::start_fresh_with(|c| {
        c.webhooks.secret = SECRET.into();
        c.webhooks.allowed_hosts = vec!["127.0.0.1".into()];
        // The receiver is on loopback, which webhooks may reach only when allowed.
        c.webhooks.addresses = AddressPolicy::allowing(["127.0.0.0/8"]).unwrap();
    })
    .await
}

async fn submit_with_webhook(t: &TestServer, port: u16) -> String {
    let capture = t.upload_capture().await;
    let body = json!({"capture_id": capture, "config": train_config(20, 10),
                      "webhook": format!("http://127.0.0.1:{port}/hook")});
    let (status, job) = status_and_json(t.post_job(&body, None).await).await;
    assert_eq!(status, 201, "{job}");
    job["id"].as_str().unwrap().to_owned()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_job_end_is_posted_signed_within_two_seconds() {
    let (_dir, t) = server().await;
    let port = process::free_port();
    let (got, _receiver) = receiver(port).await;
    let id = submit_with_webhook(&t, port).await;
    t.wait_succeeded(&id).await;
    let ended = Instant::now();
    let deadline = ended + Duration::from_secs(10);
    while got.lock().unwrap().is_empty() {
        assert!(Instant::now() < deadline, "no webhook");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let received = got.lock().unwrap()[0].clone();
    let latency = received.at.saturating_duration_since(ended);
    assert!(
        latency < Duration::from_secs(2),
        "delivered {latency:?} after the end"
    );
    verify(&received);
    let job: Value = serde_json::from_slice(&received.body).unwrap();
    assert_eq!(
        (job["id"].as_str(), job["state"].as_str()),
        (Some(&*id), Some("succeeded"))
    );
    let recorded = t
        .wait_job(&id, LONG, |j| j["webhook"]["done"] == true)
        .await;
    assert_eq!(recorded["webhook"]["attempts"], 1, "{recorded}");
    assert_eq!(recorded["webhook"]["last_status"], "delivered: 200");
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_receiver_down_for_ten_seconds_still_gets_it() {
    let (_dir, t) = server().await;
    let port = process::free_port();
    let id = submit_with_webhook(&t, port).await;
    t.wait_succeeded(&id).await;
    let failing = t
        .wait_job(&id, LONG, |j| j["webhook"]["attempts"].as_u64() >= Some(2))
        .await;
    assert!(
        failing["webhook"]["last_status"]
            .as_str()
            .unwrap()
            .starts_with("not delivered"),
        "{failing}"
    );
    assert_eq!(failing["webhook"]["done"], false);
    tokio::time::sleep(Duration::from_secs(10)).await;
    let (got, _receiver) = receiver(port).await;
    let delivered = t
        .wait_job(&id, Duration::from_secs(60), |j| {
            j["webhook"]["done"] == true
        })
        .await;
    assert_eq!(delivered["webhook"]["last_status"], "delivered: 200");
    let received = got.lock().unwrap().clone();
    assert_eq!(received.len(), 1, "delivered once");
    verify(&received[0]);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn webhooks_must_be_http_urls_of_allowed_hosts() {
    let (_dir, t) = server().await;
    let capture = t.upload_capture().await;
    for url in [
        "ftp://127.0.0.1/x",
        "http://169.254.169.254/latest",
        "not a url",
    ] {
        let body = json!({"capture_id": capture, "webhook": url});
        let message = expect_error(t.post_job(&body, None).await, 422, "invalid_webhook").await;
        assert!(!message.is_empty(), "{url}");
    }
    assert_eq!(t.get_json("/v1/jobs").await.1["jobs"], json!([]));
    t.server.shutdown().await;
}

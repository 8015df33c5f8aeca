//! What one account of a shared service cannot do, through the real server process: make the
//! service call inside its network (webhook URLs, however written), delay another account's
//! webhooks, hold every connection, grow the server with form fields, wrap a query number, or
//! start a server whose flags overflow.

mod common;

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use common::process::{free_port, ServerProcess};
use common::*;
use serde_json::{json, Value};
use tokio::io::AsyncReadExt;

const ALICE: &str = "alice-token-0123456789";
const BOB: &str = "bob-token-0123456789ab";

/// A tokens file with two accounts, in `dir`.
fn tokens_file(dir: &std::path::Path) -> String {
    let path = dir.join("tokens.txt");
    std::fs::write(&path, format!("alice {ALICE}\nbob {BOB}\n")).unwrap();
    path.to_string_lossy().into_owned()
}

/// A capture uploaded by `api`, and the answer to a job submitted on it with `webhook`.
async fn submit_with_webhook(api: &ApiClient, capture: &str, webhook: &str) -> (u16, Value) {
    let body = json!({"capture_id": capture, "config": train_config(20, 10), "webhook": webhook});
    status_and_json(api.post_job(&body, None).await).await
}

async fn upload(api: &ApiClient) -> String {
    let (status, capture) = api.upload(capture_tar()).await;
    assert_eq!(status, 201, "{capture}");
    capture["id"].as_str().unwrap().to_owned()
}

/// Every way of naming an address inside the network is refused at submit, by default and past
/// an allowlist of names; credentials are refused and never shown back.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn webhooks_cannot_reach_inside_the_network() {
    let dir = tempfile::tempdir().unwrap();
    let server = ServerProcess::start(dir.path(), &["--workers", "0"]).await;
    let capture = upload(&server.api).await;
    let port = free_port();
    let inside = [
        format!("http://127.0.0.1:{port}/x"),
        format!("http://localhost:{port}/x"),
        format!("http://LOCALHOST.:{port}/x"),
        format!("http://2130706433:{port}/x"),
        format!("http://0x7f000001:{port}/x"),
        format!("http://0177.0.0.1:{port}/x"),
        format!("http://127.1:{port}/x"),
        format!("http://0.0.0.0:{port}/x"),
        format!("http://[::1]:{port}/x"),
        format!("http://[::ffff:127.0.0.1]:{port}/x"),
        format!("http://[::]:{port}/x"),
        format!("http://ｌｏｃａｌｈｏｓｔ:{port}/x"),
        "http://169.254.169.254/latest/meta-data/".to_owned(),
        "http://10.0.0.1/x".to_owned(),
        "http://192.168.1.1/x".to_owned(),
        "http://100.64.0.1/x".to_owned(),
        "http://[fd00::1]/x".to_owned(),
        "http://[fe80::1]/x".to_owned(),
        "http://224.0.0.1/x".to_owned(),
    ];
    for url in &inside {
        let (status, body) = submit_with_webhook(&server.api, &capture, url).await;
        assert_eq!(
            (status, error_code(&body).0),
            (422, "invalid_webhook"),
            "{url}: {body}"
        );
    }
    let (status, body) =
        submit_with_webhook(&server.api, &capture, "https://bob:hunter2@example.com/x").await;
    assert_eq!((status, error_code(&body).0), (422, "invalid_webhook"));
    assert!(!body.to_string().contains("hunter2"), "{body}");
    let (status, body) =
        submit_with_webhook(&server.api, &capture, "http://no-such-host.invalid/x").await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "invalid_webhook"),
        "{body}"
    );
    assert_eq!(server.api.get_json("/v1/jobs").await.1["jobs"], json!([]));
    server.assert_up("webhook probes").await;

    // An allowlist of names is checked against the host the client calls: `\` ends the host.
    drop(server);
    let server = ServerProcess::start(
        dir.path(),
        &[
            "--workers",
            "0",
            "--webhook-hosts",
            "localhost",
            "--webhook-allow-cidr",
            "127.0.0.0/8",
        ],
    )
    .await;
    let backslash = format!("http://127.0.0.1:{port}\\@localhost:{}/x", free_port());
    let (status, body) = submit_with_webhook(&server.api, &capture, &backslash).await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "invalid_webhook"),
        "{body}"
    );
    let (status, body) =
        submit_with_webhook(&server.api, &capture, &format!("http://localhost:{port}/x")).await;
    assert_eq!(status, 201, "an allowed name on an allowed range: {body}");
    assert_eq!(body["webhook"]["url"], format!("http://localhost:{port}/x"));
}

/// A server whose range flag does not parse does not start, and says why.
#[test]
fn operator_flags_that_overflow_or_do_not_parse_are_refused_at_start() {
    let dir = tempfile::tempdir().unwrap();
    for (flags, expected) in [
        (
            vec!["--max-runtime-minutes", "200000000000000000"],
            "--max-runtime-minutes",
        ),
        (
            vec!["--webhook-allow-cidr", "10.0.0.0/33"],
            "--webhook-allow-cidr",
        ),
        (
            vec!["--max-connections-per-client", "0"],
            "--max-connections-per-client",
        ),
    ] {
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_phygap-api"))
            .arg("serve")
            .args(["--bind", &format!("127.0.0.1:{}", free_port())])
            .arg("--data-dir")
            .arg(dir.path())
            .args(&flags)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success(), "{flags:?} started");
        assert!(stderr.contains(expected), "{flags:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{flags:?}: {stderr}");
    }
}

/// A receiver on loopback that records when requests reach it; `hang`: it never answers.
async fn receiver(hang: bool) -> (u16, Arc<Mutex<Vec<Instant>>>) {
    let got: Arc<Mutex<Vec<Instant>>> = Arc::default();
    let record = got.clone();
    let app = axum::Router::new().route(
        "/hook",
        axum::routing::post(move || {
            let record = record.clone();
            async move {
                record.lock().unwrap().push(Instant::now());
                if hang {
                    tokio::time::sleep(Duration::from_secs(3600)).await;
                }
                "ok"
            }
        }),
    );
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let port = listener.local_addr().unwrap().port();
    tokio::spawn(async move { axum::serve(listener, app).await.unwrap() });
    (port, got)
}

/// Five webhooks of one account whose receiver hangs (each attempt runs to the service's 10 s
/// timeout) do not hold back another account's: it is delivered while at most two of the first
/// account's have been tried.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_hanging_receiver_delays_only_its_own_account() {
    let dir = tempfile::tempdir().unwrap();
    let tokens = tokens_file(dir.path());
    let flags = [
        "--workers",
        "0",
        "--tokens-file",
        &tokens,
        "--webhook-allow-cidr",
        "127.0.0.0/8",
    ];
    let server = ServerProcess::start(dir.path(), &flags).await;
    let base = format!("http://127.0.0.1:{}", server.port);
    let (alice, bob) = (
        ApiClient::with_token(base.clone(), ALICE),
        ApiClient::with_token(base, BOB),
    );
    let (hanging_port, hanging_got) = receiver(true).await;
    let (port, got) = receiver(false).await;

    let capture = upload(&alice).await;
    for _ in 0..5 {
        let url = format!("http://127.0.0.1:{hanging_port}/hook");
        let (status, job) = submit_with_webhook(&alice, &capture, &url).await;
        assert_eq!(status, 201, "{job}");
        // Queued jobs never run here (no workers): cancelling ends them, which fires the hook.
        assert_eq!(
            alice.cancel(job["id"].as_str().unwrap()).await.status(),
            200
        );
    }
    let deadline = Instant::now() + Duration::from_secs(30);
    while hanging_got.lock().unwrap().is_empty() {
        assert!(Instant::now() < deadline, "alice's hooks were never sent");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let capture = upload(&bob).await;
    let (status, job) =
        submit_with_webhook(&bob, &capture, &format!("http://127.0.0.1:{port}/hook")).await;
    assert_eq!(status, 201, "{job}");
    assert_eq!(bob.cancel(job["id"].as_str().unwrap()).await.status(), 200);
    let deadline = Instant::now() + Duration::from_secs(120);
    while got.lock().unwrap().is_empty() {
        assert!(Instant::now() < deadline, "bob's hook never came");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let alice_tried = hanging_got.lock().unwrap().len();
    assert!(
        alice_tried <= 2,
        "bob's hook waited behind {alice_tried} of alice's hanging deliveries"
    );
}

/// Form text fields are bounded where they are read, and error bodies quote a short prefix of
/// an input; a progress query past the stores' numbers is refused rather than wrapped.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn form_fields_and_query_numbers_are_bounded_where_they_are_read() {
    let dir = tempfile::tempdir().unwrap();
    let server = ServerProcess::start(dir.path(), &[]).await;
    let api = &server.api;
    let capture = upload(api).await;
    let (status, job) = status_and_json(
        api.post_job(
            &json!({"capture_id": capture, "config": train_config(20, 10)}),
            None,
        )
        .await,
    )
    .await;
    assert_eq!(status, 201, "{job}");
    let id = job["id"].as_str().unwrap().to_owned();

    let (status, body) = api
        .get_json(&format!("/v1/jobs/{id}/progress?from=18446744073709551615"))
        .await;
    assert_eq!(
        (status, error_code(&body).0),
        (400, "invalid_query"),
        "{body}"
    );
    let (status, body) = api
        .get_json(&format!("/v1/jobs/{id}/progress?from=18446744073709551616"))
        .await;
    assert_eq!(
        (status, error_code(&body).0),
        (400, "invalid_query"),
        "{body}"
    );

    let deadline = Instant::now() + LONG;
    loop {
        let (_, job) = api.get_json(&format!("/v1/jobs/{id}")).await;
        if job["state"] == "succeeded" {
            break;
        }
        assert!(
            job["state"] == "queued" || job["state"] == "running",
            "{job}"
        );
        assert!(Instant::now() < deadline, "the job did not end: {job}");
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    // 16 times the 4 KiB a text field may hold: refused long before its end, and small enough
    // for loopback's socket buffers to take whole, so the client is not cut off mid-write when
    // the server answers and closes (with 1 MiB it sometimes was: a broken pipe, no response).
    for field in ["rotate_deg", "webhook"] {
        let form = reqwest::multipart::Form::new().text(field, "9".repeat(64 << 10));
        let response = api
            .client
            .post(api.url(&format!("/v1/jobs/{id}/relight")))
            .multipart(form)
            .send()
            .await
            .unwrap();
        let status = response.status().as_u16();
        let body: Value = response.json().await.unwrap();
        assert_eq!(
            (status, error_code(&body).0),
            (413, "payload_too_large"),
            "{field}"
        );
        assert!(
            body.to_string().len() < 1000,
            "{field}: an error body of {} bytes",
            body.to_string().len()
        );
    }
    let form = reqwest::multipart::Form::new().text("rotate_deg", "x".repeat(4000));
    let response = api
        .client
        .post(api.url(&format!("/v1/jobs/{id}/relight")))
        .multipart(form)
        .send()
        .await
        .unwrap();
    let body: Value = response.json().await.unwrap();
    assert_eq!(error_code(&body).0, "invalid_rotate_deg", "{body}");
    assert!(
        body.to_string().len() < 1000,
        "the input was echoed: {body}"
    );
    server.assert_up("oversized form fields").await;
}

/// 600 idle connections from one client address hold at most its share of the slots: the
/// server closes the rest at once, and another client is still answered.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn one_client_cannot_hold_every_connection() {
    let dir = tempfile::tempdir().unwrap();
    let server = ServerProcess::start(dir.path(), &["--max-connections-per-client", "100"]).await;
    let baseline = server.open_sockets();
    let address: std::net::SocketAddr = format!("127.0.0.1:{}", server.port).parse().unwrap();
    let mut crowd = Vec::new();
    for _ in 0..600 {
        let socket = tokio::net::TcpSocket::new_v4().unwrap();
        // Another loopback address than the one the health check comes from.
        socket.bind("127.0.0.2:0".parse().unwrap()).unwrap();
        crowd.push(socket.connect(address).await.unwrap());
    }
    // The server closes every connection past the client's cap without reading from it.
    tokio::time::sleep(Duration::from_secs(1)).await;
    let mut closed = 0;
    for stream in &mut crowd {
        let mut byte = [0u8; 1];
        if let Ok(Ok(0)) =
            tokio::time::timeout(Duration::from_millis(20), stream.read(&mut byte)).await
        {
            closed += 1;
        }
    }
    assert!(
        closed >= 500,
        "only {closed} of 600 connections were closed"
    );
    let held = server.open_sockets().saturating_sub(baseline);
    assert!(held <= 100, "{held} connections of one client held");
    server.assert_up("600 idle connections of one client").await;
    drop(crowd);
}

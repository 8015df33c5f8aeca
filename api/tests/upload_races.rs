//! Resumable uploads and storage quotas under concurrency and misuse: a commit that finds a part
//! unreadable names it and the upload recovers; concurrent uploads against a storage quota
//! admit exactly what fits (bytes are reserved in the store with the check, on SQLite and on
//! PostgreSQL, across two API processes on one database); a body without a length is cut off
//! where it crosses the quota; an expired upload takes nothing more; part numbers are canonical.
//! (The interleavings that need a request held at a chosen point are forced in process, in
//! `routes::uploads`'s tests.)

mod common;

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Duration;

use base64::Engine as _;
use common::postgres::TempPostgres;
use common::process::ServerProcess;
use common::*;
use futures_util::StreamExt;
use phygap_api::accounts::auth::AccountToken;
use phygap_api::accounts::limits::AccountLimits;
use serde_json::{json, Value};
use sha2::{Digest, Sha256};

const PART: usize = 64 << 10;
const ALICE: &str = "alice-token-0123456789";
const BOB: &str = "bob-token-0123456789ab";
const MIB: u64 = 1 << 20;

fn content_digest(bytes: &[u8]) -> String {
    format!(
        "sha-256=:{}:",
        base64::engine::general_purpose::STANDARD.encode(Sha256::digest(bytes))
    )
}

async fn put_part(t: &ApiClient, id: &str, index: &str, bytes: &[u8]) -> reqwest::Response {
    t.client
        .put(t.url(&format!("/v1/uploads/{id}/parts/{index}")))
        .header("content-digest", content_digest(bytes))
        .body(bytes.to_vec())
        .send()
        .await
        .unwrap()
}

async fn create_upload(t: &ApiClient, size: usize) -> (u16, Value) {
    let response = t
        .client
        .post(t.url("/v1/uploads"))
        .json(&json!({ "size": size, "part_size": PART }))
        .send()
        .await
        .unwrap();
    status_and_json(response).await
}

async fn commit(t: &ApiClient, id: &str) -> (u16, Value) {
    let response = t
        .client
        .post(t.url(&format!("/v1/uploads/{id}/commit")))
        .send()
        .await
        .unwrap();
    status_and_json(response).await
}

/// alice and bob may each store 2 MiB.
fn with_quotas(config: &mut phygap_api::ServiceConfig) {
    let mut limits = AccountLimits::default();
    limits.set("max_storage_mb=2").unwrap();
    config.account_tokens = [("alice", ALICE), ("bob", BOB)]
        .map(|(account, token)| AccountToken {
            limits,
            ..AccountToken::new(account, token)
        })
        .to_vec();
}

async fn stored_bytes(t: &ApiClient) -> u64 {
    let (_, info) = t.get_json("/v1/info").await;
    info["account"]["usage"]["stored_bytes"].as_u64().unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_part_lost_from_storage_is_named_at_commit_and_the_upload_recovers() {
    let dir = tempfile::tempdir().unwrap();
    let server = ServerProcess::start(dir.path(), &["--workers", "0"]).await;
    let t = &server.api;
    let archive = padded_capture_tar();
    let (status, upload) = create_upload(t, archive.len()).await;
    assert_eq!(status, 201, "{upload}");
    let id = upload["id"].as_str().unwrap();
    let parts: Vec<&[u8]> = archive.chunks(PART).collect();
    for (index, part) in parts.iter().enumerate() {
        assert_eq!(
            put_part(t, id, &index.to_string(), part).await.status(),
            200
        );
    }
    // Part 2's stored copy goes missing (a disk fault, an operator's mistake).
    let folder = dir.path().join("uploads").join(id);
    let mut removed = 0;
    for entry in std::fs::read_dir(&folder).unwrap() {
        let entry = entry.unwrap();
        if entry.file_name().to_string_lossy().starts_with("00002.") {
            std::fs::remove_file(entry.path()).unwrap();
            removed += 1;
        }
    }
    assert_eq!(removed, 1);
    let (status, body) = commit(t, id).await;
    assert_eq!(
        (status, error_code(&body).0),
        (409, "part_unreadable"),
        "{body}"
    );
    assert!(error_code(&body).1.contains("part 2"), "{body}");
    let (_, shown) = t.get_json(&format!("/v1/uploads/{id}")).await;
    assert_eq!(shown["state"], "open", "{shown}");
    let received: Vec<u64> = shown["received"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i.as_u64().unwrap())
        .collect();
    assert!(!received.contains(&2), "{shown}");
    assert_eq!(received.len(), parts.len() - 1, "{shown}");
    // Sent again, the upload commits.
    assert_eq!(put_part(t, id, "2", parts[2]).await.status(), 200);
    let (status, capture) = commit(t, id).await;
    assert_eq!(status, 201, "{capture}");
    server.assert_up("the commits").await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn part_numbers_are_canonical_decimals_and_expired_uploads_take_nothing() {
    let (_dir, t) = TestServer::start_fresh_with(|config| {
        config.upload_expiry = Duration::from_secs(2);
    })
    .await;
    let part = vec![3u8; PART];
    let (_, upload) = create_upload(&t, 3 * PART).await;
    let id = upload["id"].as_str().unwrap();
    for index in ["+1", "01", "1.0", "0x1", " 1", "-0"] {
        let response = put_part(&t, id, index, &part).await;
        let (status, body) = status_and_json(response).await;
        assert_eq!(
            (status, error_code(&body).0),
            (400, "no_such_part"),
            "{index}: {body}"
        );
    }
    let (_, shown) = t.get_json(&format!("/v1/uploads/{id}")).await;
    assert_eq!(shown["received"], json!([]), "{shown}");
    assert_eq!(put_part(&t, id, "1", &part).await.status(), 200);

    // Past its expiry (before any sweep), it takes no part and no commit.
    tokio::time::sleep(Duration::from_millis(2500)).await;
    let (status, body) = status_and_json(put_part(&t, id, "0", &part).await).await;
    assert_eq!(
        (status, error_code(&body).0),
        (410, "upload_expired"),
        "{body}"
    );
    let (status, body) = commit(&t, id).await;
    assert_eq!(
        (status, error_code(&body).0),
        (410, "upload_expired"),
        "{body}"
    );
    t.server.shutdown().await;
}

/// Sends `n` capture uploads of `archive` at once as `client`; returns their answers.
async fn upload_at_once(client: &ApiClient, archive: &[u8], n: usize) -> Vec<(u16, Value)> {
    let sends = (0..n).map(|_| client.upload(archive.to_vec()));
    futures_util::future::join_all(sends).await
}

/// Creates `n` resumable uploads of `size` bytes at once as `client`; returns their answers.
async fn create_at_once(client: &ApiClient, size: usize, n: usize) -> Vec<(u16, Value)> {
    let sends = (0..n).map(|_| create_upload(client, size));
    futures_util::future::join_all(sends).await
}

/// How many of `answers` were 201, after checking every other one was the quota's 403.
fn admitted(answers: &[(u16, Value)]) -> usize {
    for (status, body) in answers {
        assert!(
            *status == 201 || (*status, error_code(body).0) == (403, "storage_quota_exceeded"),
            "{status} {body}"
        );
    }
    answers.iter().filter(|(status, _)| *status == 201).count()
}

/// Concurrent one-shot uploads and concurrent resumable uploads of one account admit exactly
/// what fits its 2 MiB, through `a` and `b` (two servers on one database, or one server twice).
async fn a_quota_admits_exactly_what_fits(a: &ApiClient, b: &ApiClient) {
    let alice = [a, b].map(|t| ApiClient::with_token(t.base.clone(), ALICE));
    let archive = padded_capture_tar();
    let size = archive.len() as u64;
    let fit = (2 * MIB / size) as usize;
    assert!((1..8).contains(&fit), "the test capture is {size} bytes");
    let (first, second) = tokio::join!(
        upload_at_once(&alice[0], &archive, 4),
        upload_at_once(&alice[1], &archive, 4)
    );
    let answers: Vec<_> = first.into_iter().chain(second).collect();
    assert_eq!(admitted(&answers), fit, "{answers:?}");
    assert_eq!(stored_bytes(&alice[0]).await, fit as u64 * size);

    let bob = [a, b].map(|t| ApiClient::with_token(t.base.clone(), BOB));
    let (first, second) = tokio::join!(
        create_at_once(&bob[0], archive.len(), 4),
        create_at_once(&bob[1], archive.len(), 4)
    );
    let answers: Vec<_> = first.into_iter().chain(second).collect();
    assert_eq!(admitted(&answers), fit, "{answers:?}");
    assert_eq!(stored_bytes(&bob[1]).await, fit as u64 * size);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn concurrent_uploads_fill_a_quota_and_no_more() {
    let (_dir, t) = TestServer::start_fresh_with(|config| {
        with_quotas(config);
        config.workers = 0;
    })
    .await;
    a_quota_admits_exactly_what_fits(&t, &t).await;
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn concurrent_uploads_through_two_apis_on_postgresql_fill_a_quota_and_no_more() {
    let Some(cluster) = TempPostgres::start() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let replica = || {
        let mut config = test_config(dir.path());
        config.database_url = Some(cluster.url.clone());
        config.workers = 0;
        with_quotas(&mut config);
        TestServer::start(config)
    };
    let (a, b) = (replica().await, replica().await);
    a_quota_admits_exactly_what_fits(&a, &b).await;
    a.server.shutdown().await;
    b.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_body_without_a_length_is_cut_off_where_it_crosses_the_quota() {
    let (dir, t) = TestServer::start_fresh_with(|config| {
        with_quotas(config);
        config.workers = 0;
    })
    .await;
    let alice = ApiClient::with_token(t.base.clone(), ALICE);
    // 64 MiB offered in 256 KiB chunks, with no Content-Length.
    let sent = Arc::new(AtomicU64::new(0));
    let counter = sent.clone();
    let chunks = futures_util::stream::iter(0..256).then(move |_| {
        let counter = counter.clone();
        async move {
            counter.fetch_add(256 << 10, Ordering::SeqCst);
            tokio::time::sleep(Duration::from_millis(2)).await;
            Ok::<_, std::io::Error>(vec![0u8; 256 << 10])
        }
    });
    let response = alice
        .client
        .post(alice.url("/v1/captures"))
        .body(reqwest::Body::wrap_stream(chunks))
        .send()
        .await;
    if let Ok(response) = response {
        let (status, body) = status_and_json(response).await;
        assert_eq!(
            (status, error_code(&body).0),
            (403, "storage_quota_exceeded"),
            "{body}"
        );
    }
    // The server stopped reading a little past the quota (and the bytes it drains before
    // answering), long before the 64 MiB.
    let read = sent.load(Ordering::SeqCst);
    assert!(read < 24 * MIB, "{read} bytes were taken");
    // Its reservation is released as the request ends (a moment after the answer).
    let deadline = std::time::Instant::now() + Duration::from_secs(5);
    while stored_bytes(&alice).await != 0 {
        assert!(
            std::time::Instant::now() < deadline,
            "the reservation stays"
        );
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    assert_eq!(count_files(&dir.path().join("tmp")), 0);
    // With the quota free again, a capture fits.
    let (status, body) = alice.upload(padded_capture_tar()).await;
    assert_eq!(status, 201, "{body}");
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn quota_messages_show_fractions_of_a_mib() {
    let (_dir, t) = TestServer::start_fresh_with(|config| {
        with_quotas(config);
        config.workers = 0;
    })
    .await;
    let alice = ApiClient::with_token(t.base.clone(), ALICE);
    let (status, capture) = alice.upload(padded_capture_tar()).await;
    assert_eq!(status, 201, "{capture}");
    let stored = capture["size_bytes"].as_u64().unwrap();
    let (status, body) = create_upload(&alice, 2 * MIB as usize).await;
    assert_eq!(
        (status, error_code(&body).0),
        (403, "storage_quota_exceeded"),
        "{body}"
    );
    let expected = format!("stores {:.2} MiB of its 2 MiB", stored as f64 / MIB as f64);
    assert!(
        error_code(&body).1.contains(&expected),
        "{body} lacks {expected}"
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn concurrent_submits_fill_a_queue_limit_and_no_more() {
    let (_dir, t) = TestServer::start_fresh_with(|config| {
        let mut limits = AccountLimits::default();
        limits.set("max_queued=2").unwrap();
        config.account_tokens = vec![AccountToken {
            limits,
            ..AccountToken::new("alice", ALICE)
        }];
        // No workers: every job stays queued.
        config.workers = 0;
    })
    .await;
    let alice = ApiClient::with_token(t.base.clone(), ALICE);
    let capture = alice.upload_capture().await;
    for round in 0..3 {
        let submits = (0..8).map(|_| alice.submit(&capture, train_config(6, 0)));
        let answers = futures_util::future::join_all(submits).await;
        let created = answers.iter().filter(|(status, _)| *status == 201).count();
        for (status, body) in &answers {
            assert!(
                *status == 201 || (*status, error_code(body).0) == (429, "queued_job_limit"),
                "{status} {body}"
            );
        }
        assert_eq!(created, if round == 0 { 2 } else { 0 }, "{answers:?}");
        let (_, info) = alice.get_json("/v1/info").await;
        assert_eq!(info["account"]["usage"]["queued"], 2, "{info}");
    }
    t.server.shutdown().await;
}

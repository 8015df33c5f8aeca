//! Resumable uploads: a capture sent in parts over connections that drop mid-part resumes without
//! resending finished parts and commits into the same capture a one-shot upload makes; parts,
//! digests and commits are checked; idle uploads expire; parts go to the object store when the
//! deployment has one.

mod common;

use std::io::{Read, Write};
use std::time::Duration;

use base64::Engine as _;
use common::s3::TempS3;
use common::*;
use serde_json::{json, Value};
use sha2::{Digest, Sha256};

const PART: usize = 64 << 10;

fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

fn content_digest(bytes: &[u8]) -> String {
    format!(
        "sha-256=:{}:",
        base64::engine::general_purpose::STANDARD.encode(Sha256::digest(bytes))
    )
}

async fn create(t: &ApiClient, body: Value) -> (u16, Value) {
    let response = t
        .client
        .post(t.url("/v1/uploads"))
        .json(&body)
        .send()
        .await
        .unwrap();
    status_and_json(response).await
}

async fn put_part(t: &ApiClient, id: &str, index: usize, bytes: &[u8]) -> reqwest::Response {
    t.client
        .put(t.url(&format!("/v1/uploads/{id}/parts/{index}")))
        .header("content-digest", content_digest(bytes))
        .body(bytes.to_vec())
        .send()
        .await
        .unwrap()
}

async fn commit(t: &ApiClient, id: &str) -> reqwest::Response {
    t.client
        .post(t.url(&format!("/v1/uploads/{id}/commit")))
        .send()
        .await
        .unwrap()
}

/// Sends part `index` on a raw connection that breaks off after half its bytes.
fn drop_mid_part(base: &str, id: &str, index: usize, bytes: &[u8]) {
    let address = base.trim_start_matches("http://");
    let mut stream = std::net::TcpStream::connect(address).unwrap();
    write!(
        stream,
        "PUT /v1/uploads/{id}/parts/{index} HTTP/1.1\r\nHost: {address}\r\n\
         Content-Length: {}\r\nContent-Digest: {}\r\n\r\n",
        bytes.len(),
        content_digest(bytes)
    )
    .unwrap();
    stream.write_all(&bytes[..bytes.len() / 2]).unwrap();
    stream.flush().unwrap();
    std::thread::sleep(Duration::from_millis(200));
    stream.shutdown(std::net::Shutdown::Both).unwrap();
    let mut rest = Vec::new();
    let _ = stream.read_to_end(&mut rest);
}

async fn received(t: &ApiClient, id: &str) -> Vec<u64> {
    let (status, upload) = t.get_json(&format!("/v1/uploads/{id}")).await;
    assert_eq!(status, 200, "{upload}");
    upload["received"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect()
}

/// Files under the data dir's `tmp/` (parts being received are staged there).
fn staged(data_dir: &std::path::Path) -> usize {
    count_files(&data_dir.join("tmp"))
}

/// The upload of `archive` in parts, two of them dropped mid-way first, through to its capture.
async fn upload_with_drops(t: &ApiClient, data_dir: &std::path::Path, archive: &[u8]) -> Value {
    let parts: Vec<&[u8]> = archive.chunks(PART).collect();
    assert!(parts.len() >= 4, "{} parts", parts.len());
    let (status, upload) = create(
        t,
        json!({"size": archive.len(), "part_size": PART, "sha256": sha256_hex(archive)}),
    )
    .await;
    assert_eq!(status, 201, "{upload}");
    assert_eq!(upload["parts"].as_u64(), Some(parts.len() as u64));
    assert_eq!(upload["state"], "open");
    let id = upload["id"].as_str().unwrap().to_owned();

    // Every part but 1 and 2, last first; then 1 and 2 each break off half-way.
    for index in (0..parts.len()).rev().filter(|i| ![1, 2].contains(i)) {
        let response = put_part(t, &id, index, parts[index]).await;
        let (status, part) = status_and_json(response).await;
        assert_eq!(status, 200, "{part}");
        assert_eq!(part["sha256"], sha256_hex(parts[index]));
    }
    drop_mid_part(&t.base, &id, 1, parts[1]);
    drop_mid_part(&t.base, &id, 2, parts[2]);
    let expected: Vec<u64> = (0..parts.len() as u64)
        .filter(|i| *i > 2 || *i == 0)
        .collect();
    let mut waited = 0;
    while staged(data_dir) > 0 && waited < 50 {
        tokio::time::sleep(Duration::from_millis(100)).await;
        waited += 1;
    }
    assert_eq!(staged(data_dir), 0, "a broken part left files behind");
    assert_eq!(received(t, &id).await, expected);
    let message = expect_error(commit(t, &id).await, 409, "upload_incomplete").await;
    assert!(message.starts_with("2 of"), "{message}");

    // Resume: only the missing parts are sent again.
    for (index, part) in parts.iter().enumerate().take(3).skip(1) {
        assert_eq!(put_part(t, &id, index, part).await.status(), 200);
    }
    assert_eq!(received(t, &id).await.len(), parts.len());
    let (status, capture) = status_and_json(commit(t, &id).await).await;
    assert_eq!(status, 201, "{capture}");
    assert_eq!(capture["views"], 10);
    assert_eq!(capture["size_bytes"].as_u64(), Some(archive.len() as u64));

    // Committing again (a client that lost the answer) gives the same capture.
    let (status, again) = status_and_json(commit(t, &id).await).await;
    assert_eq!((status, &again["id"]), (200, &capture["id"]));
    let (_, upload) = t.get_json(&format!("/v1/uploads/{id}")).await;
    assert_eq!(
        (&upload["state"], &upload["capture_id"]),
        (&json!("committed"), &capture["id"])
    );
    expect_error(put_part(t, &id, 0, parts[0]).await, 409, "upload_closed").await;
    capture
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn an_upload_dropped_twice_resumes_without_resending_finished_parts() {
    let (dir, t) = TestServer::start_fresh().await;
    let archive = padded_capture_tar();
    let capture = upload_with_drops(&t, dir.path(), &archive).await;
    // The parts are gone once committed; the capture trains like any other.
    assert_eq!(count_files(&dir.path().join("uploads")), 0);
    let id = t
        .submit_job(capture["id"].as_str().unwrap(), train_config(20, 10))
        .await;
    t.wait_succeeded(&id).await;
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn parts_and_commits_are_checked() {
    let (_dir, t) = TestServer::start_fresh_with(|c| c.max_upload_bytes = 4 << 20).await;
    for (body, status, code) in [
        (json!({"size": 0}), 422, "invalid_upload"),
        (json!({"size": 5 << 20}), 413, "payload_too_large"),
        (
            json!({"size": 100_000, "part_size": 1000}),
            422,
            "invalid_upload",
        ),
        (
            json!({"size": 100_000, "sha256": "abc"}),
            422,
            "invalid_upload",
        ),
        (json!({"size": 100_000, "parts": 3}), 422, "invalid_request"),
    ] {
        let (got, answer) = create(&t, body.clone()).await;
        assert_eq!(
            (got, error_code(&answer).0),
            (status, code),
            "{body}: {answer}"
        );
    }

    let archive = padded_capture_tar();
    let parts: Vec<&[u8]> = archive.chunks(PART).collect();
    let wrong_sha = "0".repeat(64);
    let (_, upload) = create(
        &t,
        json!({"size": archive.len(), "part_size": PART, "sha256": wrong_sha}),
    )
    .await;
    let id = upload["id"].as_str().unwrap().to_owned();
    let url = t.url(&format!("/v1/uploads/{id}/parts/0"));
    let no_digest = t.client.put(&url).body(parts[0].to_vec()).send().await;
    expect_error(no_digest.unwrap(), 400, "digest_required").await;
    let bad_digest = t
        .client
        .put(&url)
        .header("content-digest", "sha-256=:AAAA:")
        .body(parts[0].to_vec())
        .send()
        .await;
    expect_error(bad_digest.unwrap(), 400, "invalid_digest").await;
    let other_bytes = t
        .client
        .put(&url)
        .header("content-digest", content_digest(parts[1]))
        .body(parts[0].to_vec())
        .send()
        .await;
    expect_error(other_bytes.unwrap(), 400, "digest_mismatch").await;
    let short = put_part(&t, &id, 0, &parts[0][..100]).await;
    expect_error(short, 400, "part_size_mismatch").await;
    let past_the_end = put_part(&t, &id, parts.len(), parts[0]).await;
    expect_error(past_the_end, 400, "no_such_part").await;
    assert!(received(&t, &id).await.is_empty());

    // A part sent twice with other bytes: the second replaces the first.
    let mut garbled = parts[0].to_vec();
    garbled[10] ^= 0xff;
    assert_eq!(put_part(&t, &id, 0, &garbled).await.status(), 200);
    for (index, part) in parts.iter().enumerate() {
        assert_eq!(put_part(&t, &id, index, part).await.status(), 200);
    }
    // The archive is right but the declared SHA-256 is not: refused, and refused again.
    let message = expect_error(commit(&t, &id).await, 422, "digest_mismatch").await;
    assert!(message.contains(&sha256_hex(&archive)), "{message}");
    expect_error(commit(&t, &id).await, 422, "digest_mismatch").await;
    let (_, failed) = t.get_json(&format!("/v1/uploads/{id}")).await;
    assert_eq!(failed["state"], "failed");
    assert_eq!(failed["error"]["code"], "digest_mismatch");

    // Not an archive at all: the one-shot upload's answer.
    let junk = vec![7u8; 70_000];
    let (_, upload) = create(&t, json!({"size": junk.len(), "part_size": PART})).await;
    let id = upload["id"].as_str().unwrap().to_owned();
    for (index, part) in junk.chunks(PART).enumerate() {
        assert_eq!(put_part(&t, &id, index, part).await.status(), 200);
    }
    expect_error(commit(&t, &id).await, 415, "unsupported_archive").await;

    // Abandoned on request.
    let (_, upload) = create(&t, json!({"size": 1000})).await;
    let id = upload["id"].as_str().unwrap().to_owned();
    let deleted = t
        .send(reqwest::Method::DELETE, &format!("/v1/uploads/{id}"))
        .await;
    assert_eq!(deleted.status(), 204);
    assert_eq!(t.get_json(&format!("/v1/uploads/{id}")).await.0, 404);
    t.server.shutdown().await;
}

/// A part refused on its path or headers is answered only after its body has been read (up to
/// a bound), so a client still sending megabytes reads the refusal, not a broken pipe.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_part_refused_before_its_body_is_read_still_gets_its_answer() {
    let (_dir, t) = TestServer::start_fresh().await;
    const BIG_PART: usize = 4 << 20;
    let part = vec![7u8; BIG_PART];
    let (status, upload) = create(&t, json!({"size": 2 * BIG_PART, "part_size": BIG_PART})).await;
    assert_eq!(status, 201, "{upload}");
    let id = upload["id"].as_str().unwrap().to_owned();
    let url = t.url(&format!("/v1/uploads/{id}/parts/0"));
    for round in 0..3 {
        let no_digest = t.client.put(&url).body(part.clone()).send().await;
        let no_digest = no_digest.unwrap_or_else(|e| panic!("round {round}: {e:?}"));
        expect_error(no_digest, 400, "digest_required").await;
        let bad_digest = t
            .client
            .put(&url)
            .header("content-digest", "sha-256=:AAAA:")
            .body(part.clone())
            .send()
            .await;
        let bad_digest = bad_digest.unwrap_or_else(|e| panic!("round {round}: {e:?}"));
        expect_error(bad_digest, 400, "invalid_digest").await;
        let past_the_end = t
            .client
            .put(t.url(&format!("/v1/uploads/{id}/parts/2")))
            .header("content-digest", content_digest(&part))
            .body(part.clone())
            .send()
            .await;
        let past_the_end = past_the_end.unwrap_or_else(|e| panic!("round {round}: {e:?}"));
        expect_error(past_the_end, 400, "no_such_part").await;
    }
    assert!(received(&t, &id).await.is_empty());
    // The refusals left the connection usable: a right part is taken.
    assert_eq!(put_part(&t, &id, 0, &part).await.status(), 200);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn idle_uploads_expire_with_their_parts() {
    let (dir, t) = TestServer::start_fresh_with(|c| {
        c.upload_expiry = Duration::from_millis(1500);
        c.retention_sweep = Duration::from_millis(200);
    })
    .await;
    let (_, upload) = create(&t, json!({"size": 200_000, "part_size": PART})).await;
    let id = upload["id"].as_str().unwrap().to_owned();
    assert_eq!(put_part(&t, &id, 0, &[1u8; PART]).await.status(), 200);
    assert_eq!(
        count_files(&dir.path().join("uploads")),
        2,
        "its folder and part"
    );
    tokio::time::sleep(Duration::from_secs(3)).await;
    assert_eq!(t.get_json(&format!("/v1/uploads/{id}")).await.0, 404);
    assert_eq!(count_files(&dir.path().join("uploads")), 0);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn accounts_see_only_their_uploads() {
    let (_dir, t) = TestServer::start_fresh_with(|c| {
        c.account_tokens = vec![
            phygap_api::accounts::auth::AccountToken::new("alice", "alice-token-0123456789"),
            phygap_api::accounts::auth::AccountToken::new("bob", "bob-token-0123456789ab"),
        ];
    })
    .await;
    let alice = ApiClient::with_token(t.base.clone(), "alice-token-0123456789");
    let bob = ApiClient::with_token(t.base.clone(), "bob-token-0123456789ab");
    let (status, upload) = create(&alice, json!({"size": 1000})).await;
    assert_eq!(status, 201, "{upload}");
    let id = upload["id"].as_str().unwrap();
    assert_eq!(alice.get_json(&format!("/v1/uploads/{id}")).await.0, 200);
    assert_eq!(bob.get_json(&format!("/v1/uploads/{id}")).await.0, 404);
    expect_error(put_part(&bob, id, 0, &[0u8; 1000]).await, 404, "not_found").await;
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn parts_go_to_the_object_store() {
    let Some(bucket) = TempS3::start() else {
        return;
    };
    let (dir, t) = TestServer::start_fresh_with(|c| {
        c.artifact_url = Some(bucket.url.clone());
        c.artifact_options = bucket.options();
    })
    .await;
    let store = phygap_api::storage::bucket::Bucket::open(&bucket.url, &bucket.options()).unwrap();
    let (_, upload) = create(&t, json!({"size": 200_000, "part_size": PART})).await;
    let id = upload["id"].as_str().unwrap().to_owned();
    assert_eq!(put_part(&t, &id, 0, &[1u8; PART]).await.status(), 200);
    let stored = store.list("uploads").await.unwrap();
    assert_eq!(stored.len(), 1);
    assert!(
        stored[0].name.starts_with(&format!("{id}/00000.")),
        "{}",
        stored[0].name
    );
    assert_eq!(count_files(&dir.path().join("uploads")), 0, "parts on disk");
    let deleted = t
        .send(reqwest::Method::DELETE, &format!("/v1/uploads/{id}"))
        .await;
    assert_eq!(deleted.status(), 204);
    assert!(store.list("uploads").await.unwrap().is_empty());

    let archive = padded_capture_tar();
    let capture = upload_with_drops(&t, dir.path(), &archive).await;
    assert!(store.list("uploads").await.unwrap().is_empty());
    assert_eq!(
        t.get_json(&format!("/v1/captures/{}", capture["id"].as_str().unwrap()))
            .await
            .0,
        200
    );
    t.server.shutdown().await;
}

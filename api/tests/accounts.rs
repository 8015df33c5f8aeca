//! What a shared deployment needs besides the queue: account tokens that see only their own
//! captures and jobs (the admin token sees all), `/metrics` behind the admin token, `DELETE` of a
//! job with everything stored for it (a running one cancelled first), and the retention sweeper.

mod common;

use std::time::{Duration, Instant};

use common::*;
use phygap_api::accounts::auth::AccountToken;

const ADMIN: &str = "admin-token-0123456789";
const ALICE: &str = "alice-token-0123456789";
const BOB: &str = "bob-token-0123456789ab";

fn with_accounts(config: &mut phygap_api::ServiceConfig) {
    config.token = Some(ADMIN.into());
    config.account_tokens = [("alice", ALICE), ("bob", BOB)]
        .map(|(account, token)| AccountToken::new(account, token))
        .to_vec();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn account_tokens_see_only_their_own_captures_and_jobs() {
    let (_dir, t) = TestServer::start_fresh_with(with_accounts).await;
    let client = |token| ApiClient::with_token(t.base.clone(), token);
    let (admin, alice, bob) = (client(ADMIN), client(ALICE), client(BOB));

    let capture = alice.upload_capture().await;
    let job = alice.submit_job(&capture, train_config(6, 0)).await;
    alice.wait_succeeded(&job).await;
    let (_, listed) = alice.get_json("/v1/jobs").await;
    assert_eq!(listed["jobs"].as_array().unwrap().len(), 1);

    // Bob cannot see, use, read, cancel or delete any of it: it does not exist for him.
    for path in [
        format!("/v1/captures/{capture}"),
        format!("/v1/jobs/{job}"),
        format!("/v1/jobs/{job}/artifacts"),
        format!("/v1/jobs/{job}/artifacts/metrics.json"),
        format!("/v1/jobs/{job}/events"),
    ] {
        let (status, body) = bob.get_json(&path).await;
        assert_eq!((status, error_code(&body).0), (404, "not_found"), "{path}");
    }
    assert_eq!(bob.cancel(&job).await.status(), 404);
    assert_eq!(bob.delete_capture(&capture).await.status(), 404);
    let deleted = bob
        .send(reqwest::Method::DELETE, &format!("/v1/jobs/{job}"))
        .await;
    assert_eq!(deleted.status(), 404);
    let (status, body) = bob.submit(&capture, train_config(6, 0)).await;
    assert_eq!((status, error_code(&body).0), (422, "unknown_capture"));
    let (_, listed) = bob.get_json("/v1/jobs").await;
    assert!(listed["jobs"].as_array().unwrap().is_empty());

    // The same idempotency key from two accounts makes two jobs.
    let bobs_capture = bob.upload_capture().await;
    let body = serde_json::json!({ "capture_id": bobs_capture, "config": train_config(6, 0) });
    let first = bob.post_job(&body, Some("k1")).await;
    assert_eq!(first.status(), 201);
    let body = serde_json::json!({ "capture_id": capture, "config": train_config(6, 0) });
    let other = alice.post_job(&body, Some("k1")).await;
    assert_eq!(other.status(), 201, "a new job, not bob's");

    // The admin sees everyone's jobs; the metrics are the admin's alone.
    let (_, listed) = admin.get_json("/v1/jobs").await;
    assert_eq!(listed["jobs"].as_array().unwrap().len(), 3);
    assert_eq!(admin.get_json(&format!("/v1/jobs/{job}")).await.0, 200);
    assert_eq!(t.send(reqwest::Method::GET, "/metrics").await.status(), 401);
    let (status, body) = alice.get_json("/metrics").await;
    assert_eq!((status, error_code(&body).0), (403, "forbidden"));
    let metrics = admin.send(reqwest::Method::GET, "/metrics").await;
    assert_eq!(metrics.status(), 200);
    assert!(metrics.text().await.unwrap().contains("phygap_"));
    assert_eq!(t.get_json("/healthz").await.0, 200);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn deleting_a_job_removes_its_files_and_cancels_it_first() {
    let (dir, t) = TestServer::start_fresh().await;
    let capture = t.upload_capture().await;
    let done = t.submit_job(&capture, train_config(6, 0)).await;
    t.wait_succeeded(&done).await;
    assert!(!t.artifact_names(&done).await.is_empty());
    assert!(dir.path().join("artifacts").join(&done).is_dir());
    let running = t.submit_job(&capture, train_config(100_000, 0)).await;
    t.wait_state(&running, "running", LONG).await;

    for id in [&done, &running] {
        let deleted = t
            .send(reqwest::Method::DELETE, &format!("/v1/jobs/{id}"))
            .await;
        assert_eq!(deleted.status(), 204, "{id}");
        assert_eq!(t.get_json(&format!("/v1/jobs/{id}")).await.0, 404);
        assert!(!dir.path().join("jobs").join(id).exists(), "{id}");
        assert!(!dir.path().join("artifacts").join(id).exists(), "{id}");
    }
    let again = t
        .send(reqwest::Method::DELETE, &format!("/v1/jobs/{done}"))
        .await;
    assert_eq!(again.status(), 404);
    // With its jobs gone the capture can go too.
    assert_eq!(t.delete_capture(&capture).await.status(), 204);
    assert_eq!(count_files(&dir.path().join("captures")), 0);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn retention_removes_ended_jobs_and_unused_captures() {
    let (dir, t) = TestServer::start_fresh_with(|config| {
        config.retention = Some(Duration::from_secs(2));
        config.retention_sweep = Duration::from_millis(200);
    })
    .await;
    let capture = t.upload_capture().await;
    let job = t.submit_job(&capture, train_config(6, 0)).await;
    t.wait_succeeded(&job).await;
    // The records go first, then the files.
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        let job_gone = t.get_json(&format!("/v1/jobs/{job}")).await.0 == 404;
        let capture_gone = t.get_json(&format!("/v1/captures/{capture}")).await.0 == 404;
        let files_gone = ["captures", "artifacts", "jobs"]
            .iter()
            .all(|folder| count_files(&dir.path().join(folder)) == 0);
        if job_gone && capture_gone && files_gone {
            break;
        }
        assert!(Instant::now() < deadline, "retention did not remove them");
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
    t.server.shutdown().await;
}

//! Fair sharing between accounts (issue 30): the tokens file's limits over the server's defaults
//! — jobs queued (429 queued_job_limit), jobs running at once (the rest wait while other
//! accounts' jobs run), bytes stored (403 storage_quota_exceeded), the priority a token may ask
//! for — and a job's own time limit (it checkpoints and fails `time_limit`; a restart goes on).

mod common;

use common::*;
use phygap_api::accounts::auth::AccountToken;
use phygap_api::accounts::limits::AccountLimits;
use serde_json::json;

const ADMIN: &str = "admin-token-0123456789";
const ALICE: &str = "alice-token-0123456789";
const BOB: &str = "bob-token-0123456789ab";

/// alice: two jobs queued, one running, 1 MiB stored, priority up to 5; bob: the defaults (no
/// limits but priority 0).
fn with_limits(config: &mut phygap_api::ServiceConfig) {
    config.token = Some(ADMIN.into());
    let mut alice = AccountLimits::default();
    for word in [
        "max_queued=2",
        "max_running=1",
        "max_storage_mb=1",
        "max_priority=5",
    ] {
        alice.set(word).unwrap();
    }
    config.account_tokens = vec![
        AccountToken {
            limits: alice,
            ..AccountToken::new("alice", ALICE)
        },
        AccountToken::new("bob", BOB),
    ];
    config.account_defaults.max_priority = Some(0);
}

fn long_job(capture: &str, extra: serde_json::Value) -> serde_json::Value {
    let mut body = json!({ "capture_id": capture, "config": train_config(100_000, 20) });
    body.as_object_mut()
        .unwrap()
        .extend(extra.as_object().unwrap().clone());
    body
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn queued_jobs_priorities_time_limits_and_storage_are_held_to_each_accounts_limits() {
    // No workers: every job stays queued.
    let (_dir, t) = TestServer::start_fresh_with(|config| {
        with_limits(config);
        config.workers = 0;
    })
    .await;
    let client = |token| ApiClient::with_token(t.base.clone(), token);
    let (admin, alice, bob) = (client(ADMIN), client(ALICE), client(BOB));
    let capture = alice.upload_capture().await;

    // Priorities within the token's bounds; time limits of at least a second.
    for (extra, code) in [
        (json!({"priority": 6}), "priority_not_allowed"),
        (json!({"priority": -101}), "priority_not_allowed"),
        (json!({"max_runtime_seconds": 0}), "invalid_max_runtime"),
    ] {
        let body = long_job(&capture, extra.clone());
        expect_error(alice.post_job(&body, None).await, 422, code).await;
    }
    let first = alice
        .post_job(&long_job(&capture, json!({"priority": 5})), Some("k1"))
        .await;
    let (status, first) = status_and_json(first).await;
    assert_eq!((status, &first["priority"]), (201, &json!(5)), "{first}");
    let body = long_job(&capture, json!({"max_runtime_seconds": 600}));
    let (status, second) = status_and_json(alice.post_job(&body, None).await).await;
    assert_eq!((status, &second["max_runtime_seconds"]), (201, &json!(600)));

    // A third queued job is over alice's limit; a retry of the first is still answered.
    let third = alice.post_job(&long_job(&capture, json!({})), None).await;
    let message = expect_error(third, 429, "queued_job_limit").await;
    assert!(message.contains("2 jobs queued"), "{message}");
    let retry = alice
        .post_job(&long_job(&capture, json!({"priority": 5})), Some("k1"))
        .await;
    let (status, again) = status_and_json(retry).await;
    assert_eq!((status, &again["id"]), (200, &first["id"]));

    // bob's own capture and jobs; his priority bound is the server's default (0). The admin may
    // ask for any priority.
    let bobs = bob.upload_capture().await;
    let body = long_job(&bobs, json!({"priority": 1}));
    expect_error(bob.post_job(&body, None).await, 422, "priority_not_allowed").await;
    for _ in 0..3 {
        let (status, _) =
            status_and_json(bob.post_job(&long_job(&bobs, json!({})), None).await).await;
        assert_eq!(status, 201);
    }
    let body = long_job(&bobs, json!({"priority": 100}));
    assert_eq!(admin.post_job(&body, None).await.status(), 201);

    // Once one of alice's jobs is cancelled, she may queue another.
    assert_eq!(
        alice.cancel(first["id"].as_str().unwrap()).await.status(),
        200
    );
    let body = long_job(&capture, json!({}));
    assert_eq!(alice.post_job(&body, None).await.status(), 201);

    // What alice may hold and holds, in /v1/info.
    let (_, info) = alice.get_json("/v1/info").await;
    let account = &info["account"];
    assert_eq!(account["name"], "alice", "{info}");
    assert_eq!(account["limits"]["max_queued"], 2);
    assert_eq!(account["limits"]["max_storage_bytes"], 1 << 20);
    assert_eq!(account["usage"]["queued"], 2);
    let stored = account["usage"]["stored_bytes"].as_u64().unwrap();
    assert!(stored > 0 && stored < 1 << 20, "{info}");
    assert_eq!(admin.get_json("/v1/info").await.1["account"], json!(null));

    // Storage: an upload that would pass alice's 1 MiB is refused before any byte is kept,
    // resumable or one-shot; bob has no quota.
    let (status, body) = status_and_json(
        alice
            .client
            .post(alice.url("/v1/uploads"))
            .json(&json!({ "size": 1 << 20 }))
            .send()
            .await
            .unwrap(),
    )
    .await;
    assert_eq!(
        (status, error_code(&body).0),
        (403, "storage_quota_exceeded"),
        "{body}"
    );
    let big = vec![0u8; 1 << 20];
    let (status, body) = alice.upload(big.clone()).await;
    assert_eq!(
        (status, error_code(&body).0),
        (403, "storage_quota_exceeded"),
        "{body}"
    );
    let (status, body) = bob.upload(big).await;
    assert_ne!(
        error_code(&body).0,
        "storage_quota_exceeded",
        "{status} {body}"
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn an_account_at_its_running_limit_waits_while_others_run() {
    let (_dir, t) = TestServer::start_fresh_with(|config| {
        with_limits(config);
        config.workers = 2;
    })
    .await;
    let client = |token| ApiClient::with_token(t.base.clone(), token);
    let (alice, bob) = (client(ALICE), client(BOB));
    let (alices, bobs) = (alice.upload_capture().await, bob.upload_capture().await);
    // alice's two jobs first, bob's last: with two workers, bob's runs beside alice's first.
    let a1 = submit_long(&alice, &alices).await;
    let a2 = submit_long(&alice, &alices).await;
    let b1 = submit_long(&bob, &bobs).await;
    alice.wait_state(&a1, "running", LONG).await;
    bob.wait_state(&b1, "running", LONG).await;
    let (_, waiting) = alice.get_json(&format!("/v1/jobs/{a2}")).await;
    assert_eq!(waiting["state"], "queued", "{waiting}");
    // When alice's first ends, her second starts.
    alice.cancel(&a1).await;
    alice.wait_state(&a1, "cancelled", LONG).await;
    alice.wait_state(&a2, "running", LONG).await;
    for (who, job) in [(&alice, &a2), (&bob, &b1)] {
        who.cancel(job).await;
        who.wait_state(job, "cancelled", LONG).await;
    }
    t.server.shutdown().await;
}

/// Queues a long training job of `capture` and returns its id.
async fn submit_long(who: &ApiClient, capture: &str) -> String {
    let (status, job) =
        status_and_json(who.post_job(&long_job(capture, json!({})), None).await).await;
    assert_eq!(status, 201, "{job}");
    job["id"].as_str().unwrap().to_owned()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_job_past_its_own_time_limit_checkpoints_fails_and_restarts() {
    let (_dir, t) = TestServer::start_fresh().await;
    let capture = t.upload_capture().await;
    let body = long_job(&capture, json!({"max_runtime_seconds": 3}));
    let (status, job) = status_and_json(t.post_job(&body, None).await).await;
    assert_eq!(status, 201, "{job}");
    let id = job["id"].as_str().unwrap();
    let failed = t.wait_state(id, "failed", LONG).await;
    assert_eq!(failed["error_code"], "time_limit", "{failed}");
    let error = failed["error"].as_str().unwrap();
    assert!(
        error.contains("3 s") && error.contains("checkpointed"),
        "{error}"
    );
    let stopped_at = failed["iteration"].as_u64().unwrap();
    assert!(stopped_at > 0, "{failed}");
    // A restart goes on from the checkpoint, with a fresh time limit.
    let restarted = t
        .client
        .post(t.url(&format!("/v1/jobs/{id}/restart")))
        .send()
        .await
        .unwrap();
    assert_eq!(restarted.status(), 200);
    let running = t.wait_state(id, "running", LONG).await;
    assert_eq!(running["max_runtime_seconds"], 3);
    let again = t.wait_state(id, "failed", LONG).await;
    assert_eq!(again["error_code"], "time_limit", "{again}");
    assert!(
        again["resumed_from"].as_u64().is_some_and(|from| from > 0),
        "{again}"
    );
    t.server.shutdown().await;
}

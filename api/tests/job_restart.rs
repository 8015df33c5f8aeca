//! `POST /v1/jobs/{id}/restart`: a cancelled or failed job runs again under its id, resuming
//! from its last checkpoint, or over from the start when its settings change; jobs that did not
//! fail and bad settings are refused.

mod common;

use common::*;
use serde_json::{json, Value};

async fn restart(t: &TestServer, id: &str, body: Option<Value>) -> reqwest::Response {
    let mut request = t.client.post(t.url(&format!("/v1/jobs/{id}/restart")));
    if let Some(body) = body {
        request = request.json(&body);
    }
    request.send().await.unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_cancelled_job_resumes_or_starts_over_with_new_settings() {
    let (_dir, t) = TestServer::start_fresh().await;
    let id = t.start_training(400, 25).await;
    t.wait_iteration(&id, 60).await;
    t.cancel(&id).await;
    let cancelled = t.wait_state(&id, "cancelled", LONG).await;
    assert_eq!(cancelled["state"], "cancelled", "{cancelled}");
    let stopped_at = cancelled["iteration"].as_u64().unwrap();

    // Unchanged: it resumes from the checkpoint written when it stopped.
    let (status, job) = status_and_json(restart(&t, &id, None).await).await;
    assert_eq!(
        (status, job["state"].as_str()),
        (200, Some("queued")),
        "{job}"
    );
    assert_eq!(job["error"], Value::Null);
    let done = t.wait_succeeded(&id).await;
    assert_eq!(done["resumed_from"].as_u64(), Some(stopped_at), "{done}");
    assert_eq!(done["iteration"], 400);

    // A succeeded job does not restart.
    let refused = restart(&t, &id, None).await;
    expect_error(refused, 409, "job_not_restartable").await;

    // Changed settings on a cancelled job: over from the start, with them.
    let id = t.start_training(400, 25).await;
    t.wait_iteration(&id, 30).await;
    t.cancel(&id).await;
    t.wait_state(&id, "cancelled", LONG).await;
    let (status, job) =
        status_and_json(restart(&t, &id, Some(json!({"config": {"iterations": 60}}))).await).await;
    assert_eq!(status, 200, "{job}");
    assert_eq!(
        (
            job["attempts"].as_u64(),
            job["config"]["iterations"].as_u64()
        ),
        (Some(0), Some(60))
    );
    let done = t.wait_succeeded(&id).await;
    assert_eq!(
        (done["iteration"].as_u64(), done["resumed_from"].as_u64()),
        (Some(60), None),
        "{done}"
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn bad_restarts_are_refused() {
    let (_dir, t) = TestServer::start_fresh_with(|c| c.workers = 0).await;
    let id = t.start_training(20, 10).await;
    expect_error(restart(&t, &id, None).await, 409, "job_not_restartable").await;
    t.cancel(&id).await;
    let bad_key = restart(&t, &id, Some(json!({"config": {"iteratons": 5}}))).await;
    expect_error(bad_key, 422, "invalid_config").await;
    let bad_value = restart(&t, &id, Some(json!({"config": {"max_surfels": 0}}))).await;
    expect_error(bad_value, 422, "invalid_config").await;
    let unknown = restart(&t, &id, Some(json!({"settings": {}}))).await;
    expect_error(unknown, 422, "invalid_request").await;
    expect_error(restart(&t, "job_none", None).await, 404, "not_found").await;
    t.server.shutdown().await;
}

//! Several service processes on one PostgreSQL database and one data dir (the scale-out topology
//! on one machine): every job runs exactly once whichever API took it, a worker's cancel reaches
//! across processes, and a database outage is a 503 that loses nothing. Needs PostgreSQL (see
//! `common::postgres`).

mod common;

use common::postgres::TempPostgres;
use common::*;
use serde_json::Value;

/// A server on `data_dir` whose records live in the cluster's database.
async fn replica(cluster: &TempPostgres, data_dir: &std::path::Path, workers: usize) -> TestServer {
    let mut config = test_config(data_dir);
    config.database_url = Some(cluster.url.clone());
    config.workers = workers;
    TestServer::start(config).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn jobs_submitted_through_two_apis_run_exactly_once_on_their_workers() {
    let Some(cluster) = TempPostgres::start() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (
        replica(&cluster, dir.path(), 1).await,
        replica(&cluster, dir.path(), 1).await,
    );
    // A capture uploaded through one API is seen by the other.
    let capture = a.upload_capture().await;
    assert_eq!(b.get_json(&format!("/v1/captures/{capture}")).await.0, 200);
    let mut ids = Vec::new();
    for i in 0..6 {
        let api = if i % 2 == 0 { &a } else { &b };
        ids.push(api.submit_job(&capture, train_config(6, 0)).await);
    }
    let mut backends = std::collections::HashSet::new();
    for (i, id) in ids.iter().enumerate() {
        // Each API answers for every job, whichever took it.
        let api = if i % 2 == 0 { &b } else { &a };
        let job: Value = api.wait_succeeded(id).await;
        assert_eq!(job["attempts"], 1, "{job}");
        backends.insert(job["backend"].to_string());
    }
    let (_, listed) = a.get_json("/v1/jobs").await;
    assert_eq!(listed["jobs"].as_array().unwrap().len(), 6);
    // A cancel through one API stops a job that the other's worker may be running.
    let long = a.submit_job(&capture, train_config(100_000, 0)).await;
    b.wait_state(&long, "running", LONG).await;
    assert_eq!(b.cancel(&long).await.status(), 200);
    let cancelled = a.wait_state(&long, "cancelled", LONG).await;
    assert_eq!(cancelled["state"], "cancelled");
    a.server.shutdown().await;
    b.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_database_outage_is_a_503_and_nothing_stored_is_lost() {
    let Some(cluster) = TempPostgres::start() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let t = replica(&cluster, dir.path(), 0).await;
    let capture = t.upload_capture().await;
    let job = t.submit_job(&capture, train_config(6, 0)).await;
    cluster.stop_server();
    let message = expect_error(
        t.send(reqwest::Method::GET, &format!("/v1/jobs/{job}"))
            .await,
        503,
        "store_unavailable",
    )
    .await;
    assert!(message.contains("try again"), "{message}");
    assert_eq!(t.get_json("/healthz").await.0, 503);
    cluster.start_server();
    assert_eq!(t.get_json("/healthz").await.0, 200);
    let (status, stored) = t.get_json(&format!("/v1/jobs/{job}")).await;
    assert_eq!((status, stored["state"].as_str()), (200, Some("queued")));
    t.server.shutdown().await;
}

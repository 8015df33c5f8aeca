//! The scaled-out topology: an API process and worker processes, each with its own data dir (as
//! on separate machines), sharing one PostgreSQL database and one S3-compatible bucket. A job
//! submitted to the API runs on a worker that fetches the capture from the bucket; its artifacts
//! are served by the API from the bucket; a job stopped on one worker resumes on another from the
//! checkpoint in the bucket; a bucket outage is a 503 that records nothing. Needs PostgreSQL and
//! moto (see `common::postgres`, `common::s3`).

mod common;

use common::postgres::TempPostgres;
use common::s3::TempS3;
use common::*;
use phygap_api::ServiceConfig;

/// A process of the deployment on its own fresh data dir.
async fn process(
    cluster: &TempPostgres,
    bucket: &TempS3,
    configure: impl FnOnce(&mut ServiceConfig),
) -> (tempfile::TempDir, TestServer) {
    let dir = tempfile::tempdir().unwrap();
    let mut config = test_config(dir.path());
    config.database_url = Some(cluster.url.clone());
    config.artifact_url = Some(bucket.url.clone());
    config.artifact_options = bucket.options();
    configure(&mut config);
    let server = TestServer::start(config).await;
    (dir, server)
}

/// An API process that runs no jobs.
async fn api(cluster: &TempPostgres, bucket: &TempS3) -> (tempfile::TempDir, TestServer) {
    process(cluster, bucket, |c| c.workers = 0).await
}

/// A worker process: one job at a time, no `/v1` routes.
async fn worker(cluster: &TempPostgres, bucket: &TempS3) -> (tempfile::TempDir, TestServer) {
    process(cluster, bucket, |c| {
        c.workers = 1;
        c.api = false;
    })
    .await
}

fn servers() -> Option<(TempPostgres, TempS3)> {
    Some((TempPostgres::start()?, TempS3::start()?))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_worker_elsewhere_runs_the_job_and_the_api_serves_its_artifacts_from_the_bucket() {
    let Some((cluster, bucket)) = servers() else {
        return;
    };
    let (api_dir, api) = api(&cluster, &bucket).await;
    let (worker_dir, worker) = worker(&cluster, &bucket).await;
    // The worker's listener answers health checks, not the API.
    assert_eq!(worker.get_json("/healthz").await.0, 200);
    assert_eq!(worker.get_json("/v1/jobs").await.0, 404);

    let capture = api.upload_capture().await;
    let job = api.submit_job(&capture, train_config(8, 4)).await;
    let done = api.wait_succeeded(&job).await;
    assert_eq!(done["attempts"], 1, "{done}");
    // The worker fetched the capture it had never seen from the bucket.
    assert!(worker_dir
        .path()
        .join("captures")
        .join(&capture)
        .join("transforms.json")
        .is_file());
    // The API serves artifacts it never had on disk.
    let names = api.artifact_names(&job).await;
    assert!(names.iter().any(|n| n == "mesh.ply"), "{names:?}");
    assert_eq!(count_files(&api_dir.path().join("artifacts")), 0);
    let whole = api
        .send(
            reqwest::Method::GET,
            &format!("/v1/jobs/{job}/artifacts/metrics.json"),
        )
        .await;
    assert_eq!(whole.status(), 200);
    let metrics: serde_json::Value = whole.json().await.unwrap();
    assert!(metrics["psnr"].is_number(), "{metrics}");
    let part = api
        .get_range(&format!("/v1/jobs/{job}/artifacts/mesh.ply"), "bytes=0-2")
        .await;
    assert_eq!(part.status(), 206);
    assert_eq!(&part.bytes().await.unwrap()[..], b"ply");

    // A relight job (its inputs uploaded to the API) runs on the worker, which fetches them and
    // the parent's model from the bucket.
    let envmap_path = api_dir.path().join("sky.exr");
    phygap::formats::image_io::write_exr(
        &envmap_path,
        &phygap::formats::image_io::Image::filled(8, 4, 3, 2.0),
    )
    .unwrap();
    let response = api
        .relight(&job, std::fs::read(&envmap_path).unwrap(), "0")
        .await;
    assert_eq!(response.status(), 201);
    let relight: serde_json::Value = response.json().await.unwrap();
    let relight_id = relight["id"].as_str().unwrap();
    api.wait_succeeded(relight_id).await;
    let names = api.artifact_names(relight_id).await;
    assert!(names.iter().any(|n| n == "s0/000.exr"), "{names:?}");
    worker.server.shutdown().await;
    api.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_job_stopped_on_one_worker_resumes_on_another_from_the_bucket_checkpoint() {
    let Some((cluster, bucket)) = servers() else {
        return;
    };
    let (_api_dir, api) = api(&cluster, &bucket).await;
    let (_first_dir, first) = worker(&cluster, &bucket).await;
    let capture = api.upload_capture().await;
    let job = api.submit_job(&capture, train_config(400, 20)).await;
    let running = api.wait_iteration(&job, 45).await;
    assert_eq!(running["state"], "running", "{running}");
    // The first machine goes away (SIGTERM: it checkpoints, uploads and requeues the job) and
    // its data dir with it.
    first.server.shutdown().await;
    drop(_first_dir);
    let (_second_dir, second) = worker(&cluster, &bucket).await;
    let done = api.wait_succeeded(&job).await;
    let resumed_from = done["resumed_from"].as_u64().unwrap_or(0);
    assert!(
        resumed_from >= 40,
        "resumed from the bucket's checkpoint: {done}"
    );
    assert_eq!(done["attempts"], 2, "{done}");
    assert!(api
        .artifact_names(&job)
        .await
        .iter()
        .any(|n| n == "mesh.ply"));
    second.server.shutdown().await;
    api.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_bucket_outage_is_a_503_and_records_nothing() {
    let Some((cluster, mut bucket)) = servers() else {
        return;
    };
    let (api_dir, api) = api(&cluster, &bucket).await;
    bucket.stop();
    let message = expect_error(
        api.post_body("/v1/captures", capture_zip()).await,
        503,
        "storage_unavailable",
    )
    .await;
    assert!(message.contains("try again"), "{message}");
    assert_eq!(count_files(&api_dir.path().join("captures")), 0);
    let (status, jobs) = api.get_json("/v1/jobs").await;
    assert_eq!(
        (status, jobs["jobs"].as_array().map(Vec::len)),
        (200, Some(0))
    );
    api.server.shutdown().await;
}

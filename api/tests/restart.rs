//! Durability: jobs survive restarts. A queued job runs after a restart; a job interrupted by a
//! graceful shutdown goes back to the queue (not cancelled) and resumes from its checkpoint; a job
//! whose server process is killed with SIGKILL mid-training is requeued when its lease expires and
//! resumes from its last periodic checkpoint on the next server.

mod common;

use std::path::Path;
use std::time::{Duration, Instant};

use common::*;
use phygap_api::storage::store::{JobState, SqliteStore, Store};

const CHILD_DIR_VAR: &str = "PHYGAP_API_TEST_CHILD_DATA_DIR";

async fn stored_state(data_dir: &Path, id: &str) -> (JobState, u32) {
    let store = SqliteStore::open(&data_dir.join("phygap.sqlite3")).unwrap();
    let job = store.job(id).await.unwrap().unwrap();
    (job.state, job.progress.iteration)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn queued_job_runs_after_restart() {
    let (dir, t) = TestServer::start_fresh_with(|config| config.workers = 0).await;
    let id = t.start_training(20, 10).await;
    t.server.shutdown().await;
    assert_eq!(stored_state(dir.path(), &id).await.0, JobState::Queued);

    let t = TestServer::start_on(dir.path()).await;
    let done = t.wait_succeeded(&id).await;
    assert_eq!(
        (done["attempts"].as_u64(), done["resumed_from"].as_u64()),
        (Some(1), None)
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn graceful_shutdown_requeues_a_running_job_which_then_resumes() {
    let (dir, t) = TestServer::start_fresh().await;
    let id = t.start_training(300, 1000).await;
    t.wait_iteration(&id, 30).await;
    t.server.shutdown().await;
    let (state, iteration) = stored_state(dir.path(), &id).await;
    assert_eq!(state, JobState::Queued, "a shutdown is not a cancel");
    assert!((30..300).contains(&iteration), "{iteration}");

    let t = TestServer::start_on(dir.path()).await;
    let done = t.wait_succeeded(&id).await;
    assert_eq!(done["attempts"], 2);
    // It resumed from the checkpoint written at the shutdown (no periodic one before 1000).
    assert_eq!(
        done["resumed_from"].as_u64(),
        Some(iteration as u64),
        "{done}"
    );
    assert_eq!(done["iteration"], 300);
    t.server.shutdown().await;
}

/// Not a test of its own: the server process that `killed_server_job_resumes_on_the_next_server`
/// starts (this test binary re-run with `--ignored --exact`) and kills with SIGKILL.
#[test]
#[ignore = "child process of killed_server_job_resumes_on_the_next_server"]
fn child_server_process() {
    let Ok(data_dir) = std::env::var(CHILD_DIR_VAR) else {
        return;
    };
    let runtime = tokio::runtime::Runtime::new().unwrap();
    runtime.block_on(async {
        let t = TestServer::start_on(Path::new(&data_dir)).await;
        let addr_file = Path::new(&data_dir).join("child_addr.txt");
        std::fs::write(addr_file.with_extension("tmp"), &t.base).unwrap();
        std::fs::rename(addr_file.with_extension("tmp"), &addr_file).unwrap();
        // Serve until killed; exit by itself after two minutes at most.
        tokio::time::sleep(Duration::from_secs(120)).await;
    });
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn killed_server_job_resumes_on_the_next_server() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = std::process::Command::new(std::env::current_exe().unwrap())
        .args([
            "child_server_process",
            "--exact",
            "--ignored",
            "--nocapture",
        ])
        .env(CHILD_DIR_VAR, dir.path())
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let addr_file = dir.path().join("child_addr.txt");
    let deadline = Instant::now() + LONG;
    while !addr_file.exists() {
        assert!(Instant::now() < deadline, "child server did not start");
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    let child_api = ApiClient::new(std::fs::read_to_string(&addr_file).unwrap());
    let id = child_api.start_training(400, 25).await;
    child_api.wait_iteration(&id, 60).await;
    child.kill().unwrap(); // SIGKILL: no shutdown, no checkpoint at the interruption
    child.wait().unwrap();
    let (state, killed_at) = stored_state(dir.path(), &id).await;
    assert_eq!(state, JobState::Running, "the dead process left it running");

    let t = TestServer::start_on(dir.path()).await;
    let done = t.wait_succeeded(&id).await;
    assert_eq!(done["attempts"], 2, "{done}");
    assert_eq!(done["iteration"], 400);
    let resumed = done["resumed_from"].as_u64().unwrap();
    assert!(
        resumed >= 50 && resumed % 25 == 0,
        "resumed from a periodic checkpoint: {resumed}"
    );
    assert!(
        resumed < 400 && killed_at >= 60,
        "resumed at {resumed}, killed at {killed_at}"
    );
    let names = t.artifact_names(&id).await;
    for expected in ["surfels.ply", "envmap.exr", "metrics.json"] {
        assert!(
            names.iter().any(|name| name == expected),
            "{expected} in {names:?}"
        );
    }
    t.server.shutdown().await;
}

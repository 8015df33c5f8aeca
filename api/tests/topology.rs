//! The scaled-out deployment as processes: `deploy/local-cluster.sh` starts PostgreSQL, an
//! S3-compatible server, two `phygap-api serve --workers 0` processes and three `phygap-api
//! worker` processes, each on its own data dir, and this test uses them as clients would: 30
//! short jobs submitted through both APIs all succeed exactly once; `kill -9` of the worker running
//! a long job lets another worker resume it from its last checkpoint; 100 concurrent pollers
//! across both APIs are all answered (their latencies are printed, not asserted); `kill -9` of one
//! API leaves the other's clients without an error. Needs PostgreSQL and moto, like
//! `scale_out.rs`.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use common::*;
use serde_json::Value;

/// A started cluster, stopped on drop.
struct Cluster {
    dir: tempfile::TempDir,
    env: BTreeMap<String, String>,
}

fn script() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../deploy/local-cluster.sh")
}

/// Whether the servers the cluster needs are installed (else a notice, or a failure under CI).
fn servers_installed() -> bool {
    let postgres = std::fs::read_dir("/usr/lib/postgresql")
        .map(|versions| {
            versions
                .flatten()
                .any(|v| v.path().join("bin/initdb").is_file())
        })
        .unwrap_or(false);
    let moto = Command::new("python3")
        .args(["-c", "import moto.server"])
        .status()
        .is_ok_and(|s| s.success());
    if postgres && moto {
        return true;
    }
    let notice = "the local cluster needs PostgreSQL (apt-get install postgresql) and moto \
                  (pip install 'moto[server]'); skipping the topology test";
    assert!(!phygap::testing::running_in_ci(), "{notice}");
    eprintln!("notice: {notice}");
    false
}

impl Cluster {
    fn start() -> Cluster {
        let dir = tempfile::tempdir().unwrap();
        let status = Command::new("bash")
            .arg(script())
            .arg("start")
            .arg(dir.path())
            .env("PHYGAP_API_BIN", env!("CARGO_BIN_EXE_phygap-api"))
            .env("PHYGAP_LEASE_SECONDS", "3")
            .env("RUST_LOG", "warn")
            .status()
            .expect("running deploy/local-cluster.sh");
        // Owned before the status is checked, so a half-started cluster is stopped too.
        let mut cluster = Cluster {
            env: BTreeMap::new(),
            dir,
        };
        assert!(status.success(), "the cluster did not start");
        let text = std::fs::read_to_string(cluster.dir.path().join("cluster.env")).unwrap();
        cluster.env = text
            .lines()
            .filter_map(|l| l.split_once('='))
            .map(|(k, v)| (k.to_owned(), v.to_owned()))
            .collect();
        cluster
    }

    fn api(&self, index: usize) -> ApiClient {
        ApiClient::new(self.env[&format!("API_{index}")].clone())
    }

    fn pid(&self, name: &str) -> i32 {
        let path = self.dir.path().join("pids").join(format!("{name}.pid"));
        std::fs::read_to_string(path)
            .unwrap()
            .trim()
            .parse()
            .unwrap()
    }

    fn kill_9(&self, name: &str) {
        let status = Command::new("kill")
            .args(["-9", &self.pid(name).to_string()])
            .status()
            .unwrap();
        assert!(status.success(), "kill -9 {name}");
    }

    /// The workers whose data dirs hold the job's model folder (that ran it).
    fn workers_of(&self, job: &str) -> Vec<String> {
        (1..=3)
            .map(|i| format!("worker_{i}"))
            .filter(|name| {
                self.dir
                    .path()
                    .join(name)
                    .join("jobs")
                    .join(job)
                    .join("model")
                    .is_dir()
            })
            .collect()
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let _ = Command::new("bash")
            .arg(script())
            .arg("stop")
            .arg(self.dir.path())
            .status();
    }
}

fn percentile(sorted: &[Duration], p: f64) -> Duration {
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

/// 100 concurrent pollers spread over `apis`, 20 reads each of the job's view: every read is
/// answered; the latencies are printed (a figure for the README, never a timed assertion).
async fn report_latencies(when: &str, apis: &[&ApiClient], job: &str) {
    let mut pollers = Vec::new();
    for i in 0..100 {
        let api = apis[i % apis.len()];
        let (client, url) = (api.client.clone(), api.url(&format!("/v1/jobs/{job}")));
        pollers.push(tokio::spawn(async move {
            let mut latencies = Vec::new();
            for _ in 0..20 {
                let start = Instant::now();
                let response = client.get(&url).send().await.unwrap();
                assert_eq!(response.status(), 200);
                response.bytes().await.unwrap();
                latencies.push(start.elapsed());
            }
            latencies
        }));
    }
    let mut latencies = Vec::new();
    for poller in pollers {
        latencies.extend(poller.await.unwrap());
    }
    latencies.sort();
    println!(
        "GET /v1/jobs/{{id}} {when}, 100 pollers on {} APIs, {} requests: p50 {:.2} ms, p99 {:.2} ms",
        apis.len(),
        latencies.len(),
        percentile(&latencies, 0.5).as_secs_f64() * 1e3,
        percentile(&latencies, 0.99).as_secs_f64() * 1e3
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_local_cluster_runs_jobs_once_and_survives_killed_processes() {
    if !servers_installed() {
        return;
    }
    let cluster = Cluster::start();
    let (api_1, api_2) = (cluster.api(1), cluster.api(2));

    // 30 short jobs through both APIs: each succeeds, on its first attempt.
    let capture = api_1.upload_capture().await;
    let mut jobs = Vec::new();
    for i in 0..30 {
        let api = if i % 2 == 0 { &api_1 } else { &api_2 };
        jobs.push(api.submit_job(&capture, train_config(8, 0)).await);
    }
    for (i, job) in jobs.iter().enumerate() {
        let api = if i % 2 == 0 { &api_2 } else { &api_1 };
        let done = api.wait_succeeded(job).await;
        assert_eq!(done["attempts"], 1, "ran exactly once: {done}");
    }
    let (_, listed) = api_2.get_json("/v1/jobs").await;
    assert_eq!(listed["jobs"].as_array().unwrap().len(), 30);

    // A long job; kill -9 the worker running it once it has checkpointed.
    let long = api_1.submit_job(&capture, train_config(300, 20)).await;
    api_1.wait_iteration(&long, 45).await;
    let owners = cluster.workers_of(&long);
    assert_eq!(owners.len(), 1, "one worker runs the job: {owners:?}");
    let owner = owners[0].clone();

    // 100 pollers across both APIs while it trains.
    report_latencies("while a job trains", &[&api_1, &api_2], &long).await;

    cluster.kill_9(&owner);
    let done = api_2.wait_succeeded(&long).await;
    assert_eq!(done["attempts"], 2, "{done}");
    let resumed_from = done["resumed_from"].as_u64().unwrap_or(0);
    assert!(resumed_from >= 40, "resumed from a checkpoint: {done}");
    let owners = cluster.workers_of(&long);
    assert_eq!(
        owners.len(),
        2,
        "another worker finished the job: {owners:?}"
    );
    report_latencies("with no job running", &[&api_1, &api_2], &long).await;

    // kill -9 of one API: the other's clients see no error, before, during or after.
    let watcher = {
        let (client, url) = (api_2.client.clone(), api_2.url(&format!("/v1/jobs/{long}")));
        tokio::spawn(async move {
            let deadline = Instant::now() + Duration::from_secs(3);
            let mut answered = 0;
            while Instant::now() < deadline {
                let response = client.get(&url).send().await.unwrap();
                assert_eq!(response.status(), 200);
                let job: Value = response.json().await.unwrap();
                assert_eq!(job["state"], "succeeded");
                answered += 1;
            }
            answered
        })
    };
    tokio::time::sleep(Duration::from_millis(500)).await;
    cluster.kill_9("api_1");
    let answered = watcher.await.unwrap();
    assert!(answered > 10, "{answered}");
    let after = api_2.submit_job(&capture, train_config(8, 0)).await;
    api_2.wait_succeeded(&after).await;
}

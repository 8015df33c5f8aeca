//! Shared harness of the integration tests: a real server on loopback over the real core, each
//! job stage in a process of its own as in production ([`test_pipeline`]), a reqwest client,
//! capture archives built on the fly (small synthetic captures from `phygap::pipeline::synth`)
//! and bounded polling.

#![allow(dead_code)]

pub mod postgres;
pub mod process;
pub mod s3;

use std::io::Write;
use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, Instant};

use phygap::pipeline::synth::{synth, SynthOptions};
use phygap_api::jobs::child_process_runner::ProcessPipeline;
use phygap_api::jobs::pipeline_seam::Pipeline;
use phygap_api::{Server, ServiceConfig};
use serde_json::{json, Value};
use tempfile::TempDir;

/// The pipeline a server with `config` runs on, as in production: every stage in a child
/// process (`phygap-api stage`, this package's binary) under the config's limits.
pub fn test_pipeline(config: &ServiceConfig) -> Arc<dyn Pipeline> {
    Arc::new(ProcessPipeline::for_service(
        env!("CARGO_BIN_EXE_phygap-api").into(),
        &config.limits,
    ))
}

/// A small valid capture folder: a 10-view 24×24 full-Stokes sphere rendered by `phygap synth`.
pub fn write_capture(dir: &Path) {
    let options = SynthOptions {
        views: 10,
        size: 24,
        ..SynthOptions::default()
    };
    synth(dir, &options).unwrap();
}

/// Every file under `dir` as (relative name, bytes), sorted.
pub fn files_of(dir: &Path) -> Vec<(String, Vec<u8>)> {
    fn walk(dir: &Path, prefix: &str, out: &mut Vec<(String, Vec<u8>)>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let entry = entry.unwrap();
            let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
            if entry.file_type().unwrap().is_dir() {
                walk(&entry.path(), &format!("{name}/"), out);
            } else {
                out.push((name, std::fs::read(entry.path()).unwrap()));
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, "", &mut out);
    out.sort();
    out
}

/// A zip of arbitrary (name, bytes) entries.
pub fn zip_of(entries: &[(String, Vec<u8>)]) -> Vec<u8> {
    let mut writer = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (name, data) in entries {
        writer.start_file(name.as_str(), options).unwrap();
        writer.write_all(data).unwrap();
    }
    writer.finish().unwrap().into_inner()
}

/// A tar of arbitrary (name, bytes) entries.
pub fn tar_of(entries: &[(String, Vec<u8>)]) -> Vec<u8> {
    let mut builder = tar::Builder::new(Vec::new());
    for (name, data) in entries {
        let mut header = tar::Header::new_ustar();
        header.set_size(data.len() as u64);
        header.set_mode(0o644);
        builder
            .append_data(&mut header, name, data.as_slice())
            .unwrap();
    }
    builder.into_inner().unwrap()
}

/// The test capture as a zip, under a top-level folder `capture/` as users zip folders.
pub fn capture_zip() -> Vec<u8> {
    let dir = tempfile::tempdir().unwrap();
    write_capture(dir.path());
    let entries: Vec<_> = files_of(dir.path())
        .into_iter()
        .map(|(name, data)| (format!("capture/{name}"), data))
        .collect();
    zip_of(&entries)
}

/// The test capture as a tar (files at the top level).
pub fn capture_tar() -> Vec<u8> {
    let dir = tempfile::tempdir().unwrap();
    write_capture(dir.path());
    tar_of(&files_of(dir.path()))
}

/// The test capture as a tar with an extra file of 300 kB of noise, so that it spans several
/// parts of a resumable upload (the loader ignores files transforms.json does not name).
pub fn padded_capture_tar() -> Vec<u8> {
    let dir = tempfile::tempdir().unwrap();
    write_capture(dir.path());
    let mut entries = files_of(dir.path());
    let noise: Vec<u8> = (0..300_000u32)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    entries.push(("notes/noise.bin".into(), noise));
    tar_of(&entries)
}

/// A small training config: `iterations` steps, checkpoints every `checkpoint_interval`.
pub fn train_config(iterations: u32, checkpoint_interval: u32) -> Value {
    json!({
        "iterations": iterations,
        "checkpoint_interval": checkpoint_interval,
        "eval_interval": checkpoint_interval,
        "initial_surfels": 100,
        "max_surfels": 1000,
        // The service is under test here, not GridMap (which adds mesh and probe builds per job).
        "gridmap": false,
    })
}

/// Loopback config with short leases and fast polling.
pub fn test_config(data_dir: &Path) -> ServiceConfig {
    let mut config = ServiceConfig::new(data_dir);
    config.bind = "127.0.0.1:0".parse().unwrap();
    config.lease = Duration::from_secs(2);
    config.poll_interval = Duration::from_millis(100);
    config
}

/// How long a test waits for a job to reach a state.
pub const LONG: Duration = Duration::from_secs(240);

/// A reqwest client pointed at one server's base URL, with the API's calls as methods.
pub struct ApiClient {
    pub base: String,
    pub client: reqwest::Client,
}

/// A server plus a client pointed at it (the client's methods are the server's: `t.upload(..)`).
pub struct TestServer {
    pub server: Server,
    pub api: ApiClient,
}

impl std::ops::Deref for TestServer {
    type Target = ApiClient;

    fn deref(&self) -> &ApiClient {
        &self.api
    }
}

impl TestServer {
    pub async fn start(config: ServiceConfig) -> TestServer {
        let pipeline = test_pipeline(&config);
        Self::start_with(config, pipeline).await
    }

    pub async fn start_with(config: ServiceConfig, pipeline: Arc<dyn Pipeline>) -> TestServer {
        let server = Server::start(config, pipeline)
            .await
            .expect("server starts");
        let api = ApiClient::new(format!("http://{}", server.local_addr()));
        TestServer { server, api }
    }

    /// A server with the test config on `data_dir` (a fresh one or a restart on old state).
    pub async fn start_on(data_dir: &Path) -> TestServer {
        Self::start(test_config(data_dir)).await
    }

    /// A fresh data folder and a server with the test config on it.
    pub async fn start_fresh() -> (TempDir, TestServer) {
        Self::start_fresh_with(|_| {}).await
    }

    /// A fresh data folder and a server on it with the test config changed by `configure`.
    pub async fn start_fresh_with(
        configure: impl FnOnce(&mut ServiceConfig),
    ) -> (TempDir, TestServer) {
        let dir = tempfile::tempdir().unwrap();
        let mut config = test_config(dir.path());
        configure(&mut config);
        let server = Self::start(config).await;
        (dir, server)
    }
}

/// A request's answer as (status, JSON body or `null`).
pub async fn status_and_json(response: reqwest::Response) -> (u16, Value) {
    let status = response.status().as_u16();
    (status, response.json().await.unwrap_or(Value::Null))
}

/// Asserts that `response` is an error with `status` and `code`; returns its message.
pub async fn expect_error(response: reqwest::Response, status: u16, code: &str) -> String {
    let (got_status, body) = status_and_json(response).await;
    let (got_code, message) = error_code(&body);
    assert_eq!((got_status, got_code), (status, code), "{body}");
    message.to_string()
}

impl ApiClient {
    pub fn new(base: String) -> ApiClient {
        ApiClient {
            base,
            client: reqwest::Client::builder()
                .timeout(Duration::from_secs(30))
                // The service closes connections idle for its header timeout (15 s); a pooled
                // one reused just as it closes fails, so clients expire theirs sooner.
                .pool_idle_timeout(Duration::from_secs(5))
                .build()
                .unwrap(),
        }
    }

    /// A client that sends `Authorization: Bearer {token}` with every request.
    pub fn with_token(base: String, token: &str) -> ApiClient {
        let mut headers = reqwest::header::HeaderMap::new();
        headers.insert(
            reqwest::header::AUTHORIZATION,
            format!("Bearer {token}").parse().unwrap(),
        );
        ApiClient {
            base,
            client: reqwest::Client::builder()
                .timeout(Duration::from_secs(30))
                // The service closes connections idle for its header timeout (15 s); a pooled
                // one reused just as it closes fails, so clients expire theirs sooner.
                .pool_idle_timeout(Duration::from_secs(5))
                .default_headers(headers)
                .build()
                .unwrap(),
        }
    }

    pub fn url(&self, path: &str) -> String {
        format!("{}{path}", self.base)
    }

    /// Sends `method` to `path` with nothing more and returns the answer.
    pub async fn send(&self, method: reqwest::Method, path: &str) -> reqwest::Response {
        self.client
            .request(method, self.url(path))
            .send()
            .await
            .unwrap()
    }

    /// POSTs a raw request body to `path` (no content type).
    pub async fn post_body(&self, path: &str, body: impl Into<reqwest::Body>) -> reqwest::Response {
        self.client
            .post(self.url(path))
            .body(body)
            .send()
            .await
            .unwrap()
    }

    /// GETs `path` with `Authorization: Bearer {token}`.
    pub async fn get_with_token(&self, path: &str, token: &str) -> reqwest::Response {
        self.client
            .get(self.url(path))
            .bearer_auth(token)
            .send()
            .await
            .unwrap()
    }

    /// GETs `path` with a `Range` header.
    pub async fn get_range(&self, path: &str, range: &str) -> reqwest::Response {
        self.client
            .get(self.url(path))
            .header("range", range)
            .send()
            .await
            .unwrap()
    }

    /// DELETE /v1/captures/{id}.
    pub async fn delete_capture(&self, id: &str) -> reqwest::Response {
        self.send(reqwest::Method::DELETE, &format!("/v1/captures/{id}"))
            .await
    }

    /// POST /v1/jobs/{id}/cancel.
    pub async fn cancel(&self, id: &str) -> reqwest::Response {
        self.send(reqwest::Method::POST, &format!("/v1/jobs/{id}/cancel"))
            .await
    }

    /// POST /v1/jobs/{id}/relight with `envmap` as `sky.exr` and a rotation in degrees.
    pub async fn relight(&self, id: &str, envmap: Vec<u8>, rotate_deg: &str) -> reqwest::Response {
        let form = reqwest::multipart::Form::new()
            .part(
                "envmap",
                reqwest::multipart::Part::bytes(envmap).file_name("sky.exr"),
            )
            .text("rotate_deg", rotate_deg.to_string());
        self.client
            .post(self.url(&format!("/v1/jobs/{id}/relight")))
            .multipart(form)
            .send()
            .await
            .unwrap()
    }

    pub async fn get_json(&self, path: &str) -> (u16, Value) {
        status_and_json(self.send(reqwest::Method::GET, path).await).await
    }

    /// POSTs an archive to /v1/captures.
    pub async fn upload(&self, archive: Vec<u8>) -> (u16, Value) {
        let response = self
            .client
            .post(self.url("/v1/captures"))
            .header("content-type", "application/zip")
            .body(archive)
            .send()
            .await
            .unwrap();
        status_and_json(response).await
    }

    /// Uploads the test capture and returns its id.
    pub async fn upload_capture(&self) -> String {
        let (status, body) = self.upload(capture_zip()).await;
        assert_eq!(status, 201, "{body}");
        body["id"].as_str().unwrap().to_string()
    }

    /// POSTs `body` (any JSON, valid or not as a job request) to /v1/jobs, with an
    /// `Idempotency-Key` header when given.
    pub async fn post_job(&self, body: &Value, idempotency_key: Option<&str>) -> reqwest::Response {
        let mut request = self.client.post(self.url("/v1/jobs")).json(body);
        if let Some(key) = idempotency_key {
            request = request.header("idempotency-key", key);
        }
        request.send().await.unwrap()
    }

    /// Submits a job of `config` on the capture.
    pub async fn submit(&self, capture_id: &str, config: Value) -> (u16, Value) {
        let body = json!({ "capture_id": capture_id, "config": config });
        status_and_json(self.post_job(&body, None).await).await
    }

    /// Submits a job (which must be created: 201) and returns its id.
    pub async fn submit_job(&self, capture_id: &str, config: Value) -> String {
        let (status, job) = self.submit(capture_id, config).await;
        assert_eq!(status, 201, "{job}");
        job["id"].as_str().unwrap().to_string()
    }

    /// Uploads the test capture and submits a training job of `train_config(iterations,
    /// checkpoint_interval)` on it; returns the job id.
    pub async fn start_training(&self, iterations: u32, checkpoint_interval: u32) -> String {
        let capture_id = self.upload_capture().await;
        self.submit_job(&capture_id, train_config(iterations, checkpoint_interval))
            .await
    }

    /// Polls the job until `done(job)` or `timeout` (panics then).
    pub async fn wait_job(
        &self,
        id: &str,
        timeout: Duration,
        done: impl Fn(&Value) -> bool,
    ) -> Value {
        let deadline = Instant::now() + timeout;
        loop {
            let (status, job) = self.get_json(&format!("/v1/jobs/{id}")).await;
            assert_eq!(status, 200, "{job}");
            if done(&job) {
                return job;
            }
            assert!(
                Instant::now() < deadline,
                "timed out waiting for job {id}: {job}"
            );
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    }

    pub async fn wait_state(&self, id: &str, state: &str, timeout: Duration) -> Value {
        self.wait_job(id, timeout, |job| {
            let s = job["state"].as_str().unwrap_or("");
            s == state || (state != "failed" && s == "failed")
        })
        .await
    }

    /// Waits (up to [`LONG`]) for the job to end and asserts that it succeeded; returns it.
    pub async fn wait_succeeded(&self, id: &str) -> Value {
        let done = self.wait_state(id, "succeeded", LONG).await;
        assert_eq!(done["state"], "succeeded", "{done}");
        done
    }

    /// Waits (up to [`LONG`]) until the job has done `iterations` steps; returns it.
    pub async fn wait_iteration(&self, id: &str, iterations: u64) -> Value {
        self.wait_job(id, LONG, |job| {
            job["iteration"].as_u64().unwrap_or(0) >= iterations
        })
        .await
    }

    /// The job's artifact list (asserting it is answered).
    pub async fn artifacts(&self, id: &str) -> Vec<Value> {
        let (status, list) = self.get_json(&format!("/v1/jobs/{id}/artifacts")).await;
        assert_eq!(status, 200, "{list}");
        list["artifacts"].as_array().unwrap().clone()
    }

    /// The names in the job's artifact list, in its order.
    pub async fn artifact_names(&self, id: &str) -> Vec<String> {
        self.artifacts(id)
            .await
            .iter()
            .map(|a| a["name"].as_str().unwrap().to_string())
            .collect()
    }
}

/// The `{error: {code, message}}` of an error body.
pub fn error_code(body: &Value) -> (&str, &str) {
    (
        body["error"]["code"].as_str().unwrap_or("<no code>"),
        body["error"]["message"].as_str().unwrap_or("<no message>"),
    )
}

/// Files left in a folder (recursively), for "no partial state" checks.
pub fn count_files(dir: &Path) -> usize {
    if !dir.exists() {
        return 0;
    }
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            if e.file_type().unwrap().is_dir() {
                1 + count_files(&e.path())
            } else {
                1
            }
        })
        .sum()
}

/// The current time in unix seconds.
pub fn now_seconds() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap()
        .as_secs() as i64
}

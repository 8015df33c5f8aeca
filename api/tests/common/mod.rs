//! Shared harness of the integration tests: a real server on loopback over the pipeline chosen by
//! [`test_pipeline`], a reqwest client, capture archives built on the fly and bounded polling.
//!
//! DEVELOPMENT STAND-IN: [`DevPipeline`] below is NOT the reconstruction core. It does real file
//! work with the same contract (validates transforms.json and the files it names, "trains" by
//! writing checkpoints and emitting real `TrainEvent`s, honours cancel and resume, exports and
//! relights real PLY/EXR/PNG/JSON files) so the queue, crash and restart semantics can be tested
//! before the core lands. When `phygap::{capture, train, export, relight}` exist, the lead makes
//! `test_pipeline()` return `Arc::new(phygap_api::core_pipeline::CorePipeline)` and builds the test
//! captures with `phygap::synth::synth`. The `phygap-api` binary never uses this type.

#![allow(dead_code)]

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use phygap::config::TrainConfig;
use phygap::events::{Stage, TrainEvent};
use phygap::image_io::{read_image, write_exr, write_png, Image};
use phygap_api::pipeline::{CaptureInfo, Pipeline, PipelineError, RunOutcome};
use phygap_api::{Server, ServiceConfig};
use serde_json::{json, Value};

/// The pipeline every integration test runs on (see the module doc).
pub fn test_pipeline() -> Arc<dyn Pipeline> {
    Arc::new(DevPipeline {
        step_delay: Duration::from_millis(10),
    })
}

/// Development stand-in for the core (see the module doc).
pub struct DevPipeline {
    /// Wall time of one "iteration".
    pub step_delay: Duration,
}

const IMAGE_KEYS: [&str; 9] = [
    "file_path",
    "s0_path",
    "s1_path",
    "s2_path",
    "pol000_path",
    "pol045_path",
    "pol090_path",
    "pol135_path",
    "mask_path",
];

fn invalid(message: String) -> PipelineError {
    PipelineError::InvalidCapture(message)
}

fn failed(stage: &'static str, e: impl std::fmt::Display) -> PipelineError {
    PipelineError::Failed {
        stage,
        message: e.to_string(),
    }
}

fn write_checkpoint(model_dir: &Path, iteration: u32) -> Result<(), PipelineError> {
    let tmp = model_dir.join("checkpoint.json.tmp");
    std::fs::write(&tmp, json!({ "iteration": iteration }).to_string())
        .map_err(|e| failed("checkpoint", e))?;
    std::fs::rename(&tmp, model_dir.join("checkpoint.json")).map_err(|e| failed("checkpoint", e))
}

fn read_checkpoint(model_dir: &Path) -> Option<u32> {
    let text = std::fs::read_to_string(model_dir.join("checkpoint.json")).ok()?;
    let value: Value = serde_json::from_str(&text).ok()?;
    value["iteration"].as_u64().map(|i| i as u32)
}

impl Pipeline for DevPipeline {
    fn inspect(&self, capture_dir: &Path) -> Result<CaptureInfo, PipelineError> {
        let text = std::fs::read_to_string(capture_dir.join("transforms.json"))
            .map_err(|e| invalid(format!("transforms.json: {e}")))?;
        let value: Value =
            serde_json::from_str(&text).map_err(|e| invalid(format!("transforms.json: {e}")))?;
        let frames = value["frames"]
            .as_array()
            .ok_or_else(|| invalid("transforms.json: `frames` is missing".into()))?;
        if frames.len() < 2 {
            return Err(invalid(format!(
                "transforms.json: {} frames, at least 2 needed",
                frames.len()
            )));
        }
        let mut kinds = Vec::new();
        let mut warnings = Vec::new();
        for (i, frame) in frames.iter().enumerate() {
            for key in IMAGE_KEYS {
                if let Some(path) = frame[key].as_str() {
                    if path.split('/').any(|s| s == "..") || path.starts_with('/') {
                        return Err(invalid(format!(
                            "frame {i}: `{key}` escapes the capture folder"
                        )));
                    }
                    if !capture_dir.join(path).is_file() {
                        return Err(invalid(format!(
                            "frame {i}: `{key}` names a missing file `{path}`"
                        )));
                    }
                }
            }
            let kind = if frame["s0_path"].is_string() || frame["pol000_path"].is_string() {
                "full_stokes"
            } else if frame["polarizer_deg"].is_number() || frame["polarizer_group"].is_string() {
                "partial"
            } else {
                "rgb"
            };
            if !kinds.iter().any(|k| k == kind) {
                kinds.push(kind.to_string());
            }
            if !frame["mask_path"].is_string() {
                warnings.push(format!(
                    "frame {i}: no mask_path; the whole image is object"
                ));
            }
        }
        Ok(CaptureInfo {
            views: frames.len(),
            kinds,
            warnings,
        })
    }

    fn train(
        &self,
        capture_dir: &Path,
        model_dir: &Path,
        config: &TrainConfig,
        resume: bool,
        cancel: &AtomicBool,
        on_event: &mut dyn FnMut(&TrainEvent),
    ) -> Result<RunOutcome, PipelineError> {
        let info = self.inspect(capture_dir)?;
        let start = if resume {
            read_checkpoint(model_dir)
        } else {
            None
        };
        let mut log = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(model_dir.join("runs.log"))
            .map_err(|e| failed("training", e))?;
        writeln!(log, "start resumed_from={start:?}").map_err(|e| failed("training", e))?;
        let iterations = config.iterations;
        on_event(&TrainEvent::Started {
            iterations,
            mode: "full".into(),
            backend: "dev".into(),
            train_views: info.views - 1,
            test_views: 1,
            resumed_from: start,
        });
        let began = Instant::now();
        let first = start.unwrap_or(0);
        for iteration in first + 1..=iterations {
            if cancel.load(Ordering::SeqCst) {
                write_checkpoint(model_dir, iteration - 1)?;
                on_event(&TrainEvent::Checkpoint {
                    iteration: iteration - 1,
                });
                writeln!(log, "interrupted at {}", iteration - 1)
                    .map_err(|e| failed("training", e))?;
                return Ok(RunOutcome::Interrupted {
                    iteration: iteration - 1,
                });
            }
            std::thread::sleep(self.step_delay);
            let fraction = iteration as f64 / iterations as f64;
            let stage = if fraction <= config.geometry_stage_end {
                Stage::Geometry
            } else if fraction <= config.material_stage_end {
                Stage::Material
            } else {
                Stage::Polar
            };
            let loss = 1.0 / (1.0 + iteration as f64);
            let elapsed = began.elapsed().as_secs_f64();
            let done = (iteration - first) as f64;
            on_event(&TrainEvent::Step {
                iteration,
                iterations,
                stage,
                loss,
                losses: [
                    ("l1".to_string(), 0.8 * loss),
                    ("mask".to_string(), 0.2 * loss),
                ]
                .into(),
                num_surfels: 1000 + iteration as usize,
                elapsed_seconds: elapsed,
                eta_seconds: elapsed / done * (iterations - iteration) as f64,
            });
            if config.checkpoint_interval > 0 && iteration % config.checkpoint_interval == 0 {
                write_checkpoint(model_dir, iteration)?;
                on_event(&TrainEvent::Checkpoint { iteration });
            }
            if config.eval_interval > 0 && iteration % config.eval_interval == 0 {
                on_event(&TrainEvent::Evaluated {
                    iteration,
                    test_psnr: 20.0 + 10.0 * fraction,
                });
            }
        }
        write_checkpoint(model_dir, iterations)?;
        std::fs::write(
            model_dir.join("model.json"),
            json!({ "iterations": iterations }).to_string(),
        )
        .map_err(|e| failed("training", e))?;
        writeln!(log, "finished").map_err(|e| failed("training", e))?;
        on_event(&TrainEvent::Finished {
            iteration: iterations,
            seconds: began.elapsed().as_secs_f64(),
        });
        Ok(RunOutcome::Finished)
    }

    fn export(&self, model_dir: &Path, out_dir: &Path) -> Result<Vec<PathBuf>, PipelineError> {
        let iterations =
            read_checkpoint(model_dir).ok_or_else(|| failed("export", "no checkpoint"))?;
        let mut files = Vec::new();
        let surfels = out_dir.join("surfels.ply");
        let mut ply = String::from("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nend_header\n");
        for i in 0..4 {
            ply.push_str(&format!("{} {} {}\n", i as f32 * 0.1, 0.0, 1.0));
        }
        std::fs::write(&surfels, ply).map_err(|e| failed("export", e))?;
        files.push(surfels);
        let envmap = out_dir.join("envmap.exr");
        let image = Image::from_fn(16, 8, 3, |x, y, px| {
            px.copy_from_slice(&[x as f32 / 16.0, y as f32 / 8.0, 0.5]);
        });
        write_exr(&envmap, &image).map_err(|e| failed("export", e))?;
        files.push(envmap);
        let metrics = out_dir.join("metrics.json");
        std::fs::write(
            &metrics,
            json!({ "iterations": iterations, "test_psnr": 30.0 }).to_string(),
        )
        .map_err(|e| failed("export", e))?;
        files.push(metrics);
        std::fs::create_dir_all(out_dir.join("renders")).map_err(|e| failed("export", e))?;
        let render = out_dir.join("renders/test_000.png");
        write_png(&render, &Image::filled(8, 8, 3, 0.25), true).map_err(|e| failed("export", e))?;
        files.push(render);
        Ok(files)
    }

    fn relight(
        &self,
        model_dir: &Path,
        envmap: &Path,
        _cameras: Option<&Path>,
        out_dir: &Path,
        rotate_deg: f64,
    ) -> Result<Vec<PathBuf>, PipelineError> {
        read_checkpoint(model_dir).ok_or_else(|| failed("relighting", "no trained model"))?;
        let (map, _) =
            read_image(envmap).map_err(|e| PipelineError::InvalidInput(e.to_string()))?;
        let mean = map.data.iter().map(|&v| v as f64).sum::<f64>() / map.data.len().max(1) as f64;
        let render = out_dir.join("relit_000.png");
        write_png(&render, &Image::filled(8, 8, 3, mean as f32), true)
            .map_err(|e| failed("relighting", e))?;
        let metrics = out_dir.join("relight.json");
        std::fs::write(
            &metrics,
            json!({ "mean_radiance": mean, "rotate_deg": rotate_deg }).to_string(),
        )
        .map_err(|e| failed("relighting", e))?;
        Ok(vec![render, metrics])
    }
}

/// A small capture folder: transforms.json with 3 RGB frames and their PNGs.
pub fn write_capture(dir: &Path) {
    std::fs::create_dir_all(dir.join("images")).unwrap();
    let mut frames = Vec::new();
    for i in 0..3 {
        let name = format!("images/r_{i}.png");
        write_png(
            &dir.join(&name),
            &Image::filled(4, 4, 3, 0.1 * i as f32),
            true,
        )
        .unwrap();
        frames.push(json!({
            "file_path": name,
            "transform_matrix": [[1.0, 0.0, 0.0, i as f64], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 4.0], [0.0, 0.0, 0.0, 1.0]],
        }));
    }
    let transforms = json!({ "w": 4, "h": 4, "fl_x": 4.0, "fl_y": 4.0, "frames": frames });
    std::fs::write(dir.join("transforms.json"), transforms.to_string()).unwrap();
}

/// Every file under `dir` as (relative name, bytes), sorted.
fn files_of(dir: &Path) -> Vec<(String, Vec<u8>)> {
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

/// A small training config: `iterations` steps, checkpoints every `checkpoint_interval`.
pub fn train_config(iterations: u32, checkpoint_interval: u32) -> Value {
    json!({
        "iterations": iterations,
        "checkpoint_interval": checkpoint_interval,
        "eval_interval": checkpoint_interval,
        "initial_surfels": 100,
        "max_surfels": 1000,
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

/// A server plus a client pointed at it.
pub struct TestServer {
    pub server: Server,
    pub base: String,
    pub client: reqwest::Client,
}

impl TestServer {
    pub async fn start(config: ServiceConfig) -> TestServer {
        Self::start_with(config, test_pipeline()).await
    }

    pub async fn start_with(config: ServiceConfig, pipeline: Arc<dyn Pipeline>) -> TestServer {
        let server = Server::start(config, pipeline)
            .await
            .expect("server starts");
        let base = format!("http://{}", server.local_addr());
        TestServer {
            server,
            base,
            client: reqwest::Client::builder()
                .timeout(Duration::from_secs(30))
                .build()
                .unwrap(),
        }
    }

    pub fn url(&self, path: &str) -> String {
        format!("{}{path}", self.base)
    }

    pub async fn get_json(&self, path: &str) -> (u16, Value) {
        let response = self.client.get(self.url(path)).send().await.unwrap();
        let status = response.status().as_u16();
        (status, response.json().await.unwrap_or(Value::Null))
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
        let status = response.status().as_u16();
        (status, response.json().await.unwrap_or(Value::Null))
    }

    /// Uploads the test capture and returns its id.
    pub async fn upload_capture(&self) -> String {
        let (status, body) = self.upload(capture_zip()).await;
        assert_eq!(status, 201, "{body}");
        body["id"].as_str().unwrap().to_string()
    }

    pub async fn submit(&self, capture_id: &str, config: Value) -> (u16, Value) {
        let response = self
            .client
            .post(self.url("/v1/jobs"))
            .json(&json!({ "capture_id": capture_id, "config": config }))
            .send()
            .await
            .unwrap();
        let status = response.status().as_u16();
        (status, response.json().await.unwrap_or(Value::Null))
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

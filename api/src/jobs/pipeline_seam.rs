//! The pipeline seam: the [`Pipeline`] trait between the service and the reconstruction core,
//! and what crosses it. Everything in this crate (HTTP, queue, workers, storage) is written
//! against [`Pipeline`]. It has two runners: the service runs each call in a child process of
//! its own ([`crate::jobs::child_process_runner::ProcessPipeline`]), which calls
//! `phygap::{capture, train, export, relight}` in that process
//! ([`crate::jobs::in_process_runner::CorePipeline`]) under the job's memory, thread and time
//! limits, so no input can take the service down. Every method is blocking and may run for
//! hours: the service calls them on tokio's blocking pool, never on an async thread.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

use phygap::core::config::TrainConfig;
use phygap::core::events::TrainEvent;
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// What the capture loader says about an uploaded capture.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaptureInfo {
    /// Number of views (frames) in `transforms.json`.
    pub views: usize,
    /// Measurement kinds present (e.g. `full_stokes`, `partial`, `rgb`).
    pub kinds: Vec<String>,
    /// Non-fatal problems the loader noticed (e.g. a frame without a mask).
    pub warnings: Vec<String>,
    /// The size of its views (all views of a capture have one).
    #[serde(default)]
    pub width: u32,
    #[serde(default)]
    pub height: u32,
}

/// The compute engines a machine offers, as `phygap info` describes them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, utoipa::ToSchema)]
pub struct Engines {
    /// The GPU adapters found (Vulkan, Metal, DX12), software ones included.
    pub adapters: Vec<String>,
    /// What each `backend` choice trains on here (`auto`, `cpu`, `fast`, `gpu`), or why it
    /// cannot.
    pub backends: std::collections::BTreeMap<String, String>,
}

/// How a training run ended without error.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum RunOutcome {
    /// All iterations done; the model folder is complete.
    Finished,
    /// The cancel flag was seen; a checkpoint at `iteration` was written and training can resume.
    Interrupted { iteration: u32 },
}

/// A failure of a pipeline stage (carried from the job's process to the service as JSON).
#[derive(Debug, Error, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum PipelineError {
    /// The capture breaks the capture format (the client's fault: answered with 422), with every
    /// problem found (empty when the capture could not be read at all).
    #[error("invalid capture: {message}")]
    InvalidCapture {
        message: String,
        problems: Vec<phygap::io::capture::Problem>,
    },
    /// The capture declares more than the deployment's capture limits allow (`limit` names the
    /// one it breaks); nothing of it was decoded.
    #[error("capture too large: {message}")]
    CaptureTooLarge { limit: String, message: String },
    /// An input given to a job (environment map, cameras) is unusable.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A stage failed while running.
    #[error("{stage} failed: {message}")]
    Failed { stage: String, message: String },
    /// The process running the stage died before answering (killed, out of memory, over its
    /// time limit, crashed); the service is unharmed.
    #[error("the job's process {}: {detail}", .reason.describe())]
    Died { reason: DeathReason, detail: String },
}

impl PipelineError {
    /// This error with every mention of the given folders (as given, and canonical) removed, so
    /// files are named relative to the capture, the model or the inputs: the service's own
    /// folders are no business of its clients.
    pub fn relative_to(self, folders: &[&Path]) -> PipelineError {
        let mut prefixes: Vec<String> = Vec::new();
        for folder in folders {
            prefixes.push(folder.display().to_string());
            if let Ok(canonical) = folder.canonicalize() {
                prefixes.push(canonical.display().to_string());
            }
        }
        // Longest first, so a folder inside another is removed whole.
        prefixes.sort_by_key(|p| std::cmp::Reverse(p.len()));
        let strip = |text: String| {
            prefixes.iter().fold(text, |text, prefix| {
                text.replace(&format!("{prefix}/"), "")
                    .replace(prefix.as_str(), ".")
            })
        };
        match self {
            PipelineError::InvalidCapture { message, problems } => PipelineError::InvalidCapture {
                message: strip(message),
                problems: problems
                    .into_iter()
                    .map(|p| phygap::io::capture::Problem {
                        frame: strip(p.frame),
                        key: p.key,
                        message: strip(p.message),
                    })
                    .collect(),
            },
            PipelineError::CaptureTooLarge { limit, message } => PipelineError::CaptureTooLarge {
                limit,
                message: strip(message),
            },
            PipelineError::InvalidInput(message) => PipelineError::InvalidInput(strip(message)),
            PipelineError::Failed { stage, message } => PipelineError::Failed {
                stage,
                message: strip(message),
            },
            died @ PipelineError::Died { .. } => died,
        }
    }
}

/// Why a job's process died.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DeathReason {
    /// An allocation failed at the memory limit (or the kernel's OOM killer ended it).
    OutOfMemory,
    /// It ran past the job's time limit and was stopped.
    TimeLimit,
    /// A signal ended it (SIGKILL from outside, say).
    Killed,
    /// It aborted or crashed otherwise, or exited without an answer.
    Crashed,
}

impl DeathReason {
    /// The stable name recorded as the job's `error_code`.
    pub fn code(self) -> &'static str {
        match self {
            DeathReason::OutOfMemory => "out_of_memory",
            DeathReason::TimeLimit => "time_limit",
            DeathReason::Killed => "killed",
            DeathReason::Crashed => "crashed",
        }
    }

    fn describe(self) -> &'static str {
        match self {
            DeathReason::OutOfMemory => "ran out of memory",
            DeathReason::TimeLimit => "ran past its time limit",
            DeathReason::Killed => "was killed",
            DeathReason::Crashed => "crashed",
        }
    }
}

/// The reconstruction core as the service sees it.
pub trait Pipeline: Send + Sync + 'static {
    /// What this machine's engines are (`GET /v1/info`).
    fn engines(&self) -> Result<Engines, PipelineError>;

    /// Loads and validates the capture in `capture_dir` (the folder holding `transforms.json`).
    fn inspect(&self, capture_dir: &Path) -> Result<CaptureInfo, PipelineError>;

    /// Trains a model of the capture into `model_dir`. With `resume` and a checkpoint present it
    /// continues from the checkpoint. When `cancel` becomes true it checkpoints and returns
    /// [`RunOutcome::Interrupted`]. `on_event` receives every training event.
    #[allow(clippy::too_many_arguments)]
    fn train(
        &self,
        capture_dir: &Path,
        model_dir: &Path,
        config: &TrainConfig,
        resume: bool,
        cancel: &AtomicBool,
        on_event: &mut dyn FnMut(&TrainEvent),
    ) -> Result<RunOutcome, PipelineError>;

    /// Writes the downloadable products of a trained model into `out_dir`, and with the capture
    /// it was trained on the 8-bit previews of its test views (`captured/{s0,dolp,aolp}/NNN.png`,
    /// beside the renders); returns the files.
    fn export(
        &self,
        model_dir: &Path,
        capture_dir: Option<&Path>,
        out_dir: &Path,
    ) -> Result<Vec<PathBuf>, PipelineError>;

    /// Renders the trained model under a new environment map into `out_dir`; returns the files.
    fn relight(
        &self,
        model_dir: &Path,
        envmap: &Path,
        cameras: Option<&Path>,
        out_dir: &Path,
        rotate_deg: f64,
    ) -> Result<Vec<PathBuf>, PipelineError>;
}

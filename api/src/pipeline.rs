//! The seam between the service and the reconstruction core. Everything in this crate (HTTP, queue,
//! workers, storage) is written against [`Pipeline`]; the production implementation calls
//! `phygap::{capture, train, export, relight}` ([`crate::core_pipeline::CorePipeline`]). Every method is blocking and
//! may run for hours: the service calls them on tokio's blocking pool, never on an async thread.

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
}

/// How a training run ended without error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunOutcome {
    /// All iterations done; the model folder is complete.
    Finished,
    /// The cancel flag was seen; a checkpoint at `iteration` was written and training can resume.
    Interrupted { iteration: u32 },
}

/// A failure of a pipeline stage.
#[derive(Debug, Error)]
pub enum PipelineError {
    /// The capture breaks the capture format (the client's fault: answered with 422), with every
    /// problem found (empty when the capture could not be read at all).
    #[error("invalid capture: {message}")]
    InvalidCapture {
        message: String,
        problems: Vec<phygap::io::capture::Problem>,
    },
    /// An input given to a job (environment map, cameras) is unusable.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A stage failed while running.
    #[error("{stage} failed: {message}")]
    Failed {
        stage: &'static str,
        message: String,
    },
}

/// The reconstruction core as the service sees it.
pub trait Pipeline: Send + Sync + 'static {
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

    /// Writes the downloadable products of a trained model into `out_dir`; returns the files.
    fn export(&self, model_dir: &Path, out_dir: &Path) -> Result<Vec<PathBuf>, PipelineError>;

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

/// The pipeline the `phygap-api` binary serves with: the phygap core.
pub fn production_pipeline() -> std::sync::Arc<dyn Pipeline> {
    std::sync::Arc::new(crate::core_pipeline::CorePipeline)
}

//! The production [`Pipeline`]: the phygap core's capture loader, trainer, exporter and relighter.
//! Each call is blocking; the capture is loaded from disk per call (the service keeps no capture in
//! memory between jobs).

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

use phygap::core::config::TrainConfig;
use phygap::core::events::TrainEvent;

use crate::pipeline::{CaptureInfo, Pipeline, PipelineError, RunOutcome};

/// Calls `phygap::io::capture::load`, `phygap::pipeline::train::train`, `phygap::pipeline::export::export` and
/// `phygap::pipeline::relight::relight`.
pub struct CorePipeline;

fn load(capture_dir: &Path) -> Result<phygap::io::capture::Capture, PipelineError> {
    phygap::io::capture::load(capture_dir).map_err(|e| PipelineError::InvalidCapture {
        problems: e.problems().to_vec(),
        message: e.to_string(),
    })
}

/// The error of a core `stage` that failed while running.
fn failed(stage: &'static str, error: impl std::fmt::Display) -> PipelineError {
    PipelineError::Failed {
        stage,
        message: error.to_string(),
    }
}

impl Pipeline for CorePipeline {
    fn inspect(&self, capture_dir: &Path) -> Result<CaptureInfo, PipelineError> {
        let summary = load(capture_dir)?.summary();
        Ok(CaptureInfo {
            views: summary.views,
            kinds: summary.kinds,
            warnings: summary.warnings,
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
        let capture = load(capture_dir)?;
        match phygap::pipeline::train::train(&capture, model_dir, config, resume, cancel, on_event)
        {
            Ok(phygap::pipeline::train::TrainOutcome::Finished) => Ok(RunOutcome::Finished),
            Ok(phygap::pipeline::train::TrainOutcome::Interrupted { iteration }) => {
                Ok(RunOutcome::Interrupted { iteration })
            }
            Err(e) => Err(failed("training", e)),
        }
    }

    fn export(&self, model_dir: &Path, out_dir: &Path) -> Result<Vec<PathBuf>, PipelineError> {
        phygap::pipeline::export::export(model_dir, out_dir).map_err(|e| failed("export", e))
    }

    fn relight(
        &self,
        model_dir: &Path,
        envmap: &Path,
        cameras: Option<&Path>,
        out_dir: &Path,
        rotate_deg: f64,
    ) -> Result<Vec<PathBuf>, PipelineError> {
        phygap::pipeline::relight::relight(model_dir, envmap, cameras, out_dir, rotate_deg)
            .map_err(|e| failed("relighting", e))
    }
}

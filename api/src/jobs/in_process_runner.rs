//! The in-process runner: the reconstruction core behind [`Pipeline`] ([`CorePipeline`]), the
//! phygap core's capture loader, trainer, exporter and relighter, called in the current process.
//! The service never calls it itself: a job's child process does
//! ([`crate::jobs::child_process_runner`]), so what a hostile capture costs is that process's
//! alone. Each call is blocking; the capture is loaded from disk per call.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

use phygap::core::config::TrainConfig;
use phygap::core::events::TrainEvent;
use phygap::core::resolution::Resolution;
use phygap::io::capture::{CaptureError, CaptureLimits, LoadOptions};

use crate::jobs::pipeline_seam::{CaptureInfo, Engines, Pipeline, PipelineError, RunOutcome};

/// Calls `phygap::io::capture::load_within`, `phygap::pipeline::train::train`,
/// `phygap::pipeline::export::export` and `phygap::pipeline::relight::relight`.
#[derive(Clone, Debug, Default)]
pub struct CorePipeline {
    /// The most a capture may declare (views, pixels, decoded bytes).
    pub capture_limits: CaptureLimits,
}

impl CorePipeline {
    fn load(
        &self,
        capture_dir: &Path,
        options: &LoadOptions,
    ) -> Result<phygap::io::capture::Capture, PipelineError> {
        let capture =
            phygap::io::capture::load_with(capture_dir, options).map_err(capture_error)?;
        capture.check_trainable().map_err(capture_error)?;
        Ok(capture)
    }
}

/// A capture the loader refused, as the service reports it.
fn capture_error(e: CaptureError) -> PipelineError {
    match e {
        CaptureError::TooLarge { ref exceeded, .. } => PipelineError::CaptureTooLarge {
            limit: exceeded.limit.to_owned(),
            message: e.to_string(),
        },
        e => PipelineError::InvalidCapture {
            problems: e.problems().to_vec(),
            message: e.to_string(),
        },
    }
}

/// The error of a core `stage` that failed while running.
fn failed(stage: &str, error: impl std::fmt::Display) -> PipelineError {
    PipelineError::Failed {
        stage: stage.to_owned(),
        message: error.to_string(),
    }
}

impl Pipeline for CorePipeline {
    /// This machine's adapters and what each backend choice resolves to.
    fn engines(&self) -> Result<Engines, PipelineError> {
        use phygap::core::config::BackendChoice;
        use phygap::pipeline::backend::describe;
        let backends = [
            (BackendChoice::Auto, "auto"),
            (BackendChoice::Cpu, "cpu"),
            (BackendChoice::Fast, "fast"),
            (BackendChoice::Gpu, "gpu"),
        ]
        .into_iter()
        .map(|(choice, name)| {
            let what = describe(choice).unwrap_or_else(|e| format!("unavailable: {e}"));
            (name.to_owned(), what)
        })
        .collect();
        Ok(Engines {
            adapters: phygap::gpu::list_adapters()
                .iter()
                .map(ToString::to_string)
                .collect(),
            backends,
        })
    }

    fn inspect(&self, capture_dir: &Path) -> Result<CaptureInfo, PipelineError> {
        // Every file is read and checked; the views are kept at the host engines' working size,
        // so validating a large capture holds little of it.
        let options = LoadOptions {
            limits: self.capture_limits,
            resolution: Resolution::Auto,
            pixel_budget: Resolution::HOST_PIXEL_BUDGET,
        };
        let capture = self.load(capture_dir, &options)?;
        let summary = capture.summary();
        Ok(CaptureInfo {
            views: summary.views,
            kinds: summary.kinds,
            warnings: summary.warnings,
            width: capture.full_size.0,
            height: capture.full_size.1,
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
        use phygap::pipeline::train;
        let engine = train::engine_for(config).map_err(|e| failed("training", e))?;
        let capture = train::load_capture(capture_dir, config, &engine, &self.capture_limits)
            .map_err(capture_error)?;
        capture.check_trainable().map_err(capture_error)?;
        let mut run = |resume| {
            train::train_on(
                &engine, &capture, model_dir, config, resume, cancel, on_event,
            )
        };
        let outcome = match run(resume) {
            // A job's checkpoint from before exposure normalization cannot go on (its light is
            // in other units): the job starts over rather than failing.
            Err(train::TrainError::ExposureChanged { path, .. }) => {
                tracing::warn!(
                    checkpoint = %path.display(),
                    "the job's checkpoint predates exposure normalization: training from the start"
                );
                run(false)
            }
            outcome => outcome,
        };
        match outcome {
            Ok(phygap::pipeline::train::TrainOutcome::Finished) => Ok(RunOutcome::Finished),
            Ok(phygap::pipeline::train::TrainOutcome::Interrupted { iteration }) => {
                Ok(RunOutcome::Interrupted { iteration })
            }
            Err(e) => Err(failed("training", e)),
        }
    }

    fn export(
        &self,
        model_dir: &Path,
        capture_dir: Option<&Path>,
        out_dir: &Path,
    ) -> Result<Vec<PathBuf>, PipelineError> {
        use phygap::pipeline::previews::{write_captured_previews, CAPTURED_DIR};
        let mut files = phygap::pipeline::export::export(model_dir, out_dir)
            .map_err(|e| failed("export", e))?;
        if let Some(capture_dir) = capture_dir {
            // The previews compare with the renders: the size the model was trained at.
            let model =
                phygap::io::model::Model::load(model_dir).map_err(|e| failed("export", e))?;
            let downscale = model.info.working_resolution.map_or(1, |r| r.downscale);
            let options = LoadOptions {
                limits: self.capture_limits,
                resolution: Resolution::Downscale(downscale),
                ..LoadOptions::default()
            };
            let capture = self.load(capture_dir, &options)?;
            files.extend(
                write_captured_previews(&capture, &out_dir.join(CAPTURED_DIR))
                    .map_err(|e| failed("export", e))?,
            );
        }
        Ok(files)
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

#[cfg(test)]
mod tests {
    use super::*;
    use phygap::pipeline::synth::{synth, SynthOptions};
    use phygap::pipeline::train::state::{TrainState, CHECKPOINT_FILE};

    #[test]
    fn a_checkpoint_from_before_exposure_normalization_trains_again_from_the_start() {
        let dir = tempfile::tempdir().unwrap();
        let capture = dir.path().join("capture");
        let options = SynthOptions {
            views: 8,
            size: 24,
            ..SynthOptions::default()
        };
        synth(&capture, &options).unwrap();
        let model = dir.path().join("model");
        let config = TrainConfig {
            iterations: 40u32.into(),
            initial_surfels: 500,
            max_surfels: 2000,
            checkpoint_interval: 20,
            ..TrainConfig::default()
        };
        let pipeline = CorePipeline::default();
        let cancel = AtomicBool::new(false);
        let mut events = Vec::new();
        let mut stop_at_first_checkpoint = |e: &TrainEvent| {
            if matches!(e, TrainEvent::Checkpoint { .. }) {
                cancel.store(true, std::sync::atomic::Ordering::Relaxed);
            }
        };
        let outcome = pipeline
            .train(
                &capture,
                &model,
                &config,
                false,
                &cancel,
                &mut stop_at_first_checkpoint,
            )
            .unwrap();
        assert_eq!(outcome, RunOutcome::Interrupted { iteration: 20 });
        // Rewrite the checkpoint as an earlier version left it: the light in the capture's units.
        let path = model.join(CHECKPOINT_FILE);
        let (mut state, fingerprint) = TrainState::load(&path).unwrap();
        let scale = state.radiance_scale;
        assert_ne!(scale, 1.0);
        state.radiance_scale = 1.0;
        state.save(&path, &fingerprint).unwrap();

        cancel.store(false, std::sync::atomic::Ordering::Relaxed);
        let outcome = pipeline
            .train(&capture, &model, &config, true, &cancel, &mut |e| {
                events.push(e.clone())
            })
            .unwrap();
        assert_eq!(outcome, RunOutcome::Finished);
        // The refused resume started nothing; the run started afresh.
        let starts: Vec<Option<u32>> = events
            .iter()
            .filter_map(|e| match e {
                TrainEvent::Started { resumed_from, .. } => Some(*resumed_from),
                _ => None,
            })
            .collect();
        assert_eq!(starts, [None]);
        let (state, _) = TrainState::load(&path).unwrap();
        assert_eq!((state.iteration, state.radiance_scale), (40, scale));
    }
}

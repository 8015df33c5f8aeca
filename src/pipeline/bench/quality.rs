//! Time to quality: a whole training run with the given settings (the defaults unless told), timed
//! from the capture on disk to the evaluated model, with the test PSNR the run reports along the
//! way and the complete [`scorecard`](crate::pipeline::scorecard) at the end. `phygap bench quality` prints
//! it, so "how long until how good" is one command.

use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

use serde::{Deserialize, Serialize};

use crate::core::config::TrainConfig;
use crate::core::events::TrainEvent;
use crate::io::model::Model;
use crate::pipeline::bench::MemoryPeaks;
use crate::pipeline::evaluate::EvalReport;
use crate::pipeline::scorecard::{self, GroundTruth, ScorecardError};
use crate::pipeline::train::{self, TrainError, TrainOutcome};

/// One test-PSNR reading of the run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PsnrReading {
    pub iteration: u32,
    /// Training time when it was taken (the run's own clock).
    pub seconds: f64,
    pub test_psnr: f64,
}

/// What `phygap bench quality` reports.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QualityRun {
    /// The backend and how its steps run (the run's start event).
    pub backend: String,
    pub iterations: u32,
    /// Wall time of loading the capture and training it (the model folder written, its
    /// `metrics.json` included), and of the scorecard after it.
    pub train_wall_seconds: f64,
    pub score_wall_seconds: f64,
    /// The run's test PSNR at each evaluation (every `eval_interval` steps and at the end).
    pub progress: Vec<PsnrReading>,
    /// The run's warnings (e.g. a GridMap mesh that could not be extracted), with their step.
    pub warnings: Vec<String>,
    /// Every metric of the final model (relit and mesh metrics where `truth` has them).
    pub metrics: EvalReport,
    #[serde(flatten)]
    pub memory: MemoryPeaks,
}

#[derive(Debug, thiserror::Error)]
pub enum QualityError {
    #[error(transparent)]
    Capture(#[from] crate::io::capture::CaptureError),
    #[error(transparent)]
    Train(#[from] TrainError),
    #[error("the run was interrupted at iteration {0}")]
    Interrupted(u32),
    #[error(transparent)]
    Model(#[from] crate::io::model::ModelError),
    #[error(transparent)]
    Score(#[from] ScorecardError),
}

/// Loads the capture at `capture_dir`, trains it into `model_dir` with `config` and scores the
/// model against the capture and `truth`. Every event of the run is passed on to `on_event`.
pub fn bench_quality(
    capture_dir: &Path,
    model_dir: &Path,
    config: &TrainConfig,
    truth: &GroundTruth,
    on_event: &mut dyn FnMut(&TrainEvent),
) -> Result<QualityRun, QualityError> {
    let _span = tracing::info_span!("bench_quality", iterations = %config.iterations).entered();
    let start = Instant::now();
    let engine = train::engine_for(config)?;
    let limits = crate::io::capture::CaptureLimits::DEFAULT;
    let capture = train::load_capture(capture_dir, config, &engine, &limits)?;
    let mut backend = String::new();
    let mut progress = Vec::new();
    let mut warnings = Vec::new();
    let mut elapsed = 0.0;
    let never = AtomicBool::new(false);
    let outcome = train::train_on(
        &engine,
        &capture,
        model_dir,
        config,
        false,
        &never,
        &mut |event| {
            match event {
                TrainEvent::Started { backend: b, .. } => backend = b.clone(),
                TrainEvent::Step {
                    elapsed_seconds, ..
                } => elapsed = *elapsed_seconds,
                TrainEvent::Evaluated {
                    iteration,
                    test_psnr,
                } => progress.push(PsnrReading {
                    iteration: *iteration,
                    seconds: elapsed,
                    test_psnr: *test_psnr,
                }),
                TrainEvent::Warning { iteration, message } => {
                    warnings.push(format!("step {iteration}: {message}"));
                }
                _ => {}
            }
            on_event(event);
        },
    )?;
    if let TrainOutcome::Interrupted { iteration } = outcome {
        return Err(QualityError::Interrupted(iteration));
    }
    let train_wall_seconds = start.elapsed().as_secs_f64();
    let memory = MemoryPeaks::of(&engine);
    let model = Model::load(model_dir)?;
    let metrics = scorecard::score(&model, &capture, truth)?;
    Ok(QualityRun {
        backend,
        iterations: model.info.iterations,
        train_wall_seconds,
        score_wall_seconds: start.elapsed().as_secs_f64() - train_wall_seconds,
        progress,
        warnings,
        metrics,
        memory,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::config::BackendChoice;
    use crate::pipeline::synth::{synth, Shape, SynthOptions};

    #[test]
    fn a_short_run_reports_its_time_readings_and_metrics() {
        let dir = tempfile::tempdir().unwrap();
        let capture = dir.path().join("capture");
        synth(
            &capture,
            &SynthOptions {
                shape: Shape::Sphere,
                views: 8,
                size: 24,
                ..SynthOptions::default()
            },
        )
        .unwrap();
        let config = TrainConfig {
            iterations: 40.into(),
            initial_surfels: 800,
            envmap_resolution: 8,
            eval_interval: 20,
            backend: BackendChoice::Cpu,
            ..TrainConfig::default()
        };
        let mut steps = 0;
        let run = bench_quality(
            &capture,
            &dir.path().join("model"),
            &config,
            &GroundTruth::default(),
            &mut |e| steps += usize::from(matches!(e, TrainEvent::Step { .. })),
        )
        .unwrap();
        assert_eq!(run.iterations, 40);
        assert!(steps > 0);
        assert!(run.backend.starts_with("cpu"), "{}", run.backend);
        // One reading at step 20 and the final one at 40, each a real PSNR.
        let at: Vec<u32> = run.progress.iter().map(|r| r.iteration).collect();
        assert_eq!(at, [20, 40]);
        assert!(run
            .progress
            .iter()
            .all(|r| r.test_psnr.is_finite() && r.test_psnr > 5.0));
        assert_eq!(run.metrics.psnr, Some(run.progress[1].test_psnr));
        assert!(run.metrics.normal_mae_deg.is_some());
        assert!(run.train_wall_seconds > 0.0 && run.score_wall_seconds > 0.0);
    }
}

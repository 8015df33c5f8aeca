//! The remaining time of a run, as the progress events report it.
//!
//! Steps of the three stages cost different amounts (a plain-2DGS step only rasterizes; a shaded
//! step also runs PolarDR forward and backward, and the PolarDR stage adds the Stokes loss and
//! GridMap's rebuilds), and a step grows slower as densification adds surfels. So the estimate
//! keeps a moving average of the wall time per step of each stage seen so far — every report's
//! interval included, GridMap rebuilds, evaluations and checkpoints with it — and prices a stage
//! not reached yet from the one before it by a measured ratio of step costs.

use std::time::Instant;

use crate::core::config::TrainConfig;
use crate::core::events::Stage;

/// Wall time of a shaded (material-stage) step over a plain-2DGS step at the end of the geometry
/// stage, and of a PolarDR step over a material step, as measured on the shared captures by
/// `phygap bench quality` (cpu backend; ratios of the per-stage means in `progress.jsonl`). The
/// device engine's shaded steps cost relatively less, so its estimate starts high and corrects
/// itself as soon as a stage is measured.
const SHADED_OVER_GEOMETRY: f64 = 1.7;
const POLAR_OVER_MATERIAL: f64 = 1.4;

/// Weight of the newest interval in a stage's moving average (reports come every ~20 steps, so
/// the average spans a few hundred steps: GridMap's periodic rebuilds are spread over it).
const SMOOTHING: f64 = 0.05;

/// Per-stage step times of the run so far and the remaining time they imply.
pub(super) struct Eta {
    /// Moving average of the seconds per step of each stage (index: [`stage_index`]).
    seconds_per_step: [Option<f64>; 3],
    /// The last observation: iteration and when.
    last: Option<(u32, Instant)>,
}

fn stage_index(stage: Stage) -> usize {
    match stage {
        Stage::Geometry => 0,
        Stage::Material => 1,
        Stage::Polar => 2,
    }
}

impl Eta {
    /// Starts timing at iteration `iteration` (a fresh run's 0 or a resumed run's checkpoint).
    pub(super) fn start(iteration: u32) -> Self {
        Eta {
            seconds_per_step: [None; 3],
            last: Some((iteration, Instant::now())),
        }
    }

    /// Records that the run reached `iteration` now, its latest steps in `stage`.
    pub(super) fn observe(&mut self, iteration: u32, stage: Stage) {
        self.observe_at(iteration, stage, Instant::now());
    }

    fn observe_at(&mut self, iteration: u32, stage: Stage, now: Instant) {
        if let Some((from, then)) = self.last {
            if iteration > from {
                let per_step = (now - then).as_secs_f64() / f64::from(iteration - from);
                let average = &mut self.seconds_per_step[stage_index(stage)];
                *average = Some(match *average {
                    None => per_step,
                    Some(old) => old + SMOOTHING * (per_step - old),
                });
            }
        }
        self.last = Some((iteration, now));
    }

    /// Seconds per step of each stage: measured, or priced from a measured neighbour.
    fn rates(&self) -> Option<[f64; 3]> {
        let [geometry, material, polar] = self.seconds_per_step;
        let material = material
            .or(geometry.map(|g| g * SHADED_OVER_GEOMETRY))
            .or(polar.map(|p| p / POLAR_OVER_MATERIAL));
        let geometry = geometry.or(material.map(|m| m / SHADED_OVER_GEOMETRY));
        let polar = polar.or(material.map(|m| m * POLAR_OVER_MATERIAL));
        Some([geometry?, material?, polar?])
    }

    /// Estimated seconds until the run's last iteration, from iteration `done`; 0 before any
    /// step was timed.
    pub(super) fn remaining(&self, done: u32, config: &TrainConfig) -> f64 {
        let Some(rates) = self.rates() else {
            return 0.0;
        };
        let bounds = [
            (0, config.material_stage_start()),
            (config.material_stage_start(), config.polar_stage_start()),
            (config.polar_stage_start(), config.steps()),
        ];
        bounds
            .iter()
            .zip(rates)
            .map(|(&(start, end), rate)| {
                let left = end.saturating_sub(done.max(start));
                f64::from(left) * rate
            })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    fn config() -> TrainConfig {
        TrainConfig {
            iterations: 1000.into(),
            geometry_stage_end: 0.2,
            material_stage_end: 0.4,
            ..TrainConfig::default()
        }
    }

    #[test]
    fn unseen_stages_are_priced_from_the_measured_one() {
        let t0 = Instant::now();
        let mut eta = Eta {
            seconds_per_step: [None; 3],
            last: Some((0, t0)),
        };
        assert_eq!(eta.remaining(0, &config()), 0.0);
        // 100 geometry steps at 10 ms.
        eta.observe_at(100, Stage::Geometry, t0 + Duration::from_secs(1));
        let g = 0.01;
        let m = g * SHADED_OVER_GEOMETRY;
        let p = m * POLAR_OVER_MATERIAL;
        let expected = 100.0 * g + 200.0 * m + 600.0 * p;
        assert!((eta.remaining(100, &config()) - expected).abs() < 1e-9);
    }

    #[test]
    fn a_measured_stage_replaces_its_estimate() {
        let t0 = Instant::now();
        let mut eta = Eta::start(0);
        eta.last = Some((0, t0));
        eta.observe_at(200, Stage::Geometry, t0 + Duration::from_secs(2));
        // Material steps turn out to cost 50 ms, more than the ratio says.
        eta.observe_at(300, Stage::Material, t0 + Duration::from_secs(7));
        let expected = 100.0 * 0.05 + 600.0 * 0.05 * POLAR_OVER_MATERIAL;
        assert!((eta.remaining(300, &config()) - expected).abs() < 1e-9);
        // The moving average follows slower steps without jumping to the latest interval.
        eta.observe_at(400, Stage::Material, t0 + Duration::from_secs(17));
        let rate = eta.seconds_per_step[1].unwrap();
        assert!(rate > 0.05 && rate < 0.1, "{rate}");
        // Past the end nothing remains.
        assert_eq!(eta.remaining(1000, &config()), 0.0);
    }
}

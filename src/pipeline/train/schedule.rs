//! What a training run does at each iteration (METHOD.md §6–§7): the stage, the estimate of
//! unknown polarizer angles, GridMap's remeshes and probe rebuilds, the light's batched update,
//! progress reports, test evaluations, densification, opacity resets and checkpoints. A pure
//! function of the configuration and the iteration, so a resumed run does exactly what the
//! uninterrupted one did; the loop in `mod.rs` reads it and acts.

use crate::core::config::TrainConfig;
use crate::core::events::Stage;

/// A run's schedule: the configuration's intervals and fractions, resolved to iterations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Schedule {
    iterations: u32,
    material_start: u32,
    polar_start: u32,
    /// Densification runs after more than `densify_from` and at most `densify_until` steps, as
    /// do opacity resets (up to `densify_until`).
    densify_from: u32,
    densify_until: u32,
    densify_interval: u32,
    densify_interval_polar: u32,
    opacity_reset_interval: u32,
    opacity_recovery_steps: u32,
    gridmap: bool,
    mesh_interval: u32,
    gridmap_interval: u32,
    envmap_prefilter_interval: u32,
    eval_interval: u32,
    checkpoint_interval: u32,
    report_every: u32,
}

/// What is due before a step runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BeforeStep {
    pub stage: Stage,
    /// The PolarDR stage starts here: unknown polarizer angles are estimated (until then the
    /// material and light are not fitted well enough to tell θ from θ + 90°).
    pub estimate_angles: bool,
    /// GridMap's work, `None` while it waits (outside the PolarDR stage, with GridMap off, or
    /// while the opacities recover from a reset: its mesh is fused from rendered opacity ≥ ½,
    /// which no surfel at opacity 0.01 gives).
    pub gridmap: Option<GridMapWork>,
}

/// GridMap's scheduled work before a PolarDR step (a run without a current mesh remeshes anyway).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GridMapWork {
    /// Extract the mesh again (every `mesh_interval`, or at the end of a recovery window that a
    /// remesh fell in).
    pub remesh: bool,
    /// Rebuild the local probes (every `gridmap_interval`).
    pub probes: bool,
}

/// What is due once a step is done (`done` steps in all).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AfterStep {
    /// Apply the light's summed gradient and prefilter it again (when the step shaded).
    pub update_light: bool,
    /// Report the step's losses.
    pub report: bool,
    /// Evaluate the test views.
    pub evaluate: bool,
    /// Clone, split and prune surfels.
    pub densify: bool,
    /// Reset every opacity to 0.01.
    pub reset_opacity: bool,
    /// Write a checkpoint.
    pub checkpoint: bool,
}

impl AfterStep {
    /// Whether the surfels change (densification or a reset).
    pub fn refines(&self) -> bool {
        self.densify || self.reset_opacity
    }
}

impl Schedule {
    pub fn new(config: &TrainConfig) -> Schedule {
        let iterations = config.steps();
        let fraction = |f: f64| (f * f64::from(iterations)).round() as u32;
        Schedule {
            iterations,
            material_start: config.material_stage_start(),
            polar_start: config.polar_stage_start(),
            densify_from: fraction(config.densify_from),
            densify_until: fraction(config.densify_until),
            densify_interval: config.densify_interval.max(1),
            densify_interval_polar: config.densify_interval_polar.max(1),
            opacity_reset_interval: config.opacity_reset_interval,
            opacity_recovery_steps: config.opacity_recovery_steps,
            gridmap: config.gridmap,
            mesh_interval: config.mesh_interval,
            gridmap_interval: config.gridmap_interval,
            envmap_prefilter_interval: config.envmap_prefilter_interval,
            eval_interval: config.eval_interval,
            checkpoint_interval: config.checkpoint_interval,
            report_every: (iterations / 300).clamp(1, 25),
        }
    }

    pub fn iterations(&self) -> u32 {
        self.iterations
    }

    /// Stage of iteration `it` (0-based).
    pub fn stage(&self, it: u32) -> Stage {
        if it < self.material_start {
            Stage::Geometry
        } else if it < self.polar_start {
            Stage::Material
        } else {
            Stage::Polar
        }
    }

    /// The stage of the run's last iteration (the final evaluation lights the model as it).
    pub fn final_stage(&self) -> Stage {
        self.stage(self.iterations.saturating_sub(1))
    }

    /// What is due before iteration `it` runs.
    pub fn before(&self, it: u32) -> BeforeStep {
        let stage = self.stage(it);
        let gridmap = (stage == Stage::Polar && self.gridmap && !self.recovering_from_reset(it))
            .then(|| {
                let since = it - self.polar_start;
                let due = |interval: u32| interval > 0 && since.is_multiple_of(interval);
                GridMapWork {
                    remesh: due(self.mesh_interval) || self.deferred_remesh_due(it),
                    probes: due(self.gridmap_interval),
                }
            });
        BeforeStep {
            stage,
            estimate_angles: it == self.polar_start,
            gridmap,
        }
    }

    /// What is due once iteration `it` is done (`it + 1` steps in all).
    pub fn after(&self, it: u32) -> AfterStep {
        let done = it + 1;
        let within_run =
            |interval: u32| interval > 0 && done.is_multiple_of(interval) && done < self.iterations;
        AfterStep {
            update_light: done.is_multiple_of(self.envmap_prefilter_interval),
            report: done.is_multiple_of(self.report_every) || done == self.iterations,
            evaluate: within_run(self.eval_interval),
            densify: self.densify_due(done, self.stage(it)),
            reset_opacity: self.reset_due(done),
            checkpoint: within_run(self.checkpoint_interval),
        }
    }

    /// Whether densification is due after `done` steps, the last of them in `stage`.
    fn densify_due(&self, done: u32, stage: Stage) -> bool {
        let interval = match stage {
            Stage::Geometry => self.densify_interval,
            _ => self.densify_interval_polar,
        };
        done > self.densify_from && done <= self.densify_until && done.is_multiple_of(interval)
    }

    /// Whether an opacity reset is due after `done` steps.
    fn reset_due(&self, done: u32) -> bool {
        let reset = self.opacity_reset_interval;
        reset > 0 && done.is_multiple_of(reset) && done <= self.densify_until
    }

    /// The last opacity reset the state at the start of iteration `it` has had: a reset "at r"
    /// is applied after `r` steps, so iteration `r` is the first to see it.
    fn last_reset(&self, it: u32) -> Option<u32> {
        let interval = self.opacity_reset_interval;
        if interval == 0 {
            return None;
        }
        let last = it.min(self.densify_until) / interval * interval;
        (last > 0).then_some(last)
    }

    /// Whether iteration `it` falls in the `opacity_recovery_steps` after a reset.
    fn recovering_from_reset(&self, it: u32) -> bool {
        self.last_reset(it)
            .is_some_and(|r| it < r + self.opacity_recovery_steps)
    }

    /// Whether iteration `it` ends a recovery window inside which a PolarDR-stage remesh fell
    /// due (it runs now instead).
    fn deferred_remesh_due(&self, it: u32) -> bool {
        let (recovery, interval) = (self.opacity_recovery_steps, self.mesh_interval);
        let Some(reset) = self.last_reset(it) else {
            return false;
        };
        if recovery == 0 || interval == 0 || it != reset + recovery {
            return false;
        }
        let start = self.polar_start;
        (reset.max(start)..it).any(|i| (i - start).is_multiple_of(interval))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The iterations of a run at which `due` holds.
    fn when(schedule: &Schedule, due: impl Fn(u32) -> bool) -> Vec<u32> {
        (0..schedule.iterations()).filter(|&i| due(i)).collect()
    }

    fn thousand_steps() -> Schedule {
        Schedule::new(&TrainConfig {
            iterations: 1_000.into(),
            material_stage_end: 0.3,
            densify_from: 0.05,
            densify_until: 0.8,
            densify_interval: 100,
            densify_interval_polar: 250,
            opacity_reset_interval: 300,
            opacity_recovery_steps: 40,
            mesh_interval: 100,
            gridmap_interval: 30,
            eval_interval: 400,
            checkpoint_interval: 500,
            envmap_prefilter_interval: 10,
            ..TrainConfig::default()
        })
    }

    #[test]
    fn stages_follow_the_fractions() {
        let s = thousand_steps();
        let config = TrainConfig::default();
        let (material, polar) = (
            when(&s, |i| s.stage(i) == Stage::Material),
            when(&s, |i| s.stage(i) == Stage::Polar),
        );
        let geometry_end = (config.geometry_stage_end * 1_000.0).round() as u32;
        assert_eq!(material.first(), Some(&geometry_end));
        assert_eq!(material.last(), Some(&299));
        assert_eq!((polar[0], polar.len()), (300, 700));
        assert_eq!(s.final_stage(), Stage::Polar);
        assert_eq!(when(&s, |i| s.before(i).estimate_angles), [300]);
    }

    #[test]
    fn densification_resets_evaluations_and_checkpoints_fall_on_their_intervals() {
        let s = thousand_steps();
        // After `done` = it + 1 steps: densify in (50, 800], every 100 in geometry (ends at
        // 200), every 250 after; resets every 300 up to 800; evaluations and checkpoints never
        // after the last step.
        let done = |due: fn(&AfterStep) -> bool| -> Vec<u32> {
            when(&s, |i| due(&s.after(i)))
                .iter()
                .map(|i| i + 1)
                .collect()
        };
        assert_eq!(done(|a| a.densify), [100, 200, 250, 500, 750]);
        assert_eq!(done(|a| a.reset_opacity), [300, 600]);
        assert_eq!(done(|a| a.evaluate), [400, 800]);
        assert_eq!(done(|a| a.checkpoint), [500]);
        assert_eq!(done(|a| a.update_light).len(), 100);
        let reports = done(|a| a.report);
        assert_eq!((reports[0], reports.len()), (3, 334));
        assert_eq!(reports.last(), Some(&1_000));
        assert!(s.after(99).refines() && !s.after(100).refines());
    }

    #[test]
    fn gridmap_waits_out_each_recovery_window_and_remeshes_at_its_end() {
        let s = thousand_steps();
        // Resets after 300 and 600 steps (900 is past densify_until = 800).
        assert_eq!(s.last_reset(299), None);
        assert_eq!(s.last_reset(300), Some(300));
        assert_eq!(s.last_reset(950), Some(600));
        let waiting = when(&s, |i| s.recovering_from_reset(i));
        assert_eq!(
            waiting,
            [(300..340).collect::<Vec<_>>(), (600..640).collect()].concat()
        );
        // GridMap works only in the PolarDR stage, never inside a window; remeshes due at 300
        // and 600 fall in the windows and run at 340 and 640 instead.
        let active = when(&s, |i| s.before(i).gridmap.is_some());
        assert_eq!(active.len(), 700 - 80);
        assert!(active.iter().all(|i| !waiting.contains(i) && *i >= 300));
        let remeshes = when(&s, |i| s.before(i).gridmap.is_some_and(|g| g.remesh));
        assert_eq!(remeshes, [340, 400, 500, 640, 700, 800, 900]);
        let probes = when(&s, |i| s.before(i).gridmap.is_some_and(|g| g.probes));
        assert_eq!(probes.first(), Some(&360));
        assert!(probes.iter().all(|i| (i - 300) % 30 == 0));
        // Without GridMap there is no GridMap work.
        let off = Schedule::new(&TrainConfig {
            gridmap: false,
            ..TrainConfig::default()
        });
        assert!(when(&off, |i| off.before(i).gridmap.is_some()).is_empty());
    }

    #[test]
    fn zero_intervals_switch_their_work_off() {
        let s = Schedule::new(&TrainConfig {
            iterations: 500.into(),
            opacity_reset_interval: 0,
            mesh_interval: 0,
            gridmap_interval: 0,
            eval_interval: 0,
            checkpoint_interval: 0,
            ..TrainConfig::default()
        });
        assert!(when(&s, |i| {
            let after = s.after(i);
            after.reset_opacity || after.evaluate || after.checkpoint
        })
        .is_empty());
        assert!(when(&s, |i| s.recovering_from_reset(i)).is_empty());
        // Only the first PolarDR step meshes (the run has no mesh yet): no scheduled work.
        assert!(when(&s, |i| s
            .before(i)
            .gridmap
            .is_some_and(|g| g.remesh || g.probes))
        .is_empty());
    }
}

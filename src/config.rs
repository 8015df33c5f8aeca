//! The one training configuration: CLI flags, the `--config FILE.json` file and the service's job
//! `config` are all this struct (keys are the long flag names in snake_case). Defaults follow
//! METHOD.md §6–§7, with a shorter schedule: 6,000 steps instead of the paper's 15,000, a surfel
//! budget that follows the object's pixel count, and the material learning rates (IoR, roughness)
//! raised by the schedule's ratio, 2.5, so that they travel as far in fewer steps (README,
//! "Time to quality", has the measurements behind each choice). Stage boundaries are fractions of
//! `iterations`, so any run keeps the shape of the paper's schedule.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Which measurement the photometric loss uses (METHOD.md §1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Chosen from the capture: full if every training view has Stokes, partial if any has a
    /// polarizer image, rgb otherwise.
    #[default]
    Auto,
    /// Full Stokes: S0 photometric loss plus the S1/S2 Stokes loss.
    Full,
    /// Images behind linear polarizers; unknown angles are learned per `polarizer_group`.
    Partial,
    /// No polarization: the RGB-only ablation baseline.
    Rgb,
}

/// Compute backend.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum BackendChoice {
    /// A real GPU when one is found, else the fast host backend.
    #[default]
    Auto,
    /// The rayon f64 reference backend.
    Cpu,
    /// The rayon f32 SIMD host backend (the reference's computation, faster).
    Fast,
    /// The wgpu backend (lavapipe on machines without a GPU).
    Gpu,
}

/// Steps of the default schedule (the paper trains 15,000).
pub const DEFAULT_ITERATIONS: u32 = 6_000;

/// The paper's 15,000 steps over ours: the factor the material learning rates are raised by.
const PAPER_SCHEDULE_RATIO: f64 = 15_000.0 / DEFAULT_ITERATIONS as f64;

/// Default surfel budget per pixel of object (see `TrainConfig::surfels_per_mask_pixel`).
pub const SURFELS_PER_MASK_PIXEL: f64 = 4.0;

/// Every setting of a training run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TrainConfig {
    /// Total optimization steps (one random training view each).
    pub iterations: u32,
    pub mode: Mode,
    pub backend: BackendChoice,
    /// Seed of every random choice; equal seeds give equal runs.
    pub seed: u64,
    /// GridMap self-occlusion-aware lighting (METHOD.md §5).
    pub gridmap: bool,
    /// Weight the irradiance integral by the Fresnel transmission of the incoming light
    /// (METHOD.md §4, "known gaps" (2)); off reproduces the published model.
    pub fresnel_irradiance: bool,

    /// End of the plain-2DGS stage, as a fraction of `iterations` (the paper's 3,000 / 15,000).
    pub geometry_stage_end: f64,
    /// End of the environment/material warm-up, as a fraction of `iterations` (the paper's
    /// 5,000 / 15,000).
    pub material_stage_end: f64,

    /// Surfels sampled inside the visual hull at start.
    pub initial_surfels: u32,
    /// Upper bound on the surfel count (densification stops growing past it).
    pub max_surfels: u32,
    /// Surfel budget per pixel of object in a training view (the mean mask area): densification
    /// stops growing past this many times the object's pixels, or `max_surfels`, whichever is
    /// lower (never below `initial_surfels`). 0 leaves only `max_surfels`.
    pub surfels_per_mask_pixel: f64,
    /// Densification starts at this fraction of `iterations` (the paper's 500 / 15,000).
    pub densify_from: f64,
    /// Densification (and opacity resets) stop after this fraction of `iterations`.
    pub densify_until: f64,
    /// Steps between densifications during the geometry stage.
    pub densify_interval: u32,
    /// Steps between densify/prune passes once PolarDR is on.
    pub densify_interval_polar: u32,
    /// Screen-space gradient threshold for clone/split (pixels, averaged over views).
    pub densify_grad_threshold: f64,
    /// Surfels with opacity below this are pruned.
    pub prune_opacity: f64,
    /// Steps between opacity resets.
    pub opacity_reset_interval: u32,

    /// Learning rates (METHOD.md §7); positions are scaled by the scene extent.
    pub lr_position_init: f64,
    pub lr_position_final: f64,
    pub lr_albedo: f64,
    pub lr_opacity: f64,
    pub lr_scale: f64,
    pub lr_rotation: f64,
    pub lr_ior: f64,
    pub lr_roughness: f64,
    pub lr_envmap: f64,
    pub lr_polarizer: f64,

    /// Loss weights (METHOD.md §6).
    pub lambda_ssim: f64,
    pub lambda_stokes: f64,
    pub lambda_mask: f64,
    pub lambda_normal_smooth: f64,
    pub lambda_depth_normal: f64,

    /// Cube-map face size of the learned environment.
    pub envmap_resolution: u32,
    /// Steps between rebuilds of the environment's prefiltered mip chain and irradiance map while
    /// the map is being learned (the map moves little per step; a rebuild costs ~0.1 s at D = 64).
    pub envmap_prefilter_interval: u32,
    /// Steps between checkpoints (0: only at the end).
    pub checkpoint_interval: u32,
    /// Steps between test-view evaluations (0: only at the end).
    pub eval_interval: u32,
    /// Steps between mesh re-extractions for GridMap.
    pub mesh_interval: u32,
    /// Steps between GridMap rebuilds.
    pub gridmap_interval: u32,
    /// Steps after an opacity reset before GridMap's mesh and probes are rebuilt again (a mesh
    /// extracted from freshly reset, nearly transparent surfels is empty); a remesh that falls due
    /// meanwhile runs when they are over.
    pub opacity_recovery_steps: u32,
}

impl Default for TrainConfig {
    fn default() -> Self {
        TrainConfig {
            iterations: DEFAULT_ITERATIONS,
            mode: Mode::Auto,
            backend: BackendChoice::Auto,
            seed: 0,
            gridmap: true,
            fresnel_irradiance: false,
            geometry_stage_end: 0.2,
            material_stage_end: 1.0 / 3.0,
            initial_surfels: 20_000,
            max_surfels: 300_000,
            surfels_per_mask_pixel: SURFELS_PER_MASK_PIXEL,
            densify_from: 500.0 / 15_000.0,
            densify_until: 0.8,
            densify_interval: 100,
            densify_interval_polar: 500,
            densify_grad_threshold: 2e-4,
            prune_opacity: 0.05,
            opacity_reset_interval: 3_000,
            lr_position_init: 2e-4,
            lr_position_final: 2e-6,
            lr_albedo: 0.0075,
            lr_opacity: 0.05,
            lr_scale: 0.005,
            lr_rotation: 0.001,
            lr_ior: 0.001 * PAPER_SCHEDULE_RATIO,
            lr_roughness: 0.005 * PAPER_SCHEDULE_RATIO,
            lr_envmap: 0.01,
            lr_polarizer: 0.002,
            lambda_ssim: 0.2,
            lambda_stokes: 10.0,
            lambda_mask: 0.4,
            lambda_normal_smooth: 0.2,
            lambda_depth_normal: 0.1,
            envmap_resolution: 64,
            envmap_prefilter_interval: 10,
            checkpoint_interval: 1_000,
            eval_interval: 1_000,
            mesh_interval: 1_000,
            gridmap_interval: 300,
            opacity_recovery_steps: 300,
        }
    }
}

/// A configuration value out of its range.
#[derive(Debug, Error, PartialEq)]
#[error("invalid config: `{key}` {problem}")]
pub struct ConfigError {
    pub key: &'static str,
    pub problem: String,
}

impl TrainConfig {
    /// Parses a JSON config; unknown keys are errors (a typo must not silently use a default).
    pub fn from_json(text: &str) -> Result<Self, ConfigError> {
        let config: TrainConfig = serde_json::from_str(text).map_err(|e| ConfigError {
            key: "config",
            problem: e.to_string(),
        })?;
        config.validate()?;
        Ok(config)
    }

    /// Checks every range; the service calls this before queueing a job.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let bad = |key, problem: &str| {
            Err(ConfigError {
                key,
                problem: problem.to_owned(),
            })
        };
        if self.iterations == 0 || self.iterations > 1_000_000 {
            return bad("iterations", "must be in 1..=1000000");
        }
        if !(0.0..=1.0).contains(&self.geometry_stage_end)
            || !(self.geometry_stage_end..=1.0).contains(&self.material_stage_end)
        {
            return bad(
                "material_stage_end",
                "stage ends must satisfy 0 <= geometry_stage_end <= material_stage_end <= 1",
            );
        }
        if !(0.0..=1.0).contains(&self.densify_from) {
            return bad("densify_from", "must be a fraction in [0, 1]");
        }
        if !(self.densify_from..=1.0).contains(&self.densify_until) {
            return bad("densify_until", "must be a fraction in [densify_from, 1]");
        }
        if self.initial_surfels == 0 || self.initial_surfels > self.max_surfels {
            return bad("initial_surfels", "must be in 1..=max_surfels");
        }
        if self.envmap_prefilter_interval == 0 {
            return bad("envmap_prefilter_interval", "must be at least 1");
        }
        if !(4..=1024).contains(&self.envmap_resolution) {
            return bad("envmap_resolution", "must be in 4..=1024");
        }
        let non_negative = [
            ("lr_position_init", self.lr_position_init),
            ("lr_position_final", self.lr_position_final),
            ("lr_albedo", self.lr_albedo),
            ("lr_opacity", self.lr_opacity),
            ("lr_scale", self.lr_scale),
            ("lr_rotation", self.lr_rotation),
            ("lr_ior", self.lr_ior),
            ("lr_roughness", self.lr_roughness),
            ("lr_envmap", self.lr_envmap),
            ("lr_polarizer", self.lr_polarizer),
            ("lambda_ssim", self.lambda_ssim),
            ("lambda_stokes", self.lambda_stokes),
            ("lambda_mask", self.lambda_mask),
            ("lambda_normal_smooth", self.lambda_normal_smooth),
            ("lambda_depth_normal", self.lambda_depth_normal),
            ("densify_grad_threshold", self.densify_grad_threshold),
            ("surfels_per_mask_pixel", self.surfels_per_mask_pixel),
            ("prune_opacity", self.prune_opacity),
        ];
        for (key, value) in non_negative {
            if !value.is_finite() || value < 0.0 {
                return bad(key, "must be a finite number >= 0");
            }
        }
        if self.lambda_ssim > 1.0 {
            return bad("lambda_ssim", "must be in [0, 1]");
        }
        Ok(())
    }

    /// First iteration of the environment/material warm-up.
    pub fn material_stage_start(&self) -> u32 {
        (self.geometry_stage_end * self.iterations as f64).round() as u32
    }

    /// First iteration of the PolarDR stage.
    pub fn polar_stage_start(&self) -> u32 {
        (self.material_stage_end * self.iterations as f64).round() as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_keys_are_the_flag_names_and_unknown_keys_fail() {
        let c =
            TrainConfig::from_json(r#"{"iterations": 300, "mode": "partial", "seed": 7}"#).unwrap();
        assert_eq!((c.iterations, c.mode, c.seed), (300, Mode::Partial, 7));
        assert_eq!(c.lambda_stokes, 10.0);
        let e = TrainConfig::from_json(r#"{"iteratons": 300}"#).unwrap_err();
        assert!(e.problem.contains("iteratons"), "{e}");
    }

    #[test]
    fn out_of_range_values_name_the_key() {
        let e = TrainConfig::from_json(r#"{"lr_albedo": -1}"#).unwrap_err();
        assert_eq!(e.key, "lr_albedo");
        let e = TrainConfig::from_json(r#"{"iterations": 0}"#).unwrap_err();
        assert_eq!(e.key, "iterations");
    }

    #[test]
    fn default_stage_boundaries_keep_the_paper_schedule_shape() {
        let c = TrainConfig::default();
        assert_eq!(c.iterations, 6_000);
        assert_eq!(c.material_stage_start(), 1_200);
        assert_eq!(c.polar_stage_start(), 2_000);
        assert!((c.lr_ior - 0.0025).abs() < 1e-15);
        assert!((c.lr_roughness - 0.0125).abs() < 1e-15);
    }
}

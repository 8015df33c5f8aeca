//! The one training configuration: CLI flags, the `--config FILE.json` file and the service's job
//! `config` are all this struct (keys are the long flag names in snake_case). Defaults follow
//! METHOD.md §6–§7, with a shorter schedule: 6,000 steps instead of the paper's 15,000 (up to
//! 12,000 for small objects, whose steps cost less: `core::iterations`), a surfel budget that
//! follows the object's pixel count, and the material learning rates (IoR, roughness)
//! raised by the schedule's ratio, 2.5, so that they travel as far in fewer steps (README,
//! "Time to quality", has the measurements behind each choice). Stage boundaries are fractions of
//! `iterations`, so any run keeps the shape of the paper's schedule.

use serde::{Deserialize, Serialize};
use thiserror::Error;

pub use crate::core::gridmap::AnchorPlacement;
pub use crate::core::iterations::Iterations;
use crate::core::raster::RasterSettings;
pub use crate::core::resolution::Resolution;

/// Which measurement the photometric loss uses (METHOD.md §1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema))]
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
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema))]
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

/// Steps of the default schedule for an object of 16,000 pixels per view or more (the paper
/// trains 15,000; smaller objects get more under `auto`, [`Iterations`]).
pub const DEFAULT_ITERATIONS: u32 = Iterations::AUTO_MIN;

/// The paper's 15,000 steps over ours: the factor the material learning rates are raised by.
const PAPER_SCHEDULE_RATIO: f64 = 15_000.0 / DEFAULT_ITERATIONS as f64;

/// Default surfel budget per pixel of object (see `TrainConfig::surfels_per_mask_pixel`).
pub const SURFELS_PER_MASK_PIXEL: f64 = 6.0;

/// A setting the run decides from the capture (`auto`), or that is fixed `on` or `off`. A
/// config file may also give `true` or `false`, as it did when the setting was a plain switch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema))]
#[serde(rename_all = "snake_case")]
pub enum AutoSwitch {
    /// Decided by the run from what the capture shows (each setting says how).
    #[default]
    Auto,
    #[value(alias = "true")]
    On,
    #[value(alias = "false")]
    Off,
}

impl<'de> Deserialize<'de> for AutoSwitch {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Written {
            Switch(bool),
            Named(String),
        }
        match Written::deserialize(deserializer)? {
            Written::Switch(true) => Ok(AutoSwitch::On),
            Written::Switch(false) => Ok(AutoSwitch::Off),
            Written::Named(name) => match name.as_str() {
                "auto" => Ok(AutoSwitch::Auto),
                "on" => Ok(AutoSwitch::On),
                "off" => Ok(AutoSwitch::Off),
                other => Err(serde::de::Error::unknown_variant(
                    other,
                    &["auto", "on", "off"],
                )),
            },
        }
    }
}

/// An on/off setting on the command line (`on`, `off`, `true` or `false`).
fn parse_switch(value: &str) -> Result<bool, String> {
    match value {
        "on" | "true" => Ok(true),
        "off" | "false" => Ok(false),
        other => Err(format!("`{other}`: expected on or off")),
    }
}

/// Most surfels a run may hold (`max_surfels`): 10 million take about 5 GB with their optimizer
/// state, more than any capture needs (the knot's default budget is 58,500); a config asking for
/// more is refused before anything is allocated.
pub const MAX_SURFELS: u32 = 10_000_000;

/// Widest screen-space low-pass filter a run may ask for (pixels): wider ones blur every surfel
/// over several pixels and only make tiles longer.
pub const MAX_LOWPASS_SIGMA_PX: f64 = 4.0;

/// Most roughness levels per resolution of the specular mip chain: each level is a convolution
/// redone every `envmap_prefilter_interval` steps, and 3 already brings the shading no closer to
/// Mitsuba than 2 (README, *A finer roughness chain*).
pub const MAX_MIP_LEVELS_PER_SIZE: u8 = 4;

/// Widest band around a mask's edge the mask loss may leave alone, in pixels: a mask off by more
/// than this is a wrong mask, not an imprecise one.
pub const MAX_MASK_EDGE_PX: u32 = 16;

/// Default triangle budget of the exported mesh (`mesh_triangles`): a glTF of about 3.5 MB at
/// most (positions, normals, colour, roughness coordinate and IoR: about 35 bytes a triangle),
/// which a web viewer or a game engine loads at once. Smooth objects end well below it.
pub const DEFAULT_MESH_TRIANGLES: u32 = 100_000;

/// How `model.glb` carries the learned materials.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema))]
#[serde(rename_all = "snake_case")]
pub enum MeshMaterials {
    /// Baked into textures on a UV atlas: base colour, metallic-roughness and a tangent-space
    /// normal map.
    #[default]
    Textures,
    /// Per vertex: albedo as `COLOR_0`, roughness through a ramp texture.
    Vertex,
}

/// How the index of refraction is learned.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema))]
#[serde(rename_all = "snake_case")]
pub enum IorModel {
    /// One value per surfel and their common part, each learned by its own Adam step: the common
    /// part from the gradient of every pixel, a surfel's own from the pixels it covers.
    #[default]
    Anchored,
    /// One value for the whole object, learned from every pixel's gradient.
    Shared,
    /// One value per surfel, each learned from the pixels it covers (the published model).
    #[serde(alias = "per-surfel")]
    PerSurfel,
}

/// Every setting of a training run; also the training flags of the command line (each field a
/// `--long-name` flag with the default as its default), so the CLI, the config file and the
/// service's job `config` are one type.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, clap::Args)]
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema), schema(default))]
#[serde(default, deny_unknown_fields)]
pub struct TrainConfig {
    /// Total optimization steps (one random training view each), or auto: 6,000 for an object
    /// of 16,000 pixels per view or more, proportionally more for smaller ones, up to 12,000.
    #[arg(long, default_value_t = TrainConfig::default().iterations)]
    pub iterations: Iterations,
    /// Measurement used for the loss (auto: chosen from the capture).
    #[arg(long, value_enum, default_value_t = TrainConfig::default().mode)]
    pub mode: Mode,
    /// Compute backend.
    #[arg(long, value_enum, default_value_t = TrainConfig::default().backend)]
    pub backend: BackendChoice,
    /// Seed of every random choice; equal seeds give equal runs.
    #[arg(long, default_value_t = TrainConfig::default().seed)]
    pub seed: u64,
    /// GridMap self-occlusion-aware lighting (METHOD.md §5).
    #[arg(
        long,
        value_name = "on|off",
        value_parser = parse_switch,
        action = clap::ArgAction::Set,
        // The struct's default (a test holds them equal), in the flag's own words.
        default_value = "on"
    )]
    pub gridmap: bool,
    /// Where GridMap's probes sit on a 4×4×4 lattice over the object's box: `box`, its boundary
    /// (METHOD.md §5, the paper's 56), or `lattice`, with its 8 interior points too (those
    /// outside the mesh see into concavities; README, *GridMap's probes inside the box*).
    #[arg(long, value_enum, default_value_t = TrainConfig::default().gridmap_anchors)]
    pub gridmap_anchors: AnchorPlacement,
    /// Weight the irradiance integral by the Fresnel transmission of the incoming light
    /// (METHOD.md §4, "known gaps" (2)); off reproduces the published model.
    #[arg(
        long,
        value_name = "on|off",
        value_parser = parse_switch,
        action = clap::ArgAction::Set,
        default_value = "off"
    )]
    pub fresnel_irradiance: bool,
    /// Resolution training works at: `auto` (the engine's choice: views of at most 100,000 pixels
    /// on the host engines, 2,000,000 on a GPU, shrunk by a whole factor), `full`, a longest side
    /// in pixels (`512`) or a downscale factor (`/4`).
    #[arg(long, default_value_t = TrainConfig::default().resolution)]
    pub resolution: Resolution,
    /// Standard deviation (pixels) of the rasterizer's screen-space low-pass filter, which keeps
    /// surfels smaller than a pixel or seen edge-on visible (the model renders with it too):
    /// 2DGS's 0.707 by default. A pixel's box filter, 0.289, sharpens silhouettes of objects
    /// many pixels wide and loses thin parts (README, *Time to quality*). 0 turns it off.
    #[arg(long, default_value_t = TrainConfig::default().lowpass_sigma_px)]
    pub lowpass_sigma_px: f64,

    /// End of the plain-2DGS stage, as a fraction of `iterations` (the paper's 3,000 / 15,000).
    #[arg(long, default_value_t = TrainConfig::default().geometry_stage_end)]
    pub geometry_stage_end: f64,
    /// End of the environment/material warm-up, as a fraction of `iterations` (the paper's
    /// 5,000 / 15,000).
    #[arg(long, default_value_t = TrainConfig::default().material_stage_end)]
    pub material_stage_end: f64,

    /// Surfels sampled inside the visual hull at start.
    #[arg(long, default_value_t = TrainConfig::default().initial_surfels)]
    pub initial_surfels: u32,
    /// Upper bound on the surfel count (densification stops growing past it).
    #[arg(long, default_value_t = TrainConfig::default().max_surfels)]
    pub max_surfels: u32,
    /// Surfel budget per pixel of object in a training view (the mean mask area): densification
    /// stops growing past this many times the object's pixels, or `max_surfels`, whichever is
    /// lower (never below `initial_surfels`). 0 leaves only `max_surfels`.
    #[arg(long, default_value_t = TrainConfig::default().surfels_per_mask_pixel)]
    pub surfels_per_mask_pixel: f64,
    /// Densification starts at this fraction of `iterations` (the paper's 500 / 15,000).
    #[arg(long, default_value_t = TrainConfig::default().densify_from)]
    pub densify_from: f64,
    /// Densification (and opacity resets) stop after this fraction of `iterations`.
    #[arg(long, default_value_t = TrainConfig::default().densify_until)]
    pub densify_until: f64,
    /// Steps between densifications during the geometry stage.
    #[arg(long, default_value_t = TrainConfig::default().densify_interval)]
    pub densify_interval: u32,
    /// Steps between densify/prune passes once PolarDR is on.
    #[arg(long, default_value_t = TrainConfig::default().densify_interval_polar)]
    pub densify_interval_polar: u32,
    /// Screen-space gradient threshold for clone/split (pixels, averaged over views).
    #[arg(long, default_value_t = TrainConfig::default().densify_grad_threshold)]
    pub densify_grad_threshold: f64,
    /// Surfels with opacity below this are pruned.
    #[arg(long, default_value_t = TrainConfig::default().prune_opacity)]
    pub prune_opacity: f64,
    /// Steps between opacity resets.
    #[arg(long, default_value_t = TrainConfig::default().opacity_reset_interval)]
    pub opacity_reset_interval: u32,
    /// Before each opacity reset, prune the surfels that every training view renders a surface
    /// well in front of (`pipeline::train::hidden`), so that the reset cannot bring them back
    /// into view through the surface.
    #[arg(
        long,
        value_name = "on|off",
        value_parser = parse_switch,
        action = clap::ArgAction::Set,
        default_value = "on"
    )]
    pub prune_hidden: bool,

    /// Learning rate of positions at the start of the run (METHOD.md §7), scaled by the scene
    /// extent.
    #[arg(long, default_value_t = TrainConfig::default().lr_position_init)]
    pub lr_position_init: f64,
    /// Learning rate of positions at the end of the run (decays exponentially from the initial one).
    #[arg(long, default_value_t = TrainConfig::default().lr_position_final)]
    pub lr_position_final: f64,
    /// Learning rate of albedo.
    #[arg(long, default_value_t = TrainConfig::default().lr_albedo)]
    pub lr_albedo: f64,
    /// Learning rate of opacity (logit).
    #[arg(long, default_value_t = TrainConfig::default().lr_opacity)]
    pub lr_opacity: f64,
    /// Learning rate of the log-scales.
    #[arg(long, default_value_t = TrainConfig::default().lr_scale)]
    pub lr_scale: f64,
    /// Learning rate of the rotation quaternions.
    #[arg(long, default_value_t = TrainConfig::default().lr_rotation)]
    pub lr_rotation: f64,
    /// Learning rate of the index of refraction.
    #[arg(long, default_value_t = TrainConfig::default().lr_ior)]
    pub lr_ior: f64,
    /// How the index of refraction is learned: `anchored` (one value per surfel, and their
    /// common part learned from every pixel at once), `shared` (one value for the object) or
    /// `per-surfel` (the published model). A surfel sees too few pixels to move its own far:
    /// per surfel, the knot's IoR ends at 1.70 on average, near its start at 1.8, against the
    /// true 1.6, and the light and albedo take up the difference; its common part, learned from
    /// every pixel, ends at 1.61 (docs/results.md, *One index of refraction*). Host engines;
    /// the gpu engine learns it per surfel.
    #[arg(long, value_enum, default_value_t = TrainConfig::default().ior_model)]
    pub ior_model: IorModel,
    /// Learning rate of roughness.
    #[arg(long, default_value_t = TrainConfig::default().lr_roughness)]
    pub lr_roughness: f64,
    /// Learning rate of the environment map.
    #[arg(long, default_value_t = TrainConfig::default().lr_envmap)]
    pub lr_envmap: f64,
    /// Learning rate of the learned polarizer angles (partial mode).
    #[arg(long, default_value_t = TrainConfig::default().lr_polarizer)]
    pub lr_polarizer: f64,
    /// Learn a correction of each training view's camera pose (rotation and translation) with
    /// the surfels, from `refine_views_from` on: for captures whose poses come from
    /// structure-from-motion or a turntable's calibration, off by a fraction of a degree, which
    /// blurs every view. `auto` (the default) decides at `refine_views_from`: on where the
    /// training views' masks lie beside the silhouettes the surfels render by more than a pixel
    /// RMS (`pipeline::train::estimated_poses`), off on poses that agree, where the
    /// corrections would only drift (0.19° on the knot, 1.9 dB of S0 PSNR). Host engines
    /// (`fast`, `cpu`); the gpu engine trains on the capture's poses.
    #[arg(long, value_enum, default_value_t = TrainConfig::default().pose_refinement)]
    pub pose_refinement: AutoSwitch,
    /// Learn each training view's exposure and white balance (a factor per colour channel,
    /// normalized to the capture's mean) from `refine_views_from` on: cameras that expose or
    /// white-balance each view on their own (off by default: a highlight also changes a view's
    /// brightness, as much as a camera's exposure does on a glossy object, so the data do not
    /// say when it helps). Host engines, like `pose_refinement`.
    #[arg(
        long,
        value_name = "on|off",
        value_parser = parse_switch,
        action = clap::ArgAction::Set,
        default_value = "off"
    )]
    pub colour_refinement: bool,
    /// Pose and colour refinement start at this fraction of `iterations` (once the surfels have
    /// a shape).
    #[arg(long, default_value_t = TrainConfig::default().refine_views_from)]
    pub refine_views_from: f64,
    /// Pose refinement stops at this fraction of `iterations` (its rate has decayed by then).
    #[arg(long, default_value_t = TrainConfig::default().refine_poses_until)]
    pub refine_poses_until: f64,
    /// Learning rate of the pose corrections' rotations in radians (the translations' is this
    /// times the camera's distance to the object), decaying exponentially to 1 % of it by
    /// `refine_poses_until`.
    #[arg(long, default_value_t = TrainConfig::default().lr_pose)]
    pub lr_pose: f64,

    /// Weight of the SSIM term of the photometric loss (METHOD.md §6).
    #[arg(long, default_value_t = TrainConfig::default().lambda_ssim)]
    pub lambda_ssim: f64,
    /// Weight of the S1/S2 Stokes loss.
    #[arg(long, default_value_t = TrainConfig::default().lambda_stokes)]
    pub lambda_stokes: f64,
    /// Weight of the mask loss.
    #[arg(long, default_value_t = TrainConfig::default().lambda_mask)]
    pub lambda_mask: f64,
    /// Weight of the normal smoothness loss.
    #[arg(long, default_value_t = TrainConfig::default().lambda_normal_smooth)]
    pub lambda_normal_smooth: f64,
    /// Weight of the depth–normal consistency loss.
    #[arg(long, default_value_t = TrainConfig::default().lambda_depth_normal)]
    pub lambda_depth_normal: f64,
    /// Weight of the depth-distortion loss (2DGS), on depths in units of the object's radius.
    #[arg(long, default_value_t = TrainConfig::default().lambda_distortion)]
    pub lambda_distortion: f64,
    /// Weight of polarization's normal-azimuth prior (the AoLP lies along or across the
    /// rendered normal's azimuth), on views with full Stokes measurements, in every stage.
    #[arg(long, default_value_t = TrainConfig::default().lambda_aolp)]
    pub lambda_aolp: f64,
    /// Weigh each pixel of the AoLP prior by the share of its measured polarized power that
    /// rises above the view's own noise, measured on each view (off: by its DoLP alone, which
    /// noise inflates where the light is weakly polarized). Off by default: on the knot with
    /// 12-bit shot and read noise it did not lower the normal error (docs/results.md).
    #[arg(
        long,
        value_name = "on|off",
        value_parser = parse_switch,
        action = clap::ArgAction::Set,
        default_value = "off"
    )]
    pub polarization_snr: bool,
    /// Width in pixels (at the working resolution) of the band on either side of each mask's
    /// edge where the mask loss does not insist, for masks off by a pixel or two; the images
    /// alone place the silhouette there. 0 (the default): none; 2 takes back half of what masks
    /// off by ±2 px cost the knot, and costs exact masks as much (docs/results.md).
    #[arg(long, default_value_t = TrainConfig::default().mask_edge_px)]
    pub mask_edge_px: u32,

    /// Cube-map face size of the learned environment.
    #[arg(long, default_value_t = TrainConfig::default().envmap_resolution)]
    pub envmap_resolution: u32,
    /// Roughness levels per resolution of the prefiltered specular mip chain. 1 is METHOD.md
    /// §4's chain (roughness 0.08, 0.5 and 1 at D = 64); 2 adds levels at 0.22 and 0.36, so that a
    /// surface of intermediate roughness does not blend a near-mirror level into its highlight
    /// (README, *A finer roughness chain*). A model renders with the chain it was trained with.
    #[arg(long, default_value_t = TrainConfig::default().mip_levels_per_size)]
    pub mip_levels_per_size: u8,
    /// Steps between rebuilds of the environment's prefiltered mip chain and irradiance map while
    /// the map is being learned (the map moves little per step; a rebuild costs ~0.1 s at D = 64).
    #[arg(long, default_value_t = TrainConfig::default().envmap_prefilter_interval)]
    pub envmap_prefilter_interval: u32,
    /// Steps between checkpoints (0: only at the end).
    #[arg(long, default_value_t = TrainConfig::default().checkpoint_interval)]
    pub checkpoint_interval: u32,
    /// Steps between test-view evaluations (0: only at the end).
    #[arg(long, default_value_t = TrainConfig::default().eval_interval)]
    pub eval_interval: u32,
    /// Steps between mesh re-extractions for GridMap.
    #[arg(long, default_value_t = TrainConfig::default().mesh_interval)]
    pub mesh_interval: u32,
    /// Steps between GridMap rebuilds.
    #[arg(long, default_value_t = TrainConfig::default().gridmap_interval)]
    pub gridmap_interval: u32,
    /// Steps after an opacity reset before GridMap's mesh and probes are rebuilt again (a mesh
    /// extracted from freshly reset, nearly transparent surfels is empty); a remesh that falls due
    /// meanwhile runs when they are over.
    #[arg(long, default_value_t = TrainConfig::default().opacity_recovery_steps)]
    pub opacity_recovery_steps: u32,

    /// Most triangles of the exported mesh (`model.glb`): the dense mesh is simplified by quadric
    /// error collapses to this budget, or further where the surface is smooth enough (an error of
    /// an eighth of a TSDF voxel); 0 keeps the dense mesh. `mesh.ply` stays dense.
    #[arg(long, default_value_t = TrainConfig::default().mesh_triangles)]
    pub mesh_triangles: u32,

    /// How `model.glb` carries the materials: `textures` (a UV atlas with baked base colour,
    /// metallic-roughness and normal maps) or `vertex` (per-vertex colour and roughness).
    #[arg(long, value_enum, default_value_t = TrainConfig::default().mesh_materials)]
    pub mesh_materials: MeshMaterials,

    /// Whether the export fails when no mesh can be extracted (the TSDF of the model's depth
    /// has no zero crossing, as after a run too short to form a surface). Off: the export goes
    /// on without `mesh.ply` and `model.glb` and says why in `metrics.json`'s `warnings` (a
    /// service job succeeds with that warning).
    #[arg(
        long,
        value_name = "on|off",
        value_parser = parse_switch,
        action = clap::ArgAction::Set,
        // The struct's default, in the flag's own words.
        default_value = "off"
    )]
    pub require_mesh: bool,
}

impl Default for TrainConfig {
    fn default() -> Self {
        TrainConfig {
            iterations: Iterations::Auto,
            mode: Mode::Auto,
            backend: BackendChoice::Auto,
            seed: 0,
            gridmap: true,
            gridmap_anchors: AnchorPlacement::Box,
            fresnel_irradiance: false,
            resolution: Resolution::Auto,
            lowpass_sigma_px: std::f64::consts::FRAC_1_SQRT_2,
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
            prune_hidden: true,
            lr_position_init: 2e-4,
            lr_position_final: 2e-6,
            lr_albedo: 0.0075,
            lr_opacity: 0.05,
            lr_scale: 0.005,
            lr_rotation: 0.001,
            lr_ior: 0.001 * PAPER_SCHEDULE_RATIO,
            ior_model: IorModel::Anchored,
            lr_roughness: 0.005 * PAPER_SCHEDULE_RATIO,
            lr_envmap: 0.01,
            lr_polarizer: 0.002,
            pose_refinement: AutoSwitch::Auto,
            colour_refinement: false,
            refine_views_from: 0.05,
            refine_poses_until: 1.0,
            lr_pose: 1e-3,
            lambda_ssim: 0.2,
            lambda_stokes: 10.0,
            lambda_mask: 0.4,
            lambda_normal_smooth: 0.2,
            lambda_depth_normal: 0.1,
            lambda_distortion: 0.0,
            lambda_aolp: 3.0,
            polarization_snr: false,
            mask_edge_px: 0,
            envmap_resolution: 64,
            // A model's config.json without the key (written before the setting) reads as
            // this default, so a change of it must read those models as 1 (`Model::load`).
            mip_levels_per_size: 1,
            envmap_prefilter_interval: 10,
            checkpoint_interval: 1_000,
            eval_interval: 1_000,
            mesh_interval: 1_000,
            gridmap_interval: 300,
            opacity_recovery_steps: 300,
            mesh_triangles: DEFAULT_MESH_TRIANGLES,
            mesh_materials: MeshMaterials::Textures,
            require_mesh: false,
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
    /// The rasterizer's settings of a run: the defaults with this run's low-pass filter.
    pub fn raster_settings(&self) -> RasterSettings {
        RasterSettings {
            lowpass_sigma_px: self.lowpass_sigma_px,
            ..RasterSettings::default()
        }
    }

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
        if let Some(problem) = self.iterations.problem() {
            return bad("iterations", &problem);
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
        if !(0.0..=1.0).contains(&self.refine_views_from) {
            return bad("refine_views_from", "must be a fraction in [0, 1]");
        }
        if !(self.refine_views_from..=1.0).contains(&self.refine_poses_until) {
            return bad(
                "refine_poses_until",
                "must be a fraction in [refine_views_from, 1]",
            );
        }
        if !(self.lr_pose.is_finite() && self.lr_pose >= 0.0) {
            return bad("lr_pose", "must be a finite rate >= 0");
        }
        if !(self.densify_from..=1.0).contains(&self.densify_until) {
            return bad("densify_until", "must be a fraction in [densify_from, 1]");
        }
        if self.max_surfels == 0 || self.max_surfels > MAX_SURFELS {
            return bad("max_surfels", &format!("must be in 1..={MAX_SURFELS}"));
        }
        if self.initial_surfels == 0 || self.initial_surfels > self.max_surfels {
            return bad("initial_surfels", "must be in 1..=max_surfels");
        }
        if self.envmap_prefilter_interval == 0 {
            return bad("envmap_prefilter_interval", "must be at least 1");
        }
        if let Some(problem) = self.resolution.problem() {
            return bad("resolution", &problem);
        }
        if !(0.0..=MAX_LOWPASS_SIGMA_PX).contains(&self.lowpass_sigma_px) {
            return bad(
                "lowpass_sigma_px",
                &format!("must be in [0, {MAX_LOWPASS_SIGMA_PX}] pixels"),
            );
        }
        if !(4..=1024).contains(&self.envmap_resolution) {
            return bad("envmap_resolution", "must be in 4..=1024");
        }
        if !(1..=MAX_MIP_LEVELS_PER_SIZE).contains(&self.mip_levels_per_size) {
            return bad(
                "mip_levels_per_size",
                &format!("must be in 1..={MAX_MIP_LEVELS_PER_SIZE}"),
            );
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
            ("lambda_distortion", self.lambda_distortion),
            ("lambda_aolp", self.lambda_aolp),
            ("densify_grad_threshold", self.densify_grad_threshold),
            ("surfels_per_mask_pixel", self.surfels_per_mask_pixel),
            ("prune_opacity", self.prune_opacity),
        ];
        for (key, value) in non_negative {
            if !value.is_finite() || value < 0.0 {
                return bad(key, "must be a finite number >= 0");
            }
        }
        if self.mask_edge_px > MAX_MASK_EDGE_PX {
            return bad(
                "mask_edge_px",
                &format!("must be at most {MAX_MASK_EDGE_PX}"),
            );
        }
        if self.lambda_ssim > 1.0 {
            return bad("lambda_ssim", "must be in [0, 1]");
        }
        Ok(())
    }

    /// `self` (the defaults, or a config file's settings) with every setting that was given on
    /// the command line taken from `flags`, the same struct as parsed by clap from `matches`.
    pub fn overridden_by(&self, flags: &TrainConfig, matches: &clap::ArgMatches) -> Self {
        let (Ok(serde_json::Value::Object(mut merged)), Ok(serde_json::Value::Object(given))) =
            (serde_json::to_value(self), serde_json::to_value(flags))
        else {
            unreachable!("a TrainConfig serializes to a JSON object");
        };
        for (key, value) in given {
            if matches.value_source(&key) == Some(clap::parser::ValueSource::CommandLine) {
                merged.insert(key, value);
            }
        }
        serde_json::from_value(serde_json::Value::Object(merged))
            .expect("a merge of two TrainConfigs is a TrainConfig")
    }

    /// The run's steps: the fixed count, or for `auto` the count [`Self::for_object`] resolved
    /// (before a capture resolves it, `auto`'s least, [`Iterations::at_least`]).
    pub fn steps(&self) -> u32 {
        self.iterations.at_least()
    }

    /// This configuration with `auto` steps resolved for training views of
    /// `mean_object_pixels` mask pixels on average ([`Iterations::for_object`]).
    pub fn for_object(&self, mean_object_pixels: f64) -> TrainConfig {
        TrainConfig {
            iterations: Iterations::Fixed(self.iterations.for_object(mean_object_pixels)),
            ..self.clone()
        }
    }

    /// First iteration of the environment/material warm-up.
    pub fn material_stage_start(&self) -> u32 {
        (self.geometry_stage_end * f64::from(self.steps())).round() as u32
    }

    /// First iteration of the PolarDR stage.
    pub fn polar_stage_start(&self) -> u32 {
        (self.material_stage_end * f64::from(self.steps())).round() as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_keys_are_the_flag_names_and_unknown_keys_fail() {
        let c =
            TrainConfig::from_json(r#"{"iterations": 300, "mode": "partial", "seed": 7}"#).unwrap();
        assert_eq!((c.steps(), c.mode, c.seed), (300, Mode::Partial, 7));
        assert_eq!(c.lambda_stokes, 10.0);
        let e = TrainConfig::from_json(r#"{"iteratons": 300}"#).unwrap_err();
        assert!(e.problem.contains("iteratons"), "{e}");
        // A value as the flag spells it, or as JSON does.
        for written in ["per-surfel", "per_surfel"] {
            let c = TrainConfig::from_json(&format!(r#"{{"ior_model": "{written}"}}"#)).unwrap();
            assert_eq!(c.ior_model, IorModel::PerSurfel);
        }
    }

    #[test]
    fn out_of_range_values_name_the_key() {
        let e = TrainConfig::from_json(r#"{"lr_albedo": -1}"#).unwrap_err();
        assert_eq!(e.key, "lr_albedo");
        let e = TrainConfig::from_json(r#"{"iterations": 0}"#).unwrap_err();
        assert_eq!(e.key, "iterations");
    }

    #[test]
    fn the_lowpass_filter_is_2dgs_and_checked() {
        let c = TrainConfig::default();
        assert_eq!(c.lowpass_sigma_px, std::f64::consts::FRAC_1_SQRT_2);
        assert_eq!(c.raster_settings(), RasterSettings::default());
        for bad in ["-0.1", "4.5"] {
            let e = TrainConfig::from_json(&format!(r#"{{"lowpass_sigma_px": {bad}}}"#));
            assert_eq!(e.unwrap_err().key, "lowpass_sigma_px");
        }
        let sharp = TrainConfig::from_json(r#"{"lowpass_sigma_px": 0.2887}"#).unwrap();
        assert_eq!(sharp.raster_settings().lowpass_sigma_px, 0.2887);
        let off = TrainConfig::from_json(r#"{"lowpass_sigma_px": 0}"#).unwrap();
        assert_eq!(off.raster_settings().lowpass_sigma_px, 0.0);
    }

    /// The command line's flags are the config's fields with their defaults; a flag given
    /// overrides the file, one not given leaves it.
    #[test]
    fn flags_override_the_file_and_defaults_are_the_structs() {
        #[derive(clap::Parser)]
        struct Cli {
            #[command(flatten)]
            config: TrainConfig,
        }
        use clap::{CommandFactory, FromArgMatches};
        let parse = |args: &[&str]| {
            let matches = Cli::command().try_get_matches_from(args).unwrap();
            let cli = Cli::from_arg_matches(&matches).unwrap();
            (cli.config, matches)
        };
        let (flags, matches) = parse(&["phygap"]);
        assert_eq!(flags, TrainConfig::default(), "defaults are the struct's");
        let file = TrainConfig::from_json(r#"{"iterations": 300, "lr_albedo": 0.5}"#).unwrap();
        assert_eq!(file.overridden_by(&flags, &matches), file);
        let (flags, matches) = parse(&[
            "phygap",
            "--iterations",
            "900",
            "--gridmap",
            "off",
            "--mode",
            "rgb",
            "--lambda-stokes",
            "3",
            "--pose-refinement",
            "off",
        ]);
        let merged = file.overridden_by(&flags, &matches);
        assert_eq!(
            (
                merged.iterations,
                merged.gridmap,
                merged.mode,
                merged.lambda_stokes
            ),
            (Iterations::Fixed(900), false, Mode::Rgb, 3.0)
        );
        assert_eq!(merged.lr_albedo, 0.5, "kept from the file");
        assert_eq!(merged.pose_refinement, AutoSwitch::Off);
        assert_eq!(
            parse(&["phygap", "--pose-refinement", "true"])
                .0
                .pose_refinement,
            AutoSwitch::On,
            "the old switch's words still work"
        );
        assert!(Cli::command()
            .try_get_matches_from(["phygap", "--gridmap", "maybe"])
            .is_err());
    }

    #[test]
    fn pose_refinement_reads_auto_on_off_and_the_old_switch() {
        let read = |value: &str| {
            TrainConfig::from_json(&format!(r#"{{"pose_refinement": {value}}}"#))
                .map(|c| c.pose_refinement)
        };
        assert_eq!(TrainConfig::default().pose_refinement, AutoSwitch::Auto);
        assert_eq!(read(r#""auto""#).unwrap(), AutoSwitch::Auto);
        assert_eq!(read(r#""on""#).unwrap(), AutoSwitch::On);
        assert_eq!(read("true").unwrap(), AutoSwitch::On);
        assert_eq!(read(r#""off""#).unwrap(), AutoSwitch::Off);
        assert_eq!(read("false").unwrap(), AutoSwitch::Off);
        let e = read(r#""sometimes""#).unwrap_err();
        assert!(e.to_string().contains("sometimes"), "{e}");
        assert!(read("1").is_err());
        // Written back as a word, read back the same.
        let on = TrainConfig {
            pose_refinement: AutoSwitch::On,
            ..TrainConfig::default()
        };
        let json = serde_json::to_string(&on).unwrap();
        assert!(json.contains(r#""pose_refinement":"on""#), "{json}");
        assert_eq!(TrainConfig::from_json(&json).unwrap(), on);
    }

    #[test]
    fn the_mip_chain_setting_is_checked() {
        for bad in [0, MAX_MIP_LEVELS_PER_SIZE + 1] {
            let e = TrainConfig::from_json(&format!(r#"{{"mip_levels_per_size": {bad}}}"#));
            assert_eq!(e.unwrap_err().key, "mip_levels_per_size");
        }
        let given = TrainConfig::from_json(r#"{"mip_levels_per_size": 3}"#).unwrap();
        assert_eq!(given.mip_levels_per_size, 3);
    }

    #[test]
    fn default_stage_boundaries_keep_the_paper_schedule_shape() {
        let c = TrainConfig::default();
        assert_eq!(c.iterations, Iterations::Auto);
        assert_eq!(c.steps(), 6_000);
        assert_eq!(c.material_stage_start(), 1_200);
        assert_eq!(c.polar_stage_start(), 2_000);
        assert!((c.lr_ior - 0.0025).abs() < 1e-15);
        assert!((c.lr_roughness - 0.0125).abs() < 1e-15);
    }
}

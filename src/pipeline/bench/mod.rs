//! Timings for `phygap bench`: the rasterizer backends on a synthetic object (surfels tangent to
//! the unit sphere, seen from distance 4 with a 40° field of view, the framing of the shared
//! captures), GridMap's periodic rebuild on a trained model, training steps per second on a
//! capture ([`bench_train`]: a short run of the real schedule held in one stage), and a whole
//! run's time to quality ([`bench_quality`]).
//!
//! Surfels sit on a Fibonacci lattice of the sphere with scale `0.6 × spacing`, so the shell is
//! covered with overlap; both hemispheres are rasterized (surfels are two-sided), as in training.
//! Timings are medians over `repeats` runs after one warm-up run.

mod quality;

pub use quality::{bench_quality, PsnrReading, QualityError, QualityRun};

use std::time::Instant;

use glam::{DMat3, DQuat, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use tracing::info_span;

use crate::core::camera::Camera;
use crate::core::engine::Backend;
use crate::core::envmap::{EnvMapError, PreparedEnv};
use crate::core::gridmap::{GridMap, GridMapError};
use crate::core::mesh::DepthPixels;
use crate::core::raster::{RasterError, RasterSettings, StageTime};
use crate::core::surfels::{logit, Surfels};
use crate::gpu::GpuBackend;
use crate::io::model::Model;
use crate::pipeline::backend::Engine;
use crate::pipeline::mesh_extraction::{self, MeshingError, GRIDMAP_MESH_RESOLUTION};
use crate::pipeline::reconstruction::run_prefilter_plan;
use crate::testing::random_upstream;

/// One benchmark measurement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BenchRow {
    pub surfels: usize,
    pub width: u32,
    pub height: u32,
    /// Median forward time in milliseconds.
    pub fwd_ms: f64,
    /// Median forward + backward time in milliseconds.
    pub fwd_bwd_ms: f64,
    /// (pixel, surfel) pairs the forward pass evaluated (not serialized).
    #[serde(skip)]
    pub pixel_evaluations: u64,
    /// Device time per stage over the timed runs, where the backend measures it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<StageTime>,
}

impl BenchRow {
    /// Forward (pixel, surfel) evaluations per second.
    pub fn evaluations_per_s(&self) -> f64 {
        self.pixel_evaluations as f64 / (self.fwd_ms * 1e-3)
    }
}

/// `n` surfels tangent to the unit sphere, covering it (deterministic for a seed).
pub fn shell_surfels(n: usize, seed: u64) -> Surfels {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut s = Surfels::zeros(n);
    let spacing = (4.0 * std::f64::consts::PI / n.max(1) as f64).sqrt();
    let golden = std::f64::consts::PI * (3.0 - 5.0f64.sqrt());
    for i in 0..n {
        let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
        let r = (1.0 - z * z).sqrt();
        let phi = golden * i as f64;
        let normal = DVec3::new(r * phi.cos(), r * phi.sin(), z);
        let helper = if normal.x.abs() < 0.9 {
            DVec3::X
        } else {
            DVec3::Y
        };
        let tu = normal.cross(helper).normalize();
        let tv = normal.cross(tu);
        let q = DQuat::from_mat3(&DMat3::from_cols(tu, tv, normal)).normalize();
        s.position[i] = normal.to_array();
        let scale = (0.6 * spacing * rng.random_range(0.8..1.2f64)).ln();
        s.log_scale[i] = [scale, scale];
        s.rotation[i] = [q.w, q.x, q.y, q.z];
        s.opacity[i] = logit(rng.random_range(0.7..0.95));
        s.albedo[i] = std::array::from_fn(|_| rng.random_range(-2.0..2.0));
        s.roughness[i] = rng.random_range(-2.0..2.0);
        s.ior[i] = rng.random_range(-2.0..2.0);
    }
    s
}

/// Camera at distance 4 from the origin with a 40° horizontal field of view.
pub fn shell_camera(width: u32, height: u32) -> Camera {
    Camera::look_at(
        width,
        height,
        40f64.to_radians(),
        DVec3::new(1.5, -3.6, 0.7).normalize() * 4.0,
        DVec3::ZERO,
        DVec3::Z,
    )
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        return f64::NAN;
    }
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// Median forward and forward+backward times of `backend` for each surfel count.
pub fn bench_raster(
    backend: &dyn Backend,
    surfel_counts: &[usize],
    width: u32,
    height: u32,
    repeats: usize,
) -> Result<Vec<BenchRow>, RasterError> {
    let camera = shell_camera(width, height);
    let settings = RasterSettings::default();
    let repeats = repeats.max(1);
    let mut rows = Vec::new();
    for &n in surfel_counts {
        let _span = info_span!("bench_raster", surfels = n, backend = backend.name()).entered();
        let surfels = shell_surfels(n, 7);
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let upstream = random_upstream(&mut rng, width as usize, height as usize);
        // Warm-up.
        let fwd = backend.forward(&surfels, &camera, &settings)?;
        backend.backward(&surfels, &camera, &settings, &fwd, &upstream)?;
        let evaluations = fwd.stats.pixel_evaluations;
        drop(fwd);
        backend.take_stage_times();

        let mut fwd_times = Vec::with_capacity(repeats);
        let mut both_times = Vec::with_capacity(repeats);
        for _ in 0..repeats {
            let start = Instant::now();
            let fwd = backend.forward(&surfels, &camera, &settings)?;
            fwd_times.push(start.elapsed().as_secs_f64() * 1e3);
            drop(fwd);
            let start = Instant::now();
            let fwd = backend.forward(&surfels, &camera, &settings)?;
            let grads = backend.backward(&surfels, &camera, &settings, &fwd, &upstream)?;
            both_times.push(start.elapsed().as_secs_f64() * 1e3);
            drop((fwd, grads));
        }
        rows.push(BenchRow {
            surfels: n,
            width,
            height,
            fwd_ms: median(fwd_times),
            fwd_bwd_ms: median(both_times),
            pixel_evaluations: evaluations,
            stages: backend.take_stage_times(),
        });
    }
    Ok(rows)
}

/// What GridMap costs a training run of `model`: the mesh it traces (re-extracted every
/// `mesh_interval` steps) and the rebuild of its probes (every `gridmap_interval` steps).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GridMapTiming {
    pub surfels: usize,
    pub mesh_resolution: usize,
    pub triangles: usize,
    /// Mesh extraction (depth rendering from the training cameras, TSDF, marching cubes).
    pub mesh_seconds: f64,
    pub anchors: usize,
    /// Median rebuild (BVH, anchors, probe rendering, prefiltering).
    pub rebuild_seconds: f64,
}

/// Times the mesh extraction once and the GridMap rebuild `repeats` times (median) for `model`.
pub fn bench_gridmap(model: &Model, repeats: usize) -> Result<GridMapTiming, BenchError> {
    let _span = info_span!("bench_gridmap", surfels = model.surfels.len()).entered();
    let backend = crate::pipeline::backend::select(model.config.backend)?;
    let start = Instant::now();
    let mesh = mesh_extraction::mesh_from_surfels(
        &model.surfels,
        &mesh_extraction::model_cameras(model),
        &*backend,
        &model.raster_settings(),
        GRIDMAP_MESH_RESOLUTION,
        DepthPixels::All,
    )?;
    let mesh_seconds = start.elapsed().as_secs_f64();
    let plan = run_prefilter_plan(&model.config, model.envmap.size)?;
    let env = PreparedEnv::new(&model.envmap, plan)?;
    let mut times = Vec::with_capacity(repeats.max(1));
    let mut anchors = 0;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        let grid = GridMap::build(
            &mesh,
            &model.surfels,
            &model.envmap,
            env.clone(),
            model.config.gridmap_anchors,
        )?;
        times.push(start.elapsed().as_secs_f64());
        anchors = grid.anchors().len();
    }
    Ok(GridMapTiming {
        surfels: model.surfels.len(),
        mesh_resolution: GRIDMAP_MESH_RESOLUTION,
        triangles: mesh.triangles.len(),
        mesh_seconds,
        anchors,
        rebuild_seconds: median(times),
    })
}

/// The stage a training benchmark holds for the whole run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BenchStage {
    /// Plain 2DGS (no shading).
    Geometry,
    /// PolarDR with the Stokes loss, under GridMap when the config has it on.
    Polar,
}

/// Steps per second of a training run held in one stage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrainTiming {
    /// The backend and how the steps run (the run's start event).
    pub backend: String,
    pub stage: BenchStage,
    pub width: u32,
    pub height: u32,
    /// Steps between the first and the last progress event, and their wall time. Everything a
    /// real run does in between is included (densification, GridMap rebuilds, environment
    /// updates); what comes before the end of the first timed step (kernel compilation, uploads,
    /// the first GridMap) is `startup_seconds`.
    pub steps: u32,
    pub seconds: f64,
    pub steps_per_second: f64,
    pub startup_seconds: f64,
    /// Surfels at the first and the last timed step.
    pub surfels: (usize, usize),
    /// Device time per pass over the whole run, where the backend measures it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub passes: Vec<StageTime>,
    /// Host time of the device steps' phases over the whole run (encode, read-back, finish, submit,
    /// wait; gpu backend only).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub host_phases: Vec<StageTime>,
    #[serde(flatten)]
    pub memory: MemoryPeaks,
}

/// The most memory a benchmark's run held, on the device and on the host.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MemoryPeaks {
    /// The most buffer memory the device held at a submission (gpu backend only).
    #[serde(default)]
    pub device_peak_bytes: Option<u64>,
    /// The process's peak resident memory (`VmHWM`, Linux only).
    #[serde(default)]
    pub host_peak_rss_bytes: Option<u64>,
}

impl MemoryPeaks {
    /// The peaks so far of `backend`'s device and of this process.
    pub fn of(backend: &Engine) -> Self {
        MemoryPeaks {
            device_peak_bytes: backend.gpu().map(|g| g.buffer_memory().peak_bytes),
            host_peak_rss_bytes: crate::pipeline::peak_memory::peak_resident_bytes(),
        }
    }
}

/// Trains `capture` for `iterations` steps held in `stage` (the schedule's densification,
/// GridMap and environment intervals scale with `iterations` as in any run; no evaluation or
/// checkpoint), on `backend`, in a scratch folder, and times the steps.
pub fn bench_train(
    backend: &Engine,
    capture: &crate::io::capture::Capture,
    config: &crate::core::config::TrainConfig,
    stage: BenchStage,
) -> Result<TrainTiming, BenchError> {
    let _span = info_span!("bench_train", iterations = config.steps()).entered();
    let (end, name) = match stage {
        BenchStage::Geometry => (1.0, "geometry"),
        BenchStage::Polar => (0.0, "polar"),
    };
    let config = crate::core::config::TrainConfig {
        geometry_stage_end: end,
        material_stage_end: end,
        eval_interval: 0,
        checkpoint_interval: 0,
        ..config.clone()
    };
    let dir = std::env::temp_dir().join(format!(
        "phygap-bench-train-{}-{name}-{}",
        std::process::id(),
        backend.name()
    ));
    let mut first: Option<(u32, f64, usize)> = None;
    let mut last: Option<(u32, f64, usize)> = None;
    let mut description = String::new();
    let cancel = std::sync::atomic::AtomicBool::new(false);
    backend.take_stage_times();
    let gpu = backend.gpu();
    if let Some(gpu) = gpu {
        gpu.take_host_times();
    }
    let outcome = crate::pipeline::train::train_on(
        backend,
        capture,
        &dir,
        &config,
        false,
        &cancel,
        &mut |e| match e {
            crate::core::events::TrainEvent::Started { backend, .. } => {
                description = backend.clone()
            }
            crate::core::events::TrainEvent::Step {
                iteration,
                elapsed_seconds,
                num_surfels,
                ..
            } => {
                let now = (*iteration, *elapsed_seconds, *num_surfels);
                first.get_or_insert(now);
                last = Some(now);
            }
            _ => {}
        },
    );
    let passes = backend.take_stage_times();
    let host_phases = gpu.map(GpuBackend::take_host_times).unwrap_or_default();
    let memory = MemoryPeaks::of(backend);
    // A scratch folder: failing to remove it loses nothing.
    let _ = std::fs::remove_dir_all(&dir);
    outcome?;
    let (Some(first), Some(last)) = (first, last) else {
        return Err(BenchError::TooShort(config.steps()));
    };
    let steps = last.0 - first.0;
    if steps == 0 {
        return Err(BenchError::TooShort(config.steps()));
    }
    let seconds = last.1 - first.1;
    let camera = &capture.views[0].camera;
    Ok(TrainTiming {
        backend: description,
        stage,
        width: camera.width,
        height: camera.height,
        steps,
        seconds,
        steps_per_second: f64::from(steps) / seconds,
        startup_seconds: first.1,
        surfels: (first.2, last.2),
        passes,
        host_phases,
        memory,
    })
}

/// Why a benchmark of a trained model could not run.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error(transparent)]
    Backend(#[from] crate::pipeline::backend::BackendError),
    #[error(transparent)]
    Meshing(#[from] MeshingError),
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
    #[error(transparent)]
    GridMap(#[from] GridMapError),
    #[error(transparent)]
    Train(#[from] crate::pipeline::train::TrainError),
    #[error("{0} iterations give fewer than two timed steps; use more")]
    TooShort(u32),
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::raster::cpu::CpuBackend;

    #[test]
    fn shell_scene_covers_the_sphere_silhouette() {
        let camera = shell_camera(64, 64);
        let s = shell_surfels(4000, 1);
        let out = CpuBackend
            .forward(&s, &camera, &RasterSettings::default())
            .unwrap()
            .gbuffers;
        // Pixels whose ray passes well inside the unit sphere must be opaque, at depth ≈ 3..4.
        let mut inside = 0;
        for j in 0..64u32 {
            for i in 0..64u32 {
                let d = camera.pixel_dir(i, j);
                let o = camera.origin();
                let closest = (o - d * o.dot(d)).length();
                if closest < 0.8 {
                    inside += 1;
                    let k = (j * 64 + i) as usize;
                    assert!(out.alpha[k] > 0.95, "pixel ({i},{j}) α {}", out.alpha[k]);
                    assert!(out.depth[k] > 2.9 && out.depth[k] < 4.0);
                }
            }
        }
        assert!(inside > 500);
    }

    #[test]
    fn bench_reports_one_row_per_count() {
        let rows = bench_raster(&CpuBackend, &[100, 300], 32, 32, 1).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[1].surfels, 300);
        assert!(rows.iter().all(|r| r.fwd_ms > 0.0 && r.fwd_bwd_ms > 0.0));
        assert!(rows[1].pixel_evaluations > 0);
        let json = serde_json::to_value(&rows[0]).unwrap();
        let keys: Vec<&str> = json
            .as_object()
            .unwrap()
            .keys()
            .map(|k| k.as_str())
            .collect();
        assert_eq!(keys.len(), 5, "{keys:?}");
    }
}

//! Helpers of the backend test files: opening the gpu backend (or skipping where no adapter
//! exists), random cameras, surfels and environments, the relative-error measure and the parity
//! checks against the cpu reference ([`parity`]). Each test file uses some of them.
#![allow(dead_code)]

pub mod parity;

use glam::{DMat3, DQuat, DVec3};
use phygap::core::camera::Camera;
use phygap::core::envmap::{CubeMap, MipChainSpec, PrefilterPlan, PreparedEnv};
use phygap::core::surfels::{logit, Surfels};
use phygap::gpu::{AdapterRequirement, GpuBackend, GpuContext, GpuOptions};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Whether this runs under CI (`CI=true`), where a missing adapter is a failure.
pub fn in_ci() -> bool {
    phygap::testing::running_in_ci()
}

/// The gpu backend, or `None` (after printing why) where no adapter exists outside CI.
pub fn gpu(options: GpuOptions) -> Option<GpuBackend> {
    match GpuContext::new(AdapterRequirement::Any) {
        Ok(ctx) => Some(GpuBackend::with_options(ctx, options).expect("gpu kernels compile")),
        Err(e) => {
            assert!(!in_ci(), "CI=true but no GPU adapter could be opened: {e}");
            println!("skipping: no GPU adapter ({e})");
            None
        }
    }
}

/// A camera 3.5 units from the origin, looking at it from a random direction.
pub fn random_camera(rng: &mut ChaCha8Rng, w: u32, h: u32) -> Camera {
    let dir = DVec3::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-0.6..0.6),
    )
    .normalize();
    Camera::look_at(w, h, 0.8, 3.5 * dir, DVec3::ZERO, DVec3::Z)
}

/// Largest `|gpu − cpu| / (|cpu| + floor)` over a buffer, with its index.
pub fn worst(gpu: &[f64], cpu: &[f64], floor: f64) -> (f64, usize) {
    assert_eq!(gpu.len(), cpu.len());
    gpu.iter()
        .zip(cpu)
        .map(|(g, c)| (g - c).abs() / (c.abs() + floor))
        .enumerate()
        .fold((0.0, 0), |acc, (i, e)| if e > acc.0 { (e, i) } else { acc })
}

/// `n` random surfels in the cube [-0.8, 0.8]³ with random orientations, sizes and materials.
pub fn random_surfels(rng: &mut ChaCha8Rng, n: usize) -> Surfels {
    let mut s = Surfels::zeros(n);
    for i in 0..n {
        s.position[i] = std::array::from_fn(|_| rng.random_range(-0.8..0.8));
        let q: [f64; 4] = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
        // Raw quaternions are not unit: the activation normalizes them.
        s.rotation[i] = q.map(|v| v * 1.7);
        s.log_scale[i] = [
            rng.random_range(0.04f64..0.25).ln(),
            rng.random_range(0.04f64..0.25).ln(),
        ];
        s.opacity[i] = logit(rng.random_range(0.2..0.97));
        s.albedo[i] = std::array::from_fn(|_| rng.random_range(-2.5..2.5));
        s.roughness[i] = rng.random_range(-2.5..2.5);
        s.ior[i] = rng.random_range(-2.5..2.5);
    }
    s
}

/// `n` large surfels around the origin, each covering most of a `random_camera` view: many
/// entries per tile.
pub fn deep_stack(rng: &mut ChaCha8Rng, n: usize) -> Surfels {
    let mut s = random_surfels(rng, n);
    for i in 0..n {
        s.position[i] = std::array::from_fn(|_| rng.random_range(-0.3..0.3));
        s.log_scale[i] = [
            rng.random_range(0.6f64..1.0).ln(),
            rng.random_range(0.6f64..1.0).ln(),
        ];
    }
    s
}

/// Surfels tangent to the unit sphere (a closed, opaque shell, as in training).
pub fn shell(rng: &mut ChaCha8Rng, n: usize) -> Surfels {
    let mut s = random_surfels(rng, n);
    let golden = std::f64::consts::PI * (3.0 - 5.0f64.sqrt());
    let spacing = (4.0 * std::f64::consts::PI / n as f64).sqrt();
    for i in 0..n {
        let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
        let r = (1.0 - z * z).sqrt();
        let normal = DVec3::new(
            r * (golden * i as f64).cos(),
            r * (golden * i as f64).sin(),
            z,
        );
        let helper = if normal.x.abs() < 0.9 {
            DVec3::X
        } else {
            DVec3::Y
        };
        let tu = normal.cross(helper).normalize();
        let q = DQuat::from_mat3(&DMat3::from_cols(tu, normal.cross(tu), normal));
        s.position[i] = normal.to_array();
        s.rotation[i] = [q.w, q.x, q.y, q.z];
        let scale = (0.7 * spacing * rng.random_range(0.8..1.2f64)).ln();
        s.log_scale[i] = [scale, scale];
    }
    s
}

/// A random environment on a 16³ cube (levels 16, 8, 4; with `fine`, two roughness levels per
/// size: 16, 8, 8, 8, 4), radiance spanning sigmoid and linear branches.
pub fn random_env(rng: &mut ChaCha8Rng, fresnel_irradiance: bool, fine: bool) -> PreparedEnv {
    let spec = MipChainSpec {
        base_size: 16,
        min_size: 4,
        fresnel_irradiance,
        levels_per_size: if fine { 2 } else { 1 },
        ..MipChainSpec::default()
    };
    let cube = random_cube(rng, 16);
    PreparedEnv::new(&cube, PrefilterPlan::new(spec).unwrap()).unwrap()
}

/// A cube map of face size `size` with raw texels uniform in [−3, 2).
pub fn random_cube(rng: &mut ChaCha8Rng, size: usize) -> CubeMap {
    let raw = (0..CubeMap::num_values(size))
        .map(|_| rng.random_range(-3.0..2.0))
        .collect();
    CubeMap::from_raw(size, raw).unwrap()
}

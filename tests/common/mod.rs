//! Helpers of the gpu test files: opening the backend (or skipping where no adapter exists),
//! random cameras and the relative-error measure of the parity tests.

use glam::DVec3;
use phygap::camera::Camera;
use phygap::gpu::{AdapterRequirement, GpuBackend, GpuContext, GpuOptions};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Whether this runs under CI (`CI=true`), where a missing adapter is a failure.
pub fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true" || v == "1")
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

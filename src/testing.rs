//! Fixtures shared by the tests and benchmarks: the shared ground-truth captures' folder, and
//! random upstream gradients for the rasterizer's backward pass.

use std::path::{Path, PathBuf};

use rand::Rng;

use crate::raster::{GBufferGrads, GBuffers};

/// `../shared/data` beside the repository, or `None` after printing the skip notice that tests
/// reading the shared captures give when it is absent (the project passes from a clone alone).
pub fn shared_data_dir() -> Option<PathBuf> {
    let dir = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data"));
    if dir.is_dir() {
        Some(dir.to_path_buf())
    } else {
        println!("skipping: ../shared/data not found");
        None
    }
}

/// Upstream gradients of a `width × height` G-buffer, every entry uniform in [−1, 1), drawn
/// pixel by pixel in field order (α, depth, normal, albedo, roughness, IoR, depth-normal).
pub fn random_upstream(rng: &mut impl Rng, width: usize, height: usize) -> GBufferGrads {
    let mut g = GBuffers::zeros(width, height);
    let mut r = || rng.random_range(-1.0..1.0);
    for k in 0..width * height {
        g.alpha[k] = r();
        g.depth[k] = r();
        g.normal[k] = [r(), r(), r()];
        g.albedo[k] = [r(), r(), r()];
        g.roughness[k] = r();
        g.ior[k] = r();
        g.depth_normal[k] = [r(), r(), r()];
    }
    g
}

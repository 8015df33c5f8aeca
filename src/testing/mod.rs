//! Fixtures shared by the tests and benchmarks: the shared ground-truth captures' folder, random
//! unit vectors, random upstream gradients for the rasterizer's backward pass, surfel spheres
//! (one, or two beside each other for GridMap), [`hostile`] files that declare more than they
//! hold, and the mutational [`fuzz`]er of the readers of untrusted bytes.

pub mod fuzz;
pub mod hostile;

use std::path::{Path, PathBuf};

use glam::{DMat3, DVec2, DVec3};
use rand::Rng;

use crate::core::mesh::TriangleMesh;
use crate::core::raster::{GBufferGrads, GBuffers};
use crate::core::surfels::{Surfel, Surfels};

/// `../shared/data` beside the repository, or `None` after printing the skip notice that tests
/// reading the shared captures give when it is absent (the project passes from a clone alone).
///
/// # Panics
/// Under `CI=true`, where the folder is always provided: a missing one must fail the run, not
/// pass every test that needs it.
pub fn shared_data_dir() -> Option<PathBuf> {
    let dir = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data"));
    if dir.is_dir() {
        Some(dir.to_path_buf())
    } else {
        assert!(
            !running_in_ci(),
            "../shared/data not found, and CI=true: CI always has it"
        );
        println!("skipping: ../shared/data not found");
        None
    }
}

/// Whether the tests run under CI (`CI=true`), where nothing they need may be missing.
pub fn running_in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true" || v == "1")
}

/// A random unit vector, uniform over the sphere: a point drawn in the cube and kept when it lies
/// in the ball (and not within 0.1 of its centre, where normalising would amplify rounding).
pub fn random_unit(rng: &mut impl Rng) -> DVec3 {
    loop {
        let v = DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        if (0.1..1.0).contains(&v.length()) {
            return v.normalize();
        }
    }
}

/// Upstream gradients of a `width × height` G-buffer, every entry uniform in [−1, 1), drawn
/// pixel by pixel in field order (α, depth, normal, albedo, roughness, IoR, depth-normal,
/// squared depth).
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
        g.depth_sq[k] = r();
    }
    g
}

/// Opaque surfels tangent to a sphere, dense enough to close it.
pub fn sphere_surfels(centre: DVec3, radius: f64, count: usize, albedo: DVec3) -> Surfels {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let mut surfels = Surfels::default();
    let spacing = radius * (4.0 * std::f64::consts::PI / count as f64).sqrt();
    for n in 0..count {
        let z = 1.0 - 2.0 * (n as f64 + 0.5) / count as f64;
        let r = (1.0 - z * z).sqrt();
        let phi = golden * n as f64;
        let normal = DVec3::new(r * phi.cos(), r * phi.sin(), z);
        let helper = if normal.z.abs() < 0.9 {
            DVec3::Z
        } else {
            DVec3::X
        };
        let tu = helper.cross(normal).normalize();
        let tv = normal.cross(tu);
        surfels.push_activated(&Surfel {
            position: centre + radius * normal,
            scale: DVec2::splat(0.8 * spacing),
            rotation: DMat3::from_cols(tu, tv, normal),
            opacity: 0.98,
            albedo,
            roughness: 0.3,
            ior: 1.5,
        });
    }
    surfels
}

/// Two unit spheres as a mesh and as surfels: A at the origin with a light albedo, B at
/// (3, 0, 0), dark; each occludes part of the other's sky (GridMap's tests). The interior points
/// of GridMap's anchor lattice lie inside them.
pub fn two_spheres() -> (TriangleMesh, Surfels) {
    sphere_pair(1.0, 3.0, 3000)
}

/// Two spheres of radius 0.5, A at the origin, B dark at (2.2, 0, 0): the gap between them holds
/// the 8 interior points of GridMap's anchor lattice (`AnchorPlacement::Lattice`: 64 anchors).
pub fn spheres_with_a_gap() -> (TriangleMesh, Surfels) {
    sphere_pair(0.5, 2.2, 2000)
}

/// Spheres of `radius` at the origin (light) and at (`distance`, 0, 0) (dark), `count` surfels each.
fn sphere_pair(radius: f64, distance: f64, count: usize) -> (TriangleMesh, Surfels) {
    let b_centre = DVec3::new(distance, 0.0, 0.0);
    let mut mesh = TriangleMesh::icosphere(DVec3::ZERO, radius, 3);
    let b = TriangleMesh::icosphere(b_centre, radius, 3);
    let offset = mesh.vertices.len() as u32;
    mesh.vertices.extend(&b.vertices);
    mesh.normals.extend(&b.normals);
    mesh.triangles
        .extend(b.triangles.iter().map(|t| t.map(|i| i + offset)));
    let mut surfels = sphere_surfels(DVec3::ZERO, radius, count, DVec3::new(0.6, 0.5, 0.4));
    let dark = sphere_surfels(b_centre, radius, count, DVec3::splat(0.02));
    for i in 0..dark.len() {
        surfels.push_activated(&dark.get(i));
    }
    (mesh, surfels)
}

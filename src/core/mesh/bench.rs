//! Timing helpers for mesh extraction and ray tracing, run by `examples/mesh_bench.rs`.
//!
//! Extraction is timed on exact depth maps of a radius-0.9 sphere from cameras around it (the
//! dataset's rig: 256×256, 40° field of view, distance 3.4); the BVH on any mesh with random rays
//! from a sphere of radius 3 aimed into the unit ball, traced in parallel with rayon.

use std::time::Instant;

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::tsdf::AnalyticSphere;
use super::{extract_mesh, MeshError, TriangleMesh, TsdfParams};
use crate::core::mesh::bvh::Bvh;

/// Result of one extraction benchmark.
#[derive(Clone, Debug)]
pub struct ExtractionTiming {
    pub resolution: usize,
    pub views: usize,
    pub image_size: u32,
    pub seconds: f64,
    pub vertices: usize,
    pub triangles: usize,
    /// Largest |‖v‖ − r| over the vertices, in voxels.
    pub worst_error_voxels: f64,
}

/// Times `extract_mesh` at `resolution` on `views` exact sphere depth maps of `image_size`².
pub fn time_extraction(
    resolution: usize,
    views: usize,
    image_size: u32,
) -> Result<ExtractionTiming, MeshError> {
    let sphere = AnalyticSphere::new(0.9, views, 3.4, image_size);
    let depth_views = sphere.views(None);
    let bounds = (DVec3::splat(-1.0), DVec3::splat(1.0));
    let params = TsdfParams::automatic(resolution, &sphere.cameras, bounds);
    let start = Instant::now();
    let mesh = extract_mesh(&depth_views, bounds, &params)?;
    let seconds = start.elapsed().as_secs_f64();
    let voxel = 2.0 / resolution as f64;
    let worst = sphere.worst_radial_error(&mesh);
    Ok(ExtractionTiming {
        resolution,
        views,
        image_size,
        seconds,
        vertices: mesh.vertices.len(),
        triangles: mesh.triangles.len(),
        worst_error_voxels: worst / voxel,
    })
}

/// Result of one ray-tracing benchmark.
#[derive(Clone, Debug)]
pub struct RayTiming {
    pub triangles: usize,
    pub nodes: usize,
    pub build_seconds: f64,
    pub rays: usize,
    pub hit_fraction: f64,
    /// Closest-hit rays per second over all rayon threads.
    pub rays_per_second: f64,
    /// Closest-hit rays per second on one thread.
    pub rays_per_second_single_thread: f64,
    pub occlusion_rays_per_second: f64,
    pub closest_point_queries_per_second: f64,
}

/// Times the BVH build and `rays` random closest-hit, occlusion and closest-point queries.
pub fn time_ray_tracing(mesh: &TriangleMesh, rays: usize) -> RayTiming {
    let start = Instant::now();
    let bvh = Bvh::build(mesh);
    let build_seconds = start.elapsed().as_secs_f64();
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    let queries: Vec<(DVec3, DVec3)> = (0..rays)
        .map(|_| {
            let mut unit = || loop {
                let v = DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
                if v.length_squared() <= 1.0 && v.length_squared() > 1e-6 {
                    return v;
                }
            };
            let origin = 3.0 * unit().normalize();
            let target = unit();
            (origin, (target - origin).normalize())
        })
        .collect();
    let timed = |f: &dyn Fn() -> usize| {
        let start = Instant::now();
        let n = f();
        (n, start.elapsed().as_secs_f64())
    };
    let (hits, parallel) = timed(&|| {
        queries
            .par_iter()
            .filter(|(o, d)| bvh.intersect(*o, *d, f64::INFINITY).is_some())
            .count()
    });
    let single_count = rays.min(200_000);
    let (_, single) = timed(&|| {
        queries[..single_count]
            .iter()
            .filter(|(o, d)| bvh.intersect(*o, *d, f64::INFINITY).is_some())
            .count()
    });
    let (_, occlusion) = timed(&|| {
        queries
            .par_iter()
            .filter(|(o, d)| bvh.occluded(*o, *d, f64::INFINITY))
            .count()
    });
    let closest_count = rays.min(200_000);
    let (_, closest) = timed(&|| {
        queries[..closest_count]
            .par_iter()
            .filter(|(o, _)| bvh.closest_point(*o * 0.4).1 < 1.0)
            .count()
    });
    RayTiming {
        triangles: bvh.triangle_count(),
        nodes: bvh.node_count(),
        build_seconds,
        rays,
        hit_fraction: hits as f64 / rays as f64,
        rays_per_second: rays as f64 / parallel,
        rays_per_second_single_thread: single_count as f64 / single,
        occlusion_rays_per_second: rays as f64 / occlusion,
        closest_point_queries_per_second: closest_count as f64 / closest,
    }
}

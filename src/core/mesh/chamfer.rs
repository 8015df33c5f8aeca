//! Unidirectional Chamfer-L1 distance from a predicted mesh to a ground-truth mesh (PhyGaP
//! supplement §4.1, METHOD.md §8): points sampled uniformly by area on the prediction, those inside
//! the GT bounding box kept, mean Euclidean distance to the GT surface, in scene units.
//!
//! Sampling is sequential and seeded (deterministic); distances run in parallel with rayon over
//! the samples, each a BVH closest-point query.

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::{MeshError, TriangleMesh};
use crate::core::mesh::bvh::Bvh;

/// Points sampled on the prediction by [`chamfer_l1`].
pub const CHAMFER_SAMPLES: usize = 100_000;

/// `count` points distributed uniformly by area over the mesh surface (empty for a mesh without
/// area).
pub fn sample_surface(mesh: &TriangleMesh, count: usize, rng: &mut impl Rng) -> Vec<DVec3> {
    let mut cumulative = Vec::with_capacity(mesh.triangles.len());
    let mut total = 0.0;
    for t in 0..mesh.triangles.len() {
        let [a, b, c] = mesh.triangle_corners(t);
        total += 0.5 * (b - a).cross(c - a).length();
        cumulative.push(total);
    }
    if !(total > 0.0 && total.is_finite()) {
        return Vec::new();
    }
    (0..count)
        .map(|_| {
            let r = rng.random::<f64>() * total;
            let t = cumulative
                .partition_point(|&c| c <= r)
                .min(cumulative.len() - 1);
            let [a, b, c] = mesh.triangle_corners(t);
            let s = rng.random::<f64>().sqrt();
            let w = rng.random::<f64>();
            a * (1.0 - s) + b * (s * (1.0 - w)) + c * (s * w)
        })
        .collect()
}

/// Chamfer-L1 from `pred` to `gt` with [`CHAMFER_SAMPLES`] samples and a fixed seed.
pub fn chamfer_l1(pred: &TriangleMesh, gt: &TriangleMesh) -> Result<f64, MeshError> {
    chamfer_l1_with(pred, gt, CHAMFER_SAMPLES, 0)
}

/// Chamfer-L1 from `pred` to `gt`: mean distance to the GT surface of `samples` area-uniform points
/// on `pred` that lie inside the GT bounding box.
pub fn chamfer_l1_with(
    pred: &TriangleMesh,
    gt: &TriangleMesh,
    samples: usize,
    seed: u64,
) -> Result<f64, MeshError> {
    let _span = tracing::info_span!("chamfer_l1", samples).entered();
    let (lo, hi) = gt
        .bounds()
        .filter(|_| gt.area() > 0.0)
        .ok_or(MeshError::EmptyMesh {
            name: "ground truth",
        })?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let points = sample_surface(pred, samples, &mut rng);
    if points.is_empty() {
        return Err(MeshError::EmptyMesh { name: "prediction" });
    }
    let inside: Vec<DVec3> = points
        .into_iter()
        .filter(|p| p.cmpge(lo).all() && p.cmple(hi).all())
        .collect();
    if inside.is_empty() {
        return Err(MeshError::NoSamplesInsideBox { samples });
    }
    let bvh = Bvh::build(gt);
    let total: f64 = inside.par_iter().map(|&p| bvh.closest_point(p).1).sum();
    Ok(total / inside.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mesh_is_at_distance_zero_from_itself() {
        let mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 3);
        let d = chamfer_l1_with(&mesh, &mesh, 20_000, 1).unwrap();
        assert!(d < 1e-12, "self distance {d}");
    }

    #[test]
    fn concentric_spheres_are_their_radius_difference_apart() {
        let pred = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 6);
        let gt = TriangleMesh::icosphere(DVec3::ZERO, 1.01, 6);
        let d = chamfer_l1(&pred, &gt).unwrap();
        assert!((d - 0.01).abs() < 2e-4, "chamfer {d}");
        // Unidirectional: a small sphere inside the GT box counts fully; GT parts far from the
        // prediction do not.
        let small = TriangleMesh::icosphere(DVec3::ZERO, 0.5, 4);
        let d = chamfer_l1_with(&small, &gt, 20_000, 2).unwrap();
        assert!((d - 0.51).abs() < 2e-3, "chamfer {d}");
    }

    #[test]
    fn only_points_inside_the_gt_box_count() {
        // Half of the prediction sticks out of the GT box along +x; those points are ignored.
        let gt = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 4);
        let pred = TriangleMesh::icosphere(DVec3::new(1.0, 0.0, 0.0), 1.0, 4);
        let d = chamfer_l1_with(&pred, &gt, 20_000, 3).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let inside: Vec<DVec3> = sample_surface(&pred, 20_000, &mut rng)
            .into_iter()
            .filter(|p| p.x <= 1.0 && p.y.abs() <= 1.0 && p.z.abs() <= 1.0)
            .collect();
        assert!(inside.len() > 9_000 && inside.len() < 11_000);
        let expected =
            inside.iter().map(|p| (p.length() - 1.0).abs()).sum::<f64>() / inside.len() as f64;
        assert!((d - expected).abs() < 1e-3, "{d} vs {expected}");
        let far = TriangleMesh::icosphere(DVec3::new(10.0, 0.0, 0.0), 1.0, 1);
        assert!(matches!(
            chamfer_l1_with(&far, &gt, 1000, 0),
            Err(MeshError::NoSamplesInsideBox { .. })
        ));
        assert!(matches!(
            chamfer_l1(&TriangleMesh::default(), &gt),
            Err(MeshError::EmptyMesh { name: "prediction" })
        ));
    }

    #[test]
    fn samples_are_uniform_by_area() {
        // Two triangles, the second 3 times larger: about a quarter of the samples fall on the first.
        let mesh = TriangleMesh {
            vertices: vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, 1.0],
                [3.0, 0.0, 1.0],
                [0.0, 1.0, 1.0],
            ],
            normals: Vec::new(),
            triangles: vec![[0, 1, 2], [3, 4, 5]],
            material_ids: Vec::new(),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let points = sample_surface(&mesh, 40_000, &mut rng);
        let first = points.iter().filter(|p| p.z == 0.0).count() as f64 / 40_000.0;
        assert!((first - 0.25).abs() < 0.01, "fraction {first}");
        // Within a triangle, uniform: mean of the first triangle's points is its centroid.
        let on_first: Vec<&DVec3> = points.iter().filter(|p| p.z == 0.0).collect();
        let mean = on_first.iter().copied().sum::<DVec3>() / on_first.len() as f64;
        assert!(
            mean.abs_diff_eq(DVec3::new(1.0 / 3.0, 1.0 / 3.0, 0.0), 0.01),
            "{mean}"
        );
        assert!(points
            .iter()
            .all(|p| p.x >= 0.0 && p.y >= 0.0 && p.x + p.y / 1.0 <= 3.0 + 1e-12));
    }
}

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
    sample_barycentric(mesh, count, rng)
        .into_iter()
        .map(|(t, weights)| {
            let [a, b, c] = mesh.triangle_corners(t);
            a * weights[0] + b * weights[1] + c * weights[2]
        })
        .collect()
}

/// `count` area-uniform samples as (triangle, barycentric weights of its three corners).
fn sample_barycentric(
    mesh: &TriangleMesh,
    count: usize,
    rng: &mut impl Rng,
) -> Vec<(usize, [f64; 3])> {
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
            let s = rng.random::<f64>().sqrt();
            let w = rng.random::<f64>();
            (t, [1.0 - s, s * (1.0 - w), s * w])
        })
        .collect()
}

/// The shading normal of `mesh` at barycentric `weights` of triangle `t`: its vertex normals
/// interpolated (what a viewer shades with) when it has them, else the face normal.
fn shading_normal(mesh: &TriangleMesh, t: usize, weights: [f64; 3]) -> DVec3 {
    let [a, b, c] = mesh.triangle_corners(t);
    let face = (b - a).cross(c - a).normalize_or_zero();
    if !mesh.has_normals() {
        return face;
    }
    let n: DVec3 = (0..3)
        .map(|k| weights[k] * DVec3::from_array(mesh.normals[mesh.triangles[t][k] as usize]))
        .sum();
    n.try_normalize().unwrap_or(face)
}

/// Barycentric weights of point `p` (on the triangle's plane) in triangle `[a, b, c]`.
fn barycentric(p: DVec3, [a, b, c]: [DVec3; 3]) -> [f64; 3] {
    let (e1, e2, d) = (b - a, c - a, p - a);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (dp1, dp2) = (d.dot(e1), d.dot(e2));
    let det = d11 * d22 - d12 * d12;
    if det <= 0.0 {
        return [1.0 / 3.0; 3];
    }
    let v = (d22 * dp1 - d12 * dp2) / det;
    let w = (d11 * dp2 - d12 * dp1) / det;
    [1.0 - v - w, v, w]
}

/// Normal MAE from `pred` to `gt` with [`CHAMFER_SAMPLES`] samples and a fixed seed.
pub fn normal_mae_deg(pred: &TriangleMesh, gt: &TriangleMesh) -> Result<f64, MeshError> {
    normal_mae_deg_with(pred, gt, CHAMFER_SAMPLES, 0)
}

/// Mean angle (degrees) between the shading normal of `pred` at `samples` area-uniform points
/// that lie inside the GT bounding box and the GT's shading normal at the closest point of the
/// GT surface (vertex normals interpolated where a mesh has them, else face normals; both
/// oriented by their winding, so an inside-out surface counts as 180°).
pub fn normal_mae_deg_with(
    pred: &TriangleMesh,
    gt: &TriangleMesh,
    samples: usize,
    seed: u64,
) -> Result<f64, MeshError> {
    let _span = tracing::info_span!("normal_mae", samples).entered();
    let (lo, hi) = ground_truth_box(gt)?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let picks = sample_barycentric(pred, samples, &mut rng);
    if picks.is_empty() {
        return Err(MeshError::EmptyMesh { name: "prediction" });
    }
    let inside: Vec<(DVec3, DVec3)> = picks
        .into_iter()
        .map(|(t, weights)| {
            let [a, b, c] = pred.triangle_corners(t);
            let p = a * weights[0] + b * weights[1] + c * weights[2];
            (p, shading_normal(pred, t, weights))
        })
        .filter(|(p, _)| within(*p, lo, hi))
        .collect();
    if inside.is_empty() {
        return Err(MeshError::NoSamplesInsideBox { samples });
    }
    let bvh = Bvh::build(gt);
    let total: f64 = inside
        .par_iter()
        .map(|&(p, n)| {
            let (q, _, t) = bvh.closest_triangle(p).expect("the GT mesh has triangles");
            let t = t as usize;
            let truth = shading_normal(gt, t, barycentric(q, gt.triangle_corners(t)));
            n.dot(truth).clamp(-1.0, 1.0).acos().to_degrees()
        })
        .sum();
    Ok(total / inside.len() as f64)
}

/// The bounding box of `gt`, within which the metrics sample `pred`; an error when `gt` has no
/// surface.
fn ground_truth_box(gt: &TriangleMesh) -> Result<(DVec3, DVec3), MeshError> {
    gt.bounds()
        .filter(|_| gt.area() > 0.0)
        .ok_or(MeshError::EmptyMesh {
            name: "ground truth",
        })
}

/// Whether `p` lies in the box `lo`..=`hi`.
fn within(p: DVec3, lo: DVec3, hi: DVec3) -> bool {
    p.cmpge(lo).all() && p.cmple(hi).all()
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
    let (lo, hi) = ground_truth_box(gt)?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let points = sample_surface(pred, samples, &mut rng);
    if points.is_empty() {
        return Err(MeshError::EmptyMesh { name: "prediction" });
    }
    let inside: Vec<DVec3> = points.into_iter().filter(|&p| within(p, lo, hi)).collect();
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

    /// A coarse icosphere's interpolated normals against a fine one's: small and shrinking with
    /// the subdivision; its flat faces (no normals) err by about the angle a face spans; turned
    /// inside out it errs by 180°.
    #[test]
    fn normal_error_of_spheres() {
        let gt = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 6);
        let coarse = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 2);
        let finer = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 4);
        let (e2, e4) = (
            normal_mae_deg_with(&coarse, &gt, 20_000, 1).unwrap(),
            normal_mae_deg_with(&finer, &gt, 20_000, 1).unwrap(),
        );
        assert!(e2 < 3.0 && e4 < e2 / 3.0, "{e2}° {e4}°");
        let mut flat = coarse.clone();
        flat.normals.clear();
        let faceted = normal_mae_deg_with(&flat, &gt, 20_000, 1).unwrap();
        assert!(faceted > e2 && faceted < 10.0, "{faceted}°");
        let mut inverted = finer.clone();
        inverted.triangles.iter_mut().for_each(|t| t.swap(1, 2));
        inverted.normals.iter_mut().for_each(|n| *n = n.map(|x| -x));
        let e = normal_mae_deg_with(&inverted, &gt, 5_000, 1).unwrap();
        assert!(e > 179.0, "{e}°");
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

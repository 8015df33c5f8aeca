//! Initial surfels seeded by a capture's sparse structure-from-motion points (COLMAP's
//! `points3D`), when it has them; otherwise the visual-hull initialisation ([`super::init`]).
//!
//! Sparse points lie on the surface but also on the background and as outliers, so only the points
//! inside the visual hull of the training masks (or within 1.5 pixels of it) are kept. With more kept points than surfels
//! wanted, a seeded random subset is used; with fewer, every kept point is used and the rest are
//! drawn in the hull as usual. A point surfel's scale is the root-mean-square distance to its three
//! nearest kept neighbours (as 3D Gaussian splatting does), clamped to [10⁻⁴, 0.1] × the object's
//! radius; rotation and materials are those of `init.rs`. The hull test runs in parallel (rayon).

use glam::{DMat3, DVec2, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::init::{
    init_from_visual_hull, random_rotation, INITIAL_ALBEDO, INITIAL_IOR, INITIAL_OPACITY,
    INITIAL_ROUGHNESS,
};
use crate::core::kdtree::KdTree;
use crate::core::surfels::{Surfel, Surfels};
use crate::io::capture::Capture;

/// Neighbours whose distances set a point surfel's scale.
const NEIGHBOURS: usize = 3;
/// How far (in pixels at the object's distance) towards the centre a point may be moved to fall
/// in the hull.
const SLACK: f64 = 1.5;

/// `count` initial surfels for `capture`: from its sparse points where it has some inside the
/// visual hull, completed (or replaced) by random points inside the hull.
pub fn init_for_capture(capture: &Capture, count: usize, seed: u64) -> Surfels {
    if capture.points.is_empty() || count == 0 {
        return init_from_visual_hull(capture, count, seed);
    }
    let _span = tracing::info_span!("init_from_sparse_points", count, seed).entered();
    let hull = capture.visual_hull();
    let bounds = hull.bounds();
    // Surface points project onto silhouette pixels in grazing views, where a pixel-centre mask
    // may say background: a point also counts when a nudge of SLACK pixels (at the object's
    // distance, median over the training views) towards the centre is inside.
    let mut footprints: Vec<f64> = capture
        .train_views()
        .map(|v| (v.camera.origin() - bounds.center).length() / v.camera.fx.min(v.camera.fy))
        .collect();
    footprints.sort_by(|a, b| a.total_cmp(b));
    let nudge = SLACK * footprints.get(footprints.len() / 2).copied().unwrap_or(0.0);
    let inside: Vec<DVec3> = capture
        .points
        .par_iter()
        .map(|p| p.position)
        .filter(|p| {
            p.is_finite()
                && (hull.contains(*p)
                    || hull.contains(*p + (bounds.center - *p).normalize_or_zero() * nudge))
        })
        .collect();
    tracing::info!(
        points = capture.points.len(),
        inside = inside.len(),
        "sparse points inside the visual hull"
    );
    if inside.is_empty() {
        tracing::warn!(
            "none of the {} sparse points is inside the visual hull; initialising from the hull alone",
            capture.points.len()
        );
        return init_from_visual_hull(capture, count, seed);
    }
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut chosen = inside;
    if chosen.len() > count {
        // A partial Fisher–Yates shuffle: the first `count` entries are a uniform random subset.
        for i in 0..count {
            let j = rng.random_range(i..chosen.len());
            chosen.swap(i, j);
        }
        chosen.truncate(count);
    }
    let radius = bounds.radius;
    let tree = KdTree::build(&chosen);
    let scales: Vec<f64> = chosen
        .par_iter()
        .map(|p| {
            // The nearest is the point itself.
            let near = tree.k_nearest(*p, NEIGHBOURS + 1);
            let others = &near[1.min(near.len())..];
            let mean_sq = others.iter().map(|(_, d)| d).sum::<f64>() / others.len().max(1) as f64;
            mean_sq.sqrt().clamp(1e-4 * radius, 0.1 * radius)
        })
        .collect();
    let mut surfels = Surfels::default();
    for (p, scale) in chosen.iter().zip(&scales) {
        surfels.push_activated(&Surfel {
            position: *p,
            scale: DVec2::splat(*scale),
            rotation: DMat3::from_quat(random_rotation(&mut rng)),
            opacity: INITIAL_OPACITY,
            albedo: DVec3::splat(INITIAL_ALBEDO),
            roughness: INITIAL_ROUGHNESS,
            ior: INITIAL_IOR,
        });
    }
    let missing = count - surfels.len();
    if missing > 0 {
        let fill = init_from_visual_hull(capture, missing, seed.wrapping_add(1));
        for i in 0..fill.len() {
            surfels.push_activated(&fill.get(i));
        }
    }
    surfels
}

#[cfg(test)]
mod tests {
    use super::super::init::tests::sphere_capture;
    use super::*;
    use crate::io::capture::SparsePoint;

    fn with_points(points: Vec<DVec3>) -> Capture {
        let mut capture = sphere_capture(DVec3::ZERO, 0.5, 24);
        capture.points = points
            .into_iter()
            .map(|position| SparsePoint {
                position,
                colour: [128, 128, 128],
            })
            .collect();
        capture
    }

    /// `n` points on the sphere of radius `r` (Fibonacci spiral).
    fn sphere_points(n: usize, r: f64) -> Vec<DVec3> {
        (0..n)
            .map(|k| {
                let z = 1.0 - 2.0 * (k as f64 + 0.5) / n as f64;
                let phi = k as f64 * 2.399_963_229_728_653;
                let s = (1.0 - z * z).sqrt();
                DVec3::new(s * phi.cos(), s * phi.sin(), z) * r
            })
            .collect()
    }

    #[test]
    fn points_inside_the_hull_seed_the_surfels_and_outliers_are_dropped() {
        // 400 points on the sphere's surface and 50 background points far away.
        let mut points = sphere_points(400, 0.5);
        points.extend((0..50).map(|k| DVec3::new(2.0 + k as f64 * 0.01, 0.0, 0.0)));
        let capture = with_points(points.clone());
        let surfels = init_for_capture(&capture, 1000, 3);
        assert_eq!(surfels.len(), 1000);
        // The first 400 are the surface points, in order; none of the outliers is used.
        for (k, p) in points.iter().take(400).enumerate() {
            assert_eq!(DVec3::from_array(surfels.position[k]), *p);
        }
        assert!(surfels
            .position
            .iter()
            .all(|p| DVec3::from_array(*p).length() < 0.6));
        // Scale ≈ the spacing of 400 points on the sphere (area / count, square-rooted).
        let spacing = (4.0 * std::f64::consts::PI * 0.5f64.powi(2) / 400.0).sqrt();
        let s = surfels.get(0).scale.x;
        assert!(s > 0.5 * spacing && s < 1.5 * spacing, "{s} vs {spacing}");
        // Deterministic for a seed.
        assert_eq!(init_for_capture(&capture, 1000, 3), surfels);
    }

    #[test]
    fn more_points_than_surfels_gives_a_subset_and_no_points_falls_back_to_the_hull() {
        let capture = with_points(sphere_points(2000, 0.45));
        let surfels = init_for_capture(&capture, 500, 9);
        assert_eq!(surfels.len(), 500);
        for p in &surfels.position {
            assert!((DVec3::from_array(*p).length() - 0.45).abs() < 1e-9);
        }
        let outliers = with_points(vec![DVec3::new(5.0, 5.0, 5.0)]);
        let plain = sphere_capture(DVec3::ZERO, 0.5, 24);
        assert_eq!(
            init_for_capture(&outliers, 300, 4),
            init_from_visual_hull(&plain, 300, 4)
        );
    }
}

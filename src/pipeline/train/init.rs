//! Initial surfels: random points inside the visual hull of the training masks (METHOD.md §7),
//! with a small isotropic scale from the point density, a uniformly random rotation and the
//! initial material (opacity 0.1, albedo 0.5, roughness 0.1, IoR 1.8).
//!
//! Candidates are drawn sequentially from one seeded ChaCha8 stream (so the result depends only on
//! the seed) and tested against the hull in parallel batches (rayon); acceptance keeps draw order.

use glam::{DMat3, DQuat, DVec2, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::core::surfels::{Surfel, Surfels};
use crate::io::capture::{Bounds, Capture};

pub const INITIAL_OPACITY: f64 = 0.1;
pub const INITIAL_ALBEDO: f64 = 0.5;
pub const INITIAL_ROUGHNESS: f64 = 0.1;
pub const INITIAL_IOR: f64 = 1.8;
/// Surfel scale as a fraction of the mean point spacing (volume / count)^(1/3); about the mean
/// nearest-neighbour distance of uniformly random points (0.55 × spacing).
const SCALE_PER_SPACING: f64 = 0.5;
/// Candidates tested per batch (at least).
const BATCH: usize = 8192;
/// Batches without a single accepted point before giving up on the hull.
const MAX_EMPTY_BATCHES: usize = 64;

/// `count` surfels at random points inside the visual hull of `capture`'s training masks.
///
/// If no point of the bounding box is inside the hull (masks that never agree), the points are
/// drawn in the bounding sphere instead, with a warning.
pub fn init_from_visual_hull(capture: &Capture, count: usize, seed: u64) -> Surfels {
    let _span = tracing::info_span!("init_from_visual_hull", count, seed).entered();
    let hull = capture.visual_hull();
    let bounds = hull.bounds();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let extent = bounds.max - bounds.min;
    let mut points: Vec<DVec3> = Vec::with_capacity(count);
    // Hull fraction of the box, estimated from every candidate tested.
    let (mut tested, mut inside_total, mut empty_batches) = (0usize, 0usize, 0usize);
    while points.len() < count && empty_batches < MAX_EMPTY_BATCHES {
        let batch = BATCH.max(2 * (count - points.len()));
        let candidates: Vec<DVec3> = (0..batch)
            .map(|_| bounds.min + extent * DVec3::new(rng.random(), rng.random(), rng.random()))
            .collect();
        let inside: Vec<DVec3> = candidates
            .into_par_iter()
            .filter(|p| hull.contains(*p))
            .collect();
        tested += batch;
        inside_total += inside.len();
        if inside.is_empty() {
            empty_batches += 1;
        }
        let wanted = count - points.len();
        points.extend(inside.into_iter().take(wanted));
    }
    let box_volume = extent.x * extent.y * extent.z;
    let volume = if points.is_empty() {
        if count > 0 {
            tracing::warn!(
                "no point of the bounding box is inside the visual hull; sampling the bounding sphere"
            );
        }
        points = sample_ball(&mut rng, &bounds, count);
        4.0 / 3.0 * std::f64::consts::PI * bounds.radius.powi(3)
    } else {
        box_volume * inside_total as f64 / tested.max(1) as f64
    };
    let spacing = (volume / count.max(1) as f64).cbrt();
    let scale = SCALE_PER_SPACING * spacing;
    tracing::debug!(volume, spacing, scale, "visual-hull initialization");

    let mut surfels = Surfels::default();
    for p in points {
        surfels.push_activated(&Surfel {
            position: p,
            scale: DVec2::splat(scale),
            rotation: DMat3::from_quat(random_rotation(&mut rng)),
            opacity: INITIAL_OPACITY,
            albedo: DVec3::splat(INITIAL_ALBEDO),
            roughness: INITIAL_ROUGHNESS,
            ior: INITIAL_IOR,
        });
    }
    surfels
}

/// A uniformly distributed rotation (Shoemake's method).
pub(crate) fn random_rotation(rng: &mut ChaCha8Rng) -> DQuat {
    let (u1, u2, u3): (f64, f64, f64) = (rng.random(), rng.random(), rng.random());
    let tau = std::f64::consts::TAU;
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    DQuat::from_xyzw(
        a * (tau * u2).sin(),
        a * (tau * u2).cos(),
        b * (tau * u3).sin(),
        b * (tau * u3).cos(),
    )
}

fn sample_ball(rng: &mut ChaCha8Rng, bounds: &Bounds, count: usize) -> Vec<DVec3> {
    let mut points = Vec::with_capacity(count);
    while points.len() < count {
        let p = DVec3::new(rng.random(), rng.random(), rng.random()) * 2.0 - 1.0;
        if p.length_squared() <= 1.0 {
            points.push(bounds.center + p * bounds.radius);
        }
    }
    points
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::core::camera::Camera;
    use crate::formats::image_io::Image;
    use crate::io::capture::{GroundTruth, Measurement, Split, View};

    /// A capture of a sphere (centre, radius) seen by `n` cameras on a Fibonacci sphere of radius
    /// 4; the masks are exact (pixel-centre ray hits the sphere). The images are blank.
    pub(crate) fn sphere_capture(center: DVec3, radius: f64, n: usize) -> Capture {
        let size = 64;
        let views = (0..n)
            .map(|k| {
                let z = 1.0 - 2.0 * (k as f64 + 0.5) / n as f64;
                let phi = k as f64 * 2.399_963_229_728_653;
                let r = (1.0 - z * z).sqrt();
                let eye = DVec3::new(r * phi.cos(), r * phi.sin(), z) * 4.0;
                let up = if z.abs() > 0.9 { DVec3::X } else { DVec3::Z };
                let camera = Camera::look_at(size, size, 0.7, eye, DVec3::ZERO, up);
                let mask = Image::from_fn(size as usize, size as usize, 1, |x, y, o| {
                    let d = camera.pixel_dir(x as u32, y as u32);
                    let oc = camera.origin() - center;
                    let b = oc.dot(d);
                    let disc = b * b - (oc.length_squared() - radius * radius);
                    o[0] = if disc > 0.0 { 1.0 } else { 0.0 };
                });
                View {
                    name: format!("frame {k}"),
                    frame_index: k,
                    split: Split::Train,
                    camera,
                    measurement: Measurement::Rgb {
                        image: Image::filled(size as usize, size as usize, 3, 0.0),
                    },
                    mask,
                    ground_truth: GroundTruth::default(),
                }
            })
            .collect();
        Capture {
            root: std::path::PathBuf::from("."),
            views,
            world_up: DVec3::Z,
            warnings: Vec::new(),
            points: Vec::new(),
            raw: None,
            colmap: None,
            downscale: 1,
            full_size: (64, 64),
        }
    }

    #[test]
    fn bounds_of_a_sphere_hull_are_tight() {
        let center = DVec3::new(0.2, -0.1, 0.05);
        let capture = sphere_capture(center, 0.5, 24);
        let b = capture.object_bounds();
        assert!((b.center - center).length() < 0.03, "{b:?}");
        assert!(b.radius > 0.5 && b.radius < 0.6, "{b:?}");
        for a in 0..3 {
            assert!(
                b.min[a] < center[a] - 0.5 && b.max[a] > center[a] + 0.5,
                "{b:?}"
            );
            assert!(
                b.min[a] > center[a] - 0.65 && b.max[a] < center[a] + 0.65,
                "{b:?}"
            );
        }
    }

    #[test]
    fn points_fill_the_hull_exactly_count_and_deterministically() {
        let center = DVec3::new(0.2, -0.1, 0.05);
        let capture = sphere_capture(center, 0.5, 24);
        let count = 3000;
        let surfels = init_from_visual_hull(&capture, count, 7);
        assert_eq!(surfels.len(), count);
        let distances: Vec<f64> = surfels
            .position
            .iter()
            .map(|p| (DVec3::from_array(*p) - center).length())
            .collect();
        let max = distances.iter().cloned().fold(0.0, f64::max);
        // The hull of 24 views is slightly larger than the sphere (pixel size ≈ 0.025 at the object).
        assert!(max < 0.55, "farthest point {max}");
        // Uniform in the ball: a fraction (1/2)³ lies within half the radius.
        let inner = distances.iter().filter(|d| **d < 0.25).count() as f64 / count as f64;
        assert!((inner - 0.125).abs() < 0.03, "inner fraction {inner}");
        // Scale from density: volume of the ball / count.
        let spacing = (4.0 / 3.0 * std::f64::consts::PI * 0.125 / count as f64).cbrt();
        let s = surfels.get(0);
        assert!(
            (s.scale.x / (SCALE_PER_SPACING * spacing) - 1.0).abs() < 0.15,
            "{s:?}"
        );
        assert_eq!(s.scale.x, s.scale.y);
        assert!((s.opacity - 0.1).abs() < 1e-9 && (s.roughness - 0.1).abs() < 1e-9);
        assert!((s.ior - 1.8).abs() < 1e-9 && (s.albedo - DVec3::splat(0.5)).length() < 1e-9);
        assert!(surfels.is_finite());

        let again = init_from_visual_hull(&capture, count, 7);
        assert_eq!(again, surfels, "same seed, same surfels");
        let other = init_from_visual_hull(&capture, count, 8);
        assert_ne!(other.position, surfels.position);
        assert_eq!(init_from_visual_hull(&capture, 0, 1).len(), 0);
    }

    #[test]
    fn rotations_are_uniform() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let n = 20000;
        // Normals (third axis) of uniform rotations are uniform on the sphere: mean ≈ 0, E[z²] = 1/3.
        let (mut mean, mut zz) = (DVec3::ZERO, 0.0);
        for _ in 0..n {
            let q = random_rotation(&mut rng);
            assert!((q.length() - 1.0).abs() < 1e-12);
            let normal = q * DVec3::Z;
            mean += normal / n as f64;
            zz += normal.z * normal.z / n as f64;
        }
        assert!(
            mean.length() < 0.03 && (zz - 1.0 / 3.0).abs() < 0.02,
            "{mean} {zz}"
        );
    }
}

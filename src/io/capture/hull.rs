//! The visual hull of the training masks: a point is inside when it projects onto the object
//! (mask > 0.5) in every training view whose image it falls in, and falls in at least
//! [`MIN_VIEWS_SEEING`] of them. A view whose mask touches no image border holds the whole object,
//! so a point falling outside its image (or behind it) is outside the hull too; views with cropped
//! objects only judge the points they see. Bounds come from carving a voxel grid coarse-to-fine.
//!
//! Carving evaluates the grid in parallel (rayon, one task per z slice); each point test is
//! independent and read-only.

use glam::{DMat3, DVec3};
use rayon::prelude::*;
use serde::Serialize;

use super::View;

/// A point must fall inside this many training images (or all of them, if fewer) to count.
pub const MIN_VIEWS_SEEING: usize = 2;
/// Voxels per axis of each carving pass.
const GRID: usize = 48;
/// Carving passes, each in the box of the previous one's occupied voxels (plus one voxel).
const PASSES: usize = 3;

/// An axis-aligned box and a bounding sphere around the object.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bounds {
    pub min: DVec3,
    pub max: DVec3,
    pub center: DVec3,
    pub radius: f64,
}

/// The training views' masks and cameras, for inside/outside tests.
pub struct VisualHull<'a> {
    views: Vec<&'a View>,
    /// Per view: the mask touches no image border, so the whole object is inside the image.
    object_in_frame: Vec<bool>,
    min_views: usize,
}

/// True when no border pixel of `view`'s mask is object.
fn object_in_frame(view: &View) -> bool {
    let mask = &view.mask;
    let (w, h) = (mask.width, mask.height);
    let object = |x: usize, y: usize| mask.pixel(x, y)[0] > 0.5;
    w > 0
        && h > 0
        && !(0..w).any(|x| object(x, 0) || object(x, h - 1))
        && !(0..h).any(|y| object(0, y) || object(w - 1, y))
}

impl<'a> VisualHull<'a> {
    pub fn new(views: impl IntoIterator<Item = &'a View>) -> Self {
        let views: Vec<&View> = views.into_iter().collect();
        let min_views = MIN_VIEWS_SEEING.min(views.len()).max(1);
        let object_in_frame = views.iter().map(|v| object_in_frame(v)).collect();
        VisualHull {
            views,
            object_in_frame,
            min_views,
        }
    }

    /// True when `p` is inside the visual hull.
    pub fn contains(&self, p: DVec3) -> bool {
        let mut seen = 0;
        for (view, &in_frame) in self.views.iter().zip(&self.object_in_frame) {
            let cam = &view.camera;
            let in_image = cam.project(p).filter(|&(u, v, _)| {
                u >= 0.0 && v >= 0.0 && u < cam.width as f64 && v < cam.height as f64
            });
            let Some((u, v, _)) = in_image else {
                if in_frame {
                    return false;
                }
                continue;
            };
            let (x, y) = (u as usize, v as usize);
            if x >= view.mask.width || y >= view.mask.height || view.mask.pixel(x, y)[0] <= 0.5 {
                return false;
            }
            seen += 1;
        }
        seen >= self.min_views
    }

    /// A first guess of the object's centre: the point closest (least squares) to the rays through
    /// the mask centroids, and a radius reaching the farthest camera.
    fn initial_guess(&self) -> (DVec3, f64) {
        let mut normal_matrix = DMat3::ZERO;
        let mut rhs = DVec3::ZERO;
        for view in &self.views {
            let mask = &view.mask;
            let (mut sum_u, mut sum_v, mut weight) = (0.0, 0.0, 0.0);
            for y in 0..mask.height {
                for x in 0..mask.width {
                    if mask.pixel(x, y)[0] > 0.5 {
                        sum_u += x as f64 + 0.5;
                        sum_v += y as f64 + 0.5;
                        weight += 1.0;
                    }
                }
            }
            if weight == 0.0 {
                continue;
            }
            let d = view.camera.ray_dir(sum_u / weight, sum_v / weight);
            let projector = DMat3::IDENTITY - DMat3::from_cols(d * d.x, d * d.y, d * d.z);
            normal_matrix += projector;
            rhs += projector * view.camera.origin();
        }
        let center = if normal_matrix.determinant().abs() > 1e-9 {
            normal_matrix.inverse() * rhs
        } else {
            DVec3::ZERO
        };
        let radius = self
            .views
            .iter()
            .map(|v| (v.camera.origin() - center).length())
            .fold(0.0, f64::max);
        (center, radius.max(1e-6))
    }

    /// Bounds of the hull, by coarse-to-fine voxel carving. Falls back to the initial guess
    /// (sphere through the farthest camera) when no voxel is inside.
    pub fn bounds(&self) -> Bounds {
        let _span = tracing::info_span!("visual_hull_bounds", views = self.views.len()).entered();
        let (center, radius) = self.initial_guess();
        let mut lo = center - DVec3::splat(radius);
        let mut hi = center + DVec3::splat(radius);
        let mut result = None;
        for _ in 0..PASSES {
            let step = (hi - lo) / GRID as f64;
            let occupied = self.carve(lo, step);
            if occupied.is_empty() {
                break;
            }
            let (omin, omax) = occupied.iter().fold(
                (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
                |(a, b), p| (a.min(*p), b.max(*p)),
            );
            // Voxel centres are inside; the object may reach up to a voxel beyond them, and half a
            // pixel beyond the discrete masks: keep two voxels of margin.
            lo = omin - 2.0 * step;
            hi = omax + 2.0 * step;
            let center = 0.5 * (omin + omax);
            let half_diagonal = 0.5 * step.length();
            let radius = occupied
                .iter()
                .map(|p| (*p - center).length())
                .fold(0.0, f64::max)
                + half_diagonal;
            result = Some(Bounds {
                min: lo,
                max: hi,
                center,
                radius,
            });
        }
        result.unwrap_or(Bounds {
            min: center - DVec3::splat(radius),
            max: center + DVec3::splat(radius),
            center,
            radius,
        })
    }

    /// Centres of the voxels of the `GRID³` grid starting at `lo` that are inside the hull.
    fn carve(&self, lo: DVec3, step: DVec3) -> Vec<DVec3> {
        (0..GRID)
            .into_par_iter()
            .flat_map_iter(|k| {
                (0..GRID * GRID).filter_map(move |ij| {
                    let (i, j) = (ij % GRID, ij / GRID);
                    let p = lo + step * (DVec3::new(i as f64, j as f64, k as f64) + 0.5);
                    self.contains(p).then_some(p)
                })
            })
            .collect()
    }
}

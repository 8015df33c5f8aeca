//! How far a view's mask lies from the model's rendered silhouette, as one image-plane shift: the
//! evidence a run uses to tell estimated camera poses from exact ones (`pose_refinement: auto`).
//!
//! Once the surfels have a shape they are the consensus of every view. With exact poses each
//! view's mask lies on the silhouette it renders; with poses off by a fraction of a degree each
//! view's mask lies beside it, shifted by that view's own error. A mask eroded or dilated by a
//! pixel or two moves its contour inward or outward all around, which sums to no shift. A shape
//! the surfels have not matched yet (early in a run, an unseen side) shifts silhouettes too, but
//! those of neighbouring views alike, where pose errors are each view's own: [`own_offset`]
//! keeps only what a view does not share with its neighbours ([`crate::core::view_spread`]).
//!
//! The shift `t` minimizes `Σ (M(x) − A(x − t))²` over the pixels, with `A` the rendered opacity
//! and `M` the mask, both blurred by a Gaussian of [`BLUR_SIGMA_PX`] so that shifts of a few pixels
//! stay within the linearization's reach: Gauss–Newton steps on a bilinear resampling of `A`.
//! Threading: none (one view's image; callers run views in parallel).

use glam::{DMat2, DVec2, DVec3};

use crate::core::blur::gaussian_blur;
use crate::core::view_spread::own_part;

/// Standard deviation of the blur applied to both images, pixels.
pub const BLUR_SIGMA_PX: f64 = 2.0;
/// Gauss–Newton iterations at most; each is one pass over the image.
const MAX_ITERATIONS: usize = 12;
/// The iteration stops once a step is shorter than this, pixels.
const CONVERGED_PX: f64 = 1e-3;
/// A shift longer than this is not a pose error but a different silhouette: reported as this.
pub const MAX_SHIFT_PX: f64 = 8.0;

/// The shift that carries the rendered silhouette `rendered` (opacity in [0, 1]) onto `mask`
/// (`width × height`, row-major), in pixels (x right, y down); `None` when the images have no
/// edge to align (nothing rendered or nothing masked).
pub fn silhouette_shift(
    rendered: &[f64],
    mask: &[f32],
    width: usize,
    height: usize,
) -> Option<DVec2> {
    assert_eq!(rendered.len(), width * height, "one opacity per pixel");
    assert_eq!(mask.len(), width * height, "one mask value per pixel");
    if width < 3 || height < 3 {
        return None;
    }
    let blurred_render = Sampled::new(
        gaussian_blur(rendered, width, height, BLUR_SIGMA_PX),
        width,
        height,
    );
    let mask: Vec<f64> = mask.iter().map(|&m| f64::from(m)).collect();
    let blurred_mask = gaussian_blur(&mask, width, height, BLUR_SIGMA_PX);
    let mut shift = DVec2::ZERO;
    for _ in 0..MAX_ITERATIONS {
        let step = gauss_newton_step(&blurred_render, &blurred_mask, shift)?;
        shift += step;
        if shift.length() > MAX_SHIFT_PX {
            return Some(shift.normalize() * MAX_SHIFT_PX);
        }
        if step.length() < CONVERGED_PX {
            break;
        }
    }
    Some(shift)
}

/// An image with its central-difference gradient, sampled bilinearly together.
struct Sampled {
    width: usize,
    height: usize,
    value: Vec<f64>,
    gradient: Vec<DVec2>,
}

impl Sampled {
    fn new(value: Vec<f64>, width: usize, height: usize) -> Self {
        let at = |x: usize, y: usize| value[y * width + x];
        let gradient = (0..width * height)
            .map(|p| {
                let (x, y) = (p % width, p / width);
                let dx = at((x + 1).min(width - 1), y) - at(x.saturating_sub(1), y);
                let dy = at(x, (y + 1).min(height - 1)) - at(x, y.saturating_sub(1));
                0.5 * DVec2::new(dx, dy)
            })
            .collect();
        Sampled {
            width,
            height,
            value,
            gradient,
        }
    }

    /// The value and gradient at `at` (pixel centres at whole coordinates), interpolated
    /// bilinearly; `None` outside the image.
    fn at(&self, at: DVec2) -> Option<(f64, DVec2)> {
        let (x0, y0) = (at.x.floor(), at.y.floor());
        if x0 < 0.0 || y0 < 0.0 || x0 + 1.0 >= self.width as f64 || y0 + 1.0 >= self.height as f64 {
            return None;
        }
        let (fx, fy) = (at.x - x0, at.y - y0);
        let p = y0 as usize * self.width + x0 as usize;
        let corners = [p, p + 1, p + self.width, p + self.width + 1];
        let weights = [
            (1.0 - fx) * (1.0 - fy),
            fx * (1.0 - fy),
            (1.0 - fx) * fy,
            fx * fy,
        ];
        let mut value = 0.0;
        let mut gradient = DVec2::ZERO;
        for (&q, w) in corners.iter().zip(weights) {
            value += w * self.value[q];
            gradient += w * self.gradient[q];
        }
        Some((value, gradient))
    }
}

/// One Gauss–Newton step on `t` for `Σ (M(x) − A(x − t))²`: with `g = ∇A(x − t)`, the residual
/// changes by `g·δ` for a step `δ`, so `δ = −(Σ g gᵀ)⁻¹ Σ g (M − A)`. `None` when `Σ g gᵀ` is
/// singular (no edge in some direction).
fn gauss_newton_step(rendered: &Sampled, mask: &[f64], shift: DVec2) -> Option<DVec2> {
    let mut normal = DMat2::ZERO;
    let mut rhs = DVec2::ZERO;
    for y in 1..rendered.height - 1 {
        for x in 1..rendered.width - 1 {
            let Some((value, gradient)) = rendered.at(DVec2::new(x as f64, y as f64) - shift)
            else {
                continue;
            };
            let residual = mask[y * rendered.width + x] - value;
            normal += DMat2::from_cols(gradient * gradient.x, gradient * gradient.y);
            rhs += gradient * residual;
        }
    }
    let det = normal.determinant();
    let scale = normal.x_axis.x + normal.y_axis.y;
    if !(scale > 0.0 && det > 1e-9 * scale * scale) {
        return None;
    }
    Some(-(normal.inverse() * rhs))
}

/// What the views' silhouette shifts have of their own, RMS pixels ([`own_part`]).
pub fn own_offset(views: &[(DVec3, DVec2)]) -> Option<f64> {
    let views: Vec<(DVec3, [f64; 2])> = views.iter().map(|(d, s)| (*d, s.to_array())).collect();
    own_part(&views)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A soft-edged ellipse of semi-axes `(a, b)` centred at `centre` (one pixel of antialiasing).
    fn ellipse(width: usize, height: usize, centre: DVec2, a: f64, b: f64) -> Vec<f64> {
        let mut image = vec![0.0; width * height];
        for y in 0..height {
            for x in 0..width {
                let d = (DVec2::new(x as f64, y as f64) - centre) / DVec2::new(a, b);
                let signed_px = (1.0 - d.length()) * a.min(b);
                image[y * width + x] = (signed_px + 0.5).clamp(0.0, 1.0);
            }
        }
        image
    }

    fn as_mask(image: &[f64]) -> Vec<f32> {
        image
            .iter()
            .map(|&v| if v >= 0.5 { 1.0 } else { 0.0 })
            .collect()
    }

    #[test]
    fn a_mask_beside_the_render_is_found_where_it_lies() {
        let (w, h) = (96, 80);
        let rendered = ellipse(w, h, DVec2::new(45.0, 38.0), 22.0, 15.0);
        for offset in [
            DVec2::new(1.5, -0.7),
            DVec2::new(-3.2, 2.4),
            DVec2::new(0.3, 0.0),
        ] {
            let mask = as_mask(&ellipse(w, h, DVec2::new(45.0, 38.0) + offset, 22.0, 15.0));
            let shift = silhouette_shift(&rendered, &mask, w, h).unwrap();
            assert!(
                (shift - offset).length() < 0.15,
                "found {shift} for a mask {offset} away"
            );
        }
    }

    #[test]
    fn an_eroded_or_dilated_mask_is_not_a_shift() {
        let (w, h) = (96, 80);
        let centre = DVec2::new(45.0, 38.0);
        let rendered = ellipse(w, h, centre, 22.0, 15.0);
        for grown_px in [-2.0, 2.0] {
            let mask = as_mask(&ellipse(w, h, centre, 22.0 + grown_px, 15.0 + grown_px));
            let shift = silhouette_shift(&rendered, &mask, w, h).unwrap();
            assert!(shift.length() < 0.1, "{grown_px} px: {shift}");
        }
    }

    #[test]
    fn nothing_to_align_gives_no_shift() {
        let (w, h) = (32, 32);
        assert_eq!(
            silhouette_shift(&vec![0.0; w * h], &vec![0.0; w * h], w, h),
            None
        );
        // A vertical edge aligns across, not along: no shift is defined.
        let half: Vec<f64> = (0..w * h)
            .map(|p| f64::from(u8::from(p % w < 16)))
            .collect();
        assert_eq!(silhouette_shift(&half, &as_mask(&half), w, h), None);
    }

    #[test]
    fn a_far_mask_is_reported_at_the_limit() {
        let (w, h) = (96, 96);
        let rendered = ellipse(w, h, DVec2::new(30.0, 48.0), 10.0, 10.0);
        let mask = as_mask(&ellipse(w, h, DVec2::new(66.0, 48.0), 10.0, 10.0));
        if let Some(shift) = silhouette_shift(&rendered, &mask, w, h) {
            assert!(shift.length() <= MAX_SHIFT_PX + 1e-9, "{shift}");
        }
    }

    /// Directions on a ring of `n` views.
    fn ring(n: usize) -> Vec<DVec3> {
        (0..n)
            .map(|k| {
                let a = k as f64 / n as f64 * std::f64::consts::TAU;
                DVec3::new(a.cos(), a.sin(), 0.3).normalize()
            })
            .collect()
    }

    #[test]
    fn shifts_neighbours_share_are_not_a_views_own() {
        // A shift of 2 px that turns slowly around the ring, as an unmatched shape gives: what is
        // left is under a tenth of it.
        let smooth: Vec<(DVec3, DVec2)> = ring(48)
            .into_iter()
            .map(|d| (d, DVec2::new(2.0 * d.x, 1.0 + d.y)))
            .collect();
        assert!(
            own_offset(&smooth).unwrap() < 0.2,
            "{:?}",
            own_offset(&smooth)
        );
        // Alternating ±1.5 px, each view's own.
        let own: Vec<(DVec3, DVec2)> = ring(48)
            .into_iter()
            .enumerate()
            .map(|(k, d)| (d, DVec2::new(if k % 2 == 0 { 1.5 } else { -1.5 }, 0.0)))
            .collect();
        // Each view against its two ring neighbours (opposite) and the next but one (same).
        let expected = (1.5f64 - (-1.5 - 1.5 + 1.5) / 3.0).abs();
        assert!((own_offset(&own).unwrap() - expected).abs() < 1e-9);
        assert_eq!(own_offset(&own[..3]), None);
    }
}

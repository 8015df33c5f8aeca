//! Undistortion of views taken through COLMAP's `OPENCV` camera model (radial k1, k2 and
//! tangential p1, p2) into pinhole views with the same size and intrinsics.
//!
//! Each pinhole pixel centre is mapped through the distortion to where the lens put it, and the
//! captured image is sampled there bilinearly. Sampling is linear and the ray of a pixel is kept,
//! so Stokes images stay in their per-pixel reference frame (it depends only on the ray and the
//! camera's up vector). Pixels whose source falls outside the captured image get 0 and mask 0.
//! Rows are processed in parallel (rayon); each output pixel is independent.

use rayon::prelude::*;

use crate::core::camera::Camera;
use crate::formats::image_io::Image;

/// OpenCV's radial-tangential distortion of normalized image coordinates.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Distortion {
    pub k1: f64,
    pub k2: f64,
    pub p1: f64,
    pub p2: f64,
}

impl Distortion {
    pub fn is_identity(&self) -> bool {
        [self.k1, self.k2, self.p1, self.p2] == [0.0; 4]
    }

    /// Where the lens images the normalized pinhole point `(x, y)`.
    pub fn distort(&self, x: f64, y: f64) -> (f64, f64) {
        let r2 = x * x + y * y;
        let radial = 1.0 + self.k1 * r2 + self.k2 * r2 * r2;
        (
            x * radial + 2.0 * self.p1 * x * y + self.p2 * (r2 + 2.0 * x * x),
            y * radial + self.p1 * (r2 + 2.0 * y * y) + 2.0 * self.p2 * x * y,
        )
    }

    /// The inverse of [`Distortion::distort`] by Newton's method from `(xd, yd)` (ordinary lenses
    /// converge in a few steps); `None` where it does not converge.
    pub fn undistort(&self, xd: f64, yd: f64) -> Option<(f64, f64)> {
        let (mut x, mut y) = (xd, yd);
        for _ in 0..50 {
            let (fx, fy) = self.distort(x, y);
            let (ex, ey) = (fx - xd, fy - yd);
            if ex.abs().max(ey.abs()) < 1e-14 {
                return Some((x, y));
            }
            let r2 = x * x + y * y;
            let radial = 1.0 + self.k1 * r2 + self.k2 * r2 * r2;
            let slope = 2.0 * self.k1 + 4.0 * self.k2 * r2;
            let (dxx, dxy) = (
                radial + x * x * slope + 2.0 * self.p1 * y + 6.0 * self.p2 * x,
                x * y * slope + 2.0 * self.p1 * x + 2.0 * self.p2 * y,
            );
            let (dyx, dyy) = (
                x * y * slope + 2.0 * self.p1 * x + 2.0 * self.p2 * y,
                radial + y * y * slope + 6.0 * self.p1 * y + 2.0 * self.p2 * x,
            );
            let det = dxx * dyy - dxy * dyx;
            if !det.is_finite() || det.abs() < 1e-12 {
                return None;
            }
            x -= (dyy * ex - dxy * ey) / det;
            y -= (dxx * ey - dyx * ex) / det;
        }
        None
    }

    /// Continuous pixel coordinates in the captured image of the pinhole pixel coordinates
    /// `(u, v)` of `camera`.
    fn source(&self, camera: &Camera, u: f64, v: f64) -> (f64, f64) {
        let (x, y) = ((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy);
        let (xd, yd) = self.distort(x, y);
        (camera.fx * xd + camera.cx, camera.fy * yd + camera.cy)
    }
}

/// Bilinear sample of `image` at continuous pixel coordinates `(u, v)` (pixel centres at
/// `i + 0.5`), or `None` beyond half a pixel outside the image.
fn sample(image: &Image, u: f64, v: f64, out: &mut [f32]) -> bool {
    let (w, h) = (image.width as f64, image.height as f64);
    if !(u >= 0.0 && v >= 0.0 && u <= w && v <= h) {
        out.fill(0.0);
        return false;
    }
    let (x, y) = ((u - 0.5).clamp(0.0, w - 1.0), (v - 0.5).clamp(0.0, h - 1.0));
    let (x0, y0) = (x.floor() as usize, y.floor() as usize);
    let (x1, y1) = (
        (x0 + 1).min(image.width - 1),
        (y0 + 1).min(image.height - 1),
    );
    let (tx, ty) = ((x - x0 as f64) as f32, (y - y0 as f64) as f32);
    for (c, o) in out.iter_mut().enumerate() {
        let at = |xx: usize, yy: usize| image.pixel(xx, yy)[c];
        let top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * tx;
        let bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * tx;
        *o = top + (bottom - top) * ty;
    }
    true
}

/// The pinhole image of `camera` seen through `distortion`, and which pixels had a source.
pub fn undistort_image(
    image: &Image,
    camera: &Camera,
    distortion: &Distortion,
) -> (Image, Vec<bool>) {
    let (w, h, c) = (image.width, image.height, image.channels);
    let mut out = Image::filled(w, h, c, 0.0);
    let mut valid = vec![false; w * h];
    out.data
        .par_chunks_mut(w * c)
        .zip(valid.par_chunks_mut(w))
        .enumerate()
        .for_each(|(j, (row, valid_row))| {
            for i in 0..w {
                let (u, v) = distortion.source(camera, i as f64 + 0.5, j as f64 + 0.5);
                valid_row[i] = sample(image, u, v, &mut row[i * c..(i + 1) * c]);
            }
        });
    (out, valid)
}

/// A binary mask undistorted like the images: bilinear sample > 0.5, and 0 without a source.
pub fn undistort_mask(mask: &Image, camera: &Camera, distortion: &Distortion) -> Image {
    let (mut out, valid) = undistort_image(mask, camera, distortion);
    for (p, v) in out.data.iter_mut().enumerate() {
        let keep = valid[p / mask.channels] && *v > 0.5;
        *v = if keep { 1.0 } else { 0.0 };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn undistortion_inverts_the_lens() {
        let d = Distortion {
            k1: -0.12,
            k2: 0.03,
            p1: 0.001,
            p2: -0.0015,
        };
        for (x, y) in [(0.0, 0.0), (0.3, -0.2), (-0.45, 0.35)] {
            let (xd, yd) = d.distort(x, y);
            let (bx, by) = d.undistort(xd, yd).unwrap();
            assert!((bx - x).abs() < 1e-12 && (by - y).abs() < 1e-12);
        }
        assert!(!d.is_identity());
    }

    #[test]
    fn a_distorted_picture_of_a_smooth_scene_is_straightened() {
        let camera = Camera::look_at(
            96,
            72,
            1.0,
            DVec3::new(0.0, -4.0, 0.0),
            DVec3::ZERO,
            DVec3::Z,
        );
        let d = Distortion {
            k1: -0.15,
            k2: 0.02,
            p1: 0.002,
            p2: 0.001,
        };
        // A smooth function of the normalized pinhole coordinates: what a pinhole camera sees.
        let scene = |x: f64, y: f64| (0.5 + 0.3 * (3.0 * x).sin() * (2.0 * y).cos()) as f32;
        let pinhole = Image::from_fn(96, 72, 1, |i, j, o| {
            let (x, y) = (
                (i as f64 + 0.5 - camera.cx) / camera.fx,
                (j as f64 + 0.5 - camera.cy) / camera.fy,
            );
            o[0] = scene(x, y);
        });
        // What the lens records: at each captured pixel, the scene along its undistorted ray.
        let captured = Image::from_fn(96, 72, 1, |i, j, o| {
            let (xd, yd) = (
                (i as f64 + 0.5 - camera.cx) / camera.fx,
                (j as f64 + 0.5 - camera.cy) / camera.fy,
            );
            let (x, y) = d.undistort(xd, yd).unwrap();
            o[0] = scene(x, y);
        });
        let (straight, valid) = undistort_image(&captured, &camera, &d);
        let mut worst = 0.0f32;
        let mut before = 0.0f32;
        for j in 4..68 {
            for i in 4..92 {
                let p = j * 96 + i;
                assert!(valid[p]);
                worst = worst.max((straight.data[p] - pinhole.data[p]).abs());
                before = before.max((captured.data[p] - pinhole.data[p]).abs());
            }
        }
        eprintln!("undistortion: max error {worst:.2e} (distorted image: {before:.2e})");
        assert!(worst < 2e-4, "{worst}");
        assert!(before > 5e-3, "the distortion should matter: {before}");
    }
}

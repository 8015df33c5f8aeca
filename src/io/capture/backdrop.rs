//! A distant, cluttered backdrop for `phygap degrade`: what a photograph shows beyond the object
//! (a room, shelves, a table's far edge) where a rendered capture is black.
//!
//! Its radiance depends only on the direction of the ray through a pixel, as a backdrop at
//! infinity would: every view sees the same backdrop from its own angle, so it is as consistent
//! across views as real surroundings and a model could fit it with surfels far away. It is a grey
//! checker of 10° cells in the polar and azimuthal angles under [`BLOBS`] coloured blobs of random
//! direction, width and colour, unpolarized, with its mean near `level`. Composited with the
//! clean capture's mask m as `S0 + (1 − m) · B(d)`: behind the object nothing shows through.
//!
//! Threading: none; evaluating a direction is a few dozen exponentials.

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::core::camera::Camera;
use crate::formats::image_io::Image;

/// Coloured blobs over the checker.
pub const BLOBS: usize = 24;
/// The checker's cells, in radians of polar and azimuthal angle.
const CELL: f64 = std::f64::consts::PI / 18.0;

/// A procedural backdrop at infinity.
#[derive(Clone, Debug)]
pub struct Backdrop {
    level: f64,
    blobs: Vec<Blob>,
}

#[derive(Clone, Debug)]
struct Blob {
    centre: DVec3,
    /// Angular width in radians.
    width: f64,
    colour: [f64; 3],
}

impl Backdrop {
    /// A backdrop of mean radiance near `level`, drawn from `seed`.
    pub fn new(level: f64, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let blobs = (0..BLOBS)
            .map(|_| {
                let z: f64 = rng.random_range(-1.0..1.0);
                let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                let r = (1.0 - z * z).sqrt();
                Blob {
                    centre: DVec3::new(r * phi.cos(), r * phi.sin(), z),
                    width: rng.random_range(0.05..0.3),
                    colour: [0; 3].map(|_| rng.random_range(0.0..1.5)),
                }
            })
            .collect();
        Backdrop { level, blobs }
    }

    /// Linear RGB radiance arriving along the unit direction `d` (from the backdrop towards
    /// the camera: `d` is the ray's direction, away from the camera).
    pub fn radiance(&self, d: DVec3) -> [f64; 3] {
        let theta = d.z.clamp(-1.0, 1.0).acos();
        let phi = d.y.atan2(d.x).rem_euclid(std::f64::consts::TAU);
        let cells = (theta / CELL).floor() as i64 + (phi / CELL).floor() as i64;
        let grey = if cells % 2 == 0 { 0.45 } else { 0.2 };
        let mut rgb = [grey; 3];
        for blob in &self.blobs {
            let falloff = (-(1.0 - d.dot(blob.centre)) / (blob.width * blob.width)).exp();
            for (out, c) in rgb.iter_mut().zip(blob.colour) {
                *out += falloff * c;
            }
        }
        rgb.map(|v| self.level * v)
    }

    /// `s0` (RGB, or grey) with the backdrop added where `mask` leaves it visible: each pixel
    /// gains `(1 − m) · B(d)`, d the ray through the pixel's centre.
    pub fn behind(&self, s0: &Image, mask: &Image, camera: &Camera) -> Image {
        let mut out = s0.clone();
        for y in 0..s0.height {
            for x in 0..s0.width {
                let visible = 1.0 - f64::from(mask.data[y * mask.width + x]).clamp(0.0, 1.0);
                if visible == 0.0 {
                    continue;
                }
                let b = self.radiance(camera.pixel_dir(x as u32, y as u32));
                let at = (y * s0.width + x) * s0.channels;
                for (k, v) in out.data[at..at + s0.channels].iter_mut().enumerate() {
                    *v += (visible * b[k.min(2)]) as f32;
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_backdrop_is_cluttered_positive_and_near_its_level() {
        let backdrop = Backdrop::new(0.2, 7);
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let samples: Vec<[f64; 3]> = (0..4000)
            .map(|_| {
                let d = DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
                backdrop.radiance(d.normalize())
            })
            .collect();
        let mean = samples
            .iter()
            .map(|c| c.iter().sum::<f64>() / 3.0)
            .sum::<f64>()
            / 4000.0;
        assert!((0.05..0.4).contains(&mean), "mean {mean}");
        assert!(samples.iter().flatten().all(|&v| v > 0.0));
        let spread = samples.iter().map(|c| c[0]).fold(0.0, f64::max)
            / samples.iter().map(|c| c[0]).fold(f64::INFINITY, f64::min);
        assert!(spread > 3.0, "max over min {spread}");
        // The same seed gives the same backdrop; another seed another.
        let d = DVec3::new(0.3, -0.5, 0.8).normalize();
        assert_eq!(Backdrop::new(0.2, 7).radiance(d), backdrop.radiance(d));
        assert_ne!(Backdrop::new(0.2, 8).radiance(d), backdrop.radiance(d));
    }

    #[test]
    fn the_object_hides_the_backdrop_and_a_partial_pixel_shows_its_share() {
        let camera = Camera::look_at(4, 3, 0.8, DVec3::X * 3.0, DVec3::ZERO, DVec3::Z);
        let s0 = Image::filled(4, 3, 3, 0.5);
        let mut mask = Image::filled(4, 3, 1, 0.0);
        mask.data[5] = 1.0;
        mask.data[6] = 0.25;
        let backdrop = Backdrop::new(0.3, 2);
        let out = backdrop.behind(&s0, &mask, &camera);
        assert_eq!(&out.data[15..18], &[0.5; 3]);
        for (p, visible) in [(0, 1.0), (6, 0.75)] {
            let b = backdrop.radiance(camera.pixel_dir((p % 4) as u32, (p / 4) as u32));
            for (k, b) in b.into_iter().enumerate() {
                let expected = 0.5 + (visible * b) as f32;
                assert!((out.data[3 * p + k] - expected).abs() < 1e-6, "pixel {p}");
            }
        }
    }
}

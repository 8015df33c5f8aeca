//! Lat-long (equirectangular) ⇄ cube conversion in the convention of CAPTURE_FORMAT.md §5 /
//! DATA_FORMAT.md §6: texel (row i, column j) of an H × 2H map looks along
//! `θ = π i/(H − 1)`, `φ = 2π (j + 0.5)/W`, `dir = sinθ sinφ · r + sinθ cosφ · f + cosθ · u`,
//! bilinear, φ wrapping, θ clamping; for `world_up` (0, 0, 1): u = +Z, f = +Y, r = +X; for (0, 1, 0):
//! u = +Y, f = −Z, r = +X. Import supersamples each cube texel (4 × 4 sub-directions) so small bright
//! features (a sun disk) keep their energy. Work is split over cube rows / lat-long rows with rayon.

use std::f64::consts::PI;
use std::path::Path;

use glam::{DQuat, DVec3};
use rayon::prelude::*;

use super::{
    activate, face_uv_to_dir, inverse_activate, CubeGrid, CubeMap, EnvMapError, NUM_FACES,
};
use crate::formats::image_io::{read_image, Image};

/// Sub-samples per cube texel edge when importing a lat-long map.
const SUPERSAMPLE: usize = 4;

/// The world's up axis, which orients lat-long maps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum WorldUp {
    /// `[0, 0, 1]` (the default; the shared datasets).
    #[default]
    Z,
    /// `[0, 1, 0]`.
    Y,
}

impl WorldUp {
    /// Parses a capture's `world_up` vector.
    pub fn from_vector(v: [f64; 3]) -> Result<Self, EnvMapError> {
        match v {
            [x, y, z] if x == 0.0 && y == 0.0 && z == 1.0 => Ok(WorldUp::Z),
            [x, y, z] if x == 0.0 && y == 1.0 && z == 0.0 => Ok(WorldUp::Y),
            _ => Err(EnvMapError::WorldUp(v)),
        }
    }

    /// Reference axes (r, f, u) of the lat-long mapping.
    pub fn basis(self) -> (DVec3, DVec3, DVec3) {
        match self {
            WorldUp::Z => (DVec3::X, DVec3::Y, DVec3::Z),
            WorldUp::Y => (DVec3::X, DVec3::NEG_Z, DVec3::Y),
        }
    }

    /// The up axis u.
    pub fn axis(self) -> DVec3 {
        self.basis().2
    }
}

/// World direction of continuous lat-long coordinates (polar angle θ from up, azimuth φ).
pub fn latlong_dir(up: WorldUp, theta: f64, phi: f64) -> DVec3 {
    let (r, f, u) = up.basis();
    theta.sin() * phi.sin() * r + theta.sin() * phi.cos() * f + theta.cos() * u
}

/// Bilinear lookup of an RGB lat-long image (already validated: W = 2H, 3 channels) along `dir`.
pub fn sample_latlong(img: &Image, up: WorldUp, dir: DVec3) -> DVec3 {
    let (r, f, u) = up.basis();
    let d = dir.normalize();
    let (w, h) = (img.width, img.height);
    let theta = d.dot(u).clamp(-1.0, 1.0).acos();
    let phi = d.dot(r).atan2(d.dot(f)).rem_euclid(2.0 * PI);
    let x = phi / (2.0 * PI) * w as f64 - 0.5;
    let y = theta / PI * (h - 1) as f64;
    let x0 = x.floor();
    let fx = x - x0;
    let y0 = y.floor().clamp(0.0, (h - 1) as f64);
    let fy = y - y0;
    let y1 = (y0 as usize + 1).min(h - 1);
    let y0 = y0 as usize;
    let xa = (x0 as isize).rem_euclid(w as isize) as usize;
    let xb = (x0 as isize + 1).rem_euclid(w as isize) as usize;
    let px = |x: usize, y: usize| {
        let p = img.pixel(x, y);
        DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64)
    };
    px(xa, y0) * (1.0 - fx) * (1.0 - fy)
        + px(xb, y0) * fx * (1.0 - fy)
        + px(xa, y1) * (1.0 - fx) * fy
        + px(xb, y1) * fx * fy
}

fn validated_rgb(img: &Image) -> Result<Image, EnvMapError> {
    if img.height < 2 || img.width != 2 * img.height {
        return Err(EnvMapError::LatLongShape {
            width: img.width,
            height: img.height,
        });
    }
    if !matches!(img.channels, 1 | 3 | 4) {
        return Err(EnvMapError::LatLongChannels(img.channels));
    }
    if let Some((x, y, _)) = img.first_non_finite() {
        return Err(EnvMapError::NonFinite { x, y });
    }
    Ok(img.to_rgb())
}

impl CubeMap {
    /// Imports a linear-radiance lat-long map into a `face_size`² cube, averaging 4 × 4
    /// bilinear sub-samples per texel.
    pub fn from_latlong(img: &Image, up: WorldUp, face_size: usize) -> Result<Self, EnvMapError> {
        let _span = tracing::info_span!("envmap_from_latlong", face_size).entered();
        if face_size == 0 {
            return Err(EnvMapError::ZeroFaceSize(face_size));
        }
        let img = validated_rgb(img)?;
        let d = face_size;
        let mut raw = vec![0.0; CubeMap::num_values(d)];
        raw.par_chunks_mut(d * 3)
            .enumerate()
            .for_each(|(row, out)| {
                let (face, y) = (row / d, row % d);
                for x in 0..d {
                    let mut sum = DVec3::ZERO;
                    for sy in 0..SUPERSAMPLE {
                        for sx in 0..SUPERSAMPLE {
                            let fx = x as f64 + (sx as f64 + 0.5) / SUPERSAMPLE as f64;
                            let fy = y as f64 + (sy as f64 + 0.5) / SUPERSAMPLE as f64;
                            let u = 2.0 * fx / d as f64 - 1.0;
                            let v = 2.0 * fy / d as f64 - 1.0;
                            sum += sample_latlong(&img, up, face_uv_to_dir(face, u, v));
                        }
                    }
                    let mean = sum / (SUPERSAMPLE * SUPERSAMPLE) as f64;
                    for c in 0..3 {
                        out[x * 3 + c] = inverse_activate(mean[c]);
                    }
                }
            });
        debug_assert_eq!(raw.len(), NUM_FACES * d * d * 3);
        Ok(CubeMap { size: d, raw })
    }

    /// Reads a lat-long `.exr` / `.hdr` file (linear radiance) into a cube.
    pub fn load_latlong(path: &Path, up: WorldUp, face_size: usize) -> Result<Self, EnvMapError> {
        let (img, _) = read_image(path)?;
        Self::from_latlong(&img, up, face_size)
    }

    /// Exports the activated radiance as an RGB lat-long image of `height` rows (width 2 · height).
    pub fn to_latlong(&self, height: usize, up: WorldUp) -> Image {
        let _span = tracing::info_span!("envmap_to_latlong", height).entered();
        let (h, w) = (height.max(2), 2 * height.max(2));
        let grid = CubeGrid::new(self.size);
        let radiance = self.radiance();
        let mut data = vec![0.0f32; w * h * 3];
        data.par_chunks_mut(w * 3).enumerate().for_each(|(i, row)| {
            let theta = PI * i as f64 / (h - 1) as f64;
            for j in 0..w {
                let phi = 2.0 * PI * (j as f64 + 0.5) / w as f64;
                let value = grid.sample(&radiance, latlong_dir(up, theta, phi));
                for c in 0..3 {
                    row[j * 3 + c] = value[c] as f32;
                }
            }
        });
        Image {
            width: w,
            height: h,
            channels: 3,
            data,
        }
    }

    /// The map turned by `degrees` about the world's up axis (right-hand rule: a light at azimuth
    /// direction d moves to `R(degrees) · d`), resampled bilinearly at every texel.
    pub fn rotated_about_up(&self, degrees: f64, up: WorldUp) -> CubeMap {
        self.rotated(DQuat::from_axis_angle(up.axis(), degrees.to_radians()))
    }

    /// The map turned by `rotation` (a light from direction d comes from `rotation · d`),
    /// resampled bilinearly at every texel.
    pub fn rotated(&self, rotation: DQuat) -> CubeMap {
        let inverse = rotation.inverse();
        let grid = CubeGrid::new(self.size);
        let radiance = self.radiance();
        let raw = grid
            .dirs
            .par_iter()
            .flat_map_iter(|&d| {
                grid.sample(&radiance, inverse * d)
                    .to_array()
                    .map(inverse_activate)
            })
            .collect();
        CubeMap {
            size: self.size,
            raw,
        }
    }

    /// Radiance of texel `t` (flat texel index), activated.
    pub fn texel_radiance(&self, t: usize) -> DVec3 {
        DVec3::new(
            activate(self.raw[t * 3]),
            activate(self.raw[t * 3 + 1]),
            activate(self.raw[t * 3 + 2]),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn smooth(d: DVec3) -> DVec3 {
        DVec3::new(
            1.0 + 0.5 * d.x + 0.2 * d.z * d.z,
            0.7 + 0.3 * d.y * d.x,
            0.4 + 0.3 * d.z,
        )
    }

    fn latlong_of(height: usize, up: WorldUp, f: impl Fn(DVec3) -> DVec3) -> Image {
        Image::from_fn(2 * height, height, 3, |j, i, out| {
            let theta = PI * i as f64 / (height - 1) as f64;
            let phi = 2.0 * PI * (j as f64 + 0.5) / (2 * height) as f64;
            let v = f(latlong_dir(up, theta, phi));
            for c in 0..3 {
                out[c] = v[c] as f32;
            }
        })
    }

    #[test]
    fn latlong_cube_latlong_round_trips_a_smooth_map() {
        for up in [WorldUp::Z, WorldUp::Y] {
            let img = latlong_of(64, up, smooth);
            let cube = CubeMap::from_latlong(&img, up, 32).unwrap();
            // Each texel holds the value of the smooth function at its direction (to O(h²)).
            let grid = CubeGrid::new(32);
            for t in (0..grid.num_texels()).step_by(37) {
                let err = (cube.texel_radiance(t) - smooth(grid.dirs[t]))
                    .abs()
                    .max_element();
                assert!(err < 2e-3, "texel {t}: {err}");
            }
            let back = cube.to_latlong(64, up);
            let worst = img
                .data
                .iter()
                .zip(&back.data)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0f32, f32::max);
            assert!(worst < 5e-3, "{up:?}: worst round-trip error {worst}");
        }
    }

    #[test]
    fn orientation_follows_the_capture_format() {
        // A map bright only toward φ = 90°, θ = 90° (world +X for both up conventions).
        for up in [WorldUp::Z, WorldUp::Y] {
            let img = latlong_of(32, up, |d| {
                DVec3::splat(if d.x > 0.95 { 10.0 } else { 0.1 })
            });
            let cube = CubeMap::from_latlong(&img, up, 16).unwrap();
            assert!(cube.sample(DVec3::X).x > 5.0);
            assert!(cube.sample(DVec3::NEG_X).x < 0.2);
        }
        // φ = 0 is +Y for Z-up and −Z for Y-up.
        assert!(latlong_dir(WorldUp::Z, PI / 2.0, 0.0).abs_diff_eq(DVec3::Y, 1e-12));
        assert!(latlong_dir(WorldUp::Y, PI / 2.0, 0.0).abs_diff_eq(DVec3::NEG_Z, 1e-12));
        assert!(latlong_dir(WorldUp::Y, 0.0, 1.0).abs_diff_eq(DVec3::Y, 1e-12));
    }

    #[test]
    fn rotation_about_up_moves_a_light() {
        let img = latlong_of(32, WorldUp::Z, |d| {
            DVec3::splat(if d.x > 0.9 { 10.0 } else { 0.1 })
        });
        let cube = CubeMap::from_latlong(&img, WorldUp::Z, 16).unwrap();
        let turned = cube.rotated_about_up(90.0, WorldUp::Z);
        assert!(
            turned.sample(DVec3::Y).x > 5.0,
            "+X rotated by +90° about +Z is +Y"
        );
        assert!(turned.sample(DVec3::X).x < 0.2);
    }

    #[test]
    fn bad_latlong_maps_are_rejected() {
        let img = Image::filled(30, 20, 3, 1.0);
        assert!(matches!(
            CubeMap::from_latlong(&img, WorldUp::Z, 8),
            Err(EnvMapError::LatLongShape { .. })
        ));
        let mut img = Image::filled(8, 4, 3, 1.0);
        img.data[5] = f32::NAN;
        assert!(matches!(
            CubeMap::from_latlong(&img, WorldUp::Z, 8),
            Err(EnvMapError::NonFinite { .. })
        ));
        assert!(WorldUp::from_vector([1.0, 0.0, 0.0]).is_err());
    }

    #[test]
    fn the_sky_sun_lands_on_the_brightest_texel() {
        let Some(root) = crate::testing::shared_data_dir() else {
            return;
        };
        let scene: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(root.join("sphere/scene.json")).unwrap())
                .unwrap();
        let sun: Vec<f64> = serde_json::from_value(
            scene["env_map"]["extra"]["train_test"]["sun_direction"].clone(),
        )
        .unwrap();
        let sun = DVec3::from_slice(&sun);
        let cube = CubeMap::load_latlong(&root.join("sphere/env/sky.exr"), WorldUp::Z, 64).unwrap();
        let grid = CubeGrid::new(64);
        let brightest = (0..grid.num_texels())
            .max_by(|&a, &b| {
                cube.texel_radiance(a)
                    .x
                    .total_cmp(&cube.texel_radiance(b).x)
            })
            .unwrap();
        let angle = grid.dirs[brightest].dot(sun).acos().to_degrees();
        assert!(angle < 2.0, "brightest texel {angle}° from the sun");
        // The exported lat-long map peaks there too.
        let img = cube.to_latlong(128, WorldUp::Z);
        let (mut best, mut best_value) = (0, 0.0f32);
        for p in 0..img.num_pixels() {
            if img.data[p * 3] > best_value {
                best_value = img.data[p * 3];
                best = p;
            }
        }
        let (i, j) = (best / img.width, best % img.width);
        let d = latlong_dir(
            WorldUp::Z,
            PI * i as f64 / (img.height - 1) as f64,
            2.0 * PI * (j as f64 + 0.5) / img.width as f64,
        );
        assert!(d.dot(sun).acos().to_degrees() < 3.0);
    }
}

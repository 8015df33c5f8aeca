//! The learnable environment light: a cube map of unconstrained texels, its activation, and the
//! cube-face direction convention shared by every cube-map consumer (prefiltering, lat-long import
//! and export, GridMap).
//!
//! **Face convention** (world axes, the OpenGL / nvdiffrec cube layout). Faces are stored in the
//! order +X, −X, +Y, −Y, +Z, −Z. Texel (face f, row y, column x) of a D×D face has face coordinates
//! `u = 2 (x + 0.5)/D − 1`, `v = 2 (y + 0.5)/D − 1` and looks along the normalized
//! ```text
//! +X: ( 1, −v, −u)   −X: (−1, −v,  u)   +Y: ( u,  1,  v)
//! −Y: ( u, −1, −v)   +Z: ( u, −v,  1)   −Z: (−u, −v, −1)
//! ```
//! The cube lives in the world frame; only the lat-long import/export ([`latlong`]) depends on the
//! capture's `world_up`. Texel values are stored face-major, then row-major, RGB interleaved:
//! index `((f · D + y) · D + x) · 3 + c`.
//!
//! **Activation**: stored value x ↦ radiance f(x) = sigmoid(x) for x ≤ 0 and x + 0.5 for x > 0
//! (METHOD.md §2): positive, unbounded above (HDR), continuous at 0.

pub mod grid;
pub mod latlong;
pub mod orbit_kernel;
pub mod prefilter;
pub mod symmetry;

use glam::DVec3;
use thiserror::Error;

pub use grid::{CubeGrid, CubePoint, LookupJacobian};
pub use latlong::WorldUp;
pub use prefilter::{EnvGrad, MipChainSpec, PrefilterPlan, PreparedEnv};

/// Number of cube faces.
pub const NUM_FACES: usize = 6;

/// Errors of environment-map construction and import.
#[derive(Debug, Error)]
pub enum EnvMapError {
    #[error("cube face size must be at least 1, got {0}")]
    ZeroFaceSize(usize),
    #[error("cube map texel buffer has {found} values, expected {expected} (6 × {size}² × 3)")]
    TexelCount {
        size: usize,
        expected: usize,
        found: usize,
    },
    #[error(
        "lat-long environment map is {width}×{height}; need width = 2 × height and height ≥ 2"
    )]
    LatLongShape { width: usize, height: usize },
    #[error("lat-long environment map has {0} channels; need 1 (grey), 3 (RGB) or 4 (RGBA)")]
    LatLongChannels(usize),
    #[error("lat-long environment map has a non-finite value at pixel ({x}, {y})")]
    NonFinite { x: usize, y: usize },
    #[error("world_up must be [0,0,1] or [0,1,0], got {0:?}")]
    WorldUp([f64; 3]),
    #[error("mip chain: {0}")]
    MipChain(String),
    #[error("cube map face size {found} does not match the prefilter plan's base size {expected}")]
    PlanMismatch { expected: usize, found: usize },
    #[error(transparent)]
    Image(#[from] crate::formats::image_io::ImageError),
}

/// The radiance activation f(x): sigmoid(x) for x ≤ 0, x + 0.5 for x > 0.
pub fn activate(x: f64) -> f64 {
    if x <= 0.0 {
        1.0 / (1.0 + (-x).exp())
    } else {
        x + 0.5
    }
}

/// f′(x) of [`activate`].
pub fn activate_derivative(x: f64) -> f64 {
    if x <= 0.0 {
        let s = 1.0 / (1.0 + (-x).exp());
        s * (1.0 - s)
    } else {
        1.0
    }
}

/// Smallest radiance [`inverse_activate`] represents (the sigmoid branch never reaches 0).
pub const MIN_RADIANCE: f64 = 1e-6;

/// The stored value whose activation is the radiance `y` (clamped below at [`MIN_RADIANCE`]).
pub fn inverse_activate(y: f64) -> f64 {
    let y = if y.is_finite() { y } else { MIN_RADIANCE };
    let y = y.max(MIN_RADIANCE);
    if y <= 0.5 {
        (y / (1.0 - y)).ln()
    } else {
        y - 0.5
    }
}

/// Axes of one cube face: the direction of texel (u, v) has `d[major] = major_sign`,
/// `d[u_axis] = u_sign · u`, `d[v_axis] = v_sign · v`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FaceAxes {
    pub major: usize,
    pub major_sign: f64,
    pub u_axis: usize,
    pub u_sign: f64,
    pub v_axis: usize,
    pub v_sign: f64,
}

pub(crate) const FACES: [FaceAxes; NUM_FACES] = [
    FaceAxes {
        major: 0,
        major_sign: 1.0,
        u_axis: 2,
        u_sign: -1.0,
        v_axis: 1,
        v_sign: -1.0,
    },
    FaceAxes {
        major: 0,
        major_sign: -1.0,
        u_axis: 2,
        u_sign: 1.0,
        v_axis: 1,
        v_sign: -1.0,
    },
    FaceAxes {
        major: 1,
        major_sign: 1.0,
        u_axis: 0,
        u_sign: 1.0,
        v_axis: 2,
        v_sign: 1.0,
    },
    FaceAxes {
        major: 1,
        major_sign: -1.0,
        u_axis: 0,
        u_sign: 1.0,
        v_axis: 2,
        v_sign: -1.0,
    },
    FaceAxes {
        major: 2,
        major_sign: 1.0,
        u_axis: 0,
        u_sign: 1.0,
        v_axis: 1,
        v_sign: -1.0,
    },
    FaceAxes {
        major: 2,
        major_sign: -1.0,
        u_axis: 0,
        u_sign: -1.0,
        v_axis: 1,
        v_sign: -1.0,
    },
];

/// Unnormalized direction of face coordinates (u, v) ∈ [−1, 1]² on `face` (values outside extrapolate
/// on the face plane).
pub fn face_uv_to_dir(face: usize, u: f64, v: f64) -> DVec3 {
    let a = FACES[face];
    let mut d = [0.0; 3];
    d[a.major] = a.major_sign;
    d[a.u_axis] = a.u_sign * u;
    d[a.v_axis] = a.v_sign * v;
    DVec3::from_array(d)
}

/// Unit direction through the centre of texel (x, y) of `face` on a D×D cube.
pub fn texel_dir(size: usize, face: usize, x: usize, y: usize) -> DVec3 {
    let u = 2.0 * (x as f64 + 0.5) / size as f64 - 1.0;
    let v = 2.0 * (y as f64 + 0.5) / size as f64 - 1.0;
    face_uv_to_dir(face, u, v).normalize()
}

/// The face a direction falls on (largest |component|; ties prefer x, then y) and its face
/// coordinates (u, v) ∈ [−1, 1]². `dir` need not be unit but must be non-zero.
pub fn dir_to_face_uv(dir: DVec3) -> (usize, f64, f64) {
    let (face, _, _, u, v) = dir_to_face_uv_with_grad(dir);
    (face, u, v)
}

/// [`dir_to_face_uv`] with the gradients ∂u/∂dir and ∂v/∂dir.
#[inline]
pub fn dir_to_face_uv_with_grad(dir: DVec3) -> (usize, DVec3, DVec3, f64, f64) {
    let a = dir.abs();
    let face = if a.x >= a.y && a.x >= a.z {
        if dir.x >= 0.0 {
            0
        } else {
            1
        }
    } else if a.y >= a.z {
        if dir.y >= 0.0 {
            2
        } else {
            3
        }
    } else if dir.z >= 0.0 {
        4
    } else {
        5
    };
    let f = FACES[face];
    let d = dir.to_array();
    let m = f.major_sign * d[f.major]; // |d[major]| > 0
    let u = f.u_sign * d[f.u_axis] / m;
    let v = f.v_sign * d[f.v_axis] / m;
    let mut du = [0.0; 3];
    du[f.u_axis] = f.u_sign / m;
    du[f.major] = -u / d[f.major];
    let mut dv = [0.0; 3];
    dv[f.v_axis] = f.v_sign / m;
    dv[f.major] = -v / d[f.major];
    (face, DVec3::from_array(du), DVec3::from_array(dv), u, v)
}

/// Exact solid angle of the texel (x, y) of a D×D cube face (the same on every face).
pub fn texel_solid_angle(size: usize, x: usize, y: usize) -> f64 {
    let area = |u: f64, v: f64| (u * v).atan2((u * u + v * v + 1.0).sqrt());
    let s = size as f64;
    let (u0, u1) = (2.0 * x as f64 / s - 1.0, 2.0 * (x + 1) as f64 / s - 1.0);
    let (v0, v1) = (2.0 * y as f64 / s - 1.0, 2.0 * (y + 1) as f64 / s - 1.0);
    area(u1, v1) - area(u0, v1) - area(u1, v0) + area(u0, v0)
}

/// A cube-map environment light: `6 × size² × 3` unconstrained texels (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct CubeMap {
    /// Face edge length D in texels.
    pub size: usize,
    /// Unconstrained stored values; radiance = [`activate`] of each.
    pub raw: Vec<f64>,
}

impl CubeMap {
    /// Number of stored values for a face size: `6 · D² · 3`.
    pub fn num_values(size: usize) -> usize {
        NUM_FACES * size * size * 3
    }

    /// A map of uniform radiance.
    pub fn constant(size: usize, radiance: DVec3) -> Result<Self, EnvMapError> {
        if size == 0 {
            return Err(EnvMapError::ZeroFaceSize(size));
        }
        let texel = radiance.to_array().map(inverse_activate);
        let raw = (0..NUM_FACES * size * size)
            .flat_map(|_| texel)
            .collect::<Vec<_>>();
        Ok(CubeMap { size, raw })
    }

    /// A map holding the given stored (unconstrained) values.
    pub fn from_raw(size: usize, raw: Vec<f64>) -> Result<Self, EnvMapError> {
        if size == 0 {
            return Err(EnvMapError::ZeroFaceSize(size));
        }
        let expected = Self::num_values(size);
        if raw.len() != expected {
            return Err(EnvMapError::TexelCount {
                size,
                expected,
                found: raw.len(),
            });
        }
        Ok(CubeMap { size, raw })
    }

    /// A map whose activated radiance is `radiance` (one RGB triple per texel, clamped below at
    /// [`MIN_RADIANCE`]).
    pub fn from_radiance(size: usize, radiance: &[f64]) -> Result<Self, EnvMapError> {
        Self::from_raw(
            size,
            radiance.iter().map(|&y| inverse_activate(y)).collect(),
        )
    }

    /// Activated radiance of every texel (same layout as `raw`).
    pub fn radiance(&self) -> Vec<f64> {
        self.raw.iter().map(|&x| activate(x)).collect()
    }

    /// Bilinearly interpolated radiance arriving from direction `dir` (seamless across faces).
    pub fn sample(&self, dir: DVec3) -> DVec3 {
        let grid = CubeGrid::new(self.size);
        grid.sample(&self.radiance(), dir)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn activation_is_continuous_and_inverts() {
        assert!((activate(0.0) - 0.5).abs() < 1e-15);
        assert!((activate(1e-12) - 0.5).abs() < 1e-11);
        for y in [1e-4, 0.1, 0.5, 0.7, 3.0, 400.0] {
            assert!(
                (activate(inverse_activate(y)) - y).abs() < 1e-12 * y.max(1.0),
                "{y}"
            );
        }
        assert!(activate(inverse_activate(-1.0)) > 0.0);
        for x in [-3.0, -0.2, 0.3, 5.0] {
            let h = 1e-6;
            let fd = (activate(x + h) - activate(x - h)) / (2.0 * h);
            assert!((fd - activate_derivative(x)).abs() < 1e-8);
        }
    }

    #[test]
    fn face_convention_round_trips_and_matches_the_table() {
        assert!(texel_dir(2, 0, 1, 1).abs_diff_eq(DVec3::new(1.0, -0.5, -0.5).normalize(), 1e-12));
        assert!(texel_dir(2, 4, 1, 0).abs_diff_eq(DVec3::new(0.5, 0.5, 1.0).normalize(), 1e-12));
        assert!(texel_dir(2, 5, 1, 0).abs_diff_eq(DVec3::new(-0.5, 0.5, -1.0).normalize(), 1e-12));
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..200 {
            let d = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let (face, u, v) = dir_to_face_uv(d * 3.0);
            assert!(u.abs() <= 1.0 && v.abs() <= 1.0);
            assert!(face_uv_to_dir(face, u, v)
                .normalize()
                .abs_diff_eq(d.normalize(), 1e-12));
        }
    }

    #[test]
    fn solid_angles_sum_to_the_sphere() {
        for size in [1, 3, 16] {
            let total: f64 = (0..size)
                .flat_map(|y| (0..size).map(move |x| texel_solid_angle(size, x, y)))
                .sum::<f64>()
                * 6.0;
            assert!(
                (total - 4.0 * std::f64::consts::PI).abs() < 1e-12,
                "{size}: {total}"
            );
        }
    }

    #[test]
    fn face_uv_gradient_matches_finite_differences() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for _ in 0..50 {
            let d = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let (face, du, dv, _, _) = dir_to_face_uv_with_grad(d);
            let mut f = |x: &[f64]| {
                let (f2, u, _) = dir_to_face_uv(DVec3::from_slice(x));
                assert_eq!(f2, face, "probe crossed a face edge");
                u
            };
            crate::core::gradcheck::assert_gradient(
                "du/ddir",
                &mut f,
                &d.to_array(),
                &du.to_array(),
                1e-7,
                1e-6,
                1e-6,
            );
            let mut g = |x: &[f64]| dir_to_face_uv(DVec3::from_slice(x)).2;
            crate::core::gradcheck::assert_gradient(
                "dv/ddir",
                &mut g,
                &d.to_array(),
                &dv.to_array(),
                1e-7,
                1e-6,
                1e-6,
            );
        }
    }
}

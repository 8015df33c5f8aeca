//! Cameras of the IDR/NeuS layout: `cameras.npz` (or `cameras_sphere.npz`, `cameras_new.npz`)
//! holding per view `world_mat_i`, the 4×4 projection K·[R | t] (OpenCV axes: +X right, +Y down,
//! looking along +Z; world to image), and optionally `scale_mat_i`, which maps the normalised
//! frame (the object inside the unit sphere) to the world.
//!
//! As NeuS's loader does, P = world_mat · scale_mat is decomposed into K, R and the camera centre
//! C: the left 3×3 block M = K·R by an RQ decomposition (K upper triangular with a positive
//! diagonal, R a rotation: M is negated first when its determinant is negative, which P's
//! projective scale allows), C = −M⁻¹·p₄, and K is divided by K₂₂. The cameras come out in the
//! normalised frame. IDR and NeuS cast the ray of pixel (i, j) through (i, j) of K's image
//! coordinates, where phygap puts pixel centres at (i + 0.5, j + 0.5): the principal point is
//! shifted by half a pixel so the rays are the same.

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::core::camera::{Camera, CameraConvention, Intrinsics};

/// Camera files of the layout, in the order one is chosen when several are present: NeuS's
/// normalised cameras first.
pub const CAMERA_FILES: [&str; 3] = ["cameras_sphere.npz", "cameras_new.npz", "cameras.npz"];

/// Skew above this fraction of the focal length is refused (phygap's cameras have none).
const MAX_RELATIVE_SKEW: f64 = 1e-3;

/// A projection matrix decomposed: intrinsics K (K₂₂ = 1), world-to-camera rotation R (OpenCV
/// axes) and camera centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decomposed {
    pub k: DMat3,
    pub rotation: DMat3,
    pub centre: DVec3,
}

/// The rows of the top 3×4 block of `p`.
fn rows3x4(p: &DMat4) -> [DVec4; 3] {
    [p.row(0), p.row(1), p.row(2)]
}

/// Decomposes the 3×4 projection in the top rows of `p` (OpenCV's decomposeProjectionMatrix up
/// to the sign of P); `None` when its left 3×3 block is singular or not finite.
pub fn decompose_projection(p: &DMat4) -> Option<Decomposed> {
    let [r0, r1, r2] = rows3x4(p);
    let mut m = [r0.truncate(), r1.truncate(), r2.truncate()];
    let mut p4 = DVec3::new(r0.w, r1.w, r2.w);
    let det = DMat3::from_cols(m[0], m[1], m[2]).transpose().determinant();
    if !det.is_finite() || det.abs() < 1e-300 {
        return None;
    }
    if det < 0.0 {
        m = m.map(|row| -row);
        p4 = -p4;
    }
    // RQ by Gram–Schmidt from the last row up: M = K·R with R's rows orthonormal.
    let k22 = m[2].length();
    let q2 = m[2] / k22;
    let k12 = m[1].dot(q2);
    let u1 = m[1] - k12 * q2;
    let k11 = u1.length();
    let q1 = u1 / k11;
    let k02 = m[0].dot(q2);
    let k01 = m[0].dot(q1);
    let u0 = m[0] - k02 * q2 - k01 * q1;
    let k00 = u0.length();
    let q0 = u0 / k00;
    let rotation = DMat3::from_cols(q0, q1, q2).transpose();
    let m_matrix = DMat3::from_cols(m[0], m[1], m[2]).transpose();
    let centre = -(m_matrix.inverse() * p4);
    let k = DMat3::from_cols(
        DVec3::new(k00, 0.0, 0.0),
        DVec3::new(k01, k11, 0.0),
        DVec3::new(k02, k12, k22),
    ) * (1.0 / k22);
    let finite = k.is_finite() && rotation.is_finite() && centre.is_finite();
    finite.then_some(Decomposed {
        k,
        rotation,
        centre,
    })
}

/// The phygap camera of a view of `width × height` from its `world_mat` and `scale_mat`
/// (identity when absent), or why it cannot be one.
pub fn camera_from_matrices(
    world_mat: &DMat4,
    scale_mat: &DMat4,
    width: u32,
    height: u32,
) -> Result<Camera, String> {
    let p = *world_mat * *scale_mat;
    let d = decompose_projection(&p).ok_or_else(|| {
        "world_mat · scale_mat is singular or not finite: not a projection matrix".to_owned()
    })?;
    let (fx, fy, skew) = (d.k.x_axis.x, d.k.y_axis.y, d.k.y_axis.x);
    if skew.abs() > MAX_RELATIVE_SKEW * fx {
        return Err(format!(
            "the camera has a skew of {skew:.4} px (focal length {fx:.2} px); phygap's pinhole \
             cameras have none"
        ));
    }
    let c2w = DMat4::from_cols(
        d.rotation.row(0).extend(0.0),
        d.rotation.row(1).extend(0.0),
        d.rotation.row(2).extend(0.0),
        d.centre.extend(1.0),
    );
    let intrinsics = Intrinsics {
        width,
        height,
        fx,
        fy,
        cx: d.k.z_axis.x + 0.5,
        cy: d.k.z_axis.y + 0.5,
    };
    Ok(Camera::new(intrinsics, c2w, CameraConvention::OpenCV))
}

/// The `world_mat` of `camera` in the world frame where normalised points x map to
/// `scale · x + offset` (the inverse of [`camera_from_matrices`] with that `scale_mat`).
pub fn world_mat_of(camera: &Camera, scale: f64, offset: DVec3) -> DMat4 {
    let (w2c, _) = camera.world_to_camera_opencv();
    let centre_world = scale * camera.origin() + offset;
    let t = -(w2c * centre_world);
    let k = DMat3::from_cols(
        DVec3::new(camera.fx, 0.0, 0.0),
        DVec3::new(0.0, camera.fy, 0.0),
        DVec3::new(camera.cx - 0.5, camera.cy - 0.5, 1.0),
    );
    let kr = k * w2c;
    let kt = k * t;
    DMat4::from_cols(
        kr.x_axis.extend(0.0),
        kr.y_axis.extend(0.0),
        kr.z_axis.extend(0.0),
        kt.extend(1.0),
    )
}

/// The `scale_mat` mapping normalised points x to `scale · x + offset`.
pub fn scale_mat(scale: f64, offset: DVec3) -> DMat4 {
    DMat4::from_cols(
        DVec4::new(scale, 0.0, 0.0, 0.0),
        DVec4::new(0.0, scale, 0.0, 0.0),
        DVec4::new(0.0, 0.0, scale, 0.0),
        offset.extend(1.0),
    )
}

/// A 4×4 matrix from 16 row-major values (as NumPy stores a C-order 4×4 array).
pub fn mat4_from_rows(values: &[f64]) -> DMat4 {
    DMat4::from_cols_array(&std::array::from_fn(|i| values[(i % 4) * 4 + i / 4]))
}

/// The 16 row-major values of a 4×4 matrix.
pub fn rows_of_mat4(m: &DMat4) -> Vec<f64> {
    (0..4).flat_map(|r| m.row(r).to_array()).collect()
}

//! Pinhole cameras, pixel rays and the per-pixel Stokes reference frame.
//!
//! Conventions (DATA_FORMAT.md §3, CAPTURE_FORMAT.md §4): the camera-to-world matrix is kept in
//! OpenGL axes (+X right, +Y up, looking along −Z); pixel (i, j) has its centre at (i + 0.5, j + 0.5)
//! with row 0 on top; projection and back-projection use the OpenCV axes
//! `R_cv = R_gl · diag(1, −1, −1)`. All math is f64: the cpu backend and the gradient tests share it.

use glam::{DMat3, DMat4, DVec3};
use serde::{Deserialize, Serialize};

/// Image size, focal lengths and principal point, in pixels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Intrinsics {
    pub width: u32,
    pub height: u32,
    pub fx: f64,
    pub fy: f64,
    pub cx: f64,
    pub cy: f64,
}

/// A pinhole camera with square or non-square pixels and a principal point.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Focal length along x, in pixels.
    pub fx: f64,
    /// Focal length along y, in pixels.
    pub fy: f64,
    /// Principal point x, in pixels.
    pub cx: f64,
    /// Principal point y, in pixels.
    pub cy: f64,
    /// Camera-to-world transform in OpenGL axes.
    pub c2w: DMat4,
}

/// The axes of a camera-to-world matrix as given by a capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum CameraConvention {
    /// +X right, +Y up, looking along −Z (nerfstudio, Blender).
    OpenGL,
    /// +X right, +Y down, looking along +Z.
    OpenCV,
}

/// `diag(1, −1, −1, 1)`: converts between OpenGL and OpenCV camera axes (it is its own inverse).
const FLIP_YZ: DMat4 = DMat4::from_cols_array(&[
    1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
]);

impl Camera {
    /// Builds a camera from a camera-to-world matrix in the given convention.
    pub fn new(intrinsics: Intrinsics, c2w: DMat4, convention: CameraConvention) -> Self {
        let c2w = match convention {
            CameraConvention::OpenGL => c2w,
            CameraConvention::OpenCV => c2w * FLIP_YZ,
        };
        let Intrinsics {
            width,
            height,
            fx,
            fy,
            cx,
            cy,
        } = intrinsics;
        Camera {
            width,
            height,
            fx,
            fy,
            cx,
            cy,
            c2w,
        }
    }

    /// The camera's intrinsics.
    pub fn intrinsics(&self) -> Intrinsics {
        Intrinsics {
            width: self.width,
            height: self.height,
            fx: self.fx,
            fy: self.fy,
            cx: self.cx,
            cy: self.cy,
        }
    }

    /// A camera at `eye` looking at `target`, with `up` as the approximate image-up direction.
    pub fn look_at(
        width: u32,
        height: u32,
        fov_x_rad: f64,
        eye: DVec3,
        target: DVec3,
        up: DVec3,
    ) -> Self {
        let back = (eye - target).normalize();
        let right = up.cross(back).normalize();
        let cam_up = back.cross(right);
        let c2w = DMat4::from_cols(
            right.extend(0.0),
            cam_up.extend(0.0),
            back.extend(0.0),
            eye.extend(1.0),
        );
        let f = 0.5 * width as f64 / (0.5 * fov_x_rad).tan();
        let intrinsics = Intrinsics {
            width,
            height,
            fx: f,
            fy: f,
            cx: width as f64 / 2.0,
            cy: height as f64 / 2.0,
        };
        Camera::new(intrinsics, c2w, CameraConvention::OpenGL)
    }

    /// Camera centre in world coordinates.
    pub fn origin(&self) -> DVec3 {
        self.c2w.w_axis.truncate()
    }

    /// The camera's up vector (second column of the OpenGL matrix).
    pub fn up(&self) -> DVec3 {
        self.c2w.y_axis.truncate()
    }

    /// The viewing direction (−Z of the OpenGL axes).
    pub fn forward(&self) -> DVec3 {
        -self.c2w.z_axis.truncate()
    }

    /// This camera's intrinsics at another pose: its OpenCV axes (the columns of `axes`: right,
    /// down, forward, in world coordinates) and its centre `origin`.
    pub fn placed(&self, axes: DMat3, origin: DVec3) -> Camera {
        let c2w = DMat4::from_cols(
            axes.x_axis.extend(0.0),
            axes.y_axis.extend(0.0),
            axes.z_axis.extend(0.0),
            origin.extend(1.0),
        );
        Camera::new(self.intrinsics(), c2w, CameraConvention::OpenCV)
    }

    /// Rotation whose columns are the OpenCV camera axes (right, down, forward) in world coordinates.
    pub fn rotation_opencv(&self) -> DMat3 {
        let r = DMat3::from_mat4(self.c2w);
        DMat3::from_cols(r.x_axis, -r.y_axis, -r.z_axis)
    }

    /// World-to-camera transform in OpenCV axes (z = depth along the viewing axis).
    pub fn world_to_camera_opencv(&self) -> (DMat3, DVec3) {
        let rt = self.rotation_opencv().transpose();
        (rt, -(rt * self.origin()))
    }

    /// A world point in OpenCV camera coordinates.
    pub fn to_camera(&self, x: DVec3) -> DVec3 {
        self.rotation_opencv().transpose() * (x - self.origin())
    }

    /// Projects a world point to continuous pixel coordinates `(u, v)` and its z-depth.
    /// Returns `None` for points at or behind the camera plane.
    pub fn project(&self, x: DVec3) -> Option<(f64, f64, f64)> {
        let c = self.to_camera(x);
        (c.z > 1e-12).then(|| {
            (
                self.fx * c.x / c.z + self.cx,
                self.fy * c.y / c.z + self.cy,
                c.z,
            )
        })
    }

    /// Unnormalized OpenCV camera-space direction through continuous pixel coordinates (z = 1).
    pub fn camera_dir(&self, u: f64, v: f64) -> DVec3 {
        DVec3::new((u - self.cx) / self.fx, (v - self.cy) / self.fy, 1.0)
    }

    /// Unit world direction of the ray through continuous pixel coordinates `(u, v)`.
    pub fn ray_dir(&self, u: f64, v: f64) -> DVec3 {
        (self.rotation_opencv() * self.camera_dir(u, v)).normalize()
    }

    /// Unit world direction of the ray through the centre of pixel (column `i`, row `j`).
    pub fn pixel_dir(&self, i: u32, j: u32) -> DVec3 {
        self.ray_dir(i as f64 + 0.5, j as f64 + 0.5)
    }

    /// World point seen at pixel coordinates `(u, v)` with the given z-depth.
    pub fn backproject(&self, u: f64, v: f64, depth: f64) -> DVec3 {
        self.origin() + self.rotation_opencv() * (self.camera_dir(u, v) * depth)
    }

    /// Per-pixel Stokes reference axes `(x̂, ŷ)` for a unit ray direction `d` (CAPTURE_FORMAT.md §4):
    /// `x̂ = normalize(d × up)`, `ŷ = x̂ × d`.
    pub fn stokes_frame(&self, d: DVec3) -> (DVec3, DVec3) {
        stokes_frame(d, self.up())
    }

    /// Number of pixels.
    pub fn num_pixels(&self) -> usize {
        self.width as usize * self.height as usize
    }
}

/// Stokes reference axes for a ray direction `d` and a camera up vector.
pub fn stokes_frame(d: DVec3, up: DVec3) -> (DVec3, DVec3) {
    let x = d.cross(up).normalize();
    (x, x.cross(d))
}

/// True when `m` is a finite rigid transform: orthonormal rotation (det +1), last row (0, 0, 0, 1).
pub fn is_rigid(m: &DMat4, tolerance: f64) -> bool {
    if !m.to_cols_array().iter().all(|v| v.is_finite()) {
        return false;
    }
    let r = DMat3::from_mat4(*m);
    let should_be_identity = r.transpose() * r;
    let orthonormal = should_be_identity.abs_diff_eq(DMat3::IDENTITY, tolerance);
    let last_row = DVec3::new(m.x_axis.w, m.y_axis.w, m.z_axis.w);
    orthonormal
        && (r.determinant() - 1.0).abs() < tolerance
        && last_row.abs().max_element() < tolerance
        && (m.w_axis.w - 1.0).abs() < tolerance
}

#[cfg(test)]
mod tests {
    use super::*;

    fn intrinsics() -> Intrinsics {
        Intrinsics {
            width: 256,
            height: 256,
            fx: 351.677,
            fy: 351.677,
            cx: 128.0,
            cy: 128.0,
        }
    }

    /// Example 1 of DATA_FORMAT.md §3: camera at (0, −4, 0), image right = +X, image up = +Z.
    fn example_camera() -> Camera {
        let m = DMat4::from_cols_array_2d(&[
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0, 0.0],
            [0.0, -4.0, 0.0, 1.0],
        ]);
        Camera::new(intrinsics(), m, CameraConvention::OpenGL)
    }

    #[test]
    fn example_camera_axes_match_the_data_format() {
        let cam = example_camera();
        assert!(cam.origin().abs_diff_eq(DVec3::new(0.0, -4.0, 0.0), 1e-12));
        assert!(cam.forward().abs_diff_eq(DVec3::Y, 1e-12));
        let d = cam.ray_dir(128.0, 128.0);
        assert!(d.abs_diff_eq(DVec3::Y, 1e-12));
        let (x, y) = cam.stokes_frame(d);
        assert!(
            x.abs_diff_eq(DVec3::X, 1e-12),
            "x̂ = image right = +X, got {x}"
        );
        assert!(y.abs_diff_eq(DVec3::Z, 1e-12), "ŷ = image up = +Z, got {y}");
        // A point above the origin projects above the image centre (smaller row).
        let (u, v, z) = cam.project(DVec3::new(0.0, 0.0, 0.5)).unwrap();
        assert!((u - 128.0).abs() < 1e-9 && v < 128.0 && (z - 4.0).abs() < 1e-12);
    }

    #[test]
    fn project_and_backproject_are_inverse() {
        let cam = Camera::look_at(
            64,
            48,
            0.8,
            DVec3::new(1.0, -3.0, 2.0),
            DVec3::ZERO,
            DVec3::Z,
        );
        for p in [DVec3::new(0.1, 0.2, -0.3), DVec3::new(-0.5, 0.4, 0.2)] {
            let (u, v, z) = cam.project(p).unwrap();
            assert!(cam.backproject(u, v, z).abs_diff_eq(p, 1e-9));
            let d = cam.ray_dir(u, v);
            assert!(d.abs_diff_eq((p - cam.origin()).normalize(), 1e-9));
        }
    }

    #[test]
    fn opencv_convention_is_converted() {
        let gl = example_camera();
        let cv = Camera::new(intrinsics(), gl.c2w * FLIP_YZ, CameraConvention::OpenCV);
        assert!(cv.c2w.abs_diff_eq(gl.c2w, 1e-12));
    }

    #[test]
    fn rigidity_check_rejects_scaled_and_nan_matrices() {
        let cam = example_camera();
        assert!(is_rigid(&cam.c2w, 1e-6));
        assert!(!is_rigid(
            &(cam.c2w * DMat4::from_scale(DVec3::splat(2.0))),
            1e-3
        ));
        let mut nan = cam.c2w;
        nan.x_axis.x = f64::NAN;
        assert!(!is_rigid(&nan, 1e-3));
    }
}

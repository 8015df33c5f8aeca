//! Cameras of the LLFF layout: `poses_bounds.npy`, an N × 17 array, one row a view (in the name
//! order of its images): a row-major 3 × 5 matrix [R | t | hwf] and the near/far depth bounds.
//! R's columns are the camera's down, right and backward axes in world coordinates (LLFF's order),
//! t the camera centre, and hwf the height, width and focal length in pixels of the images the
//! poses were computed for.
//!
//! phygap's OpenGL camera-to-world matrix is [right, −down, backward | t]. Images of another size
//! than hwf's (LLFF's downscaled `images_4`) scale the focal length by their width over hwf's;
//! the principal point is the image centre.

use glam::{DMat4, DVec3};

use crate::core::camera::{Camera, CameraConvention, Intrinsics};

/// The poses file of the layout.
pub const POSES_FILE: &str = "poses_bounds.npy";

/// Values a view has in `poses_bounds.npy`.
pub const ROW_LENGTH: usize = 17;

/// One view of `poses_bounds.npy`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LlffPose {
    /// Columns down, right, backward (LLFF's order), camera centre.
    pub down: DVec3,
    pub right: DVec3,
    pub back: DVec3,
    pub centre: DVec3,
    pub height: f64,
    pub width: f64,
    pub focal: f64,
    pub near: f64,
    pub far: f64,
}

impl LlffPose {
    /// Reads one 17-value row.
    pub fn from_row(row: &[f64]) -> LlffPose {
        let column = |c: usize| DVec3::new(row[c], row[5 + c], row[10 + c]);
        LlffPose {
            down: column(0),
            right: column(1),
            back: column(2),
            centre: column(3),
            height: row[4],
            width: row[9],
            focal: row[14],
            near: row[15],
            far: row[16],
        }
    }

    /// The 17 values of its row.
    pub fn to_row(&self) -> [f64; ROW_LENGTH] {
        let mut row = [0.0; ROW_LENGTH];
        for (c, v) in [self.down, self.right, self.back, self.centre]
            .iter()
            .enumerate()
        {
            row[c] = v.x;
            row[5 + c] = v.y;
            row[10 + c] = v.z;
        }
        row[4] = self.height;
        row[9] = self.width;
        row[14] = self.focal;
        row[15] = self.near;
        row[16] = self.far;
        row
    }

    /// The pose of `camera` (square pixels: its `fx`), with the given bounds.
    pub fn of_camera(camera: &Camera, near: f64, far: f64) -> LlffPose {
        let axis = |c: usize| camera.c2w.col(c).truncate();
        LlffPose {
            down: -axis(1),
            right: axis(0),
            back: axis(2),
            centre: camera.origin(),
            height: f64::from(camera.height),
            width: f64::from(camera.width),
            focal: camera.fx,
            near,
            far,
        }
    }

    /// The phygap camera for images of `width × height`, or why there is none.
    pub fn camera(&self, width: u32, height: u32) -> Result<Camera, String> {
        if !(self.focal > 0.0 && self.width > 0.0 && self.height > 0.0) {
            return Err(format!(
                "hwf = ({}, {}, {}): height, width and focal length must be positive",
                self.height, self.width, self.focal
            ));
        }
        let scale = f64::from(width) / self.width;
        let aspect_error =
            (f64::from(height) / self.height - scale).abs() / scale.max(f64::MIN_POSITIVE);
        if aspect_error > 0.01 {
            return Err(format!(
                "the images are {width}×{height} but hwf says {}×{}: another aspect ratio",
                self.width, self.height
            ));
        }
        let focal = self.focal * scale;
        let c2w = DMat4::from_cols(
            self.right.extend(0.0),
            (-self.down).extend(0.0),
            self.back.extend(0.0),
            self.centre.extend(1.0),
        );
        let intrinsics = Intrinsics {
            width,
            height,
            fx: focal,
            fy: focal,
            cx: f64::from(width) / 2.0,
            cy: f64::from(height) / 2.0,
        };
        Ok(Camera::new(intrinsics, c2w, CameraConvention::OpenGL))
    }
}

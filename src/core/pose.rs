//! Learned corrections of a view's camera pose (pose refinement): a small rigid motion in the
//! camera's own OpenCV axes, `x_c' = exp([ω]×) x_c + τ`, that moves what the camera sees without
//! moving the scene.
//!
//! The rasterizer's backward pass returns the gradient of a loss with respect to a correction at
//! zero, `(dL/dω, dL/dτ)` ([`crate::core::raster::RasterGrads::pose`]): a surfel's camera-space
//! centre `c` and tangent axes `a`, `b` move by `ω × c + τ`, `ω × a`, `ω × b`, so
//! `dL/dω = Σ a × g_a + b × g_b + c × g_c` and `dL/dτ = Σ g_c` over the projected surfels. It is
//! the gradient *through the projection*: the shading's view directions and the depth normals'
//! pixel rays also follow the camera, and are not differentiated (second order for corrections of
//! a fraction of a degree).

use glam::{DMat3, DQuat, DVec3};
use serde::{Deserialize, Serialize};

use crate::core::camera::Camera;

/// A rigid correction of a camera: rotation vector `ω` (radians) and translation `τ` (scene
/// units), both in the camera's OpenCV axes (x right, y down, z forward).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PoseCorrection {
    pub rotation: [f64; 3],
    pub translation: [f64; 3],
}

/// A gradient with respect to a [`PoseCorrection`]: rotation (3), then translation (3).
pub type PoseGrad = [f64; 6];

impl PoseCorrection {
    /// No correction.
    pub const IDENTITY: PoseCorrection = PoseCorrection {
        rotation: [0.0; 3],
        translation: [0.0; 3],
    };

    /// Rotation then translation, the layout of [`PoseGrad`].
    pub fn to_array(self) -> [f64; 6] {
        let [a, b, c] = self.rotation;
        let [d, e, f] = self.translation;
        [a, b, c, d, e, f]
    }

    pub fn from_array(v: [f64; 6]) -> Self {
        PoseCorrection {
            rotation: [v[0], v[1], v[2]],
            translation: [v[3], v[4], v[5]],
        }
    }

    /// The rotation's angle in degrees.
    pub fn angle_deg(&self) -> f64 {
        DVec3::from_array(self.rotation).length().to_degrees()
    }

    /// The correction that moves `camera` to where `moved` is: `between(c, m).apply(c)` is `m`
    /// (up to rounding) for cameras with the same intrinsics.
    pub fn between(camera: &Camera, moved: &Camera) -> PoseCorrection {
        let (r, t) = camera.world_to_camera_opencv();
        let (r_moved, t_moved) = moved.world_to_camera_opencv();
        let e = r_moved * r.transpose();
        PoseCorrection {
            rotation: DQuat::from_mat3(&e).to_scaled_axis().to_array(),
            translation: (t_moved - e * t).to_array(),
        }
    }

    /// `camera` moved by this correction (intrinsics unchanged).
    pub fn apply(&self, camera: &Camera) -> Camera {
        if *self == PoseCorrection::IDENTITY {
            return *camera;
        }
        let (r, t) = camera.world_to_camera_opencv();
        let e = rotation_matrix(DVec3::from_array(self.rotation));
        let r_new = e * r;
        let t_new = e * t + DVec3::from_array(self.translation);
        // Camera-to-world in OpenCV axes: rotation R'ᵀ, origin −R'ᵀ t'.
        let rt = r_new.transpose();
        camera.placed(rt, -(rt * t_new))
    }
}

/// `exp([ω]×)`: the rotation by `|ω|` radians about `ω`.
pub fn rotation_matrix(omega: DVec3) -> DMat3 {
    DMat3::from_quat(DQuat::from_scaled_axis(omega))
}

/// The error of `camera`'s pose against `truth`'s: the angle of the relative rotation (degrees)
/// and the distance between their centres (scene units).
pub fn pose_error(camera: &Camera, truth: &Camera) -> (f64, f64) {
    let relative = camera.rotation_opencv().transpose() * truth.rotation_opencv();
    let cos =
        ((relative.x_axis.x + relative.y_axis.y + relative.z_axis.z - 1.0) / 2.0).clamp(-1.0, 1.0);
    (
        cos.acos().to_degrees(),
        (camera.origin() - truth.origin()).length(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_camera(rng: &mut ChaCha8Rng) -> Camera {
        let eye = DVec3::new(
            rng.random_range(-3.0..3.0),
            rng.random_range(-3.0..3.0),
            rng.random_range(1.0..3.0),
        );
        Camera::look_at(40, 30, 0.8, eye, DVec3::ZERO, DVec3::Z)
    }

    fn random_correction(rng: &mut ChaCha8Rng, size: f64) -> PoseCorrection {
        PoseCorrection {
            rotation: std::array::from_fn(|_| rng.random_range(-size..size)),
            translation: std::array::from_fn(|_| rng.random_range(-size..size)),
        }
    }

    #[test]
    fn a_correction_moves_camera_coordinates_by_the_rigid_motion() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        for _ in 0..10 {
            let camera = random_camera(&mut rng);
            let c = random_correction(&mut rng, 0.3);
            let moved = c.apply(&camera);
            let e = rotation_matrix(DVec3::from_array(c.rotation));
            let x = DVec3::new(rng.random_range(-1.0..1.0), 0.3, -0.2);
            let expected = e * camera.to_camera(x) + DVec3::from_array(c.translation);
            assert!(moved.to_camera(x).abs_diff_eq(expected, 1e-12));
            assert_eq!(moved.fx, camera.fx);
        }
        let camera = random_camera(&mut rng);
        assert_eq!(PoseCorrection::IDENTITY.apply(&camera), camera);
    }

    #[test]
    fn the_correction_between_two_cameras_moves_one_onto_the_other() {
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        for _ in 0..10 {
            let camera = random_camera(&mut rng);
            let c = random_correction(&mut rng, 0.3);
            let moved = c.apply(&camera);
            let found = PoseCorrection::between(&camera, &moved);
            for (a, b) in found.to_array().iter().zip(c.to_array()) {
                assert!((a - b).abs() < 1e-10, "{found:?} against {c:?}");
            }
        }
    }

    #[test]
    fn rodrigues_is_a_rotation_by_the_vector_length() {
        let omega = DVec3::new(0.3, -0.2, 0.5);
        let r = rotation_matrix(omega);
        assert!((r * r.transpose()).abs_diff_eq(DMat3::IDENTITY, 1e-12));
        assert!((r * omega).abs_diff_eq(omega, 1e-12));
        let camera = Camera::look_at(8, 8, 0.8, DVec3::new(0.0, -3.0, 0.0), DVec3::ZERO, DVec3::Z);
        let turned = PoseCorrection {
            rotation: omega.to_array(),
            translation: [0.0; 3],
        }
        .apply(&camera);
        let (angle, distance) = pose_error(&turned, &camera);
        assert!((angle - omega.length().to_degrees()).abs() < 1e-9);
        assert!(distance < 1e-12, "a rotation about the centre keeps it");
    }
}

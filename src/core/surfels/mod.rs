//! 2D Gaussian surfels: raw (unconstrained) parameters and their activations (METHOD.md §2).
//!
//! Parameters are stored structure-of-arrays so the optimizer can treat each group as one flat
//! slice. Gradients with respect to the raw parameters use the same layout ([`SurfelGrads`]).

pub mod ply;

use glam::{DMat3, DQuat, DVec2, DVec3};

use crate::core::filled::filled;
use crate::core::similarity::Similarity;

/// Offset of the IoR activation: η = `IOR_MIN` + sigmoid(raw), so η ∈ (1.3, 2.3).
pub const IOR_MIN: f64 = 1.3;

/// Raw parameters of N surfels.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Surfels {
    /// Centres in world coordinates.
    pub position: Vec<[f64; 3]>,
    /// Log of the two tangent scales (s_u, s_v = exp(·)).
    pub log_scale: Vec<[f64; 2]>,
    /// Rotation quaternion (w, x, y, z), normalized on activation.
    pub rotation: Vec<[f64; 4]>,
    /// Opacity logit (o = sigmoid(·)).
    pub opacity: Vec<f64>,
    /// Albedo logits (λ = sigmoid(·) per channel).
    pub albedo: Vec<[f64; 3]>,
    /// Roughness logit (r = sigmoid(·)).
    pub roughness: Vec<f64>,
    /// IoR logit (η = 1.3 + sigmoid(·)).
    pub ior: Vec<f64>,
}

/// Gradients of a loss with respect to the raw parameters, laid out like [`Surfels`].
pub type SurfelGrads = Surfels;

/// One surfel with activated parameters, as the renderer uses it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surfel {
    pub position: DVec3,
    /// Tangent scales (s_u, s_v).
    pub scale: DVec2,
    /// Columns: tangent t_u, tangent t_v, normal t_u × t_v (not yet flipped toward a camera).
    pub rotation: DMat3,
    pub opacity: f64,
    pub albedo: DVec3,
    pub roughness: f64,
    pub ior: f64,
}

pub fn sigmoid(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

/// Inverse of [`sigmoid`]; the argument is clamped into (1e-6, 1 − 1e-6).
pub fn logit(p: f64) -> f64 {
    let p = p.clamp(1e-6, 1.0 - 1e-6);
    (p / (1.0 - p)).ln()
}

/// Rotation matrix of a (not necessarily unit) quaternion stored as (w, x, y, z).
pub fn rotation_matrix(q: [f64; 4]) -> DMat3 {
    DMat3::from_quat(DQuat::from_xyzw(q[1], q[2], q[3], q[0]).normalize())
}

/// Keeps the entries of a per-surfel array whose flag in `keep` is true, in order (entries past
/// the end of `keep` are kept).
pub fn retain_flagged<T>(values: &mut Vec<T>, keep: &[bool]) {
    let mut k = keep.iter();
    values.retain(|_| *k.next().unwrap_or(&true));
}

impl Surfels {
    /// N surfels with every parameter zero (the layout of a gradient buffer).
    pub fn zeros(n: usize) -> Self {
        Surfels {
            position: filled(n, [0.0; 3]),
            log_scale: filled(n, [0.0; 2]),
            rotation: filled(n, [0.0; 4]),
            opacity: filled(n, 0.0),
            albedo: filled(n, [0.0; 3]),
            roughness: filled(n, 0.0),
            ior: filled(n, 0.0),
        }
    }

    pub fn len(&self) -> usize {
        self.position.len()
    }

    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// Appends one surfel given activated values (inverse activations are applied here).
    pub fn push_activated(&mut self, surfel: &Surfel) {
        let Surfel {
            position,
            scale,
            rotation,
            opacity,
            albedo,
            roughness,
            ior,
        } = *surfel;
        self.position.push(position.to_array());
        self.log_scale.push([scale.x.ln(), scale.y.ln()]);
        let q = DQuat::from_mat3(&rotation).normalize();
        self.rotation.push([q.w, q.x, q.y, q.z]);
        self.opacity.push(logit(opacity));
        self.albedo
            .push([logit(albedo.x), logit(albedo.y), logit(albedo.z)]);
        self.roughness.push(logit(roughness));
        self.ior.push(logit(ior - IOR_MIN));
    }

    /// The activated parameters of surfel `i`.
    pub fn get(&self, i: usize) -> Surfel {
        let [su, sv] = self.log_scale[i];
        let a = self.albedo[i];
        Surfel {
            position: DVec3::from_array(self.position[i]),
            scale: DVec2::new(su.exp(), sv.exp()),
            rotation: rotation_matrix(self.rotation[i]),
            opacity: sigmoid(self.opacity[i]),
            albedo: DVec3::new(sigmoid(a[0]), sigmoid(a[1]), sigmoid(a[2])),
            roughness: sigmoid(self.roughness[i]),
            ior: IOR_MIN + sigmoid(self.ior[i]),
        }
    }

    /// Keeps the surfels whose flag is true, in order.
    pub fn retain(&mut self, keep: &[bool]) {
        assert_eq!(keep.len(), self.len(), "one flag per surfel");
        retain_flagged(&mut self.position, keep);
        retain_flagged(&mut self.log_scale, keep);
        retain_flagged(&mut self.rotation, keep);
        retain_flagged(&mut self.opacity, keep);
        retain_flagged(&mut self.albedo, keep);
        retain_flagged(&mut self.roughness, keep);
        retain_flagged(&mut self.ior, keep);
    }

    /// Appends copies of the surfels at `indices`.
    pub fn extend_from_indices(&mut self, indices: &[usize]) {
        for &i in indices {
            self.position.push(self.position[i]);
            self.log_scale.push(self.log_scale[i]);
            self.rotation.push(self.rotation[i]);
            self.opacity.push(self.opacity[i]);
            self.albedo.push(self.albedo[i]);
            self.roughness.push(self.roughness[i]);
            self.ior.push(self.ior[i]);
        }
    }

    /// Every parameter group as a flat mutable slice, with its name (for the optimizer).
    pub fn groups_mut(&mut self) -> [(&'static str, &mut [f64]); 7] {
        [
            ("position", self.position.as_flattened_mut()),
            ("scale", self.log_scale.as_flattened_mut()),
            ("rotation", self.rotation.as_flattened_mut()),
            ("opacity", &mut self.opacity[..]),
            ("albedo", self.albedo.as_flattened_mut()),
            ("roughness", &mut self.roughness[..]),
            ("ior", &mut self.ior[..]),
        ]
    }

    /// Every parameter group as a flat slice, in the order of [`Surfels::groups_mut`].
    pub fn groups(&self) -> [(&'static str, &[f64]); 7] {
        [
            ("position", self.position.as_flattened()),
            ("scale", self.log_scale.as_flattened()),
            ("rotation", self.rotation.as_flattened()),
            ("opacity", &self.opacity[..]),
            ("albedo", self.albedo.as_flattened()),
            ("roughness", &self.roughness[..]),
            ("ior", &self.ior[..]),
        ]
    }

    /// Moves every surfel with the scene by `motion`: centres carried, tangent frames turned,
    /// extents scaled (the materials stay).
    pub fn move_by(&mut self, motion: &Similarity) {
        let log_scale = motion.scale.ln();
        for p in &mut self.position {
            *p = motion.apply(DVec3::from_array(*p)).to_array();
        }
        for s in &mut self.log_scale {
            *s = s.map(|v| v + log_scale);
        }
        for q in &mut self.rotation {
            let turned = motion.rotation * DQuat::from_xyzw(q[1], q[2], q[3], q[0]);
            *q = [turned.w, turned.x, turned.y, turned.z];
        }
    }

    /// True when every parameter is finite.
    pub fn is_finite(&self) -> bool {
        self.groups()
            .iter()
            .all(|(_, g)| g.iter().all(|v| v.is_finite()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One surfel turned off the axes, with materials away from their activations' middles.
    fn a_surfel() -> Surfel {
        let q = DQuat::from_rotation_z(0.3) * DQuat::from_rotation_x(-1.1);
        Surfel {
            position: DVec3::new(0.1, -0.2, 0.3),
            scale: DVec2::new(0.02, 0.05),
            rotation: DMat3::from_quat(q),
            opacity: 0.7,
            albedo: DVec3::new(0.5, 0.18, 0.08),
            roughness: 0.1,
            ior: 1.8,
        }
    }

    #[test]
    fn moving_surfels_moves_their_activated_frames() {
        let mut s = Surfels::default();
        let before = a_surfel();
        s.push_activated(&before);
        let motion = Similarity {
            rotation: DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 0.7),
            scale: 1.3,
            translation: DVec3::new(0.2, 0.0, -1.0),
        };
        s.move_by(&motion);
        let after = s.get(0);
        assert!(after
            .position
            .abs_diff_eq(motion.apply(before.position), 1e-12));
        assert!(after.scale.abs_diff_eq(1.3 * before.scale, 1e-12));
        let turned = DMat3::from_quat(motion.rotation) * before.rotation;
        assert!(after.rotation.abs_diff_eq(turned, 1e-12));
        assert!((after.opacity - before.opacity).abs() < 1e-12);
        assert!(after.albedo.abs_diff_eq(before.albedo, 1e-12));
    }

    #[test]
    fn activations_invert_the_initial_values() {
        let mut s = Surfels::default();
        let q = DQuat::from_rotation_z(0.3) * DQuat::from_rotation_x(-1.1);
        s.push_activated(&a_surfel());
        let a = s.get(0);
        assert!((a.scale - DVec2::new(0.02, 0.05)).abs().max_element() < 1e-12);
        assert!((a.opacity - 0.7).abs() < 1e-12);
        assert!((a.roughness - 0.1).abs() < 1e-12);
        assert!((a.ior - 1.8).abs() < 1e-12);
        assert!((a.albedo - DVec3::new(0.5, 0.18, 0.08)).abs().max_element() < 1e-12);
        let normal = a.rotation.x_axis.cross(a.rotation.y_axis);
        assert!(normal.abs_diff_eq(a.rotation.z_axis, 1e-12));
        assert!(a.rotation.abs_diff_eq(DMat3::from_quat(q), 1e-12));
    }

    #[test]
    fn ior_stays_in_its_range() {
        for raw in [-50.0, 0.0, 50.0] {
            let mut s = Surfels::zeros(1);
            s.ior[0] = raw;
            s.rotation[0] = [1.0, 0.0, 0.0, 0.0];
            let eta = s.get(0).ior;
            assert!((IOR_MIN..=IOR_MIN + 1.0).contains(&eta));
        }
    }

    #[test]
    fn retain_and_extend_keep_groups_aligned() {
        let mut s = Surfels::zeros(4);
        for i in 0..4 {
            s.opacity[i] = i as f64;
            s.position[i] = [i as f64; 3];
        }
        s.retain(&[true, false, true, true]);
        s.extend_from_indices(&[0, 2]);
        assert_eq!(s.opacity, vec![0.0, 2.0, 3.0, 0.0, 3.0]);
        assert_eq!(s.position[4], [3.0; 3]);
        assert_eq!(
            s.groups().iter().map(|(_, g)| g.len()).sum::<usize>(),
            5 * 15
        );
    }
}

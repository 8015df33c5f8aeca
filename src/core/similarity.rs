//! Similarity transforms of a scene (a rotation, a uniform scale and a translation), and the one
//! that best carries one set of cameras onto another.
//!
//! Moving the cameras, the surfels and the distant light by one similarity changes no image: a
//! camera sees `s·R·x + t` where it saw `x`, at `s` times the depth. So a run that refines its
//! poses fixes the frame it ends in only up to such a motion, and its images cannot say which.
//! [`Similarity::between_cameras`] finds the one under which one set of cameras sees the object
//! as another does, on average over the views: Horn's closed-form absolute orientation over
//! points of the object as each pair of cameras places them (the rotation is the dominant
//! eigenvector of a 4×4 symmetric matrix, by Jacobi rotations), with the scale taken from how
//! far apart the cameras stand.

use glam::{DMat3, DQuat, DVec3};

use crate::core::camera::Camera;

/// `x ↦ scale · rotation · x + translation`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    pub rotation: DQuat,
    pub scale: f64,
    pub translation: DVec3,
}

impl Similarity {
    pub const IDENTITY: Similarity = Similarity {
        rotation: DQuat::IDENTITY,
        scale: 1.0,
        translation: DVec3::ZERO,
    };

    /// Where the point `x` goes.
    pub fn apply(&self, x: DVec3) -> DVec3 {
        self.scale * (self.rotation * x) + self.translation
    }

    /// The rotation's angle, degrees.
    pub fn angle_deg(&self) -> f64 {
        self.rotation.angle_between(DQuat::IDENTITY).to_degrees()
    }

    /// `camera` moved with the scene: its centre goes where the point does, its axes turn by the
    /// rotation, and its intrinsics stay (the scale only changes every depth it sees).
    pub fn camera(&self, camera: &Camera) -> Camera {
        let axes = DMat3::from_quat(self.rotation) * camera.rotation_opencv();
        camera.placed(axes, self.apply(camera.origin()))
    }

    /// The similarity that carries the frame of the cameras `from` into the frame of the cameras
    /// `to` (paired in order) so that each pair sees the object alike: every point `x` of the
    /// object (its centre and the six points at `radius` along the axes), seen by camera `to[i]`
    /// at some place in its image and depth, is where `from[i]` would see that place, `z`; the
    /// fit carries the `z` onto the `x` with the least squared error. An error that moves the
    /// image little (a camera turned about the object's centre) counts little, as it does in
    /// the images. The scale is the ratio of the two sets' spreads (a single camera keeps it).
    /// `None` for no pairs, differing counts or non-finite cameras.
    pub fn between_cameras(
        from: &[Camera],
        to: &[Camera],
        centre: DVec3,
        radius: f64,
    ) -> Option<Similarity> {
        if from.is_empty() || from.len() != to.len() || !(radius.is_finite() && radius > 0.0) {
            return None;
        }
        let object: Vec<DVec3> = std::iter::once(centre)
            .chain(
                [DVec3::X, DVec3::Y, DVec3::Z]
                    .into_iter()
                    .flat_map(|axis| [centre + radius * axis, centre - radius * axis]),
            )
            .collect();
        // A camera sees a scene scaled by `s` about anything as it saw it, at `s` times the
        // depth: the scale is in how far apart the cameras stand.
        let depth_scale =
            spread(from)
                .zip(spread(to))
                .map_or(1.0, |(f, t)| if t > 0.0 { f / t } else { 1.0 });
        let (mut z, mut x) = (Vec::new(), Vec::new());
        for (f, t) in from.iter().zip(to) {
            for &point in &object {
                z.push(f.rotation_opencv() * (depth_scale * t.to_camera(point)) + f.origin());
                x.push(point);
            }
        }
        between_points(&z, &x)
    }
}

/// The similarity minimizing `Σ |S(a_i) − b_i|²` (Horn 1987 for the rotation; the scale of the
/// least-squares fit given it). `None` when the points are not finite or all coincide.
pub fn between_points(a: &[DVec3], b: &[DVec3]) -> Option<Similarity> {
    if a.len() != b.len() {
        return None;
    }
    let (mean_a, mean_b) = (mean(a)?, mean(b)?);
    let mut covariance = Covariance::default();
    for (p, q) in a.iter().zip(b) {
        covariance.add(*p - mean_a, *q - mean_b);
    }
    let rotation = covariance.best_rotation()?;
    let scale = least_squares_scale(rotation, a, mean_a, b, mean_b)?;
    Some(Similarity {
        rotation,
        scale,
        translation: mean_b - scale * (rotation * mean_a),
    })
}

/// The RMS distance of the cameras' centres from their mean; `None` when not finite.
fn spread(cameras: &[Camera]) -> Option<f64> {
    let centres: Vec<DVec3> = cameras.iter().map(Camera::origin).collect();
    let mean = mean(&centres)?;
    let sum: f64 = centres.iter().map(|c| (*c - mean).length_squared()).sum();
    Some((sum / centres.len() as f64).sqrt())
}

/// The mean of finite points; `None` for none or a non-finite one.
fn mean(points: &[DVec3]) -> Option<DVec3> {
    (!points.is_empty() && points.iter().all(|p| p.is_finite()))
        .then(|| points.iter().sum::<DVec3>() / points.len() as f64)
}

/// `Σ b'·R a' / Σ |a'|²` over the centred points; `None` when the `a` all coincide.
fn least_squares_scale(
    rotation: DQuat,
    a: &[DVec3],
    mean_a: DVec3,
    b: &[DVec3],
    mean_b: DVec3,
) -> Option<f64> {
    let spread: f64 = a.iter().map(|p| (*p - mean_a).length_squared()).sum();
    let turned: f64 = a
        .iter()
        .zip(b)
        .map(|(p, q)| (rotation * (*p - mean_a)).dot(*q - mean_b))
        .sum();
    let scale = turned / spread;
    (spread > 1e-300 && scale.is_finite() && scale > 0.0).then_some(scale)
}

/// `Σ a bᵀ` over pairs of vectors, and the rotation `R` that maximizes `Σ b·R a`.
#[derive(Default)]
struct Covariance([[f64; 3]; 3]);

impl Covariance {
    fn add(&mut self, a: DVec3, b: DVec3) {
        let (a, b) = (a.to_array(), b.to_array());
        for (row, ai) in self.0.iter_mut().zip(a) {
            for (entry, bj) in row.iter_mut().zip(b) {
                *entry += ai * bj;
            }
        }
    }

    /// Horn's quaternion: the dominant eigenvector of the 4×4 symmetric matrix built from the
    /// covariance. `None` when the vectors were all zero.
    fn best_rotation(&self) -> Option<DQuat> {
        let [[xx, xy, xz], [yx, yy, yz], [zx, zy, zz]] = self.0;
        if self.0.iter().flatten().all(|v| v.abs() < 1e-300) {
            return None;
        }
        let horn = [
            [xx + yy + zz, yz - zy, zx - xz, xy - yx],
            [yz - zy, xx - yy - zz, xy + yx, zx + xz],
            [zx - xz, xy + yx, -xx + yy - zz, yz + zy],
            [xy - yx, zx + xz, yz + zy, -xx - yy + zz],
        ];
        let [w, x, y, z] = dominant_eigenvector(horn);
        let rotation = DQuat::from_xyzw(x, y, z, w).normalize();
        rotation.is_finite().then_some(rotation)
    }
}

/// The eigenvector of the largest eigenvalue of a symmetric 4×4 matrix, by cyclic Jacobi
/// rotations (exact to rounding for a matrix this small).
fn dominant_eigenvector(mut m: [[f64; 4]; 4]) -> [f64; 4] {
    let mut v = [[0.0f64; 4]; 4];
    for (i, row) in v.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    let norm: f64 = m.iter().flatten().map(|x| x * x).sum();
    for _sweep in 0..50 {
        let off: f64 = (0..4)
            .flat_map(|i| (0..4).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| m[i][j] * m[i][j])
            .sum();
        if off <= 1e-30 * norm {
            break;
        }
        for p in 0..3 {
            for q in p + 1..4 {
                if m[p][q].abs() < 1e-300 {
                    continue;
                }
                let theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let sn = t * c;
                let turn = |a: f64, b: f64| (c * a - sn * b, sn * a + c * b);
                // m ← Jᵀ m J and v ← v J, J the rotation in the (p, q) plane.
                for row in m.iter_mut().chain(v.iter_mut()) {
                    (row[p], row[q]) = turn(row[p], row[q]);
                }
                let (row_p, row_q) = (m[p], m[q]);
                m[p] = std::array::from_fn(|k| turn(row_p[k], row_q[k]).0);
                m[q] = std::array::from_fn(|k| turn(row_p[k], row_q[k]).1);
            }
        }
    }
    let largest = (0..4)
        .max_by(|&i, &j| m[i][i].total_cmp(&m[j][j]))
        .unwrap_or(0);
    std::array::from_fn(|k| v[k][largest])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::random_unit;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_similarity(rng: &mut ChaCha8Rng) -> Similarity {
        Similarity {
            rotation: DQuat::from_axis_angle(random_unit(rng), rng.random_range(-3.0..3.0)),
            scale: rng.random_range(0.3..3.0),
            translation: DVec3::new(
                rng.random_range(-2.0..2.0),
                rng.random_range(-2.0..2.0),
                rng.random_range(-2.0..2.0),
            ),
        }
    }

    fn ring(n: usize) -> Vec<Camera> {
        (0..n)
            .map(|k| {
                let a = k as f64 / n as f64 * std::f64::consts::TAU;
                let eye = DVec3::new(3.0 * a.cos(), 3.0 * a.sin(), 1.0 + 0.3 * (3.0 * a).sin());
                Camera::look_at(64, 48, 0.8, eye, DVec3::ZERO, DVec3::Z)
            })
            .collect()
    }

    #[test]
    fn points_moved_by_a_similarity_give_it_back() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..20 {
            let truth = random_similarity(&mut rng);
            let a: Vec<DVec3> = (0..12).map(|_| 2.0 * random_unit(&mut rng)).collect();
            let b: Vec<DVec3> = a.iter().map(|&p| truth.apply(p)).collect();
            let fit = between_points(&a, &b).expect("a fit");
            assert!(fit.rotation.dot(truth.rotation).abs() > 1.0 - 1e-12);
            assert!((fit.scale - truth.scale).abs() < 1e-10);
            assert!(fit.translation.abs_diff_eq(truth.translation, 1e-9));
        }
    }

    #[test]
    fn far_and_large_scenes_fit_as_well() {
        let mut rng = ChaCha8Rng::seed_from_u64(13);
        let truth = Similarity {
            translation: DVec3::new(4000.0, -2500.0, 900.0),
            ..random_similarity(&mut rng)
        };
        let a: Vec<DVec3> = (0..12)
            .map(|_| DVec3::splat(1.0e4) + 300.0 * random_unit(&mut rng))
            .collect();
        let b: Vec<DVec3> = a.iter().map(|&p| truth.apply(p)).collect();
        let fit = between_points(&a, &b).expect("a fit");
        assert!(fit.rotation.angle_between(truth.rotation) < 1e-9);
        assert!((fit.scale / truth.scale - 1.0).abs() < 1e-10);
        for (p, q) in a.iter().zip(&b) {
            assert!(fit.apply(*p).distance(*q) < 1e-6 * q.length());
        }
    }

    #[test]
    fn degenerate_points_give_no_fit() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert_eq!(between_points(&[p, p, p], &[p, p, p]), None);
        assert_eq!(between_points(&[p], &[p, p]), None);
        assert_eq!(between_points(&[p, DVec3::NAN], &[p, p]), None);
    }

    #[test]
    fn a_moved_camera_sees_the_moved_point_where_it_saw_the_point() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for camera in ring(6) {
            let s = random_similarity(&mut rng);
            let moved = s.camera(&camera);
            let x = 0.5 * random_unit(&mut rng);
            let (u, v, depth) = camera.project(x).expect("in front");
            let (u2, v2, depth2) = moved.project(s.apply(x)).expect("in front");
            assert!((u - u2).abs() < 1e-9 && (v - v2).abs() < 1e-9);
            assert!((depth2 - s.scale * depth).abs() < 1e-9);
        }
    }

    #[test]
    fn cameras_moved_together_and_jittered_give_the_common_motion_back() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let truth = random_similarity(&mut rng);
        let cameras = ring(40);
        // Each camera moved by the common similarity, then turned by its own 0.5° about the
        // object's centre: the jitter averages out over the ring.
        let moved: Vec<Camera> = cameras
            .iter()
            .map(|c| {
                let jitter = Similarity {
                    rotation: DQuat::from_axis_angle(random_unit(&mut rng), 0.5f64.to_radians()),
                    ..Similarity::IDENTITY
                };
                truth.camera(&jitter.camera(c))
            })
            .collect();
        let fit = Similarity::between_cameras(&cameras, &moved, DVec3::ZERO, 1.0).expect("a fit");
        let residual = fit.rotation.angle_between(truth.rotation).to_degrees();
        assert!(residual < 0.25, "{residual}");
        assert!((fit.scale / truth.scale - 1.0).abs() < 0.01);
        let exact =
            Similarity::between_cameras(&cameras, &cameras, DVec3::ZERO, 1.0).expect("a fit");
        assert!(exact.angle_deg() < 1e-6 && (exact.scale - 1.0).abs() < 1e-12);
        assert!(exact.translation.length() < 1e-12);
    }

    #[test]
    fn cameras_on_a_line_still_fix_the_rotation() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let truth = random_similarity(&mut rng);
        let line: Vec<Camera> = (0..5)
            .map(|k| {
                let eye = DVec3::new(k as f64 * 0.2, -3.0, 0.5);
                Camera::look_at(64, 48, 0.8, eye, eye + DVec3::Y, DVec3::Z)
            })
            .collect();
        let moved: Vec<Camera> = line.iter().map(|c| truth.camera(c)).collect();
        let fit = Similarity::between_cameras(&line, &moved, DVec3::new(0.0, 0.0, 0.5), 1.0)
            .expect("a fit");
        assert!(fit.rotation.dot(truth.rotation).abs() > 1.0 - 1e-12);
        assert!((fit.scale - truth.scale).abs() < 1e-9);
    }
}

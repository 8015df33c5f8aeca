//! An implicit quadric surface `f(x) = xᵀAx + bᵀx + c = 0` fitted to points with their normals,
//! so that `f` is close to a signed distance near them: each point asks `f(p) = 0` and
//! `∇f(p) = 2Ap + b = n`, which is linear in the quadric's ten coefficients; the least-squares
//! coefficients solve a 10 × 10 system (its normal equations). Spheres, cylinders, cones and
//! planes are fitted exactly. The points are centred and scaled to unit spread first, and a small
//! ridge on `A` keeps the curvature zero along directions the points do not span (a plane's
//! normal), whatever the mesh's units.
//!
//! Used to continue a surface over a hole in it ([`super::holes`]). Single-threaded: a fit reads
//! a few thousand points.

use glam::DVec3;

/// Number of coefficients: `A`'s six (xx, yy, zz, xy, xz, yz), `b`'s three, `c`.
const COEFFICIENTS: usize = 10;

/// Ridge on `A`'s coefficients, per point (in the normalised coordinates).
const CURVATURE_RIDGE: f64 = 1e-6;

/// Most fits of [`Quadric::fit_robust`].
const ROBUST_ROUNDS: usize = 5;

/// Newton steps of [`Quadric::project`].
const PROJECTION_STEPS: usize = 32;

/// A quadric fitted by [`Quadric::fit`], in coordinates centred on its points and scaled by
/// their spread.
#[derive(Clone, Debug)]
pub struct Quadric {
    /// Coefficients in the order of [`features`].
    coefficients: [f64; COEFFICIENTS],
    centre: DVec3,
    scale: f64,
}

/// How well a quadric describes the points it was fitted to.
#[cfg(test)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadricResidual {
    /// Root mean square of `f` at the points (a distance, in the points' units).
    pub distance_rms: f64,
    /// Root mean square angle between `∇f` and the points' normals, in degrees.
    pub normal_rms_deg: f64,
}

/// The rows of the fit for one normalised point `p`: `f(p)`, then `∂f/∂x`, `∂f/∂y`, `∂f/∂z`.
fn features(p: DVec3) -> [[f64; COEFFICIENTS]; 4] {
    let (x, y, z) = (p.x, p.y, p.z);
    [
        [
            x * x,
            y * y,
            z * z,
            2.0 * x * y,
            2.0 * x * z,
            2.0 * y * z,
            x,
            y,
            z,
            1.0,
        ],
        [2.0 * x, 0.0, 0.0, 2.0 * y, 2.0 * z, 0.0, 1.0, 0.0, 0.0, 0.0],
        [0.0, 2.0 * y, 0.0, 2.0 * x, 0.0, 2.0 * z, 0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 2.0 * z, 0.0, 2.0 * x, 2.0 * y, 0.0, 0.0, 1.0, 0.0],
    ]
}

impl Quadric {
    /// The least-squares quadric through `points` with gradients `normals` (unit, outward), or
    /// `None` for fewer than ten points, non-finite input or a singular system.
    pub fn fit(points: &[DVec3], normals: &[DVec3]) -> Option<Quadric> {
        if points.len() < COEFFICIENTS || points.len() != normals.len() {
            return None;
        }
        let centre = points.iter().sum::<DVec3>() / points.len() as f64;
        let spread = (points
            .iter()
            .map(|p| p.distance_squared(centre))
            .sum::<f64>()
            / points.len() as f64)
            .sqrt();
        if !spread.is_finite() || spread <= 0.0 {
            return None;
        }
        let mut matrix = [[0.0; COEFFICIENTS]; COEFFICIENTS];
        let mut rhs = [0.0; COEFFICIENTS];
        for (&p, &n) in points.iter().zip(normals) {
            let rows = features((p - centre) / spread);
            let targets = [0.0, n.x, n.y, n.z];
            for (row, target) in rows.iter().zip(targets) {
                for i in 0..COEFFICIENTS {
                    rhs[i] += row[i] * target;
                    for j in 0..COEFFICIENTS {
                        matrix[i][j] += row[i] * row[j];
                    }
                }
            }
        }
        let ridge = CURVATURE_RIDGE * points.len() as f64;
        for (i, row) in matrix.iter_mut().enumerate().take(6) {
            row[i] += ridge;
        }
        let coefficients = solve(matrix, rhs)?;
        Some(Quadric {
            coefficients,
            centre,
            scale: spread,
        })
    }

    /// [`Quadric::fit`] made robust to outliers (a fin or a floater in the points): refitted to
    /// the points it describes to within `distance` and `angle_deg` until they stop changing (at
    /// most [`ROBUST_ROUNDS`] fits). Returns the quadric and the fraction of the points it
    /// describes, or `None` where a fit fails.
    pub fn fit_robust(
        points: &[DVec3],
        normals: &[DVec3],
        distance: f64,
        angle_deg: f64,
    ) -> Option<(Quadric, f64)> {
        let min_cos = angle_deg.to_radians().cos();
        let describes = |quadric: &Quadric, p: DVec3, n: DVec3| {
            let (value, gradient) = quadric.value_and_gradient(p);
            value.abs() <= distance && gradient.normalize_or_zero().dot(n) >= min_cos
        };
        let mut inliers: Vec<bool> = vec![true; points.len()];
        let mut quadric = Quadric::fit(points, normals)?;
        for _ in 1..ROBUST_ROUNDS {
            let next: Vec<bool> = points
                .iter()
                .zip(normals)
                .map(|(&p, &n)| describes(&quadric, p, n))
                .collect();
            if next == inliers {
                break;
            }
            inliers = next;
            let (kept_points, kept_normals): (Vec<DVec3>, Vec<DVec3>) = points
                .iter()
                .zip(normals)
                .zip(&inliers)
                .filter(|(_, &inlier)| inlier)
                .map(|((&p, &n), _)| (p, n))
                .unzip();
            quadric = Quadric::fit(&kept_points, &kept_normals)?;
        }
        let described = points
            .iter()
            .zip(normals)
            .filter(|(&p, &n)| describes(&quadric, p, n))
            .count();
        Some((quadric, described as f64 / points.len() as f64))
    }

    /// `f` at `x` in `x`'s units (about the signed distance near the fitted points) and its
    /// gradient (about the unit normal there).
    pub fn value_and_gradient(&self, x: DVec3) -> (f64, DVec3) {
        let rows = features((x - self.centre) / self.scale);
        let dot = |row: &[f64; COEFFICIENTS]| -> f64 {
            row.iter().zip(&self.coefficients).map(|(a, b)| a * b).sum()
        };
        (
            self.scale * dot(&rows[0]),
            DVec3::new(dot(&rows[1]), dot(&rows[2]), dot(&rows[3])),
        )
    }

    /// How well the quadric describes `points` and `normals`.
    #[cfg(test)]
    pub fn residual(&self, points: &[DVec3], normals: &[DVec3]) -> QuadricResidual {
        let count = points.len().max(1) as f64;
        let (mut distance, mut angle) = (0.0, 0.0);
        for (&p, &n) in points.iter().zip(normals) {
            let (value, gradient) = self.value_and_gradient(p);
            distance += value * value;
            let cos = gradient.normalize_or_zero().dot(n).clamp(-1.0, 1.0);
            angle += cos.acos().to_degrees().powi(2);
        }
        QuadricResidual {
            distance_rms: (distance / count).sqrt(),
            normal_rms_deg: (angle / count).sqrt(),
        }
    }

    /// The point of the surface `f = 0` reached from `x` by Newton steps along the gradient, or
    /// `None` where they do not converge to within `tolerance` (a gradient that vanishes, or a
    /// surface out of reach).
    pub fn project(&self, x: DVec3, tolerance: f64) -> Option<DVec3> {
        let mut p = x;
        for _ in 0..PROJECTION_STEPS {
            let (value, gradient) = self.value_and_gradient(p);
            if value.abs() <= tolerance {
                return Some(p);
            }
            let length_squared = gradient.length_squared();
            // (NaN fails the comparison too.)
            if length_squared.is_nan() || length_squared <= 1e-12 {
                return None;
            }
            p -= gradient * (value / length_squared);
        }
        (self.value_and_gradient(p).0.abs() <= tolerance).then_some(p)
    }
}

/// Solves a small dense system by Gaussian elimination with partial pivoting; `None` when it is
/// singular or the solution is not finite.
fn solve(
    mut matrix: [[f64; COEFFICIENTS]; COEFFICIENTS],
    mut rhs: [f64; COEFFICIENTS],
) -> Option<[f64; COEFFICIENTS]> {
    let largest = matrix.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    for column in 0..COEFFICIENTS {
        let pivot = (column..COEFFICIENTS)
            .max_by(|&a, &b| matrix[a][column].abs().total_cmp(&matrix[b][column].abs()))?;
        let magnitude = matrix[pivot][column].abs();
        if magnitude.is_nan() || magnitude <= 1e-14 * largest {
            return None;
        }
        matrix.swap(column, pivot);
        rhs.swap(column, pivot);
        let pivot_row = matrix[column];
        for row in column + 1..COEFFICIENTS {
            let factor = matrix[row][column] / pivot_row[column];
            for (entry, above) in matrix[row][column..].iter_mut().zip(&pivot_row[column..]) {
                *entry -= factor * above;
            }
            rhs[row] -= factor * rhs[column];
        }
    }
    let mut solution = [0.0; COEFFICIENTS];
    for row in (0..COEFFICIENTS).rev() {
        let known: f64 = (row + 1..COEFFICIENTS)
            .map(|k| matrix[row][k] * solution[k])
            .sum();
        solution[row] = (rhs[row] - known) / matrix[row][row];
    }
    solution.iter().all(|v| v.is_finite()).then_some(solution)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::random_unit;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Points on a patch of a sphere (a quarter of it, around one pole): the fit is the sphere's
    /// signed distance to first order, everywhere near it and across the unseen rest.
    #[test]
    fn a_patch_of_a_sphere_gives_back_the_sphere() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let (centre, radius) = (DVec3::new(0.3, -1.2, 2.0), 0.7);
        let normals: Vec<DVec3> = (0..400)
            .map(|_| random_unit(&mut rng))
            .filter(|n| n.z > 0.5)
            .collect();
        let points: Vec<DVec3> = normals.iter().map(|n| centre + radius * *n).collect();
        let quadric = Quadric::fit(&points, &normals).unwrap();
        let residual = quadric.residual(&points, &normals);
        assert!(residual.distance_rms < 1e-6 && residual.normal_rms_deg < 1e-3);
        for _ in 0..50 {
            let n = random_unit(&mut rng);
            let on = centre + radius * n;
            let (value, gradient) = quadric.value_and_gradient(on);
            assert!(value.abs() < 1e-5, "{value}");
            assert!(gradient.normalize().dot(n) > 0.99999);
            let (outside, _) = quadric.value_and_gradient(on + 0.01 * n);
            assert!((outside - 0.01).abs() < 1e-3, "{outside}");
            let start = on + 0.2 * random_unit(&mut rng);
            let projected = quadric.project(start, 1e-9).unwrap();
            let off = (projected.distance(centre) - radius).abs();
            assert!(off < 1e-5, "{off}");
        }
    }

    /// Noisy points of a plane: the fit is the plane (no curvature along its normal, which the
    /// points do not span), and projecting moves a point straight onto it.
    #[test]
    fn a_noisy_plane_stays_a_plane() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let normal = DVec3::new(1.0, 2.0, 2.0).normalize();
        let (u, v) = normal.any_orthonormal_pair();
        let points: Vec<DVec3> = (0..300)
            .map(|_| {
                u * rng.random_range(-2.0..2.0)
                    + v * rng.random_range(-2.0..2.0)
                    + normal * (0.5 + rng.random_range(-1e-3..1e-3))
            })
            .collect();
        let normals = vec![normal; points.len()];
        let quadric = Quadric::fit(&points, &normals).unwrap();
        let residual = quadric.residual(&points, &normals);
        assert!(residual.distance_rms < 1e-3, "{residual:?}");
        for height in [-3.0, 0.0, 2.5] {
            let x = u * 5.0 - v * 4.0 + normal * height;
            let (value, _) = quadric.value_and_gradient(x);
            assert!((value - (height - 0.5)).abs() < 0.01, "{value} at {height}");
            let projected = quadric.project(x, 1e-9).unwrap();
            assert!((projected.dot(normal) - 0.5).abs() < 2e-3);
            assert!((projected - x).cross(normal).length() < 0.01);
        }
    }

    #[test]
    fn too_few_or_degenerate_points_give_no_quadric() {
        let points = vec![DVec3::ONE; 20];
        let normals = vec![DVec3::Z; 20];
        assert!(Quadric::fit(&points[..5], &normals[..5]).is_none());
        assert!(Quadric::fit(&points, &normals).is_none());
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut scattered: Vec<DVec3> = (0..20).map(|_| random_unit(&mut rng)).collect();
        assert!(Quadric::fit(&scattered, &normals[..19]).is_none());
        scattered[4] = DVec3::NAN;
        assert!(Quadric::fit(&scattered, &normals).is_none());
    }
}

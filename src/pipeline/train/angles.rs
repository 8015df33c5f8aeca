//! Estimates of the learned polarizer angles. When shading starts (and again when the Stokes loss
//! starts) each group's angle is set in closed form from the current model, then refined by
//! gradient descent. Behind a polarizer at θ a pixel sees `I = ½ α (S0 + S1 cos 2θ + S2 sin 2θ)`,
//! so with the rendered Stokes vector the residual `r = 2I/α − S0` is linear in
//! `(x, y) = (cos 2θ, sin 2θ)`: least squares over the group's pixels gives `(x, y)` and
//! `θ = ½ atan2(y, x)`. Gradient descent alone can stall near the angle 90° from the truth, where
//! the loss is at a maximum.

use std::collections::BTreeMap;

use super::state::TrainState;
use super::{Run, TrainError};
use crate::core::envmap::PreparedEnv;
use crate::core::step::Polarizer;

/// Views per group rendered for the estimate.
const VIEWS_PER_GROUP: usize = 6;
/// Pixels whose rendered opacity is below this are left out (their S/α is unreliable).
const MIN_ALPHA: f64 = 0.5;

/// Returns the estimated angle (radians, [0, π)) of every learned group; a group whose normal
/// equations are singular (no polarization signal) keeps its current angle.
pub(super) fn estimate(
    run: &Run,
    state: &TrainState,
    env: &PreparedEnv,
) -> Result<BTreeMap<String, f64>, TrainError> {
    let _span =
        tracing::info_span!("polarizer_angle_estimate", iteration = state.iteration).entered();
    let scene = run.scene(state, env);
    let mut angles = state.polarizer_angles.clone();
    for (group, angle) in angles.iter_mut() {
        let mut fit = AngleFit::default();
        let views = run
            .targets
            .iter()
            .enumerate()
            .filter(|(_, t)| matches!(&t.polarizer, Some(Polarizer::Learned(g)) if g == group))
            .take(VIEWS_PER_GROUP);
        for (index, target) in views {
            let rendered = scene.render(&run.poses.camera(&state.poses, index))?;
            let s = &rendered.shaded;
            for (p, &a) in rendered.gbuffers().alpha.iter().enumerate() {
                if a < MIN_ALPHA || target.mask[p] < 0.5 {
                    continue;
                }
                for c in 0..3 {
                    let captured = f64::from(target.photometric[p * 3 + c] * target.gain);
                    fit.add(a, s.s0[p][c], s.s1[p][c], s.s2[p][c], captured);
                }
            }
        }
        match fit.angle() {
            Some(theta) => {
                *angle = theta;
                tracing::info!(
                    group,
                    degrees = theta.to_degrees(),
                    "polarizer angle estimate"
                );
            }
            None => tracing::warn!(
                group,
                "no polarization signal to estimate the polarizer angle"
            ),
        }
    }
    Ok(angles)
}

/// Least squares of `S1 x + S2 y = 2I/α − S0` over samples, for `(x, y) = (cos 2θ, sin 2θ)`.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct AngleFit {
    a11: f64,
    a12: f64,
    a22: f64,
    b1: f64,
    b2: f64,
}

impl AngleFit {
    /// One sample: opacity, rendered Stokes and the intensity captured behind the polarizer.
    pub(crate) fn add(&mut self, alpha: f64, s0: f64, s1: f64, s2: f64, captured: f64) {
        let r = 2.0 * captured / alpha - s0;
        self.a11 += s1 * s1;
        self.a12 += s1 * s2;
        self.a22 += s2 * s2;
        self.b1 += s1 * r;
        self.b2 += s2 * r;
    }

    /// The angle in [0, π), or `None` when the samples carry no polarization (singular system).
    pub(crate) fn angle(&self) -> Option<f64> {
        let det = self.a11 * self.a22 - self.a12 * self.a12;
        if det.is_nan() || det <= 1e-12 * (self.a11 * self.a22).max(f64::MIN_POSITIVE) {
            return None;
        }
        let x = (self.a22 * self.b1 - self.a12 * self.b2) / det;
        let y = (self.a11 * self.b2 - self.a12 * self.b1) / det;
        Some((0.5 * y.atan2(x)).rem_euclid(std::f64::consts::PI))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn exact_samples_give_the_exact_angle_and_no_signal_gives_none() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        for degrees in [0.0f64, 20.0, 89.0, 110.0, 179.5] {
            let theta = degrees.to_radians();
            let mut fit = AngleFit::default();
            for _ in 0..50 {
                let (a, s0): (f64, f64) = (rng.random_range(0.5..1.0), rng.random_range(0.1..1.0));
                let (s1, s2) = (rng.random_range(-0.1..0.1), rng.random_range(-0.1..0.1));
                let captured = 0.5 * a * (s0 + s1 * (2.0 * theta).cos() + s2 * (2.0 * theta).sin());
                fit.add(a, s0, s1, s2, captured);
            }
            let got = fit.angle().unwrap().to_degrees();
            let error = (got - degrees).rem_euclid(180.0);
            assert!(error.min(180.0 - error) < 1e-6, "{degrees}° → {got}°");
        }
        let mut unpolarized = AngleFit::default();
        unpolarized.add(1.0, 0.5, 0.0, 0.0, 0.25);
        assert_eq!(unpolarized.angle(), None);
    }
}

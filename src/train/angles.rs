//! Initial values of the learned polarizer angles: when the PolarDR stage starts, each group's
//! angle is set by a coarse search (every 5° over [0°, 180°)) minimizing the L1 distance between
//! the rendered I(θ) and the group's captured images. Gradient descent alone can stall near the
//! angle 90° away from the truth, where the loss is at a maximum.

use std::collections::BTreeMap;

use glam::DVec3;

use super::state::TrainState;
use super::targets::Polarizer;
use super::{Run, TrainError};
use crate::envmap::PreparedEnv;

/// Views per group rendered for the search.
const VIEWS_PER_GROUP: usize = 4;
/// Candidate angles per 180°.
const CANDIDATES: usize = 36;

/// Returns the searched angle (radians) of every learned group; other entries are unchanged.
pub(super) fn initialize(
    run: &Run,
    state: &TrainState,
    env: &PreparedEnv,
) -> Result<BTreeMap<String, f64>, TrainError> {
    let _span = tracing::info_span!("polarizer_angle_search").entered();
    let scene = run.scene(state, env);
    let mut angles = state.polarizer_angles.clone();
    for (group, angle) in angles.iter_mut() {
        let mut cost = [0.0f64; CANDIDATES];
        let views = run
            .targets
            .iter()
            .filter(|t| matches!(&t.polarizer, Some(Polarizer::Learned(g)) if g == group))
            .take(VIEWS_PER_GROUP);
        for target in views {
            let rendered = scene.render(&run.capture.views[target.view].camera)?;
            let s = &rendered.shaded;
            let alpha = &rendered.gbuffers().alpha;
            for (k, c) in cost.iter_mut().enumerate() {
                let theta = std::f64::consts::PI * k as f64 / CANDIDATES as f64;
                let (cos, sin) = ((2.0 * theta).cos(), (2.0 * theta).sin());
                for (p, &a) in alpha.iter().enumerate() {
                    if a <= 0.0 {
                        continue;
                    }
                    let predicted = 0.5 * a * (s.s0[p] + s.s1[p] * cos + s.s2[p] * sin);
                    let captured = DVec3::from_slice(&target.photometric[p * 3..p * 3 + 3]);
                    *c += (predicted - captured).abs().element_sum();
                }
            }
        }
        let best = (0..CANDIDATES)
            .min_by(|&a, &b| cost[a].total_cmp(&cost[b]))
            .unwrap_or(0);
        *angle = std::f64::consts::PI * best as f64 / CANDIDATES as f64;
        tracing::info!(
            group,
            degrees = angle.to_degrees(),
            "initial polarizer angle"
        );
    }
    Ok(angles)
}

//! Adaptive density control (3DGS rules adapted to surfels, METHOD.md §7): clone small surfels and
//! split large ones where the screen-space positional gradient is high, prune transparent and
//! oversized ones, and periodically reset opacities.
//!
//! Densification is planned from statistics ([`DensifyStats`]) and applied as two index operations
//! (`retain`, then `extend_from_indices`) so the optimizer state can follow the surfels exactly.

use glam::{DVec2, DVec3};
use rand::Rng;
use serde::{Deserialize, Serialize};

use crate::core::surfels::{logit, retain_flagged, sigmoid, Surfels};

/// Screen-space gradient statistics accumulated between densifications.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DensifyStats {
    /// Sum over views of |dL/d projected centre| in normalized device units.
    pub grad_sum: Vec<f64>,
    /// Number of views in which the surfel received any gradient.
    pub seen: Vec<u32>,
}

impl DensifyStats {
    pub fn new(n: usize) -> Self {
        DensifyStats {
            grad_sum: vec![0.0; n],
            seen: vec![0; n],
        }
    }

    /// Keeps the statistics of the surfels `keep` marks (as [`Surfels::retain`] keeps them).
    pub fn retain(&mut self, keep: &[bool]) {
        retain_flagged(&mut self.grad_sum, keep);
        retain_flagged(&mut self.seen, keep);
    }

    /// Adds one view's per-surfel gradient norms, given in pixels, for an image of `width × height`.
    /// Converted to normalized device units (half the image spans 1) as in 3DGS, so the 3DGS
    /// threshold (2e-4) keeps its meaning at any resolution.
    pub fn add_view(&mut self, grad_norm_pixels: &[f64], width: usize, height: usize) {
        let to_ndc = 0.5 * width.max(height) as f64;
        for ((sum, seen), &g) in self
            .grad_sum
            .iter_mut()
            .zip(self.seen.iter_mut())
            .zip(grad_norm_pixels)
        {
            if g > 0.0 {
                *sum += g * to_ndc;
                *seen += 1;
            }
        }
    }

    fn mean(&self, i: usize) -> f64 {
        if self.seen[i] == 0 {
            0.0
        } else {
            self.grad_sum[i] / self.seen[i] as f64
        }
    }
}

/// Thresholds of one densify/prune pass.
#[derive(Clone, Copy, Debug)]
pub struct DensifyRules {
    /// Mean NDC gradient above which a surfel is cloned or split.
    pub grad_threshold: f64,
    /// Surfels whose larger scale exceeds this (scene units) are split, smaller ones cloned.
    pub split_scale: f64,
    /// Surfels with opacity below this are pruned.
    pub prune_opacity: f64,
    /// Surfels whose larger scale exceeds this (scene units) are pruned.
    pub prune_scale: f64,
    /// The surfel count is never grown past this.
    pub max_surfels: usize,
}

impl DensifyRules {
    /// 3DGS defaults relative to the scene extent (the radius of the object's bounding sphere).
    pub fn for_extent(
        extent: f64,
        grad_threshold: f64,
        prune_opacity: f64,
        max_surfels: usize,
    ) -> Self {
        DensifyRules {
            grad_threshold,
            split_scale: 0.01 * extent,
            prune_opacity,
            prune_scale: 0.1 * extent,
            max_surfels,
        }
    }
}

/// What a pass changes: surfels to keep, then copies to append (split children are appended with
/// new positions and scales written by [`apply`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DensifyPlan {
    /// One flag per surfel before the pass; false = pruned.
    pub keep: Vec<bool>,
    /// Indices (in the kept, re-indexed array) whose copies are appended, in order.
    pub append_from: Vec<usize>,
    pub cloned: usize,
    pub split: usize,
    pub pruned: usize,
}

/// Plans one densify-and-prune pass.
///
/// Surfels that are transparent or oversized are pruned; of the rest, those whose mean gradient
/// reaches the threshold grow (a clone or a split adds one surfel each). When they are more than
/// the cap leaves room for (counted after pruning), the room goes to the largest gradients, so
/// the detail a run still lacks is where it grows at its budget, whatever order the surfels are
/// stored in.
pub fn plan(surfels: &Surfels, stats: &DensifyStats, rules: &DensifyRules) -> DensifyPlan {
    let n = surfels.len();
    let keep: Vec<bool> = (0..n)
        .map(|i| {
            sigmoid(surfels.opacity[i]) >= rules.prune_opacity
                && larger_scale(surfels, i) <= rules.prune_scale
        })
        .collect();
    let kept = keep.iter().filter(|k| **k).count();
    let room = rules.max_surfels.saturating_sub(kept);
    let mut growing: Vec<usize> = (0..n)
        .filter(|&i| keep[i] && stats.mean(i) >= rules.grad_threshold)
        .collect();
    if growing.len() > room {
        // Largest mean gradient first; ties by index, so a plan is a function of its inputs.
        let by_gradient =
            |a: &usize, b: &usize| stats.mean(*b).total_cmp(&stats.mean(*a)).then(a.cmp(b));
        if room > 0 {
            growing.select_nth_unstable_by(room - 1, by_gradient);
        }
        growing.truncate(room);
        growing.sort_unstable();
    }
    let (clone, split): (Vec<usize>, Vec<usize>) = growing
        .into_iter()
        .partition(|&i| larger_scale(surfels, i) <= rules.split_scale);
    // Indices after `retain(keep)`: split parents survive it and are dropped by `apply` once their
    // two children have been appended.
    let mut remap = vec![usize::MAX; n];
    let mut next = 0;
    for (slot, &kept) in remap.iter_mut().zip(&keep) {
        if kept {
            *slot = next;
            next += 1;
        }
    }
    let mut append_from: Vec<usize> = clone.iter().map(|&i| remap[i]).collect();
    for &i in &split {
        append_from.extend([remap[i], remap[i]]);
    }
    DensifyPlan {
        pruned: keep.iter().filter(|k| !**k).count(),
        keep,
        append_from,
        cloned: clone.len(),
        split: split.len(),
    }
}

/// Surfel `i`'s larger scale, in scene units.
fn larger_scale(surfels: &Surfels, i: usize) -> f64 {
    surfels.log_scale[i][0].max(surfels.log_scale[i][1]).exp()
}

/// Applies a plan to the surfels: retain, append copies, move split children apart inside their
/// parent's plane (one tangent-plane Gaussian sample each, scales / 1.6), then drop split parents.
/// Returns the final keep mask over the extended array, which the caller applies to any state
/// aligned with the surfels (after `retain(plan.keep)` and `extend_from_indices(plan.append_from)`).
pub fn apply(surfels: &mut Surfels, plan: &DensifyPlan, rng: &mut impl Rng) -> Vec<bool> {
    surfels.retain(&plan.keep);
    let kept = surfels.len();
    surfels.extend_from_indices(&plan.append_from);
    let first_child = kept + plan.cloned;
    let mut final_keep = vec![true; surfels.len()];
    for c in first_child..surfels.len() {
        let parent = plan.append_from[c - kept];
        final_keep[parent] = false;
        let s = surfels.get(c);
        let offset = DVec2::new(gaussian(rng), gaussian(rng)) * s.scale;
        let p = s.position + s.rotation.x_axis * offset.x + s.rotation.y_axis * offset.y;
        surfels.position[c] = p.to_array();
        for v in &mut surfels.log_scale[c] {
            *v -= 1.6f64.ln();
        }
    }
    surfels.retain(&final_keep);
    final_keep
}

/// Sets every opacity to at most `ceiling` (3DGS opacity reset).
pub fn reset_opacity(surfels: &mut Surfels, ceiling: f64) {
    let raw_ceiling = logit(ceiling);
    for o in &mut surfels.opacity {
        *o = o.min(raw_ceiling);
    }
}

/// A standard normal sample (Box–Muller), reproducible from the caller's seeded generator.
fn gaussian(rng: &mut impl Rng) -> f64 {
    let u1: f64 = rng.random::<f64>().max(1e-300);
    let u2: f64 = rng.random();
    (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
}

/// Centre of a surfel set's bounding box and the radius of its bounding sphere around it.
pub fn extent(surfels: &Surfels) -> (DVec3, f64) {
    if surfels.is_empty() {
        return (DVec3::ZERO, 1.0);
    }
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for p in &surfels.position {
        let p = DVec3::from_array(*p);
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let centre = 0.5 * (lo + hi);
    (centre, (0.5 * (hi - lo)).length().max(1e-6))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::surfels::Surfel;
    use glam::DMat3;
    use rand::SeedableRng;

    fn scene() -> Surfels {
        let mut s = Surfels::default();
        let mut add = |x: f64, scale: f64, opacity: f64| {
            s.push_activated(&Surfel {
                position: DVec3::new(x, 0.0, 0.0),
                scale: DVec2::splat(scale),
                rotation: DMat3::IDENTITY,
                opacity,
                albedo: DVec3::splat(0.5),
                roughness: 0.1,
                ior: 1.8,
            })
        };
        add(0.0, 0.005, 0.9); // small, high gradient: cloned
        add(1.0, 0.05, 0.9); // large, high gradient: split
        add(2.0, 0.05, 0.01); // transparent: pruned
        add(3.0, 0.05, 0.9); // low gradient: untouched
        s
    }

    #[test]
    fn clone_split_and_prune_follow_the_rules() {
        let mut s = scene();
        let mut stats = DensifyStats::new(4);
        stats.add_view(&[1e-3, 1e-3, 1e-3, 1e-7], 100, 100);
        let rules = DensifyRules::for_extent(1.0, 2e-4, 0.05, 100);
        let plan = plan(&s, &stats, &rules);
        assert_eq!((plan.cloned, plan.split, plan.pruned), (1, 1, 1));
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        apply(&mut s, &plan, &mut rng);
        // Kept: 0, 3; clone of 0; two children of 1.
        assert_eq!(s.len(), 5);
        let xs: Vec<f64> = s.position.iter().map(|p| p[0]).collect();
        assert_eq!(&xs[..3], &[0.0, 3.0, 0.0]);
        for c in 3..5 {
            let child = s.get(c);
            assert!((child.scale.x - 0.05 / 1.6).abs() < 1e-12);
            assert!(
                (child.position.x - 1.0).abs() < 0.25,
                "child stays near its parent"
            );
            assert_eq!(child.position.z, 0.0, "children stay in the parent's plane");
        }
    }

    #[test]
    fn growth_stops_at_the_cap() {
        let s = scene();
        let mut stats = DensifyStats::new(4);
        stats.add_view(&[1.0; 4], 100, 100);
        let rules = DensifyRules::for_extent(1.0, 2e-4, 0.0, 4);
        let plan = plan(&s, &stats, &rules);
        assert_eq!(plan.cloned + plan.split, 0);
    }

    #[test]
    fn at_the_cap_the_largest_gradients_grow() {
        let s = scene();
        let mut stats = DensifyStats::new(4);
        // Surfel 3 has the largest gradient, surfel 0 the smallest above the threshold.
        stats.add_view(&[3e-4, 5e-4, 1e-3, 9e-4], 100, 100);
        // Surfel 2 is pruned (transparent), which leaves room for two of the three others.
        let rules = DensifyRules::for_extent(1.0, 2e-4, 0.05, 5);
        let plan = plan(&s, &stats, &rules);
        assert_eq!(plan.pruned, 1);
        assert_eq!(
            (plan.cloned, plan.split),
            (0, 2),
            "surfels 1 and 3, both large"
        );
        // After `retain`, surfels 1 and 3 are at 1 and 2; each split appends two children.
        assert_eq!(plan.append_from, vec![1, 1, 2, 2]);
    }

    #[test]
    fn opacity_reset_only_lowers() {
        let mut s = scene();
        reset_opacity(&mut s, 0.01);
        assert!((sigmoid(s.opacity[0]) - 0.01).abs() < 1e-9);
        assert!(sigmoid(s.opacity[2]) <= 0.01 + 1e-12);
    }
}

//! Adam over named parameter groups of flat `f64` slices (METHOD.md §7), the exponential
//! learning-rate schedule of 3DGS, and the per-group learning rates of a training run.
//!
//! The optimizer state (first and second moments and a step count per group, as PyTorch keeps per
//! parameter tensor) follows densification: [`Adam::retain`] and [`Adam::extend_from_indices`] mirror
//! `Surfels::retain` / `Surfels::extend_from_indices`; appended entries start with **zero moments**
//! and the group keeps its step count (as 3DGS's `cat_tensors_to_optimizer`). [`Adam::reset_entries`]
//! zeroes the moments of chosen entries (opacity reset, as 3DGS's `replace_tensor_to_optimizer`).
//! The state is serde-serializable; with `serde_json` (feature `float_roundtrip`) a checkpoint
//! restores it bit for bit.
//!
//! Threading: the element-wise update runs on rayon for large groups; each element is updated
//! independently, so results do not depend on the thread count.

use std::collections::BTreeMap;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::core::config::TrainConfig;
use crate::core::surfels::Surfels;

/// Name of the optimizer group of the environment-map texels.
pub const ENVMAP_GROUP: &str = "envmap";
/// Name of the optimizer group of the learned polarizer angles.
pub const POLARIZER_GROUP: &str = "polarizer";
/// Name of the optimizer group of the index of refraction the surfels share, or of its common
/// part ([`crate::core::config::IorModel`]).
pub const SHARED_IOR_GROUP: &str = "ior_shared";

/// Groups shorter than this are updated on the calling thread.
const PARALLEL_MIN_LEN: usize = 1 << 14;

/// Adam hyper-parameters.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AdamConfig {
    pub beta1: f64,
    pub beta2: f64,
    /// Added to √v̂ in the denominator; 1e-15 as the authors (METHOD.md §7).
    pub eps: f64,
}

impl Default for AdamConfig {
    fn default() -> Self {
        AdamConfig {
            beta1: 0.9,
            beta2: 0.999,
            eps: 1e-15,
        }
    }
}

/// The state of one parameter group.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GroupState {
    /// Steps taken on this group (the t of the bias correction).
    pub step: u64,
    /// Values per entry (3 for positions, 1 for opacities, ...): the unit of retain/extend.
    pub width: usize,
    /// First moment m.
    pub exp_avg: Vec<f64>,
    /// Second moment v.
    pub exp_avg_sq: Vec<f64>,
}

impl GroupState {
    fn zeros(len: usize, width: usize) -> Self {
        GroupState {
            step: 0,
            width,
            exp_avg: vec![0.0; len],
            exp_avg_sq: vec![0.0; len],
        }
    }

    /// Number of entries (values / width).
    pub fn entries(&self) -> usize {
        self.exp_avg.len() / self.width
    }
}

/// An optimizer call that does not fit the state or the parameters.
#[derive(Debug, Error, PartialEq)]
pub enum OptimError {
    #[error("optimizer group `{group}`: {what} has {got} values, expected {expected}")]
    LengthMismatch {
        group: String,
        what: &'static str,
        expected: usize,
        got: usize,
    },
    #[error("optimizer group `{group}`: index {index} is out of range for {entries} entries")]
    IndexOutOfRange {
        group: String,
        index: usize,
        entries: usize,
    },
    #[error("optimizer group `{group}`: width must be at least 1 and divide its {len} values")]
    BadWidth { group: String, len: usize },
}

/// Values per surfel of each surfel parameter group, from the layout of [`Surfels`].
pub fn surfel_group_widths() -> Vec<(&'static str, usize)> {
    Surfels::zeros(1)
        .groups()
        .iter()
        .map(|(name, values)| (*name, values.len()))
        .collect()
}

/// Adam over named groups. A group is created (zero moments, step 0) by its first [`Adam::step`]
/// or by [`Adam::add_group`].
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Adam {
    pub config: AdamConfig,
    groups: BTreeMap<String, GroupState>,
}

impl Adam {
    pub fn new(config: AdamConfig) -> Self {
        Adam {
            config,
            groups: BTreeMap::new(),
        }
    }

    /// The state of a group, if it exists.
    pub fn group(&self, name: &str) -> Option<&GroupState> {
        self.groups.get(name)
    }

    /// Names of the groups with state, in sorted order.
    pub fn group_names(&self) -> impl Iterator<Item = &str> {
        self.groups.keys().map(String::as_str)
    }

    /// Creates (or replaces) a group of `len` values in entries of `width`, with zero moments.
    pub fn add_group(&mut self, name: &str, len: usize, width: usize) -> Result<(), OptimError> {
        if width == 0 || !len.is_multiple_of(width) {
            return Err(OptimError::BadWidth {
                group: name.to_owned(),
                len,
            });
        }
        self.groups
            .insert(name.to_owned(), GroupState::zeros(len, width));
        Ok(())
    }

    /// Installs a group's state as saved by a checkpoint.
    pub fn insert_group(&mut self, name: &str, state: GroupState) -> Result<(), OptimError> {
        let len = state.exp_avg.len();
        if state.width == 0 || !len.is_multiple_of(state.width) || state.exp_avg_sq.len() != len {
            return Err(OptimError::BadWidth {
                group: name.to_owned(),
                len,
            });
        }
        self.groups.insert(name.to_owned(), state);
        Ok(())
    }

    /// Removes a group's state (e.g. when the environment map is replaced).
    pub fn remove_group(&mut self, name: &str) -> Option<GroupState> {
        self.groups.remove(name)
    }

    /// One Adam step on `params` with gradient `grads` and learning rate `lr`:
    /// `m ← β1 m + (1 − β1) g`, `v ← β2 v + (1 − β2) g²`,
    /// `p ← p − lr · (m / (1 − β1ᵗ)) / (√(v / (1 − β2ᵗ)) + ε)`.
    /// A group seen for the first time gets zero moments; its entry width is the surfel layout's
    /// for a surfel group name and 1 otherwise.
    pub fn step(
        &mut self,
        group: &str,
        params: &mut [f64],
        grads: &[f64],
        lr: f64,
    ) -> Result<(), OptimError> {
        let mismatch = |what, expected, got| OptimError::LengthMismatch {
            group: group.to_owned(),
            what,
            expected,
            got,
        };
        check_gradient_length(group, params, grads)?;
        if !self.groups.contains_key(group) {
            let width = surfel_group_widths()
                .into_iter()
                .find(|(name, _)| *name == group)
                .map_or(1, |(_, w)| w);
            self.add_group(group, params.len(), width)?;
        }
        let AdamConfig { beta1, beta2, eps } = self.config;
        let state = self
            .groups
            .get_mut(group)
            .ok_or_else(|| mismatch("state", params.len(), 0))?;
        if state.exp_avg.len() != params.len() {
            return Err(mismatch("parameter", state.exp_avg.len(), params.len()));
        }
        state.step += 1;
        let t = i32::try_from(state.step).unwrap_or(i32::MAX);
        let bias1 = 1.0 - beta1.powi(t);
        let bias2 = 1.0 - beta2.powi(t);
        let update = |(((p, &g), m), v): (((&mut f64, &f64), &mut f64), &mut f64)| {
            *m = beta1 * *m + (1.0 - beta1) * g;
            *v = beta2 * *v + (1.0 - beta2) * g * g;
            *p -= lr * (*m / bias1) / ((*v / bias2).sqrt() + eps);
        };
        if params.len() >= PARALLEL_MIN_LEN {
            params
                .par_iter_mut()
                .zip(grads.par_iter())
                .zip(state.exp_avg.par_iter_mut())
                .zip(state.exp_avg_sq.par_iter_mut())
                .with_min_len(PARALLEL_MIN_LEN / 4)
                .for_each(update);
        } else {
            params
                .iter_mut()
                .zip(grads)
                .zip(state.exp_avg.iter_mut())
                .zip(state.exp_avg_sq.iter_mut())
                .for_each(update);
        }
        Ok(())
    }

    /// One Adam step on a single value that every entry of `params` holds (a tied parameter):
    /// its gradient is the sum of the entries' `grads` (each entry is the value), its moments live
    /// in `group` (one entry), and every entry is set to the stepped value. Entries that disagree
    /// (a model written with one value per entry) start from their mean. No entries hold no value
    /// to learn: the group is left as it is.
    pub fn step_tied(
        &mut self,
        group: &str,
        params: &mut [f64],
        grads: &[f64],
        lr: f64,
    ) -> Result<(), OptimError> {
        let Some(&first) = params.first() else {
            return check_gradient_length(group, params, grads);
        };
        if params.iter().any(|&p| p != first) {
            let mean = params.iter().sum::<f64>() / params.len() as f64;
            params.fill(mean);
        }
        self.step_common_offset(group, params, grads, lr)
    }

    /// One Adam step on an offset every entry of `params` carries (the entries' common part):
    /// its gradient is the sum of the entries' `grads`, its moments live in `group` (one entry),
    /// and every entry moves by the offset's step, keeping its own difference from the others.
    pub fn step_common_offset(
        &mut self,
        group: &str,
        params: &mut [f64],
        grads: &[f64],
        lr: f64,
    ) -> Result<(), OptimError> {
        check_gradient_length(group, params, grads)?;
        let mut offset = [0.0];
        self.step(group, &mut offset, &[grads.iter().sum()], lr)?;
        params.iter_mut().for_each(|p| *p += offset[0]);
        Ok(())
    }

    /// Keeps the entries of `group` whose flag is true, in order (as `Surfels::retain`). A group
    /// without state is left alone.
    pub fn retain(&mut self, group: &str, keep: &[bool]) -> Result<(), OptimError> {
        let Some(state) = self.groups.get_mut(group) else {
            return Ok(());
        };
        if keep.len() != state.entries() {
            return Err(OptimError::LengthMismatch {
                group: group.to_owned(),
                what: "keep mask",
                expected: state.entries(),
                got: keep.len(),
            });
        }
        let width = state.width;
        let filter = |values: &mut Vec<f64>| {
            *values = values
                .chunks_exact(width)
                .zip(keep)
                .filter(|(_, &k)| k)
                .flat_map(|(chunk, _)| chunk.iter().copied())
                .collect();
        };
        filter(&mut state.exp_avg);
        filter(&mut state.exp_avg_sq);
        Ok(())
    }

    /// Appends one entry per index, with **zero moments** (the new parameters are copies, as in
    /// `Surfels::extend_from_indices`, but their optimizer history starts afresh as in 3DGS). A
    /// group without state is left alone.
    pub fn extend_from_indices(
        &mut self,
        group: &str,
        indices: &[usize],
    ) -> Result<(), OptimError> {
        let Some(state) = self.groups.get_mut(group) else {
            return Ok(());
        };
        let entries = state.entries();
        if let Some(&index) = indices.iter().find(|&&i| i >= entries) {
            return Err(OptimError::IndexOutOfRange {
                group: group.to_owned(),
                index,
                entries,
            });
        }
        let added = indices.len() * state.width;
        state.exp_avg.resize(state.exp_avg.len() + added, 0.0);
        state.exp_avg_sq.resize(state.exp_avg_sq.len() + added, 0.0);
        Ok(())
    }

    /// Zeroes both moments of the given entries (the step count is kept).
    pub fn reset_entries(&mut self, group: &str, entries: &[usize]) -> Result<(), OptimError> {
        let Some(state) = self.groups.get_mut(group) else {
            return Ok(());
        };
        let count = state.entries();
        let width = state.width;
        for &e in entries {
            if e >= count {
                return Err(OptimError::IndexOutOfRange {
                    group: group.to_owned(),
                    index: e,
                    entries: count,
                });
            }
            state.exp_avg[e * width..(e + 1) * width].fill(0.0);
            state.exp_avg_sq[e * width..(e + 1) * width].fill(0.0);
        }
        Ok(())
    }

    /// Zeroes both moments of every entry of a group (the step count is kept).
    pub fn reset_group(&mut self, group: &str) {
        if let Some(state) = self.groups.get_mut(group) {
            state.exp_avg.fill(0.0);
            state.exp_avg_sq.fill(0.0);
        }
    }

    /// [`Adam::retain`] on every surfel group (the names of `Surfels::groups`).
    pub fn retain_surfels(&mut self, keep: &[bool]) -> Result<(), OptimError> {
        surfel_group_widths()
            .iter()
            .try_for_each(|(name, _)| self.retain(name, keep))
    }

    /// [`Adam::extend_from_indices`] on every surfel group.
    pub fn extend_surfels_from_indices(&mut self, indices: &[usize]) -> Result<(), OptimError> {
        surfel_group_widths()
            .iter()
            .try_for_each(|(name, _)| self.extend_from_indices(name, indices))
    }
}

/// An error naming `group` unless `grads` holds one value per parameter of `params`.
fn check_gradient_length(group: &str, params: &[f64], grads: &[f64]) -> Result<(), OptimError> {
    if grads.len() == params.len() {
        return Ok(());
    }
    Err(OptimError::LengthMismatch {
        group: group.to_owned(),
        what: "gradient",
        expected: params.len(),
        got: grads.len(),
    })
}

/// Log-linear decay from `init` at step 0 to `final_` at step `steps` (held after), as 3DGS's
/// `get_expon_lr_func` without the delay: `exp((1 − t)·ln init + t·ln final)`, t = step / steps.
/// When either end is not positive it falls back to linear interpolation (a log-lerp is undefined).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ExponentialLr {
    pub init: f64,
    pub final_: f64,
    pub steps: u32,
}

impl ExponentialLr {
    /// Learning rate at `step`.
    pub fn at(&self, step: u32) -> f64 {
        let t = if self.steps == 0 {
            1.0
        } else {
            (f64::from(step) / f64::from(self.steps)).min(1.0)
        };
        if self.init > 0.0 && self.final_ > 0.0 {
            ((1.0 - t) * self.init.ln() + t * self.final_.ln()).exp()
        } else {
            (1.0 - t) * self.init + t * self.final_
        }
    }
}

/// Learning rate of every optimizer group of a run (METHOD.md §7).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearningRates {
    /// Already multiplied by the scene extent.
    pub position: ExponentialLr,
    pub scale: f64,
    pub rotation: f64,
    pub opacity: f64,
    pub albedo: f64,
    pub roughness: f64,
    pub ior: f64,
    pub envmap: f64,
    pub polarizer: f64,
}

impl LearningRates {
    /// From the config; the position rate decays over all `iterations` and scales with
    /// `scene_extent` (the radius of the cameras' or object's bounding sphere, as 3DGS).
    pub fn from_config(config: &TrainConfig, scene_extent: f64) -> Self {
        LearningRates {
            position: ExponentialLr {
                init: config.lr_position_init * scene_extent,
                final_: config.lr_position_final * scene_extent,
                steps: config.steps(),
            },
            scale: config.lr_scale,
            rotation: config.lr_rotation,
            opacity: config.lr_opacity,
            albedo: config.lr_albedo,
            roughness: config.lr_roughness,
            ior: config.lr_ior,
            envmap: config.lr_envmap,
            polarizer: config.lr_polarizer,
        }
    }

    /// The rate of a group (the names of `Surfels::groups`, [`ENVMAP_GROUP`], [`POLARIZER_GROUP`])
    /// at `step`; `None` for an unknown name.
    pub fn for_group(&self, group: &str, step: u32) -> Option<f64> {
        Some(match group {
            "position" => self.position.at(step),
            "scale" => self.scale,
            "rotation" => self.rotation,
            "opacity" => self.opacity,
            "albedo" => self.albedo,
            "roughness" => self.roughness,
            "ior" => self.ior,
            ENVMAP_GROUP => self.envmap,
            POLARIZER_GROUP => self.polarizer,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn a_tied_step_is_a_step_of_the_one_value_with_the_summed_gradient() {
        let config = AdamConfig::default();
        let (mut tied, mut single) = (Adam::new(config), Adam::new(config));
        let mut params = vec![0.25; 5];
        let mut value = [0.25];
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        for _ in 0..20 {
            let grads: Vec<f64> = (0..5).map(|_| rng.random_range(-1.0..1.5)).collect();
            tied.step_tied("tied", &mut params, &grads, 0.01).unwrap();
            single
                .step("tied", &mut value, &[grads.iter().sum()], 0.01)
                .unwrap();
            assert!(
                params.iter().all(|&p| p == value[0]),
                "{params:?} {value:?}"
            );
        }
        assert!(
            (value[0] - 0.25).abs() > 0.05,
            "the value moved: {}",
            value[0]
        );
        // Entries that disagree start from their mean.
        let mut spread = vec![0.0, 1.0];
        Adam::new(config)
            .step_tied("spread", &mut spread, &[0.0, 0.0], 0.01)
            .unwrap();
        assert_eq!(spread, vec![0.5, 0.5]);
        assert!(tied.step_tied("tied", &mut params, &[1.0], 0.01).is_err());
        // No entries: nothing is stepped, and a gradient for them is still an error.
        let mut none = Adam::new(config);
        none.step_tied("empty", &mut [], &[], 0.01).unwrap();
        assert!(none.group("empty").is_none());
        assert!(none.step_tied("empty", &mut [], &[1.0], 0.01).is_err());
    }

    #[test]
    fn a_common_offset_step_moves_every_entry_by_the_step_of_the_summed_gradient() {
        let config = AdamConfig::default();
        let (mut offset, mut single) = (Adam::new(config), Adam::new(config));
        let start = vec![0.1, -0.4, 0.9];
        let mut params = start.clone();
        let mut value = [0.0];
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for _ in 0..20 {
            let grads: Vec<f64> = (0..3).map(|_| rng.random_range(-1.0..1.5)).collect();
            offset
                .step_common_offset("offset", &mut params, &grads, 0.01)
                .unwrap();
            single
                .step("offset", &mut value, &[grads.iter().sum()], 0.01)
                .unwrap();
        }
        assert!(value[0].abs() > 0.05, "the offset moved: {}", value[0]);
        for (p, s) in params.iter().zip(&start) {
            assert!((p - s - value[0]).abs() < 1e-12, "{p} = {s} + {}", value[0]);
        }
        assert!(offset
            .step_common_offset("offset", &mut params, &[1.0], 0.01)
            .is_err());
    }

    #[test]
    fn converges_on_a_quadratic() {
        // f(p) = Σ a_i (p_i − c_i)², minimum at c.
        let a = [1.0, 10.0, 0.1, 3.0];
        let c = [0.5, -2.0, 3.0, 0.0];
        let mut p = vec![0.0; 4];
        let mut adam = Adam::new(AdamConfig {
            eps: 1e-8,
            ..AdamConfig::default()
        });
        let schedule = ExponentialLr {
            init: 0.1,
            final_: 1e-4,
            steps: 3000,
        };
        for step in 0..3000 {
            let g: Vec<f64> = (0..4).map(|i| 2.0 * a[i] * (p[i] - c[i])).collect();
            adam.step("x", &mut p, &g, schedule.at(step)).unwrap();
        }
        for i in 0..4 {
            assert!((p[i] - c[i]).abs() < 1e-3, "p[{i}] = {} vs {}", p[i], c[i]);
        }
        assert_eq!(adam.group("x").unwrap().step, 3000);
    }

    #[test]
    fn steps_follow_the_textbook_formula() {
        let (b1, b2, eps, lr) = (0.9f64, 0.999f64, 1e-15, 0.01);
        let mut adam = Adam::default();
        let mut p = vec![1.0, -2.0, 0.5];
        let g1 = [0.3, -0.1, 0.0];
        adam.step("g", &mut p, &g1, lr).unwrap();
        // Step 1: m̂ = g, v̂ = g², so p moves by lr·sign(g) (0 where g = 0).
        assert!((p[0] - (1.0 - lr)).abs() < 1e-15);
        assert!((p[1] - (-2.0 + lr)).abs() < 1e-15);
        assert_eq!(p[2], 0.5);
        // Step 2 by hand.
        let g2 = [0.1, 0.2, 0.4];
        let before = p.clone();
        adam.step("g", &mut p, &g2, lr).unwrap();
        for i in 0..3 {
            let m = b1 * (1.0 - b1) * g1[i] + (1.0 - b1) * g2[i];
            let v = b2 * (1.0 - b2) * g1[i] * g1[i] + (1.0 - b2) * g2[i] * g2[i];
            let m_hat = m / (1.0 - b1 * b1);
            let v_hat = v / (1.0 - b2 * b2);
            let expected = before[i] - lr * m_hat / (v_hat.sqrt() + eps);
            assert!(
                (p[i] - expected).abs() < 1e-15,
                "{i}: {} vs {expected}",
                p[i]
            );
            let state = adam.group("g").unwrap();
            assert!((state.exp_avg[i] - m).abs() < 1e-18);
            assert!((state.exp_avg_sq[i] - v).abs() < 1e-18);
        }
    }

    #[test]
    fn large_groups_update_like_small_ones() {
        // The rayon path must give the same bits as the serial one.
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let n = PARALLEL_MIN_LEN + 7;
        let p0: Vec<f64> = (0..n).map(|_| rng.random_range(-1.0..1.0)).collect();
        let g: Vec<f64> = (0..n).map(|_| rng.random_range(-1.0..1.0)).collect();
        let mut big = p0.clone();
        let mut adam = Adam::default();
        adam.step("big", &mut big, &g, 0.01).unwrap();
        adam.step("big", &mut big, &g, 0.01).unwrap();
        let mut small_adam = Adam::default();
        for (k, (chunk, gc)) in p0.chunks(100).zip(g.chunks(100)).enumerate() {
            let mut c = chunk.to_vec();
            small_adam.remove_group("s");
            small_adam.step("s", &mut c, gc, 0.01).unwrap();
            small_adam.step("s", &mut c, gc, 0.01).unwrap();
            assert_eq!(&big[k * 100..k * 100 + c.len()], &c[..]);
        }
    }

    #[test]
    fn retain_and_extend_keep_moments_aligned_with_the_surfels() {
        let mut surfels = Surfels::zeros(4);
        for i in 0..4 {
            surfels.opacity[i] = i as f64;
            surfels.position[i] = [i as f64, 10.0 + i as f64, 20.0 + i as f64];
        }
        let mut adam = Adam::default();
        // Gradients equal to the parameters, so each moment identifies its surfel.
        let grads = surfels.clone();
        for ((name, params), (_, g)) in surfels.groups_mut().into_iter().zip(grads.groups()) {
            adam.step(name, params, g, 0.0).unwrap();
        }
        let keep = [true, false, true, true];
        surfels.retain(&keep);
        adam.retain_surfels(&keep).unwrap();
        surfels.extend_from_indices(&[0, 2]);
        adam.extend_surfels_from_indices(&[0, 2]).unwrap();
        for (name, params) in surfels.groups() {
            let state = adam.group(name).unwrap();
            assert_eq!(state.exp_avg.len(), params.len(), "{name}");
            assert_eq!(state.exp_avg_sq.len(), params.len(), "{name}");
        }
        let m = &adam.group("opacity").unwrap().exp_avg;
        // Moments of surfels 0, 2, 3 are (1 − β1)·g; the two appended ones start at zero.
        let expected = [0.0, 0.2, 0.3, 0.0, 0.0];
        assert!(
            m.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-15),
            "{m:?}"
        );
        let pm = &adam.group("position").unwrap().exp_avg;
        assert!((pm[3] - 0.2).abs() < 1e-15 && (pm[4] - 1.2).abs() < 1e-15);
        assert!((pm[6] - 0.3).abs() < 1e-15 && (pm[8] - 2.3).abs() < 1e-15);
        assert!(pm[9..].iter().all(|&v| v == 0.0));
        assert_eq!(adam.group("position").unwrap().step, 1);
        // A later step works on the new length.
        let grads = Surfels::zeros(surfels.len());
        for ((name, params), (_, g)) in surfels.groups_mut().into_iter().zip(grads.groups()) {
            adam.step(name, params, g, 0.01).unwrap();
        }
    }

    #[test]
    fn mismatches_are_errors_naming_the_group() {
        let mut adam = Adam::default();
        let mut p = vec![0.0; 6];
        adam.step("position", &mut p, &[1.0; 6], 0.1).unwrap();
        assert_eq!(adam.group("position").unwrap().width, 3);
        let e = adam.retain("position", &[true; 3]).unwrap_err();
        assert!(e.to_string().contains("`position`"), "{e}");
        let e = adam.extend_from_indices("position", &[2]).unwrap_err();
        assert_eq!(
            e,
            OptimError::IndexOutOfRange {
                group: "position".into(),
                index: 2,
                entries: 2
            }
        );
        let e = adam
            .step("position", &mut [0.0; 3], &[0.0; 3], 0.1)
            .unwrap_err();
        assert!(matches!(
            e,
            OptimError::LengthMismatch {
                what: "parameter",
                ..
            }
        ));
        let e = adam.step("x", &mut [0.0; 3], &[0.0; 2], 0.1).unwrap_err();
        assert!(matches!(
            e,
            OptimError::LengthMismatch {
                what: "gradient",
                ..
            }
        ));
        assert!(adam.add_group("x", 5, 2).is_err());
    }

    #[test]
    fn reset_entries_zeroes_moments_but_keeps_the_step() {
        let mut adam = Adam::default();
        let mut p = vec![0.0; 4];
        adam.step("opacity", &mut p, &[1.0, 2.0, 3.0, 4.0], 0.1)
            .unwrap();
        adam.reset_entries("opacity", &[1, 3]).unwrap();
        let s = adam.group("opacity").unwrap();
        assert_eq!(s.exp_avg[1], 0.0);
        assert_eq!(s.exp_avg_sq[3], 0.0);
        assert!(s.exp_avg[0] > 0.0 && s.exp_avg_sq[2] > 0.0);
        assert_eq!(s.step, 1);
        adam.reset_group("opacity");
        assert!(adam
            .group("opacity")
            .unwrap()
            .exp_avg
            .iter()
            .all(|&v| v == 0.0));
    }

    #[test]
    fn serde_round_trip_is_bit_exact() {
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let mut adam = Adam::default();
        let mut p: Vec<f64> = (0..50).map(|_| rng.random_range(-1.0..1.0)).collect();
        for _ in 0..3 {
            let g: Vec<f64> = (0..50).map(|_| rng.random_range(-1e-3..1e-3)).collect();
            adam.step(ENVMAP_GROUP, &mut p, &g, 0.01).unwrap();
        }
        let json = serde_json::to_string(&adam).unwrap();
        let back: Adam = serde_json::from_str(&json).unwrap();
        let bits = |a: &Adam| {
            a.group(ENVMAP_GROUP)
                .unwrap()
                .exp_avg
                .iter()
                .chain(&a.group(ENVMAP_GROUP).unwrap().exp_avg_sq)
                .map(|v| v.to_bits())
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(&adam), bits(&back));
        assert_eq!(adam, back);
        // Continuing from the restored state gives the same parameters.
        let g = vec![1e-4; 50];
        let (mut p1, mut p2) = (p.clone(), p.clone());
        let mut restored = back;
        adam.step(ENVMAP_GROUP, &mut p1, &g, 0.01).unwrap();
        restored.step(ENVMAP_GROUP, &mut p2, &g, 0.01).unwrap();
        assert_eq!(p1, p2);
    }

    #[test]
    fn exponential_schedule_is_log_linear() {
        let s = ExponentialLr {
            init: 2e-4,
            final_: 2e-6,
            steps: 1000,
        };
        assert!((s.at(0) - 2e-4).abs() < 1e-18);
        assert!((s.at(500) - 2e-5).abs() < 1e-18); // geometric mean at the midpoint
        assert!((s.at(1000) - 2e-6).abs() < 1e-19);
        assert_eq!(s.at(5000), s.at(1000));
        let zero = ExponentialLr {
            init: 0.0,
            final_: 0.0,
            steps: 10,
        };
        assert_eq!(zero.at(3), 0.0);
    }

    #[test]
    fn learning_rates_scale_the_position_by_the_extent() {
        let config = TrainConfig::default();
        let rates = LearningRates::from_config(&config, 2.5);
        assert!((rates.for_group("position", 0).unwrap() - 5e-4).abs() < 1e-18);
        assert!((rates.for_group("position", 15_000).unwrap() - 5e-6).abs() < 1e-19);
        assert_eq!(rates.for_group("opacity", 7), Some(0.05));
        assert_eq!(rates.for_group(POLARIZER_GROUP, 7), Some(0.002));
        assert_eq!(rates.for_group("nope", 0), None);
        for (name, _) in surfel_group_widths() {
            assert!(rates.for_group(name, 0).is_some(), "{name}");
        }
    }
}

//! Everything a training run carries from one iteration to the next, and its checkpoint: surfels,
//! the raw environment cube map, learned polarizer angles, the training views' pose corrections,
//! Adam moments and densification statistics. A checkpoint restores a run bit for bit (randomness is derived from the seed and the
//! iteration number, so no generator state is stored).

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::core::densify::DensifyStats;
use crate::core::envmap::CubeMap;
use crate::core::optim::{Adam, AdamConfig, GroupState};
use crate::core::pose::PoseCorrection;
use crate::core::surfels::Surfels;
use crate::formats::checkpoint::{Archive, CheckpointError};

/// File name of the checkpoint inside a model folder.
pub const CHECKPOINT_FILE: &str = "checkpoint.bin";

/// The mutable state of a run.
#[derive(Clone, Debug)]
pub struct TrainState {
    /// Iterations completed.
    pub iteration: u32,
    pub surfels: Surfels,
    pub envmap: CubeMap,
    /// Learned polarizer angle per `polarizer_group`, radians in [0, π).
    pub polarizer_angles: BTreeMap<String, f64>,
    /// The learned correction of each training view's pose, in the order of the run's targets
    /// (empty in a checkpoint written before runs refined poses: no correction).
    pub poses: Vec<PoseCorrection>,
    /// Whether the poses are refined: fixed by `pose_refinement` `on` or `off`, decided under
    /// `auto` where refinement would start (`None` until then; `train::poses::decide`).
    pub refine_poses: Option<bool>,
    /// What that decision measured: how far the training views' masks lay beside the rendered
    /// silhouettes, each view's own part, RMS pixels (`train::estimated_poses`).
    pub silhouette_offset_px: Option<f64>,
    /// Each training view's colour: its exposure and white balance over the run's, per channel
    /// (`train::colour`; empty in a checkpoint written before runs learned them: all 1).
    pub colours: Vec<[f64; 3]>,
    pub adam: Adam,
    pub densify: DensifyStats,
    /// Wall time spent in earlier sessions of this run.
    pub elapsed_seconds: f64,
    /// The capture's radiance per unit of `envmap`'s (`train::exposure`); 1 in a checkpoint
    /// written before runs normalized their exposure.
    pub radiance_scale: f64,
}

#[derive(Serialize, Deserialize)]
struct Meta {
    iteration: u32,
    envmap_size: usize,
    polarizer_angles: BTreeMap<String, f64>,
    adam_config: AdamConfig,
    adam_groups: BTreeMap<String, (u64, usize)>,
    elapsed_seconds: f64,
    /// Fingerprint of the config the run started with (a resume with another config is refused).
    config_fingerprint: String,
    #[serde(default = "capture_units")]
    radiance_scale: f64,
    /// Absent in a checkpoint from before `auto` decided (its config said, `TrainState::refine_poses`).
    #[serde(default)]
    refine_poses: Option<bool>,
    #[serde(default)]
    silhouette_offset_px: Option<f64>,
}

/// The radiance scale of a checkpoint from before exposure normalization: the capture's units.
fn capture_units() -> f64 {
    1.0
}

impl TrainState {
    /// Writes the checkpoint atomically.
    pub fn save(&self, path: &Path, config_fingerprint: &str) -> Result<(), CheckpointError> {
        let adam_groups = self
            .adam
            .group_names()
            .filter_map(|name| {
                let g = self.adam.group(name)?;
                Some((name.to_owned(), (g.step, g.width)))
            })
            .collect();
        let meta = Meta {
            iteration: self.iteration,
            envmap_size: self.envmap.size,
            polarizer_angles: self.polarizer_angles.clone(),
            adam_config: self.adam.config,
            adam_groups,
            elapsed_seconds: self.elapsed_seconds,
            config_fingerprint: config_fingerprint.to_owned(),
            radiance_scale: self.radiance_scale,
            refine_poses: self.refine_poses,
            silhouette_offset_px: self.silhouette_offset_px,
        };
        let mut archive = Archive::new(serde_json::to_value(&meta).expect("plain data"));
        for (name, values) in self.surfels.groups() {
            archive.put(&format!("surfels.{name}"), values);
        }
        archive.put("envmap", &self.envmap.raw);
        let poses: Vec<f64> = self.poses.iter().flat_map(|p| p.to_array()).collect();
        archive.put("poses", &poses);
        archive.put("colours", self.colours.as_flattened());
        archive.put("densify.grad_sum", &self.densify.grad_sum);
        let seen: Vec<f64> = self.densify.seen.iter().map(|&s| f64::from(s)).collect();
        archive.put("densify.seen", &seen);
        for name in self.adam.group_names() {
            let g = self.adam.group(name).expect("listed group exists");
            archive.put(&format!("adam.{name}.m"), &g.exp_avg);
            archive.put(&format!("adam.{name}.v"), &g.exp_avg_sq);
        }
        archive.write(path)
    }

    /// Reads a checkpoint; returns the state and the config fingerprint it was saved with.
    pub fn load(path: &Path) -> Result<(TrainState, String), CheckpointError> {
        let archive = Archive::read(path)?;
        let corrupt = |problem: String| CheckpointError::Corrupt {
            path: path.to_owned(),
            problem,
        };
        let meta: Meta = serde_json::from_value(archive.meta.clone())
            .map_err(|e| corrupt(format!("metadata: {e}")))?;
        let n = archive.require(path, "surfels.opacity")?.len();
        let mut surfels = Surfels::zeros(n);
        for (name, values) in surfels.groups_mut() {
            let stored = archive.require(path, &format!("surfels.{name}"))?;
            if stored.len() != values.len() {
                return Err(corrupt(format!(
                    "surfel group `{name}` has the wrong length"
                )));
            }
            values.copy_from_slice(stored);
        }
        let envmap = CubeMap::from_raw(meta.envmap_size, archive.require(path, "envmap")?.to_vec())
            .map_err(|e| corrupt(e.to_string()))?;
        let poses = match archive.get("poses") {
            None => Vec::new(),
            Some(values) if values.len() % 6 == 0 => values
                .chunks_exact(6)
                .map(|v| PoseCorrection::from_array(v.try_into().expect("six values")))
                .collect(),
            Some(_) => return Err(corrupt("pose corrections are not whole".to_owned())),
        };
        let colours = match archive.get("colours") {
            None => Vec::new(),
            Some(values) if values.len() % 3 == 0 => {
                values.chunks_exact(3).map(|v| [v[0], v[1], v[2]]).collect()
            }
            Some(_) => return Err(corrupt("view colours are not whole".to_owned())),
        };
        let densify = DensifyStats {
            grad_sum: archive.require(path, "densify.grad_sum")?.to_vec(),
            seen: archive
                .require(path, "densify.seen")?
                .iter()
                .map(|&s| s as u32)
                .collect(),
        };
        let mut adam = Adam::new(meta.adam_config);
        for (name, (step, width)) in &meta.adam_groups {
            let state = GroupState {
                step: *step,
                width: *width,
                exp_avg: archive.require(path, &format!("adam.{name}.m"))?.to_vec(),
                exp_avg_sq: archive.require(path, &format!("adam.{name}.v"))?.to_vec(),
            };
            adam.insert_group(name, state)
                .map_err(|e| corrupt(e.to_string()))?;
        }
        let state = TrainState {
            iteration: meta.iteration,
            surfels,
            envmap,
            polarizer_angles: meta.polarizer_angles,
            poses,
            refine_poses: meta.refine_poses,
            silhouette_offset_px: meta.silhouette_offset_px,
            colours,
            adam,
            densify,
            elapsed_seconds: meta.elapsed_seconds,
            radiance_scale: meta.radiance_scale,
        };
        Ok((state, meta.config_fingerprint))
    }
}

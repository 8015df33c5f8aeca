//! Typed training events: one stream consumed by the progress bar, the JSON-lines progress file and
//! the service's job records, so the three never disagree.

use serde::{Deserialize, Serialize};

/// The stage of the schedule (METHOD.md §7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// Plain 2DGS: colour = albedo, photometric + mask + depth–normal losses.
    Geometry,
    /// Environment map and roughness warm-up.
    Material,
    /// PolarDR with the Stokes loss.
    Polar,
}

/// What a training run reports while it runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum TrainEvent {
    /// The run started (or resumed from `resumed_from`).
    Started {
        iterations: u32,
        mode: String,
        /// The compute backend, what it runs on and how the steps run (e.g. `cpu (16 threads);
        /// steps on the host`, `gpu on NVIDIA …; whole steps on the device`).
        backend: String,
        train_views: usize,
        test_views: usize,
        resumed_from: Option<u32>,
        /// The views' size as trained, e.g. `306×256 (1224×1024 ÷ 4)`.
        #[serde(default)]
        resolution: String,
        /// The capture's radiance per unit of the run's: the views are divided by it
        /// (`pipeline::train::exposure`; 1 in a log from before exposure normalization).
        #[serde(default = "unit_scale")]
        radiance_scale: f64,
    },
    /// One optimization step finished (emitted every few steps, not every one).
    Step {
        iteration: u32,
        iterations: u32,
        stage: Stage,
        /// Total loss and its named terms.
        loss: f64,
        losses: std::collections::BTreeMap<String, f64>,
        num_surfels: usize,
        elapsed_seconds: f64,
        eta_seconds: f64,
        /// The training process's peak resident memory so far, bytes (`None` where the system
        /// does not say, and in logs from before it was reported).
        #[serde(default)]
        peak_rss_bytes: Option<u64>,
    },
    /// Test-view PSNR (sRGB 8-bit S0 inside the mask).
    Evaluated { iteration: u32, test_psnr: f64 },
    /// Something went wrong that the run works around (e.g. GridMap's mesh could not be
    /// extracted and the previous one is kept); the message says what and how.
    Warning { iteration: u32, message: String },
    /// The run decided a setting the config left to it (`auto`) from what it measured:
    /// `setting` is the config key (`pose_refinement`), `on` the decision, `evidence` the
    /// measurement in words.
    Decided {
        iteration: u32,
        setting: String,
        on: bool,
        evidence: String,
    },
    /// A checkpoint was written; training can resume from here.
    Checkpoint { iteration: u32 },
    /// The run finished; the model folder is complete.
    Finished {
        iteration: u32,
        seconds: f64,
        /// The training process's peak resident memory over the run, bytes (as in `Step`).
        #[serde(default)]
        peak_rss_bytes: Option<u64>,
    },
}

/// The radiance scale of a run logged before exposure normalization: the capture's own units.
fn unit_scale() -> f64 {
    1.0
}

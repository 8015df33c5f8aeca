//! Where a run's steps execute. [`StepEngine::Host`]: on the host through the rasterizer backend
//! ([`host_step::run`]), with Adam and the densification statistics applied to the state in host
//! memory (the cpu backend; the gpu backend's per-call kernels). [`StepEngine::Device`]: wholly on
//! the gpu backend's device ([`DeviceTrainer`]), the surfels, their Adam moments and the
//! statistics resident there between the points where the loop needs them on the host
//! (densification and opacity resets, GridMap rebuilds, polarizer-angle estimates, evaluations,
//! checkpoints: [`StepEngine::sync`], then [`StepEngine::load`] after the host changed them).
//!
//! Either way the loop keeps the environment map and the polarizer angles on the host: the
//! light's gradient is summed per step (on the host in [`Pending`], or on the device) and applied
//! every `envmap_prefilter_interval` steps; the angles' gradients come back with every step.

use std::collections::BTreeMap;

use super::host_step::{self, StepInputs};
use super::state::TrainState;
use super::{colour, Run, TrainError};
use crate::core::step::StepPlan;
use std::sync::Arc;

use crate::core::config::IorModel;
use crate::core::envmap::{CubeMap, EnvGrad, PrefilterPlan, PreparedEnv};
use crate::core::events::Stage;
use crate::core::gridmap::GridMap;
use crate::core::light::LightProbe;
use crate::core::optim::{AdamConfig, SHARED_IOR_GROUP};
use crate::gpu::{DeviceStep, DeviceTrainer, GpuError};

/// The light's gradient waiting for the next environment update.
#[derive(Default)]
pub(super) struct Pending {
    /// Shaded steps since the last update.
    pub(super) steps: u32,
    /// Their summed gradient, where the host holds it ([`StepEngine::Host`]).
    pub(super) sum: Option<EnvGrad>,
}

/// What the loop needs from a step.
pub(super) struct StepOutcome {
    /// Named loss terms (weighted) and their sum.
    pub(super) losses: BTreeMap<String, f64>,
    pub(super) total: f64,
    /// Gradient of each learned polarizer angle the view is behind.
    pub(super) angles: BTreeMap<String, f64>,
    /// The step produced a light gradient (a shaded stage).
    pub(super) shaded: bool,
    /// The device's update left every parameter finite (the host checks its own state).
    pub(super) finite: bool,
}

pub(super) enum StepEngine<'r> {
    Host,
    Device(Box<DeviceTrainer<'r>>),
}

impl<'r> StepEngine<'r> {
    /// The device engine where the run's backend is the gpu backend, else the host engine.
    pub(super) fn new(run: &'r Run) -> Result<Self, TrainError> {
        let Some(gpu) = run.backend.gpu() else {
            return Ok(StepEngine::Host);
        };
        let cameras = run.poses.capture_cameras().to_vec();
        let trainer = DeviceTrainer::new(
            gpu,
            run.settings,
            run.loss_weights,
            AdamConfig::default(),
            run.lut,
            &run.targets,
            &cameras,
        );
        match trainer {
            Ok(trainer) => Ok(StepEngine::Device(Box::new(trainer))),
            Err(e @ GpuError::BufferTooLarge { .. }) => {
                tracing::warn!(
                    "{e}: training with host steps (the gpu backend splits large images)"
                );
                Ok(StepEngine::Host)
            }
            Err(e) => Err(e.into()),
        }
    }

    /// Whether `error` is a buffer beyond the device's limits, which the host steps avoid (the
    /// gpu backend's rasterizer splits images into bands of tile rows).
    pub(super) fn is_oversized(error: &TrainError) -> bool {
        matches!(error, TrainError::Gpu(GpuError::BufferTooLarge { .. }))
    }

    /// Continues on the host: the light's pending gradient comes back into `pending`, and with
    /// `state` the device's surfels, moments and statistics (leave it out when the host's state
    /// is the newer one, after a failed [`StepEngine::load`]).
    pub(super) fn fall_back_to_host(
        &mut self,
        state: Option<&mut TrainState>,
        pending: &mut Pending,
    ) -> Result<(), TrainError> {
        if let StepEngine::Device(trainer) = self {
            if pending.steps > 0 {
                pending.sum = Some(trainer.take_light_grad()?);
            }
            if let Some(state) = state {
                trainer.sync(&mut state.surfels, &mut state.adam, &mut state.densify)?;
            }
        }
        *self = StepEngine::Host;
        Ok(())
    }

    /// How the steps run, for the start event.
    pub(super) fn describe(&self) -> &'static str {
        match self {
            StepEngine::Host => "steps on the host",
            StepEngine::Device(_) => "whole steps on the device",
        }
    }

    /// Puts the host's state on the device (nothing to do for the host engine).
    pub(super) fn load(&mut self, state: &TrainState) -> Result<(), TrainError> {
        if let StepEngine::Device(trainer) = self {
            trainer.load(&state.surfels, &state.adam, &state.densify)?;
        }
        Ok(())
    }

    /// Brings the device's state back to the host (nothing to do for the host engine).
    pub(super) fn sync(&mut self, state: &mut TrainState) -> Result<(), TrainError> {
        if let StepEngine::Device(trainer) = self {
            trainer.sync(&mut state.surfels, &mut state.adam, &mut state.densify)?;
        }
        Ok(())
    }

    /// The learned environment of the following steps. The device engine prefilters it on the
    /// device (the host engine's steps read the host's `PreparedEnv`).
    pub(super) fn set_environment(
        &mut self,
        cube: &CubeMap,
        plan: &Arc<PrefilterPlan>,
    ) -> Result<(), TrainError> {
        if let StepEngine::Device(trainer) = self {
            trainer.set_envmap(cube, plan)?;
        }
        Ok(())
    }

    /// Whether [`Self::set_environment`] prefilters on the device (then the host's prefiltered
    /// copy need not follow every update).
    pub(super) fn prefilters_on_device(&self) -> bool {
        matches!(self, StepEngine::Device(_))
    }

    /// GridMap's probes over the global light, or none.
    pub(super) fn set_gridmap(&mut self, grid: Option<&GridMap>) -> Result<(), TrainError> {
        if let StepEngine::Device(trainer) = self {
            trainer.set_gridmap(grid)?;
        }
        Ok(())
    }

    /// The gradient on the learned cube map's raw texels of the light's gradient summed since
    /// the last update (`env` is the prefilter the host engine's steps were lit by), and starts
    /// the sum again; `None` when no step was shaded.
    pub(super) fn take_env_raw_grad(
        &mut self,
        pending: &mut Pending,
        env: &PreparedEnv,
    ) -> Result<Option<Vec<f64>>, TrainError> {
        if pending.steps == 0 {
            return Ok(None);
        }
        pending.steps = 0;
        Ok(match self {
            StepEngine::Host => pending.sum.take().map(|sum| env.backward(&sum)),
            StepEngine::Device(trainer) => Some(trainer.take_envmap_grad()?),
        })
    }

    /// One step on `run.targets[target]`: forward, losses, backward, the surfels' Adam update and
    /// the densification statistics; the light's gradient goes to `pending`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn step(
        &mut self,
        run: &Run,
        state: &mut TrainState,
        light: &dyn LightProbe,
        target: usize,
        stage: Stage,
        pending: &mut Pending,
    ) -> Result<StepOutcome, TrainError> {
        let it = state.iteration;
        let view = &run.targets[target];
        let camera = &run.poses.camera(&state.poses, target);
        let weights = run.loss_weights;
        let rates = run.surfel_rates(stage, it);
        let outcome = match self {
            StepEngine::Host => {
                let inputs = StepInputs {
                    backend: &**run.backend,
                    settings: run.settings,
                    lut: run.lut,
                    weights,
                };
                let result = host_step::run(
                    &inputs,
                    &state.surfels,
                    light,
                    &state.polarizer_angles,
                    camera,
                    view,
                    state.colours[target],
                    stage,
                )?;
                let grads = result.surfels.groups();
                for (((name, params), (_, grad)), lr) in
                    state.surfels.groups_mut().into_iter().zip(grads).zip(rates)
                {
                    let Some(lr) = lr else { continue };
                    match (name, run.config.ior_model) {
                        ("ior", IorModel::Shared) => {
                            state.adam.step_tied(SHARED_IOR_GROUP, params, grad, lr)?
                        }
                        ("ior", IorModel::Anchored) => {
                            state.adam.step(name, params, grad, lr)?;
                            state
                                .adam
                                .step_common_offset(SHARED_IOR_GROUP, params, grad, lr)?
                        }
                        _ => state.adam.step(name, params, grad, lr)?,
                    }
                }
                let shaded = result.env.is_some();
                if let Some(env_grad) = result.env {
                    match &mut pending.sum {
                        Some(sum) => sum.add(&env_grad),
                        None => pending.sum = Some(env_grad),
                    }
                }
                state
                    .densify
                    .add_view(&result.mean2d_grad_norm, result.width, result.height);
                if let (Some(grad), Some(rate)) =
                    (result.pose, run.poses.rate(it, state.refine_poses))
                {
                    run.poses
                        .update(&mut state.adam, &mut state.poses, target, &grad, rate)?;
                }
                if run.refines_colours(it) {
                    colour::update(&mut state.colours, target, result.colour_ratio);
                }
                StepOutcome {
                    losses: result.losses,
                    total: result.total,
                    angles: result.angles,
                    shaded,
                    finite: true,
                }
            }
            StepEngine::Device(trainer) => {
                let plan = StepPlan::new(view, stage, &state.polarizer_angles, &weights);
                let result = trainer.step(&DeviceStep {
                    view: target,
                    camera,
                    plan: &plan,
                    rates,
                })?;
                let losses = plan.losses(&result.sums, &weights, camera.num_pixels());
                let mut angles = BTreeMap::new();
                if let Some(name) = &plan.learned_angle {
                    angles.insert(name.clone(), result.angle_grad);
                }
                StepOutcome {
                    total: losses.values().sum(),
                    losses,
                    angles,
                    shaded: plan.shaded,
                    finite: result.finite,
                }
            }
        };
        if outcome.shaded {
            pending.steps += 1;
        }
        Ok(outcome)
    }
}

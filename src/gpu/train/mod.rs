//! The resident trainer: whole training steps on the device, with the surfels, their Adam
//! moments, the densification statistics, every view's targets and the light kept there between
//! steps. Per step the host writes four small uniform buffers, encodes one submission and reads
//! back the step status (a few dozen words: the loss sums, the polarizer angle's gradient, the
//! tile-entry count and two flags); the state comes back only when the training loop needs it on
//! the host (densification, GridMap, evaluation, checkpoints: [`DeviceTrainer::sync`]), and the
//! light's gradient when the environment is updated ([`DeviceTrainer::take_light_grad`]).
//!
//! One step ([`DeviceTrainer::step`], each stage a compute pass; the plan of
//! [`crate::core::step::StepPlan`] decides what applies):
//! projection (`project.wgsl`), a device scan of the tile counts (`scan.wgsl`, which also writes
//! the indirect dispatch sizes), binning and the radix sort over all 31 depth bits and the tile
//! bits (indirect), tile ranges, rasterization, the shader's inputs and the depth-derived normals
//! (`train_pixels.wgsl`), PolarDR shading under the global light or GridMap (`shade*.wgsl`), the
//! prediction, SSIM and the other loss terms with their gradients (`train_loss.wgsl`), the
//! shader's backward pass, the depth normal's backward pass and the upstream gradient of every
//! G-buffer, the rasterizer's and the projection's backward passes, and Adam with the
//! densification statistics (`train_update.wgsl`).
//!
//! Tile entries: their buffer holds a capacity chosen from the previous steps. A step whose
//! entries do not fit drops the excess, skips its update (the kernels read the overflow flag the
//! scan wrote) and is rerun with a larger buffer, so no step is ever applied from a partial sort.
//! Entries beyond the device's binding limit fail with [`GpuError::BufferTooLarge`].
//!
//! Precision: f32 throughout (parameters and moments included); the parity tests compare a step's
//! losses and gradients with the host's f64 step, and short training runs with the cpu backend's.
//! Threading: one step at a time (the trainer is `&mut`); the kernels' threading is in their files.

mod buffers;
mod kernels;
mod passes;

use std::sync::Arc;

use tracing::info_span;

use super::backend::GpuBackend;
use super::bind_cache::{BindCache, BindCounts};
use super::device::Device;
use super::light::{HostLight, HostProbes, LightBuffers, ProbeBuffers};
use super::params::{ParamsGpu, ENTRY_BYTES, NUM_RAW_GRAD};
use super::prefilter::DevicePrefilter;
use super::GpuError;
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::densify::DensifyStats;
use crate::core::envmap::{CubeMap, EnvGrad, PrefilterPlan, PreparedEnv};
use crate::core::gridmap::GridMap;
use crate::core::loss::LossWeights;
use crate::core::optim::{Adam, AdamConfig};
use crate::core::raster::RasterSettings;
use crate::core::shading::ShadingError;
use crate::core::step::{LossSums, StepPlan, ViewTarget};
use crate::core::surfels::Surfels;
use buffers::{EntryBuffers, FrameBuffers, SurfelBuffers, GROUP_SLOTS, TARGET_FLOATS};
use kernels::{
    AdamParamsGpu, ScanParamsGpu, TrainKernels, TrainParamsGpu, STATUS_ENTRIES, STATUS_NONFINITE,
    STATUS_OVERFLOW, STATUS_WORDS, SUM_FIRST,
};

/// Bits of the f32 centre depth the sort orders by: all but the sign, which is 0 for every
/// surfel in front of the camera.
const DEPTH_BITS: u32 = 31;
/// Tile entries per surfel the first step makes room for.
const INITIAL_ENTRIES_PER_SURFEL: u64 = 8;

/// One step's inputs.
pub struct DeviceStep<'a> {
    /// The view's index in the targets given to [`DeviceTrainer::new`].
    pub view: usize,
    pub camera: &'a Camera,
    pub plan: &'a StepPlan,
    /// The learning rate of each surfel parameter group, in the order of `Surfels::groups`;
    /// `None` for a group frozen in this stage.
    pub rates: [Option<f64>; 7],
}

/// What a step brings back.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceStepResult {
    pub sums: LossSums,
    /// dL/dθ of the view's learned polarizer angle (0 when it has none).
    pub angle_grad: f64,
    pub tile_entries: u64,
    /// False when the update left a non-finite parameter (the run diverged).
    pub finite: bool,
}

/// The global light on the device, with the gradient of the current step and the sum waiting
/// for the next environment update.
struct LightState {
    host: HostLight,
    buffers: LightBuffers,
    step_grad: wgpu::Buffer,
    pending: wgpu::Buffer,
}

/// Whole training steps on a [`GpuBackend`]'s device.
pub struct DeviceTrainer<'g> {
    gpu: &'g GpuBackend,
    kernels: TrainKernels,
    settings: RasterSettings,
    weights: LossWeights,
    adam: AdamConfig,
    lut: &'g BrdfLut,
    /// Per training view: its target ([`TARGET_FLOATS`] per pixel) and its image size.
    targets: Vec<(wgpu::Buffer, u32, u32)>,
    surfels: Option<SurfelBuffers>,
    /// Adam's step count of each surfel group, `None` for a group without state yet.
    group_steps: [(&'static str, Option<u64>); 7],
    entries: Option<EntryBuffers>,
    frame: Option<FrameBuffers>,
    light: Option<LightState>,
    probes: Option<ProbeBuffers>,
    /// The environment prefilter, once [`DeviceTrainer::set_envmap`] has run.
    prefilter: Option<DevicePrefilter>,
    status: wgpu::Buffer,
    dispatch: wgpu::Buffer,
    scan_params: wgpu::Buffer,
    adam_params: wgpu::Buffer,
    /// The bind groups of the last two steps' dispatches.
    binds: BindCache,
    /// The device holds steps the host's state has not seen.
    host_stale: bool,
}

/// A view's target laid out per pixel as the run fits it: photometric RGB, mask, S1 and S2 RGB
/// (zero without them), the photometric and Stokes samples times the view's gain; then the
/// confidence of the pixel's polarization and its weight in the mask loss (1 without them).
fn target_values(target: &ViewTarget) -> Vec<f32> {
    let pixels = target.mask.len();
    let mut out = Vec::with_capacity(pixels * TARGET_FLOATS as usize);
    let g = target.gain;
    for p in 0..pixels {
        let rgb = |v: &[f32]| [v[3 * p] * g, v[3 * p + 1] * g, v[3 * p + 2] * g];
        let (s1, s2) = match &target.stokes {
            Some((s1, s2)) => (rgb(s1), rgb(s2)),
            None => ([0.0; 3], [0.0; 3]),
        };
        let photometric = rgb(&target.photometric);
        let per_pixel = |plane: &Option<Vec<f32>>| plane.as_ref().map_or(1.0, |v| v[p]);
        out.extend(
            photometric
                .into_iter()
                .chain([target.mask[p]])
                .chain(s1)
                .chain(s2)
                .chain([
                    per_pixel(&target.polarization_confidence),
                    per_pixel(&target.mask_weight),
                ]),
        );
    }
    out
}

impl<'g> DeviceTrainer<'g> {
    /// Compiles the kernels and uploads every view's target (`cameras[i]` sees `targets[i]`), one
    /// at a time: each upload is flushed before the next view's values are built, so wgpu's
    /// staging copies of them are not all held at once (42 training views of 1224×1024 would
    /// hold 2.1 GB of them until the first step).
    pub fn new(
        gpu: &'g GpuBackend,
        settings: RasterSettings,
        weights: LossWeights,
        adam: AdamConfig,
        lut: &'g BrdfLut,
        targets: &[ViewTarget],
        cameras: &[Camera],
    ) -> Result<Self, GpuError> {
        let device = gpu.device();
        let kernels = TrainKernels::compile(device)?;
        let targets = targets
            .iter()
            .zip(cameras)
            .map(|(t, c)| {
                let values = target_values(t);
                let buffer = device.storage_init("view target", bytemuck::cast_slice(&values))?;
                device.flush_uploads()?;
                Ok((buffer, c.width, c.height))
            })
            .collect::<Result<Vec<_>, GpuError>>()?;
        let storage =
            |name: &str, words: usize, extra| device.storage(name, words as u64 * 4, extra);
        Ok(DeviceTrainer {
            status: storage(
                "step status",
                STATUS_WORDS,
                wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
            )?,
            dispatch: storage("indirect dispatches", 6, wgpu::BufferUsages::INDIRECT)?,
            scan_params: device.uniform("scan params", &[0; size_of::<ScanParamsGpu>()]),
            adam_params: device.uniform("adam params", &[0; size_of::<AdamParamsGpu>()]),
            gpu,
            kernels,
            settings,
            weights,
            adam,
            lut,
            targets,
            surfels: None,
            group_steps: GROUP_SLOTS.map(|(name, _)| (name, None)),
            entries: None,
            frame: None,
            light: None,
            probes: None,
            prefilter: None,
            binds: BindCache::default(),
            host_stale: false,
        })
    }

    fn device(&self) -> &'g Device {
        self.gpu.device()
    }

    /// Puts the host's surfels, their Adam moments (and step counts) and densification
    /// statistics on the device, replacing what it held.
    pub fn load(
        &mut self,
        surfels: &Surfels,
        adam: &Adam,
        densify: &DensifyStats,
    ) -> Result<(), GpuError> {
        let _span = info_span!("device_load", surfels = surfels.len()).entered();
        let device = self.device();
        let buffers = device.scoped("load", || {
            SurfelBuffers::upload(device, surfels, adam, densify)
        })?;
        for (name, step) in &mut self.group_steps {
            *step = adam.group(name).map(|g| g.step);
        }
        let wanted = (surfels.len() as u64 * INITIAL_ENTRIES_PER_SURFEL).max(1 << 16);
        if self.entries.as_ref().is_none_or(|e| e.capacity < wanted) {
            let capacity = wanted.min(device.binding_limit() / ENTRY_BYTES);
            self.entries = Some(EntryBuffers::new(device, capacity)?);
        }
        self.surfels = Some(buffers);
        self.host_stale = false;
        Ok(())
    }

    /// Brings the device's surfels, Adam moments and statistics back into the host's state, if
    /// steps ran since they were last there.
    pub fn sync(
        &mut self,
        surfels: &mut Surfels,
        adam: &mut Adam,
        densify: &mut DensifyStats,
    ) -> Result<(), GpuError> {
        if !self.host_stale {
            return Ok(());
        }
        let Some(buffers) = &self.surfels else {
            return Ok(());
        };
        let _span = info_span!("device_sync", surfels = buffers.count).entered();
        let device = self.device();
        let steps = self.group_steps;
        device.scoped("sync", || {
            buffers.download(device, surfels, adam, &steps, densify)
        })?;
        self.host_stale = false;
        Ok(())
    }

    /// Replaces the global light (the learned environment moved). The gradient waiting for the
    /// next update is kept when the layout is the same.
    pub fn set_light(&mut self, env: &PreparedEnv) -> Result<(), ShadingError> {
        let host = HostLight::new(env, self.lut)?;
        let device = self.device();
        let old = self.light.take();
        let light = device.scoped("light upload", || Self::light_state(device, host, old))?;
        self.light = Some(light);
        Ok(())
    }

    /// Replaces the global light by the prefilter of the learned cube map `cube` under `plan`,
    /// computed on the device (the map goes up raw). The gradient waiting for the next update is
    /// kept.
    pub fn set_envmap(
        &mut self,
        cube: &CubeMap,
        plan: &Arc<PrefilterPlan>,
    ) -> Result<(), ShadingError> {
        let _span = info_span!("device_prefilter", size = cube.size).entered();
        let device = self.device();
        if self
            .prefilter
            .as_ref()
            .is_none_or(|p| !Arc::ptr_eq(p.plan(), plan))
        {
            self.prefilter = Some(DevicePrefilter::new(device, plan.clone())?);
        }
        let layout = HostLight::layout(plan, self.lut)?;
        if self
            .light
            .as_ref()
            .is_none_or(|l| !l.host.same_layout(&layout))
        {
            let light =
                device.scoped("light upload", || Self::light_state(device, layout, None))?;
            self.light = Some(light);
        }
        let (Some(prefilter), Some(light)) = (&self.prefilter, &self.light) else {
            unreachable!("both were just made");
        };
        device.scoped("prefilter", || -> Result<(), GpuError> {
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            prefilter.encode_forward(device, &mut encoder, cube, light.buffers.values())?;
            device.queue().submit([encoder.finish()]);
            Ok(())
        })?;
        Ok(())
    }

    /// The gradient on the learned cube map's raw texels of the light's gradient summed since
    /// the last call (the transposed prefilter on the device, for lights of
    /// [`Self::set_envmap`]); the sum starts again from zero.
    pub fn take_envmap_grad(&mut self) -> Result<Vec<f64>, GpuError> {
        let (Some(prefilter), Some(light)) = (&self.prefilter, &self.light) else {
            return Err(GpuError::Device(
                "no prefiltered environment on the device".into(),
            ));
        };
        let device = self.device();
        let grad = device.scoped("environment gradient", || -> Result<Vec<f32>, GpuError> {
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            prefilter.encode_backward(device, &mut encoder, &light.pending)?;
            encoder.clear_buffer(&light.pending, 0, None);
            let (raw_grad, bytes) = prefilter.raw_gradient();
            let data = device.submit_and_read(encoder, &[(raw_grad, bytes)])?;
            Ok(bytemuck::pod_collect_to_vec(&data[0]))
        })?;
        Ok(grad.into_iter().map(f64::from).collect())
    }

    /// A light's buffers, with the gradient buffers of `old` when it has the same layout.
    fn light_state(
        device: &Device,
        host: HostLight,
        old: Option<LightState>,
    ) -> Result<LightState, GpuError> {
        let buffers = host.upload(device)?;
        let (step_grad, pending) = match old {
            Some(old) if old.host.same_layout(&host) => (old.step_grad, old.pending),
            _ => {
                let bytes = host.gradient_bytes();
                let usage = wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST;
                (
                    device.storage("light gradient (step)", bytes, usage)?,
                    device.storage("light gradient", bytes, usage)?,
                )
            }
        };
        Ok(LightState {
            host,
            buffers,
            step_grad,
            pending,
        })
    }

    /// Lights the following steps with GridMap's probes (over the global light of
    /// [`Self::set_light`]), or with the global light alone.
    pub fn set_gridmap(&mut self, grid: Option<&GridMap>) -> Result<(), ShadingError> {
        let device = self.device();
        self.probes = match grid {
            None => None,
            Some(grid) => {
                let host = HostProbes::new(grid)?;
                Some(device.scoped("GridMap upload", || host.upload(device))?)
            }
        };
        Ok(())
    }

    /// The light's gradient summed over the steps since the last call (zero when none shaded),
    /// shaped like the global light's; the sum starts again from zero.
    pub fn take_light_grad(&mut self) -> Result<EnvGrad, GpuError> {
        let Some(light) = &self.light else {
            return Err(GpuError::Device("no light on the device".into()));
        };
        let device = self.device();
        let sums = device.scoped("light gradient", || -> Result<Vec<f32>, GpuError> {
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            let bytes = light.host.gradient_bytes();
            let usage = wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST;
            let copy = device.storage("light gradient (read)", bytes, usage)?;
            encoder.copy_buffer_to_buffer(&light.pending, 0, &copy, 0, bytes);
            encoder.clear_buffer(&light.pending, 0, None);
            let data = device.submit_and_read(encoder, &[(&copy, bytes)])?;
            Ok(bytemuck::pod_collect_to_vec(&data[0]))
        })?;
        Ok(light.host.env_grad(&sums))
    }

    /// Runs one step: forward, losses, backward and the Adam update of every unfrozen group.
    pub fn step(&mut self, step: &DeviceStep) -> Result<DeviceStepResult, GpuError> {
        let _span = info_span!("device_step", view = step.view).entered();
        if self.surfels.is_none() {
            return Err(GpuError::Device(
                "no surfels on the device (load them first)".into(),
            ));
        }
        let &(_, width, height) = self
            .targets
            .get(step.view)
            .ok_or_else(|| GpuError::Device(format!("no target for view {}", step.view)))?;
        if (step.camera.width, step.camera.height) != (width, height) {
            return Err(GpuError::Device(format!(
                "view {} is {}×{} but its target {width}×{height}",
                step.view, step.camera.width, step.camera.height
            )));
        }
        if step.plan.shaded && self.light.is_none() {
            return Err(GpuError::Device(
                "a shaded step needs a light (set_light)".into(),
            ));
        }
        let device = self.device();
        if self
            .frame
            .as_ref()
            .is_none_or(|f| (f.width, f.height) != (width, height))
        {
            self.frame = Some(FrameBuffers::new(
                device,
                width,
                height,
                std::mem::size_of::<TrainParamsGpu>(),
            )?);
        }
        let status = loop {
            let status = device.scoped("training step", || self.run(step))?;
            let total = u64::from(status[STATUS_ENTRIES]);
            let capacity = self.entries.as_ref().map_or(0, |e| e.capacity);
            // Room for the next steps (a view sees a similar number of entries).
            if total > capacity * 9 / 10 {
                let limit = device.binding_limit() / ENTRY_BYTES;
                if total > limit {
                    return Err(device.too_large("tile entries", total * ENTRY_BYTES));
                }
                let grown = (total + total / 4 + 1024).min(limit);
                tracing::debug!(
                    entries = total,
                    capacity = grown,
                    "growing the tile entries"
                );
                self.entries = Some(EntryBuffers::new(device, grown)?);
            }
            if status[STATUS_OVERFLOW] == 0 {
                break status;
            }
        };
        for ((_, steps), rate) in self.group_steps.iter_mut().zip(step.rates) {
            if rate.is_some() {
                *steps = Some(steps.unwrap_or(0) + 1);
            }
        }
        self.host_stale = true;
        let sum = |slot: usize| f64::from(f32::from_bits(status[SUM_FIRST + slot]));
        Ok(DeviceStepResult {
            sums: LossSums {
                l1: sum(0),
                ssim: sum(1),
                mask: sum(2),
                stokes: sum(3),
                normal_smooth: sum(4),
                depth_normal: sum(5),
                depth_normal_pixels: sum(6),
                distortion: sum(8),
                aolp: sum(9),
            },
            angle_grad: sum(7),
            tile_entries: u64::from(status[STATUS_ENTRIES]),
            finite: status[STATUS_NONFINITE] == 0,
        })
    }

    /// The step's uniform parameters.
    fn write_params(&self, step: &DeviceStep, frame: &FrameBuffers, surfels: u32) {
        let device = self.device();
        let queue = device.queue();
        let camera = step.camera;
        let raster = ParamsGpu::whole_image(camera, &self.settings, surfels);
        queue.write_buffer(&frame.raster_params, 0, bytemuck::bytes_of(&raster));
        let train = TrainParamsGpu::new(step, frame, &self.weights, &self.settings);
        queue.write_buffer(&frame.train_params, 0, bytemuck::bytes_of(&train));
        if let Some(light) = &self.light {
            let shade = light
                .host
                .params(camera, 0, frame.pixels as usize, self.probes.as_ref());
            queue.write_buffer(&frame.shade_params, 0, bytemuck::bytes_of(&shade));
        }
        let capacity = self.entries.as_ref().map_or(0, |e| e.capacity);
        let scan = ScanParamsGpu {
            n: surfels,
            capacity: capacity.min(u64::from(u32::MAX)) as u32,
            max_groups: device.wgpu().limits().max_compute_workgroups_per_dimension,
            pad0: 0,
        };
        queue.write_buffer(&self.scan_params, 0, bytemuck::bytes_of(&scan));
        let adam = AdamParamsGpu::new(&self.adam, surfels, frame, &step.rates, &self.group_steps);
        queue.write_buffer(&self.adam_params, 0, bytemuck::bytes_of(&adam));
    }

    /// The light's texel values as the shading kernels read them (every level, then every
    /// irradiance map), for the tests of the device prefilter.
    #[doc(hidden)]
    pub fn light_texels(&self) -> Result<Vec<f32>, GpuError> {
        let Some(light) = &self.light else {
            return Ok(Vec::new());
        };
        let device = self.device();
        let bytes = light.host.gradient_bytes();
        let encoder = device.wgpu().create_command_encoder(&Default::default());
        let data = device.scoped("read light", || {
            device.submit_and_read(encoder, &[(light.buffers.values(), bytes)])
        })?;
        Ok(bytemuck::pod_collect_to_vec(&data[0]))
    }

    /// Room for this many tile entries (the next steps grow it as they need), for the tests of
    /// the overflow path.
    #[doc(hidden)]
    pub fn set_entry_capacity(&mut self, capacity: u64) -> Result<(), GpuError> {
        self.entries = Some(EntryBuffers::new(self.device(), capacity.max(1))?);
        Ok(())
    }

    /// Bind groups the steps created and reused, for the tests of the cache.
    #[doc(hidden)]
    pub fn bind_counts(&self) -> BindCounts {
        self.binds.counts()
    }

    /// Bind groups the cache holds now.
    #[doc(hidden)]
    pub fn cached_bind_groups(&self) -> usize {
        self.binds.len()
    }

    /// The tile entries the buffer holds.
    pub fn entry_capacity(&self) -> u64 {
        self.entries.as_ref().map_or(0, |e| e.capacity)
    }

    /// The raw gradients of the last step (16 per surfel, project_backward.wgsl's layout), for
    /// the parity tests.
    #[doc(hidden)]
    pub fn last_raw_gradients(&self) -> Result<Vec<f32>, GpuError> {
        let Some(s) = &self.surfels else {
            return Ok(Vec::new());
        };
        let device = self.device();
        let bytes = s.count as u64 * NUM_RAW_GRAD as u64 * 4;
        let encoder = device.wgpu().create_command_encoder(&Default::default());
        let data = device.scoped("read gradients", || {
            device.submit_and_read(encoder, &[(&s.raw_grad, bytes)])
        })?;
        Ok(bytemuck::pod_collect_to_vec(&data[0]))
    }
}

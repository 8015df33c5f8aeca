//! The resident trainer's own kernels (`shaders/scan.wgsl`, `train_*.wgsl`) and the uniform
//! parameters they read. The rasterization and shading kernels are the [`super::GpuBackend`]'s.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use super::buffers::{FrameBuffers, GROUP_SLOTS};
use super::DeviceStep;
use crate::gpu::device::Device;
use crate::gpu::GpuError;
use crate::loss::LossWeights;
use crate::optim::AdamConfig;
use crate::raster::RasterSettings;
use crate::render::SHADE_ALPHA_MIN;

const SCAN: &str = include_str!("../../../shaders/scan.wgsl");
const TRAIN_COMMON: &str = include_str!("../../../shaders/train_common.wgsl");
const TRAIN_PARAMS: &str = include_str!("../../../shaders/train_params.wgsl");
const TRAIN_PIXELS: &str = include_str!("../../../shaders/train_pixels.wgsl");
const TRAIN_LOSS: &str = include_str!("../../../shaders/train_loss.wgsl");
const TRAIN_UPDATE: &str = include_str!("../../../shaders/train_update.wgsl");

/// Counts per block of `scan_blocks` (`SCAN_BLOCK`).
pub(super) const SCAN_BLOCK: u64 = 1024;
/// Partial-sum slots of the loss kernels (`SLOTS` of train_common.wgsl).
pub(super) const SLOTS: u64 = 8;
/// Words of the step status (`STATUS_*` of train_common.wgsl and the sums from `SUM_FIRST`;
/// word 0, the entries that fit, is read by the kernels only).
pub(super) const STATUS_WORDS: usize = 16;
pub(super) const STATUS_ENTRIES: usize = 1;
pub(super) const STATUS_OVERFLOW: usize = 2;
pub(super) const STATUS_NONFINITE: usize = 3;
pub(super) const SUM_FIRST: usize = 8;

/// The resident trainer's kernels.
pub(super) struct TrainKernels {
    pub(super) scan_blocks: wgpu::ComputePipeline,
    pub(super) scan_sums: wgpu::ComputePipeline,
    pub(super) scan_add: wgpu::ComputePipeline,
    pub(super) prepare_pixels: wgpu::ComputePipeline,
    pub(super) depth_normal_backward: wgpu::ComputePipeline,
    pub(super) assemble_upstream: wgpu::ComputePipeline,
    pub(super) compose: wgpu::ComputePipeline,
    pub(super) ssim_moments_h: wgpu::ComputePipeline,
    pub(super) ssim_moments_v: wgpu::ComputePipeline,
    pub(super) ssim_adjoint_h: wgpu::ComputePipeline,
    pub(super) loss_chain: wgpu::ComputePipeline,
    pub(super) reduce_losses: wgpu::ComputePipeline,
    pub(super) adam: wgpu::ComputePipeline,
    pub(super) accumulate_light: wgpu::ComputePipeline,
}

impl TrainKernels {
    pub(super) fn compile(device: &Device) -> Result<Self, GpuError> {
        device.compile_all(|d| {
            let pixels =
                |entry: &str| d.pipeline(entry, &[TRAIN_COMMON, TRAIN_PARAMS, TRAIN_PIXELS], entry);
            let loss =
                |entry: &str| d.pipeline(entry, &[TRAIN_COMMON, TRAIN_PARAMS, TRAIN_LOSS], entry);
            let update = |entry: &str| d.pipeline(entry, &[TRAIN_COMMON, TRAIN_UPDATE], entry);
            TrainKernels {
                scan_blocks: d.pipeline("scan_blocks", &[SCAN], "scan_blocks"),
                scan_sums: d.pipeline("scan_sums", &[SCAN], "scan_sums"),
                scan_add: d.pipeline("scan_add", &[SCAN], "scan_add"),
                prepare_pixels: pixels("prepare_pixels"),
                depth_normal_backward: pixels("depth_normal_backward"),
                assemble_upstream: pixels("assemble_upstream"),
                compose: loss("compose"),
                ssim_moments_h: loss("ssim_moments_h"),
                ssim_moments_v: loss("ssim_moments_v"),
                ssim_adjoint_h: loss("ssim_adjoint_h"),
                loss_chain: loss("loss_chain"),
                reduce_losses: loss("reduce_losses"),
                adam: update("adam"),
                accumulate_light: update("accumulate_light"),
            }
        })
    }
}

/// `ScanParams` of scan.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(super) struct ScanParamsGpu {
    pub(super) n: u32,
    pub(super) capacity: u32,
    pub(super) max_groups: u32,
    pub(super) unused: u32,
}

/// `TrainParams` of train_params.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub(super) struct TrainParamsGpu {
    pub(super) dims: [u32; 4],
    pub(super) mode: [u32; 4],
    pub(super) theta: [f32; 4],
    pub(super) weights: [f32; 4],
    pub(super) weights2: [f32; 4],
    pub(super) rot: [[f32; 4]; 3],
    pub(super) origin: [f32; 4],
    pub(super) intr: [f32; 4],
    pub(super) gauss: [f32; 12],
}

fn v4(v: DVec3) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, 0.0]
}

impl TrainParamsGpu {
    /// The parameters of `step` on `frame`: which terms and weights apply (the step's plan),
    /// the polarizer angle, the camera, and SSIM's window.
    pub(super) fn new(
        step: &DeviceStep,
        frame: &FrameBuffers,
        weights: &LossWeights,
        settings: &RasterSettings,
    ) -> Self {
        let (camera, plan) = (step.camera, step.plan);
        let when = |on: bool, value: f64| if on { value as f32 } else { 0.0 };
        let (cos2, sin2) = plan
            .theta
            .map_or((1.0, 0.0), |t| ((2.0 * t).cos(), (2.0 * t).sin()));
        let r = camera.rotation_opencv();
        let window = crate::loss::ssim::gaussian_kernel();
        TrainParamsGpu {
            dims: [
                frame.width,
                frame.height,
                frame.pixels as u32,
                frame.groups(),
            ],
            mode: [
                u32::from(plan.shaded),
                u32::from(plan.stokes_loss),
                u32::from(plan.theta.is_some()),
                0,
            ],
            theta: [
                cos2 as f32,
                sin2 as f32,
                plan.unpolarized_scale as f32,
                when(plan.extra_l1, weights.lambda_stokes),
            ],
            weights: [
                weights.lambda_ssim as f32,
                when(plan.stokes_loss, weights.lambda_stokes),
                weights.lambda_mask as f32,
                when(plan.normal_smooth, weights.lambda_normal_smooth),
            ],
            weights2: [
                when(plan.depth_normal, weights.lambda_depth_normal),
                settings.normalize_alpha_min as f32,
                SHADE_ALPHA_MIN as f32,
                0.0,
            ],
            rot: [v4(r.x_axis), v4(r.y_axis), v4(r.z_axis)],
            origin: v4(camera.origin()),
            intr: [
                camera.fx as f32,
                camera.fy as f32,
                camera.cx as f32,
                camera.cy as f32,
            ],
            gauss: std::array::from_fn(|k| window.get(k).map_or(0.0, |&v| v as f32)),
        }
    }
}

/// `AdamParams` of train_update.wgsl: per raw slot, its group's rate, bias corrections and
/// whether it is trained.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub(super) struct AdamParamsGpu {
    pub(super) counts: [u32; 4],
    pub(super) betas: [f32; 4],
    pub(super) lr: [f32; 16],
    pub(super) bias1: [f32; 16],
    pub(super) bias2: [f32; 16],
    pub(super) trained: [u32; 16],
}

impl AdamParamsGpu {
    /// One Adam step of `surfels` surfels on `frame`'s view: each group's rate (`rates`, `None`
    /// for a frozen group) and the bias corrections of its next step (`steps`: the steps each
    /// group has taken, `None` before its first).
    pub(super) fn new(
        config: &AdamConfig,
        surfels: u32,
        frame: &FrameBuffers,
        rates: &[Option<f64>; 7],
        steps: &[(&str, Option<u64>); 7],
    ) -> Self {
        let mut params = AdamParamsGpu {
            counts: [surfels, 0, 0, 0],
            betas: [
                config.beta1 as f32,
                config.beta2 as f32,
                config.eps as f32,
                (0.5 * f64::from(frame.width.max(frame.height))) as f32,
            ],
            ..AdamParamsGpu::default()
        };
        for ((&(_, slots), rate), &(_, taken)) in GROUP_SLOTS.iter().zip(rates).zip(steps) {
            let Some(lr) = *rate else {
                continue;
            };
            let t = i32::try_from(taken.unwrap_or(0) + 1).unwrap_or(i32::MAX);
            let bias1 = 1.0 / (1.0 - config.beta1.powi(t));
            let bias2 = 1.0 / (1.0 - config.beta2.powi(t));
            for &slot in slots {
                params.lr[slot] = lr as f32;
                params.bias1[slot] = bias1 as f32;
                params.bias2[slot] = bias2 as f32;
                params.trained[slot] = 1;
            }
        }
        params
    }
}

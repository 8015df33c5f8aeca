//! The resident trainer's own kernels (`shaders/scan.wgsl`, `train_*.wgsl`) and the uniform
//! parameters they read. The rasterization and shading kernels are the [`super::GpuBackend`]'s.

use bytemuck::{Pod, Zeroable};

use super::super::device::Device;
use super::super::GpuError;

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

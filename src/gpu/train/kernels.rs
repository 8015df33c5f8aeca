//! The resident trainer's own kernels (`shaders/scan.wgsl`, `train_*.wgsl`; what each is compiled
//! from and binds is in [`crate::gpu::shaders`]) and the uniform parameters they read. The
//! rasterization and shading kernels are the [`super::GpuBackend`]'s.
//!
//! Threading: the parameters are built on the calling thread; the kernels' threading is in their
//! WGSL files.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use super::buffers::{FrameBuffers, GROUP_SLOTS};
use super::DeviceStep;
use crate::core::loss::LossWeights;
use crate::core::optim::AdamConfig;
use crate::core::raster::RasterSettings;
use crate::core::render::SHADE_ALPHA_MIN;
use crate::gpu::device::{Device, Kernel};
use crate::gpu::layout::wgsl_mirror;
use crate::gpu::shaders;
use crate::gpu::GpuError;

/// Words of the step status (`STATUS_*` of train_common.wgsl and the sums from `SUM_FIRST`;
/// word 0, the entries that fit, is read by the kernels only).
pub(super) const STATUS_WORDS: usize = 18;
pub(super) const STATUS_ENTRIES: usize = 1;
pub(super) const STATUS_OVERFLOW: usize = 2;
pub(super) const STATUS_NONFINITE: usize = 3;
pub(super) const SUM_FIRST: usize = 8;

/// The resident trainer's kernels.
pub(super) struct TrainKernels {
    pub(super) scan_blocks: Kernel,
    pub(super) scan_sums: Kernel,
    pub(super) scan_add: Kernel,
    pub(super) prepare_pixels: Kernel,
    pub(super) depth_normal_backward: Kernel,
    pub(super) assemble_upstream: Kernel,
    pub(super) compose: Kernel,
    pub(super) ssim_moments_h: Kernel,
    pub(super) ssim_moments_v: Kernel,
    pub(super) ssim_adjoint_h: Kernel,
    pub(super) loss_chain: Kernel,
    pub(super) reduce_losses: Kernel,
    pub(super) adam: Kernel,
    pub(super) accumulate_light: Kernel,
}

impl TrainKernels {
    pub(super) fn compile(device: &Device) -> Result<Self, GpuError> {
        device.compile_all(|d| TrainKernels {
            scan_blocks: d.kernel(&shaders::SCAN_BLOCKS),
            scan_sums: d.kernel(&shaders::SCAN_SUMS),
            scan_add: d.kernel(&shaders::SCAN_ADD),
            prepare_pixels: d.kernel(&shaders::PREPARE_PIXELS),
            depth_normal_backward: d.kernel(&shaders::DEPTH_NORMAL_BACKWARD),
            assemble_upstream: d.kernel(&shaders::ASSEMBLE_UPSTREAM),
            compose: d.kernel(&shaders::COMPOSE),
            ssim_moments_h: d.kernel(&shaders::SSIM_MOMENTS_H),
            ssim_moments_v: d.kernel(&shaders::SSIM_MOMENTS_V),
            ssim_adjoint_h: d.kernel(&shaders::SSIM_ADJOINT_H),
            loss_chain: d.kernel(&shaders::LOSS_CHAIN),
            reduce_losses: d.kernel(&shaders::REDUCE_LOSSES),
            adam: d.kernel(&shaders::ADAM),
            accumulate_light: d.kernel(&shaders::ACCUMULATE_LIGHT),
        })
    }
}

wgsl_mirror! {
    /// `ScanParams` of scan.wgsl.
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    pub(super) struct ScanParamsGpu = "ScanParams" {
        pub(super) n: u32,
        pub(super) capacity: u32,
        pub(super) max_groups: u32,
        pub(super) pad0: u32,
    }
}

wgsl_mirror! {
    /// `TrainParams` of train_params.wgsl.
    #[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
    pub(super) struct TrainParamsGpu = "TrainParams" {
        width: u32,
        height: u32,
        pixels: u32,
        groups: u32,
        shaded: u32,
        stokes_loss: u32,
        has_theta: u32,
        lambda_aolp: f32,
        cos_2theta: f32,
        sin_2theta: f32,
        unpolarized_scale: f32,
        lambda_extra_l1: f32,
        lambda_ssim: f32,
        lambda_stokes: f32,
        lambda_mask: f32,
        lambda_normal_smooth: f32,
        lambda_depth_normal: f32,
        normalize_alpha_min: f32,
        shade_alpha_min: f32,
        lambda_distortion: f32,
        rot0: [f32; 4],
        rot1: [f32; 4],
        rot2: [f32; 4],
        origin: [f32; 4],
        fx: f32,
        fy: f32,
        cx: f32,
        cy: f32,
        gauss: [f32; 12],
    }
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
        let (cos2, sin2) = plan.polarizer_cos_sin().unwrap_or((1.0, 0.0));
        let r = camera.rotation_opencv();
        let window = crate::core::loss::ssim::gaussian_kernel();
        TrainParamsGpu {
            width: frame.width,
            height: frame.height,
            pixels: frame.pixels as u32,
            groups: frame.groups(),
            shaded: u32::from(plan.shaded),
            stokes_loss: u32::from(plan.stokes_loss),
            has_theta: u32::from(plan.theta.is_some()),
            lambda_aolp: when(plan.aolp, weights.lambda_aolp),
            cos_2theta: cos2 as f32,
            sin_2theta: sin2 as f32,
            unpolarized_scale: plan.unpolarized_scale as f32,
            lambda_extra_l1: when(plan.extra_l1, weights.lambda_stokes),
            lambda_ssim: weights.lambda_ssim as f32,
            lambda_stokes: when(plan.stokes_loss, weights.lambda_stokes),
            lambda_mask: weights.lambda_mask as f32,
            lambda_normal_smooth: when(plan.normal_smooth, weights.lambda_normal_smooth),
            lambda_depth_normal: when(plan.depth_normal, weights.lambda_depth_normal),
            normalize_alpha_min: settings.normalize_alpha_min as f32,
            shade_alpha_min: SHADE_ALPHA_MIN as f32,
            lambda_distortion: when(plan.distortion, weights.distortion_per_scene_unit()),
            rot0: v4(r.x_axis),
            rot1: v4(r.y_axis),
            rot2: v4(r.z_axis),
            origin: v4(camera.origin()),
            fx: camera.fx as f32,
            fy: camera.fy as f32,
            cx: camera.cx as f32,
            cy: camera.cy as f32,
            gauss: std::array::from_fn(|k| window.get(k).map_or(0.0, |&v| v as f32)),
        }
    }
}

wgsl_mirror! {
    /// `AdamParams` of train_update.wgsl: per raw slot, its group's rate, bias corrections and
    /// whether it is trained.
    #[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
    pub(super) struct AdamParamsGpu = "AdamParams" {
        surfels: u32,
        pad0: u32,
        pad1: u32,
        pad2: u32,
        beta1: f32,
        beta2: f32,
        eps: f32,
        ndc_scale: f32,
        pub(super) lr: [f32; 16],
        pub(super) bias1: [f32; 16],
        pub(super) bias2: [f32; 16],
        pub(super) trained: [u32; 16],
    }
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
            surfels,
            beta1: config.beta1 as f32,
            beta2: config.beta2 as f32,
            eps: config.eps as f32,
            ndc_scale: (0.5 * f64::from(frame.width.max(frame.height))) as f32,
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

#[cfg(test)]
mod tests {
    use super::super::buffers::SCAN_BLOCK;
    use super::*;
    use crate::gpu::test_backend;
    use rand::{Rng, SeedableRng};

    /// A kernel, its bindings and its workgroup grid.
    type Stage<'a> = (&'a Kernel, Vec<(&'a str, &'a wgpu::Buffer)>, (u32, u32));

    #[test]
    fn trainer_params_mirror_the_wgsl() {
        use crate::gpu::layout::assert_mirrors;
        assert_mirrors::<ScanParamsGpu>(&shaders::SCAN_BLOCKS);
        assert_mirrors::<TrainParamsGpu>(&shaders::PREPARE_PIXELS);
        assert_mirrors::<AdamParamsGpu>(&shaders::ADAM);
    }

    /// The three scan kernels give the exclusive prefix sum of random tile counts, the total,
    /// the entries that fit and the overflow flag, and size the indirect grids from what fits;
    /// at sizes around the 1024-count block and over many blocks.
    #[test]
    fn device_scan_matches_the_host_prefix_sum() {
        let Some(gpu) = test_backend() else { return };
        let device = gpu.device();
        let kernels = TrainKernels::compile(device).unwrap();
        let max_groups = device.wgpu().limits().max_compute_workgroups_per_dimension;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        for (n, capacity) in [
            (1u32, 10u32),
            (1023, 1 << 20),
            (1024, 1 << 20),
            (1025, 100),
            (300_000, 1 << 30),
        ] {
            // Mostly zeros and small counts, as surfels cover few tiles.
            let counts: Vec<u32> = (0..n)
                .map(|_| rng.random_range(0..12u32).saturating_sub(6))
                .collect();
            let n64 = u64::from(n);
            let counts_buf = device
                .storage_init("counts", bytemuck::cast_slice(&counts))
                .unwrap();
            let offsets = device
                .storage("offsets", n64 * 4, wgpu::BufferUsages::COPY_SRC)
                .unwrap();
            let block_sums = device
                .storage(
                    "block sums",
                    n64.div_ceil(SCAN_BLOCK) * 4,
                    wgpu::BufferUsages::empty(),
                )
                .unwrap();
            let status = device
                .storage(
                    "status",
                    STATUS_WORDS as u64 * 4,
                    wgpu::BufferUsages::COPY_SRC,
                )
                .unwrap();
            let dispatch = device
                .storage("dispatch", 6 * 4, wgpu::BufferUsages::COPY_SRC)
                .unwrap();
            let params = ScanParamsGpu {
                n,
                capacity,
                max_groups,
                pad0: 0,
            };
            let params = device.uniform("scan", bytemuck::bytes_of(&params));
            let blocks = device.workgroup_grid(n64.div_ceil(SCAN_BLOCK)).unwrap();
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            let stages: [Stage; 3] = [
                (
                    &kernels.scan_blocks,
                    vec![
                        ("scan", &params),
                        ("counts", &counts_buf),
                        ("offsets", &offsets),
                        ("block_sums", &block_sums),
                    ],
                    blocks,
                ),
                (
                    &kernels.scan_sums,
                    vec![
                        ("scan", &params),
                        ("block_sums", &block_sums),
                        ("status", &status),
                        ("dispatch", &dispatch),
                    ],
                    (1, 1),
                ),
                (
                    &kernels.scan_add,
                    vec![
                        ("scan", &params),
                        ("offsets", &offsets),
                        ("block_sums", &block_sums),
                    ],
                    blocks,
                ),
            ];
            for (kernel, bindings, (x, y)) in &stages {
                let group = device.bind(kernel, bindings);
                let mut pass = device.begin_pass(&mut encoder, "scan");
                pass.set_pipeline(kernel.pipeline());
                pass.set_bind_group(0, &group, &[]);
                pass.dispatch_workgroups(*x, *y, 1);
            }
            let out = device
                .submit_and_read(
                    encoder,
                    &[
                        (&offsets, n64 * 4),
                        (&status, STATUS_WORDS as u64 * 4),
                        (&dispatch, 6 * 4),
                    ],
                )
                .unwrap();
            let got: Vec<u32> = bytemuck::pod_collect_to_vec(&out[0]);
            let expected: Vec<u32> = counts
                .iter()
                .scan(0u32, |run, &c| {
                    let before = *run;
                    *run += c;
                    Some(before)
                })
                .collect();
            assert_eq!(got, expected, "{n} counts");
            let total: u32 = counts.iter().sum();
            let fits = total.min(capacity);
            let words: Vec<u32> = bytemuck::pod_collect_to_vec(&out[1]);
            assert_eq!(
                &words[..3],
                &[fits, total, u32::from(total > capacity)],
                "{n} counts"
            );
            let grids: Vec<u32> = bytemuck::pod_collect_to_vec(&out[2]);
            let cover = |at: usize, per: u32| {
                let groups = u64::from(grids[at]) * u64::from(grids[at + 1]);
                groups >= u64::from(fits.div_ceil(per)) && grids[at] <= max_groups
            };
            assert!(
                cover(0, 2048) && cover(3, 256),
                "{n} counts: grids {grids:?}"
            );
        }
    }
}

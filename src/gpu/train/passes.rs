//! The passes of one device step, encoded in order into one command encoder and submitted
//! together: binning (projection, the device scan, emission, the indirect radix sort and tile
//! ranges), rasterization and shading, the losses, the backward passes, and the update. Each
//! pass is one compute pass (timed when profiling); each dispatch binds its kernel's buffers by
//! their WGSL names (the numbers, and what each kernel binds, are in [`crate::gpu::shaders`]).
//!
//! Threading: encoding on the calling thread (one step at a time); the kernels' threading is in
//! their WGSL files.

use std::time::Instant;

use super::buffers::SCAN_BLOCK;
use super::buffers::{EntryBuffers, FrameBuffers, SurfelBuffers, TARGET_FLOATS};
use super::kernels::STATUS_WORDS;
use super::{DeviceStep, DeviceTrainer, LightState, DEPTH_BITS};
use crate::gpu::bind_cache::Binder;
use crate::gpu::device::{Device, Kernel};
use crate::gpu::light::ProbeBuffers;
use crate::gpu::params::TILE;
use crate::gpu::shade::LightPipelines;
use crate::gpu::sort::{varying_bits, KeyBits, SortDispatch, SortInputs};
use crate::gpu::GpuError;

/// Bindings of one dispatch: (WGSL name, buffer).
type Bindings<'b> = [(&'static str, &'b wgpu::Buffer)];

/// One step's command encoder, where its bind groups come from, and the dispatch shapes its
/// passes use.
struct Passes<'a> {
    device: &'a Device,
    binder: Binder<'a>,
    frame: &'a FrameBuffers,
    encoder: wgpu::CommandEncoder,
}

impl Passes<'_> {
    fn dispatch(
        &mut self,
        label: &'static str,
        kernel: &Kernel,
        bindings: &Bindings,
        grid: (u32, u32),
    ) {
        let group = self.binder.bind(kernel, bindings);
        let mut pass = self.device.begin_pass(&mut self.encoder, label);
        pass.set_pipeline(kernel.pipeline());
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups(grid.0, grid.1, 1);
    }

    /// One thread per pixel.
    fn per_pixel(&mut self, label: &'static str, kernel: &Kernel, bindings: &Bindings) {
        let grid = self.frame.grid;
        self.dispatch(label, kernel, bindings, grid);
    }

    /// One 8×8 workgroup per tile.
    fn per_tile(&mut self, label: &'static str, kernel: &Kernel, bindings: &Bindings) {
        let grid = (
            self.frame.width.div_ceil(TILE),
            self.frame.height.div_ceil(TILE),
        );
        self.dispatch(label, kernel, bindings, grid);
    }

    /// One thread per item (surfel, light value).
    fn per_item(
        &mut self,
        label: &'static str,
        kernel: &Kernel,
        bindings: &Bindings,
        items: u64,
    ) -> Result<(), GpuError> {
        let group = self.binder.bind(kernel, bindings);
        self.device
            .dispatch_1d(&mut self.encoder, label, kernel, &group, items)
    }
}

impl DeviceTrainer<'_> {
    /// Encodes, submits and reads back one attempt at a step: the step status.
    pub(super) fn run(&self, step: &DeviceStep) -> Result<Vec<u32>, GpuError> {
        let start = Instant::now();
        let device = self.device();
        let (Some(s), Some(e), Some(f)) = (&self.surfels, &self.entries, &self.frame) else {
            return Err(GpuError::Device("the trainer's buffers are missing".into()));
        };
        self.write_params(step, f, s.count as u32);
        let mut passes = Passes {
            device,
            binder: Binder::Cached(device, &self.binds),
            frame: f,
            encoder: device.wgpu().create_command_encoder(&Default::default()),
        };
        let encoder = &mut passes.encoder;
        for buffer in [&self.status, &s.acc, &f.ranges, &f.stokes, &f.shade_grads] {
            encoder.clear_buffer(buffer, 0, None);
        }
        let target = &self.targets[step.view].0;
        encoder.copy_buffer_to_buffer(target, 0, &f.target, 0, f.pixels * TARGET_FLOATS * 4);

        let sorted = self.encode_binning(&mut passes, s, e)?;
        let shading = self.encode_forward(&mut passes, s, &sorted, step.plan.shaded);
        self.encode_losses(&mut passes);
        self.encode_backward(&mut passes, s, &sorted, shading)?;
        self.encode_update(&mut passes, s, shading)?;
        self.binds.end_step();
        device.record_host_time("encode", start);
        let data = device
            .submit_step_and_read(passes.encoder, &[(&self.status, STATUS_WORDS as u64 * 4)])?;
        Ok(bytemuck::pod_collect_to_vec(&data[0]))
    }

    /// Projection, the device scan of the tile counts (which also writes the entry total and the
    /// indirect dispatch sizes), emission, the radix sort and the tile ranges. Returns the
    /// buffer that holds the sorted entries.
    fn encode_binning(
        &self,
        passes: &mut Passes,
        s: &SurfelBuffers,
        e: &EntryBuffers,
    ) -> Result<wgpu::Buffer, GpuError> {
        let device = self.device();
        let raster = self.gpu.raster();
        let k = &self.kernels;
        let f = passes.frame;
        let rp = &f.raster_params;
        let n = s.count as u64;
        passes.per_item(
            "project",
            &raster.project,
            &[
                ("params", rp),
                ("raw", &s.raw),
                ("proj", &s.proj),
                ("tile_counts", &s.tile_counts),
            ],
            n,
        )?;
        let blocks = device.workgroup_grid(n.div_ceil(SCAN_BLOCK).max(1))?;
        let sp = &self.scan_params;
        passes.dispatch(
            "scan",
            &k.scan_blocks,
            &[
                ("scan", sp),
                ("counts", &s.tile_counts),
                ("offsets", &s.offsets),
                ("block_sums", &s.block_sums),
            ],
            blocks,
        );
        passes.dispatch(
            "scan",
            &k.scan_sums,
            &[
                ("scan", sp),
                ("block_sums", &s.block_sums),
                ("status", &self.status),
                ("dispatch", &self.dispatch),
            ],
            (1, 1),
        );
        passes.dispatch(
            "scan",
            &k.scan_add,
            &[
                ("scan", sp),
                ("offsets", &s.offsets),
                ("block_sums", &s.block_sums),
            ],
            blocks,
        );
        passes.per_item(
            "emit",
            &raster.emit,
            &[
                ("params", rp),
                ("proj", &s.proj),
                ("offsets", &s.offsets),
                ("entries", &e.entries[0]),
            ],
            n,
        )?;
        let tiles = f.width.div_ceil(TILE) * f.height.div_ceil(TILE);
        let sorted = self.gpu.sort().encode(
            passes.binder,
            &mut passes.encoder,
            e.entries.clone(),
            &SortInputs {
                hist: &e.hist,
                count: &self.status,
                bits: KeyBits {
                    depth: DEPTH_BITS,
                    tile: varying_bits(0, tiles.max(1) - 1),
                },
                dispatch: SortDispatch::Indirect {
                    args: &self.dispatch,
                    offset: 0,
                },
            },
        )?;
        let group = passes.binder.bind(
            &raster.tile_ranges,
            &[
                ("entries", &sorted),
                ("ranges", &f.ranges),
                ("entry_count", &self.status),
            ],
        );
        let mut pass = device.begin_pass(&mut passes.encoder, "tile_ranges");
        pass.set_pipeline(raster.tile_ranges.pipeline());
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups_indirect(&self.dispatch, 12);
        Ok(sorted)
    }

    /// Rasterization, the shader's inputs and depth normals, and (when `shaded`) PolarDR. Returns
    /// the light and kernels the step shades with.
    fn encode_forward<'s>(
        &'s self,
        passes: &mut Passes,
        s: &SurfelBuffers,
        sorted: &wgpu::Buffer,
        shaded: bool,
    ) -> Option<(&'s LightState, &'s LightPipelines)> {
        let raster = self.gpu.raster();
        let f = passes.frame;
        passes.per_tile(
            "rasterize",
            &raster.rasterize,
            &[
                ("params", &f.raster_params),
                ("entries", sorted),
                ("ranges", &f.ranges),
                ("proj", &s.proj),
                ("gbuf", &f.gbuf),
                ("final_t", &f.final_t),
                ("contrib", &f.contrib),
                ("evals", &f.evals),
            ],
        );
        passes.per_pixel(
            "prepare_pixels",
            &self.kernels.prepare_pixels,
            &[
                ("train", &f.train_params),
                ("gbuf", &f.gbuf),
                ("shade_in", &f.shade_in),
                ("active_pixels", &f.active),
                ("depth_normal", &f.depth_normal),
            ],
        );
        let light = self.light.as_ref().filter(|_| shaded)?;
        let kernels = if self.probes.is_some() {
            &self.gpu.shading().gridmap
        } else {
            &self.gpu.shading().global
        };
        let mut bindings = vec![
            ("params", &f.shade_params),
            ("pixels", &f.shade_in),
            ("active_pixels", &f.active),
            ("stokes", &f.stokes),
        ];
        bindings.extend(light.buffers.bindings());
        bindings.extend(self.probes.iter().flat_map(ProbeBuffers::bindings));
        passes.per_pixel("shade", &kernels.forward, &bindings);
        Some((light, kernels))
    }

    /// The prediction, SSIM's moments and adjoints, every other loss term with its gradient,
    /// and the reduction of the partial sums into the step status.
    fn encode_losses(&self, passes: &mut Passes) {
        let k = &self.kernels;
        let f = passes.frame;
        let tp = &f.train_params;
        passes.per_pixel(
            "compose",
            &k.compose,
            &[
                ("train", tp),
                ("gbuf", &f.gbuf),
                ("stokes", &f.stokes),
                ("pred", &f.pred),
            ],
        );
        passes.per_pixel(
            "ssim_moments_h",
            &k.ssim_moments_h,
            &[
                ("train", tp),
                ("target_image", &f.target),
                ("pred", &f.pred),
                ("blur_a", &f.blur_a),
            ],
        );
        passes.per_pixel(
            "ssim_moments_v",
            &k.ssim_moments_v,
            &[
                ("train", tp),
                ("blur_a", &f.blur_a),
                ("blur_b", &f.blur_b),
                ("partials", &f.partials),
            ],
        );
        passes.per_pixel(
            "ssim_adjoint_h",
            &k.ssim_adjoint_h,
            &[("train", tp), ("blur_a", &f.blur_a), ("blur_b", &f.blur_b)],
        );
        passes.per_pixel(
            "loss_chain",
            &k.loss_chain,
            &[
                ("train", tp),
                ("gbuf", &f.gbuf),
                ("stokes", &f.stokes),
                ("target_image", &f.target),
                ("pred", &f.pred),
                ("blur_a", &f.blur_a),
                ("partials", &f.partials),
                ("d_stokes", &f.d_stokes),
                ("up_partial", &f.up_partial),
                ("dn_grad", &f.dn_grad),
                ("depth_normal", &f.depth_normal),
            ],
        );
        passes.dispatch(
            "reduce_losses",
            &k.reduce_losses,
            &[
                ("train", tp),
                ("partials", &f.partials),
                ("status", &self.status),
            ],
            (1, 1),
        );
    }

    /// The shader's backward pass, the depth normal's, the upstream gradient of every G-buffer,
    /// and the rasterizer's and projection's backward passes.
    fn encode_backward(
        &self,
        passes: &mut Passes,
        s: &SurfelBuffers,
        sorted: &wgpu::Buffer,
        shading: Option<(&LightState, &LightPipelines)>,
    ) -> Result<(), GpuError> {
        let k = &self.kernels;
        let f = passes.frame;
        let tp = &f.train_params;
        if let Some((light, kernels)) = shading {
            passes.encoder.clear_buffer(&light.step_grad, 0, None);
            let mut bindings = vec![
                ("params", &f.shade_params),
                ("pixels", &f.shade_in),
                ("active_pixels", &f.active),
                ("upstream", &f.d_stokes),
                ("pixel_grads", &f.shade_grads),
                ("grad_acc", &light.step_grad),
            ];
            bindings.extend(light.buffers.bindings());
            bindings.extend(self.probes.iter().flat_map(ProbeBuffers::bindings));
            passes.per_pixel("shade_backward", &kernels.backward, &bindings);
        }
        passes.per_pixel(
            "depth_normal_backward",
            &k.depth_normal_backward,
            &[
                ("train", tp),
                ("gbuf", &f.gbuf),
                ("dn_grad", &f.dn_grad),
                ("status", &self.status),
                ("gdxy", &f.gdxy),
            ],
        );
        passes.per_pixel(
            "assemble_upstream",
            &k.assemble_upstream,
            &[
                ("train", tp),
                ("active_pixels", &f.active),
                ("dn_grad", &f.dn_grad),
                ("status", &self.status),
                ("gdxy", &f.gdxy),
                ("up_partial", &f.up_partial),
                ("shade_grads", &f.shade_grads),
                ("upstream", &f.upstream),
            ],
        );
        let raster = self.gpu.raster();
        let rp = &f.raster_params;
        passes.per_tile(
            "rasterize_backward",
            &raster.rasterize_backward,
            &[
                ("params", rp),
                ("entries", sorted),
                ("ranges", &f.ranges),
                ("proj", &s.proj),
                ("gbuf", &f.gbuf),
                ("upstream", &f.upstream),
                ("final_t", &f.final_t),
                ("contrib", &f.contrib),
                ("grad_acc", &s.acc),
            ],
        );
        passes.per_item(
            "project_backward",
            &raster.project_backward,
            &[
                ("params", rp),
                ("raw", &s.raw),
                ("proj", &s.proj),
                ("grad_acc", &s.acc),
                ("raw_grads", &s.raw_grad),
            ],
            s.count as u64,
        )
    }

    /// Adam with the densification statistics, and the step's light gradient added into the
    /// sum waiting for the next environment update.
    fn encode_update(
        &self,
        passes: &mut Passes,
        s: &SurfelBuffers,
        shading: Option<(&LightState, &LightPipelines)>,
    ) -> Result<(), GpuError> {
        let k = &self.kernels;
        passes.per_item(
            "adam",
            &k.adam,
            &[
                ("adam_params", &self.adam_params),
                ("raw", &s.raw),
                ("moment1", &s.moment1),
                ("moment2", &s.moment2),
                ("raw_grad", &s.raw_grad),
                ("grad_sum", &s.grad_sum),
                ("seen", &s.seen),
                ("step_status", &self.status),
            ],
            s.count as u64,
        )?;
        if let Some((light, _)) = shading {
            passes.per_item(
                "accumulate_light",
                &k.accumulate_light,
                &[
                    ("step_status", &self.status),
                    ("light_step", &light.step_grad),
                    ("light_pending", &light.pending),
                ],
                light.host.gradient_bytes() / 4,
            )?;
        }
        Ok(())
    }
}

//! The resident trainer's device buffers: the surfels' raw parameters, Adam moments and
//! densification statistics (and their conversion from and to the host's f64 training state),
//! the tile entries of the binning sort, and the per-pixel buffers of one image size.
//!
//! Threading: created and read back on the calling thread, inside the trainer's
//! [`Device::scoped`] calls.

use super::super::device::Device;
use super::super::light::ShadeParamsGpu;
use super::super::params::{
    raw_surfels, ParamsGpu, RawGpu, ENTRY_BYTES, NUM_ACC, NUM_OUT, NUM_RAW_GRAD, PROJ_BYTES, TILE,
};
use super::super::shade::{GRAD_FLOATS, INPUT_VECTORS, STOKES_FLOATS};
use super::super::sort::RADIX_BLOCK;
use super::super::GpuError;
use crate::core::densify::DensifyStats;
use crate::core::optim::{Adam, GroupState};
use crate::core::surfels::Surfels;

/// Counts per block of `scan_blocks` (`SCAN_BLOCK` of scan.wgsl): the block sums' buffer holds
/// one a block.
pub(super) const SCAN_BLOCK: u64 = 1024;
/// Partial-sum slots of the loss kernels (`SLOTS` of train_common.wgsl), per workgroup.
pub(super) const SLOTS: u64 = 10;

/// f32 values per surfel of the raw parameters and of each Adam moment (the layout of `Raw`).
pub(super) const RAW_FLOATS: usize = 16;

/// The raw-value slots (layout of `Raw` in shaders/common.wgsl) of each surfel parameter group,
/// in the order of `Surfels::groups`.
pub(super) const GROUP_SLOTS: [(&str, &[usize]); 7] = [
    ("position", &[0, 1, 2]),
    ("scale", &[8, 9]),
    ("rotation", &[4, 5, 6, 7]),
    ("opacity", &[3]),
    ("albedo", &[12, 13, 14]),
    ("roughness", &[10]),
    ("ior", &[11]),
];

const COPY: wgpu::BufferUsages = wgpu::BufferUsages::COPY_SRC.union(wgpu::BufferUsages::COPY_DST);

/// The surfels on the device.
pub(super) struct SurfelBuffers {
    pub(super) count: usize,
    /// Raw parameters, first and second Adam moments: [`RAW_FLOATS`] f32 per surfel.
    pub(super) raw: wgpu::Buffer,
    pub(super) moment1: wgpu::Buffer,
    pub(super) moment2: wgpu::Buffer,
    /// Σ of the screen-space gradient norm (NDC units) and the views that saw each surfel.
    pub(super) grad_sum: wgpu::Buffer,
    pub(super) seen: wgpu::Buffer,
    pub(super) proj: wgpu::Buffer,
    pub(super) tile_counts: wgpu::Buffer,
    pub(super) offsets: wgpu::Buffer,
    pub(super) block_sums: wgpu::Buffer,
    /// The rasterizer's per-surfel gradient sums and the raw gradients.
    pub(super) acc: wgpu::Buffer,
    pub(super) raw_grad: wgpu::Buffer,
}

/// A group's moments in the layout of `Raw` (zero in the other groups' slots).
fn moments_of(adam: &Adam, count: usize) -> Result<[Vec<f32>; 2], GpuError> {
    let mut m = vec![0.0f32; count * RAW_FLOATS];
    let mut v = vec![0.0f32; count * RAW_FLOATS];
    for (name, slots) in GROUP_SLOTS {
        let Some(group) = adam.group(name) else {
            continue;
        };
        if group.entries() != count || group.width != slots.len() {
            return Err(GpuError::Device(format!(
                "optimizer group `{name}` holds {} entries of width {} for {count} surfels",
                group.entries(),
                group.width
            )));
        }
        for i in 0..count {
            for (k, &slot) in slots.iter().enumerate() {
                m[i * RAW_FLOATS + slot] = group.exp_avg[i * slots.len() + k] as f32;
                v[i * RAW_FLOATS + slot] = group.exp_avg_sq[i * slots.len() + k] as f32;
            }
        }
    }
    Ok([m, v])
}

impl SurfelBuffers {
    /// Uploads the surfels, the moments of the groups `adam` has and the statistics.
    pub(super) fn upload(
        device: &Device,
        surfels: &Surfels,
        adam: &Adam,
        densify: &DensifyStats,
    ) -> Result<Self, GpuError> {
        let n = surfels.len();
        if densify.grad_sum.len() != n || densify.seen.len() != n {
            return Err(GpuError::Device(format!(
                "densification statistics for {} surfels, not {n}",
                densify.grad_sum.len()
            )));
        }
        let [m, v] = moments_of(adam, n)?;
        let grad_sum: Vec<f32> = densify.grad_sum.iter().map(|&g| g as f32).collect();
        let per_surfel = |name: &str, bytes: u64| device.storage(name, n as u64 * bytes, COPY);
        Ok(SurfelBuffers {
            count: n,
            raw: device.storage_init("raw surfels", bytemuck::cast_slice(&raw_surfels(surfels)))?,
            moment1: device.storage_init("adam m", bytemuck::cast_slice(&m))?,
            moment2: device.storage_init("adam v", bytemuck::cast_slice(&v))?,
            grad_sum: device.storage_init("densify grad sums", bytemuck::cast_slice(&grad_sum))?,
            seen: device.storage_init("densify views", bytemuck::cast_slice(&densify.seen))?,
            proj: per_surfel("projected surfels", PROJ_BYTES)?,
            tile_counts: per_surfel("tile counts", 4)?,
            offsets: per_surfel("entry offsets", 4)?,
            block_sums: device.storage(
                "scan block sums",
                (n as u64).div_ceil(SCAN_BLOCK) * 4,
                wgpu::BufferUsages::empty(),
            )?,
            acc: per_surfel("gradient sums", NUM_ACC * 4)?,
            raw_grad: per_surfel("raw gradients", NUM_RAW_GRAD as u64 * 4)?,
        })
    }

    /// Reads the surfels, the moments (`groups`: the groups that have state, with their step
    /// counts) and the statistics back into the host's state.
    pub(super) fn download(
        &self,
        device: &Device,
        surfels: &mut Surfels,
        adam: &mut Adam,
        groups: &[(&'static str, Option<u64>)],
        densify: &mut DensifyStats,
    ) -> Result<(), GpuError> {
        let n = self.count as u64;
        let encoder = device.wgpu().create_command_encoder(&Default::default());
        let raw_bytes = n * RAW_FLOATS as u64 * 4;
        let data = device.submit_and_read(
            encoder,
            &[
                (&self.raw, raw_bytes),
                (&self.moment1, raw_bytes),
                (&self.moment2, raw_bytes),
                (&self.grad_sum, n * 4),
                (&self.seen, n * 4),
            ],
        )?;
        let raw: Vec<RawGpu> = bytemuck::pod_collect_to_vec(&data[0]);
        let m: Vec<f32> = bytemuck::pod_collect_to_vec(&data[1]);
        let v: Vec<f32> = bytemuck::pod_collect_to_vec(&data[2]);
        let mut host = Surfels::zeros(self.count);
        let d = f64::from;
        for (i, r) in raw.iter().enumerate() {
            host.position[i] = [d(r.pos_op[0]), d(r.pos_op[1]), d(r.pos_op[2])];
            host.opacity[i] = d(r.pos_op[3]);
            host.rotation[i] = r.quat.map(d);
            host.log_scale[i] = [d(r.scale_rough_ior[0]), d(r.scale_rough_ior[1])];
            host.roughness[i] = d(r.scale_rough_ior[2]);
            host.ior[i] = d(r.scale_rough_ior[3]);
            host.albedo[i] = [d(r.albedo[0]), d(r.albedo[1]), d(r.albedo[2])];
        }
        *surfels = host;
        for ((name, slots), &(group, step)) in GROUP_SLOTS.iter().zip(groups) {
            debug_assert_eq!(*name, group);
            let Some(step) = step else {
                continue;
            };
            let gather = |values: &[f32]| -> Vec<f64> {
                values
                    .chunks_exact(RAW_FLOATS)
                    .flat_map(|surfel| slots.iter().map(|&s| f64::from(surfel[s])))
                    .collect()
            };
            let state = GroupState {
                step,
                width: slots.len(),
                exp_avg: gather(&m),
                exp_avg_sq: gather(&v),
            };
            adam.insert_group(name, state)
                .map_err(|e| GpuError::Device(e.to_string()))?;
        }
        let grad_sum: Vec<f32> = bytemuck::pod_collect_to_vec(&data[3]);
        densify.grad_sum = grad_sum.into_iter().map(f64::from).collect();
        densify.seen = bytemuck::pod_collect_to_vec(&data[4]);
        Ok(())
    }
}

/// The binning entries of the sort, and its histogram, for at most `capacity` entries.
pub(super) struct EntryBuffers {
    pub(super) capacity: u64,
    /// The sort ping-pongs between the two.
    pub(super) entries: [wgpu::Buffer; 2],
    pub(super) hist: wgpu::Buffer,
}

impl EntryBuffers {
    pub(super) fn new(device: &Device, capacity: u64) -> Result<Self, GpuError> {
        let bytes = capacity * ENTRY_BYTES;
        let none = wgpu::BufferUsages::empty();
        Ok(EntryBuffers {
            capacity,
            entries: [
                device.storage("tile entries", bytes, none)?,
                device.storage("tile entries (sort)", bytes, none)?,
            ],
            hist: device.storage(
                "radix histogram",
                capacity.div_ceil(RADIX_BLOCK) * 16 * 4,
                none,
            )?,
        })
    }
}

/// Per-pixel buffers of one image size.
pub(super) struct FrameBuffers {
    pub(super) width: u32,
    pub(super) height: u32,
    pub(super) pixels: u64,
    /// Workgroup grid of the per-pixel kernels; its size is the number of partial sums per slot.
    pub(super) grid: (u32, u32),
    pub(super) raster_params: wgpu::Buffer,
    pub(super) train_params: wgpu::Buffer,
    pub(super) shade_params: wgpu::Buffer,
    pub(super) ranges: wgpu::Buffer,
    pub(super) gbuf: wgpu::Buffer,
    pub(super) final_t: wgpu::Buffer,
    pub(super) contrib: wgpu::Buffer,
    pub(super) evals: wgpu::Buffer,
    pub(super) shade_in: wgpu::Buffer,
    pub(super) active: wgpu::Buffer,
    pub(super) depth_normal: wgpu::Buffer,
    pub(super) stokes: wgpu::Buffer,
    pub(super) target: wgpu::Buffer,
    pub(super) pred: wgpu::Buffer,
    pub(super) blur_a: wgpu::Buffer,
    pub(super) blur_b: wgpu::Buffer,
    pub(super) partials: wgpu::Buffer,
    pub(super) d_stokes: wgpu::Buffer,
    pub(super) up_partial: wgpu::Buffer,
    pub(super) dn_grad: wgpu::Buffer,
    pub(super) shade_grads: wgpu::Buffer,
    pub(super) gdxy: wgpu::Buffer,
    pub(super) upstream: wgpu::Buffer,
}

/// f32 values per pixel of a view's target: photometric RGB, mask, S1 and S2 RGB.
pub(super) const TARGET_FLOATS: u64 = 12;

impl FrameBuffers {
    /// The buffers of a `width` × `height` image; `train_params_bytes`: the size of the
    /// kernels' `TrainParams` uniform.
    pub(super) fn new(
        device: &Device,
        width: u32,
        height: u32,
        train_params_bytes: usize,
    ) -> Result<Self, GpuError> {
        let p = u64::from(width) * u64::from(height);
        let grid = device.grid(p)?;
        let groups = u64::from(grid.0) * u64::from(grid.1);
        let tiles = u64::from(width.div_ceil(TILE)) * u64::from(height.div_ceil(TILE));
        let floats = |name: &str, per_pixel: u64| device.storage(name, p * per_pixel * 4, COPY);
        let uniform = |name: &str, bytes: usize| device.uniform(name, &vec![0u8; bytes]);
        Ok(FrameBuffers {
            width,
            height,
            pixels: p,
            grid,
            raster_params: uniform("raster params", size_of::<ParamsGpu>()),
            train_params: uniform("train params", train_params_bytes),
            shade_params: uniform("shade params", size_of::<ShadeParamsGpu>()),
            ranges: device.storage("tile ranges", tiles * 8, COPY)?,
            gbuf: floats("g-buffers", NUM_OUT as u64)?,
            final_t: floats("final transmittance", 1)?,
            contrib: floats("contributors", 1)?,
            evals: floats("evaluations", 1)?,
            shade_in: floats("shading inputs", INPUT_VECTORS * 4)?,
            active: floats("active pixels", 1)?,
            depth_normal: floats("depth normals", 4)?,
            stokes: floats("stokes", STOKES_FLOATS)?,
            target: floats("target", TARGET_FLOATS)?,
            pred: floats("prediction", 3)?,
            blur_a: floats("ssim planes", 15)?,
            blur_b: floats("ssim planes (2)", 15)?,
            partials: device.storage("loss partial sums", SLOTS * groups * 4, COPY)?,
            d_stokes: floats("stokes gradient", 9)?,
            up_partial: floats("loss g-buffer gradient", NUM_OUT as u64)?,
            dn_grad: floats("depth-normal gradient", 6)?,
            shade_grads: floats("shading input gradient", GRAD_FLOATS)?,
            gdxy: floats("depth difference gradient", 6)?,
            upstream: floats("upstream gradient", NUM_OUT as u64)?,
        })
    }

    /// Workgroups of a per-pixel kernel (partial sums per slot).
    pub(super) fn groups(&self) -> u32 {
        self.grid.0 * self.grid.1
    }
}

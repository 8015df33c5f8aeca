//! The radix sort of the binning entries (`shaders/radix_sort.wgsl`): a stable sort of
//! (tile, depth, surfel) entries by (tile, depth), 4 bits per pass, over only the low key bits
//! that can differ between the entries ([`KeyBits`]). The rasterizer (`super::raster`) sorts a
//! count the host knows; the resident trainer (`super::train`) sorts the count its device scan
//! wrote, with the block kernels dispatched indirectly ([`SortDispatch::Indirect`]).
//!
//! Threading: one pass is three kernels in one compute pass: `radix_count` and `radix_scatter`
//! run one 128-thread workgroup per block of [`RADIX_BLOCK`] entries, `radix_scan` a single
//! workgroup (details in the WGSL file). The encoding runs on the calling thread, inside the
//! caller's [`super::device::Device::scoped`].

use bytemuck::{Pod, Zeroable};

use std::sync::{Mutex, PoisonError};

use super::bind_cache::Binder;
use super::device::{Device, Kernel};
use super::layout::wgsl_mirror;
use super::shaders;
use super::GpuError;
use crate::core::camera::Camera;
use crate::core::surfels::Surfels;

/// Bits sorted per radix pass (`RADIX_BINS` = 2^bits in shaders/radix_sort.wgsl).
pub(super) const RADIX_BITS: u32 = 4;
/// Entries per radix-sort workgroup (`RADIX_BLOCK`).
pub(super) const RADIX_BLOCK: u64 = 2048;

/// Key words of a binning entry, as `RadixPass::word` names them.
const DEPTH_WORD: u32 = 0;
const TILE_WORD: u32 = 1;

wgsl_mirror! {
    /// One radix-sort pass (`RadixPass` in shaders/radix_sort.wgsl).
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    struct RadixPassGpu = "RadixPass" {
        shift: u32,
        word: u32,
        pad0: u32,
        pad1: u32,
    }
}

/// How the radix sort's block kernels are dispatched.
#[derive(Clone, Copy)]
pub(super) enum SortDispatch<'a> {
    /// The host knows how many entries there are.
    Direct { total: u64 },
    /// The device wrote the workgroup grid (x, y, z) into `args` at byte `offset`.
    Indirect { args: &'a wgpu::Buffer, offset: u64 },
}

/// What a sort reads besides its entries.
pub(super) struct SortInputs<'a> {
    /// Per-block digit counts: at least 16 × ⌈entries / RADIX_BLOCK⌉ u32.
    pub(super) hist: &'a wgpu::Buffer,
    /// The number of entries, in its first u32.
    pub(super) count: &'a wgpu::Buffer,
    pub(super) bits: KeyBits,
    pub(super) dispatch: SortDispatch<'a>,
}

/// How many low bits of each key word can differ between the entries of one sort: the radix sort
/// runs passes over those only (the bits above are the same in every entry, so their passes would
/// move nothing).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct KeyBits {
    pub(super) depth: u32,
    pub(super) tile: u32,
}

/// Bits below (and at) the highest bit in which `lo` and `hi` differ: every value between them
/// shares the bits above.
pub(super) fn varying_bits(lo: u32, hi: u32) -> u32 {
    u32::BITS - (lo ^ hi).leading_zeros()
}

/// The low bits of the f32 centre depth (the sort key, `Proj::q1.w`; a positive f32 orders like
/// its bit pattern) that can differ between the surfels in front of the camera. Computed on the
/// host in f64, with a relative margin of 1e-5 on the range and on `near` that covers the device's
/// f32 rounding, so the range can only come out wider than the device's, never narrower.
pub(super) fn varying_depth_bits(surfels: &Surfels, camera: &Camera, near: f64) -> u32 {
    let (rot, trans) = camera.world_to_camera_opencv();
    let (lo, hi) = surfels
        .position
        .iter()
        .map(|&p| (rot * glam::DVec3::from_array(p)).z + trans.z)
        .filter(|&z| z > near * (1.0 - 1e-5))
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), z| {
            (lo.min(z), hi.max(z))
        });
    if lo > hi {
        return 0;
    }
    let lo = (lo * (1.0 - 1e-5)) as f32;
    let hi = (hi * (1.0 + 1e-5)) as f32;
    varying_bits(lo.to_bits(), hi.to_bits())
}

/// The sort's three kernels, and the uniform buffer of the last sort's passes (a resident run
/// sorts over the same bits every step, and reusing it keeps the step's bind groups the same).
pub(super) struct RadixSort {
    count: Kernel,
    scan: Kernel,
    scatter: Kernel,
    pass_params: Mutex<Option<(Vec<u8>, wgpu::Buffer)>>,
}

impl RadixSort {
    /// Compiles the kernels (inside the caller's [`Device::compile_all`]).
    pub(super) fn new(device: &Device) -> Self {
        RadixSort {
            count: device.kernel(&shaders::RADIX_COUNT),
            scan: device.kernel(&shaders::RADIX_SCAN),
            scatter: device.kernel(&shaders::RADIX_SCATTER),
            pass_params: Mutex::new(None),
        }
    }

    /// A uniform buffer holding `bytes`: the last one when it holds the same (a buffer is never
    /// rewritten, so a sort still in flight keeps reading its own).
    fn pass_buffer(&self, device: &Device, bytes: Vec<u8>) -> wgpu::Buffer {
        let mut last = self
            .pass_params
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        match &*last {
            Some((held, buffer)) if *held == bytes => buffer.clone(),
            _ => {
                let buffer = device.uniform("radix passes", &bytes);
                *last = Some((bytes, buffer.clone()));
                buffer
            }
        }
    }

    /// Encodes the radix sort of the entries of `buffers[0]` (as many as `inputs.count[0]`) by
    /// (tile, depth) and returns the buffer that holds the result (the passes alternate between
    /// the two). The passes cover the varying low bits of the depth, then of the tile index
    /// ([`KeyBits`]); each reads its digit from its own aligned slice of a uniform buffer.
    pub(super) fn encode(
        &self,
        binder: Binder,
        encoder: &mut wgpu::CommandEncoder,
        buffers: [wgpu::Buffer; 2],
        inputs: &SortInputs,
    ) -> Result<wgpu::Buffer, GpuError> {
        let device = binder.device();
        let [mut keys, mut other] = buffers;
        let grid = match inputs.dispatch {
            SortDispatch::Direct { total } if total < 2 => return Ok(keys),
            SortDispatch::Direct { total } => {
                let (x, y) = device.workgroup_grid(total.div_ceil(RADIX_BLOCK))?;
                Some((x, y))
            }
            SortDispatch::Indirect { .. } => None,
        };
        let bits = inputs.bits;
        let passes: Vec<RadixPassGpu> = (0..bits.depth.div_ceil(RADIX_BITS))
            .map(|p| (p * RADIX_BITS, DEPTH_WORD))
            .chain((0..bits.tile.div_ceil(RADIX_BITS)).map(|p| (p * RADIX_BITS, TILE_WORD)))
            .map(|(shift, word)| RadixPassGpu {
                shift,
                word,
                pad0: 0,
                pad1: 0,
            })
            .collect();
        if passes.is_empty() {
            return Ok(keys);
        }
        let stride = u64::from(device.wgpu().limits().min_uniform_buffer_offset_alignment).max(16);
        let mut bytes = vec![0u8; passes.len() * stride as usize];
        for (i, p) in passes.iter().enumerate() {
            let at = i * stride as usize;
            bytes[at..at + 16].copy_from_slice(bytemuck::bytes_of(p));
        }
        let pass_buf = self.pass_buffer(device, bytes);
        let (hist, count) = (inputs.hist, inputs.count);
        let mut compute = device.begin_pass(encoder, "radix sort");
        for i in 0..passes.len() {
            let pass_params = || {
                wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &pass_buf,
                    offset: i as u64 * stride,
                    size: wgpu::BufferSize::new(16),
                })
            };
            let dispatch_blocks = |compute: &mut wgpu::ComputePass| match (grid, inputs.dispatch) {
                (Some((x, y)), _) => compute.dispatch_workgroups(x, y, 1),
                (None, SortDispatch::Indirect { args, offset }) => {
                    compute.dispatch_workgroups_indirect(args, offset)
                }
                (None, SortDispatch::Direct { .. }) => unreachable!("direct sorts have a grid"),
            };
            let group = binder.bind_resources(
                &self.count,
                [
                    ("pass_", pass_params()),
                    ("keys_in", keys.as_entire_binding()),
                    ("hist", hist.as_entire_binding()),
                    ("sort_count", count.as_entire_binding()),
                ],
            );
            compute.set_pipeline(self.count.pipeline());
            compute.set_bind_group(0, &group, &[]);
            dispatch_blocks(&mut compute);
            let group = binder.bind(&self.scan, &[("hist", hist), ("sort_count", count)]);
            compute.set_pipeline(self.scan.pipeline());
            compute.set_bind_group(0, &group, &[]);
            compute.dispatch_workgroups(1, 1, 1);
            let group = binder.bind_resources(
                &self.scatter,
                [
                    ("pass_", pass_params()),
                    ("keys_in", keys.as_entire_binding()),
                    ("keys_out", other.as_entire_binding()),
                    ("hist", hist.as_entire_binding()),
                    ("sort_count", count.as_entire_binding()),
                ],
            );
            compute.set_pipeline(self.scatter.pipeline());
            compute.set_bind_group(0, &group, &[]);
            dispatch_blocks(&mut compute);
            std::mem::swap(&mut keys, &mut other);
        }
        Ok(keys)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::{test_backend, GpuBackend};
    use glam::DVec3;
    use rand::{Rng, SeedableRng};

    /// Sorts binning entries (tile, depth key, surfel, unused) on the device by (tile, depth)
    /// over the given varying bits.
    fn device_sort(gpu: &GpuBackend, entries: &[[u32; 4]], bits: KeyBits) -> Vec<[u32; 4]> {
        let device = gpu.device();
        let total = entries.len() as u64;
        let bytes = total * 16;
        let keys = device
            .storage_init("keys", bytemuck::cast_slice(entries))
            .unwrap();
        let other = device
            .storage("other", bytes, wgpu::BufferUsages::COPY_SRC)
            .unwrap();
        let count = device
            .storage_init("count", bytemuck::bytes_of(&(entries.len() as u32)))
            .unwrap();
        let hist = device
            .storage(
                "hist",
                total.div_ceil(RADIX_BLOCK) * (1u64 << RADIX_BITS) * 4,
                wgpu::BufferUsages::empty(),
            )
            .unwrap();
        let mut encoder = device.wgpu().create_command_encoder(&Default::default());
        let sorted = gpu
            .sort()
            .encode(
                Binder::Fresh(device),
                &mut encoder,
                [keys, other],
                &SortInputs {
                    hist: &hist,
                    count: &count,
                    bits,
                    dispatch: SortDispatch::Direct { total },
                },
            )
            .unwrap();
        let out = device
            .submit_and_read(encoder, &[(&sorted, bytes)])
            .unwrap();
        bytemuck::pod_collect_to_vec(&out[0])
    }

    /// The radix sort is a stable sort by (tile, depth key) on random keys, at sizes around its
    /// block of 2048 entries, with few and many varying bits.
    #[test]
    fn radix_sort_is_a_stable_sort_by_tile_then_depth() {
        let Some(gpu) = test_backend() else { return };
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        for (n, depth_bits, tiles) in [
            (1usize, 3u32, 1u32),
            (2047, 12, 5),
            (2048, 22, 64),
            (2049, 32, 300),
            (9000, 9, 1000),
        ] {
            // Keys vary only in their low `depth_bits` (as the frame's depth range promises);
            // few distinct values make ties, which must keep their input order.
            let high = 0x4040_0000u32 & !(u32::MAX.checked_shr(32 - depth_bits).unwrap_or(0));
            let entries: Vec<[u32; 4]> = (0..n as u32)
                .map(|i| {
                    let low = rng
                        .random::<u32>()
                        .checked_shr(32 - depth_bits)
                        .unwrap_or(0)
                        % 97;
                    [rng.random_range(0..tiles), high | low, i, 0]
                })
                .collect();
            let bits = KeyBits {
                depth: depth_bits,
                tile: varying_bits(0, tiles - 1),
            };
            let mut expected = entries.clone();
            expected.sort_by_key(|e| (e[0], e[1]));
            assert_eq!(device_sort(&gpu, &entries, bits), expected, "{n} entries");
        }
    }

    #[test]
    fn radix_pass_mirrors_the_wgsl() {
        crate::gpu::layout::assert_mirrors::<RadixPassGpu>(&shaders::RADIX_COUNT);
    }

    #[test]
    fn varying_bits_counts_up_to_the_highest_differing_bit() {
        assert_eq!(varying_bits(0, 0), 0);
        assert_eq!(varying_bits(0, 1), 1);
        assert_eq!(varying_bits(0, 1023), 10);
        assert_eq!(varying_bits(0, 1024), 11);
        assert_eq!(varying_bits(0xF0F0, 0xF0F1), 1);
        assert_eq!(varying_bits(0x8000_0000, 0), 32);
    }

    /// Surfels at view depths 3.1 and 3.5 share the f32 bits above bit 21 (3.1 = 0x40466666,
    /// 3.5 = 0x40600000), margin included; surfels behind the camera do not count; none in front
    /// needs no pass.
    #[test]
    fn depth_bits_cover_the_surfels_in_front_of_the_camera() {
        let camera = Camera::look_at(
            64,
            48,
            0.8,
            DVec3::new(0.0, 0.0, 4.0),
            DVec3::ZERO,
            DVec3::Y,
        );
        let mut surfels = Surfels::zeros(3);
        surfels.position = vec![[0.0, 0.0, 0.9], [0.1, 0.0, 0.5], [0.0, 0.0, 9.0]];
        assert_eq!(varying_depth_bits(&surfels, &camera, 0.01), 22);
        let f32_bits = |z: f64| (z as f32).to_bits();
        assert_eq!(varying_bits(f32_bits(3.1), f32_bits(3.5)), 22);
        surfels.position = vec![[0.0, 0.0, 9.0]];
        assert_eq!(varying_depth_bits(&surfels, &camera, 0.01), 0);
        // One surfel: only the low bits within the margin (±1e-5, ±130 ulps at 3.1) vary, far
        // fewer than a full sort's 32.
        surfels.position = vec![[0.0, 0.0, 0.9]];
        let bits = varying_depth_bits(&surfels, &camera, 0.01);
        assert!((8..16).contains(&bits), "{bits}");
    }
}

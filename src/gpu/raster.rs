//! [`GpuBackend`]: the rasterizer's forward and backward passes as wgpu compute kernels.
//!
//! Forward (each stage in a `tracing` span): `upload` (raw surfels as f32), `project` (kernel,
//! one thread per surfel, then the per-surfel tile counts are read back), `scan` (host exclusive
//! scan into entry offsets), `bin_sort` (kernels: emit (tile, depth, surfel) entries, a stable
//! 4-bit radix sort by (tile, depth), per-tile ranges), `rasterize` (kernel, one 8×8 workgroup per
//! tile, one thread per pixel), `readback` (G-buffers and evaluation counts) and `depth_normal`
//! (host, f64). The tiles are always 8×8 on the device whatever `RasterSettings::tile_size` says:
//! the output does not depend on the tile size. (Measured on lavapipe at 200k surfels, 8×8 tiles
//! halve the per-pixel walks of 16×16 ones for ~1.5× the entries, and the radix sort is ~4× faster
//! than the bitonic sort it replaced.)
//!
//! Backward: the host chains the depth-normal gradient into the depth gradient (f64) and uploads
//! the per-pixel upstream gradient; `rasterize_backward` (one thread per pixel) accumulates into
//! 22 per-surfel sums with float atomics (or a CAS loop, [`AtomicsMode`]); `project_backward`
//! (one thread per surfel) chains them to raw parameters and |dL/dμ|; the result is read back.
//! Buffers the backward pass needs (projections, sorted entries, tile ranges, G-buffers, final
//! transmittance, contributor counts) stay on the device in the forward result.
//!
//! Limits: every buffer is checked against the device's `max_storage_buffer_binding_size` and
//! `max_buffer_size` (or [`GpuOptions::max_binding_bytes`]) as it is created. An image whose
//! per-pixel buffers or tile entries would exceed them is rasterized in bands of tile rows: as
//! many rows as the G-buffer allows, and a band whose entries do not fit is halved until they do.
//! The projection is the same for every band (only the tile counts and entries are the band's),
//! so the backward passes of all bands add into one set of per-surfel sums. What cannot be split
//! (the per-surfel buffers, or one tile row's entries) fails with [`RasterError::Gpu`] naming the
//! buffer. Workgroup memory: only the radix sort's (8 KiB per workgroup).
//!
//! The resident trainer (`super::train`) runs the same kernels without the host round trips: the
//! scan on the device, the sort and the range kernels dispatched indirectly (their entry count
//! is read from a buffer, [`SortInputs`]).
//!
//! Threading: calls on one [`GpuBackend`] are serialized (a mutex); the host-side conversions
//! are single-threaded.

use bytemuck::{Pod, Zeroable};
use tracing::info_span;
use wgpu::util::DeviceExt;

use super::device::Device;
use super::layout::wgsl_mirror;
use super::shade::{Lighting, ShadePipelines};
use super::{GpuContext, GpuError};
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::envmap::EnvGrad;
use crate::core::light::{LightKind, LightProbe};
use crate::core::raster::{
    begin_backward, depth_normals, depth_upstream, validate_inputs, Backend, GBufferGrads,
    GBuffers, RasterError, RasterGrads, RasterSettings, RasterStats, Rasterized, SavedForward,
    StageTime,
};
use crate::core::shading::{
    self, GBufferGrad, SavedShading, ShadingBuffers, ShadingError, StokesImage, StokesImageGrad,
};
use crate::core::surfels::{SurfelGrads, Surfels};

/// Tile edge of the device kernels (`TILE` in shaders/common.wgsl).
pub(super) const TILE: u32 = 8;
/// Per-surfel gradient accumulators (`NUM_ACC`).
pub(super) const NUM_ACC: u64 = 22;
/// Per-pixel forward outputs (`NUM_OUT`).
pub(super) const NUM_OUT: usize = 10;
/// Per-surfel raw gradient outputs of `project_backward`.
pub(super) const NUM_RAW_GRAD: usize = 16;

const COMMON: &str = include_str!("../../shaders/common.wgsl");
const PROJECT: &str = include_str!("../../shaders/project.wgsl");
const BIN: &str = include_str!("../../shaders/bin.wgsl");
const RADIX_SORT: &str = include_str!("../../shaders/radix_sort.wgsl");
const TILE_LIST: &str = include_str!("../../shaders/tile_list.wgsl");
const RASTERIZE: &str = include_str!("../../shaders/rasterize.wgsl");
const RASTERIZE_BACKWARD: &str = include_str!("../../shaders/rasterize_backward.wgsl");
const ATOMIC_FLOAT: &str = include_str!("../../shaders/atomic_float.wgsl");
const ATOMIC_CAS: &str = include_str!("../../shaders/atomic_cas.wgsl");
const WALK_OWN: &str = include_str!("../../shaders/walk_own.wgsl");
const WALK_SUBGROUP: &str = include_str!("../../shaders/walk_subgroup.wgsl");
const PROJECT_BACKWARD: &str = include_str!("../../shaders/project_backward.wgsl");

/// How the backward pass adds into the per-surfel gradient sums.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AtomicsMode {
    /// Native `atomicAdd` on `atomic<f32>` (`SHADER_FLOAT32_ATOMIC`).
    Float,
    /// Compare-and-swap loop on the f32 bit pattern in an `atomic<u32>`.
    CompareExchange,
}

/// How far back each thread of the backward pass walks its tile's list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Walk {
    /// From its own last composited entry.
    OwnEntries,
    /// From the last entry any thread of its subgroup composited, in step with them (`SUBGROUP`).
    Subgroup,
}

/// Options of [`GpuBackend::with_options`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GpuOptions {
    /// Use the compare-and-swap path even where float atomics exist (to test it).
    pub force_compare_exchange: bool,
    /// Walk each pixel's own entries in the backward pass even where subgroups exist (to test it).
    pub force_own_walk: bool,
    /// Treat buffers above this many bytes as beyond the device's binding limit (to test the
    /// splitting of large renders into bands on small scenes).
    pub max_binding_bytes: Option<u64>,
    /// Time every compute pass on the device (where the adapter has `TIMESTAMP_QUERY`), for
    /// [`Backend::take_stage_times`].
    pub profile: bool,
}

wgsl_mirror! {
    /// `Params` of shaders/common.wgsl.
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    pub(super) struct ParamsGpu = "Params" {
        rot0: [f32; 4],
        rot1: [f32; 4],
        rot2: [f32; 4],
        trans: [f32; 4],
        origin: [f32; 4],
        fx: f32,
        fy: f32,
        cx: f32,
        cy: f32,
        width: u32,
        height: u32,
        tiles_x: u32,
        tiles_y: u32,
        surfels: u32,
        pad0: u32,
        pad1: u32,
        lowpass: u32,
        near: f32,
        alpha_min: f32,
        alpha_max: f32,
        transmittance_min: f32,
        lowpass_sigma_px: f32,
        inv_lowpass_sigma2: f32,
        normalize_alpha_min: f32,
        pad2: f32,
        band_tile_first: u32,
        band_tile_end: u32,
        band_pixel_first: u32,
        band_pixel_rows: u32,
    }
}

impl ParamsGpu {
    /// The parameters of a whole image of `camera` (one band).
    pub(super) fn whole_image(camera: &Camera, settings: &RasterSettings, surfels: u32) -> Self {
        let band = Band {
            first: 0,
            end: camera.height.div_ceil(TILE),
        };
        Self::new(camera, settings, surfels, band)
    }

    /// The parameters of `band` of an image of `camera`.
    fn new(camera: &Camera, settings: &RasterSettings, surfels: u32, band: Band) -> Self {
        let (rot, trans) = camera.world_to_camera_opencv();
        let v4 = |v: glam::DVec3| [v.x as f32, v.y as f32, v.z as f32, 0.0];
        let sigma = settings.lowpass_sigma_px;
        let lowpass = sigma > 0.0;
        ParamsGpu {
            rot0: v4(rot.x_axis),
            rot1: v4(rot.y_axis),
            rot2: v4(rot.z_axis),
            trans: v4(trans),
            origin: v4(camera.origin()),
            fx: camera.fx as f32,
            fy: camera.fy as f32,
            cx: camera.cx as f32,
            cy: camera.cy as f32,
            width: camera.width,
            height: camera.height,
            tiles_x: camera.width.div_ceil(TILE),
            tiles_y: camera.height.div_ceil(TILE),
            surfels,
            pad0: 0,
            pad1: 0,
            lowpass: lowpass as u32,
            near: settings.near as f32,
            alpha_min: settings.alpha_min as f32,
            alpha_max: settings.alpha_max as f32,
            transmittance_min: settings.transmittance_min as f32,
            lowpass_sigma_px: sigma as f32,
            inv_lowpass_sigma2: if lowpass {
                (1.0 / (sigma * sigma)) as f32
            } else {
                0.0
            },
            normalize_alpha_min: settings.normalize_alpha_min as f32,
            pad2: 0.0,
            band_tile_first: band.first,
            band_tile_end: band.end,
            band_pixel_first: band.first * TILE,
            band_pixel_rows: band.pixel_rows(camera.height),
        }
    }
}

/// A band of tile rows `[first, end)`: a large image is rasterized one band at a time so that
/// no per-pixel buffer or entry list exceeds the device's binding limit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Band {
    first: u32,
    end: u32,
}

impl Band {
    fn tile_rows(self) -> u32 {
        self.end - self.first
    }

    /// Pixel rows of the band in an image of `height` rows.
    fn pixel_rows(self, height: u32) -> u32 {
        (self.end * TILE).min(height) - self.first * TILE
    }

    /// The band's rows of a row-major per-pixel array with `per_row` values per image row.
    fn rows_of<T>(self, values: &[T], height: u32, per_row: usize) -> &[T] {
        let start = (self.first * TILE) as usize * per_row;
        &values[start..start + self.pixel_rows(height) as usize * per_row]
    }

    fn halves(self) -> (Band, Band) {
        let mid = self.first + self.tile_rows() / 2;
        (
            Band {
                first: self.first,
                end: mid,
            },
            Band {
                first: mid,
                end: self.end,
            },
        )
    }
}

wgsl_mirror! {
    /// `Raw` of shaders/common.wgsl: a surfel's raw parameters, 16 values.
    #[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
    pub(super) struct RawGpu = "Raw" {
        pub(super) pos_op: [f32; 4],
        pub(super) quat: [f32; 4],
        pub(super) scale_rough_ior: [f32; 4],
        pub(super) albedo: [f32; 4],
    }
}

/// The surfels' raw parameters in the kernels' layout (f32).
pub(super) fn raw_surfels(surfels: &Surfels) -> Vec<RawGpu> {
    let f = |v: f64| v as f32;
    (0..surfels.len())
        .map(|i| {
            let p = surfels.position[i];
            let s = surfels.log_scale[i];
            let a = surfels.albedo[i];
            RawGpu {
                pos_op: [f(p[0]), f(p[1]), f(p[2]), f(surfels.opacity[i])],
                quat: surfels.rotation[i].map(f),
                scale_rough_ior: [f(s[0]), f(s[1]), f(surfels.roughness[i]), f(surfels.ior[i])],
                albedo: [f(a[0]), f(a[1]), f(a[2]), 0.0],
            }
        })
        .collect()
}

/// Bytes of one `Proj` (7 × vec4).
pub(super) const PROJ_BYTES: u64 = 112;
/// Bytes of one sort entry (vec4<u32>).
pub(super) const ENTRY_BYTES: u64 = 16;

/// Bits sorted per radix pass (`RADIX_BINS` = 2^bits in shaders/radix_sort.wgsl).
const RADIX_BITS: u32 = 4;
/// Entries per radix-sort workgroup (`RADIX_BLOCK`).
pub(super) const RADIX_BLOCK: u64 = 2048;

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
fn varying_depth_bits(surfels: &Surfels, camera: &Camera, near: f64) -> u32 {
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

/// Key words of a binning entry, as `RadixPass::word` names them.
const DEPTH_WORD: u32 = 0;
const TILE_WORD: u32 = 1;

pub(super) struct Pipelines {
    pub(super) project: wgpu::ComputePipeline,
    pub(super) emit: wgpu::ComputePipeline,
    pub(super) tile_ranges: wgpu::ComputePipeline,
    radix_count: wgpu::ComputePipeline,
    radix_scan: wgpu::ComputePipeline,
    radix_scatter: wgpu::ComputePipeline,
    pub(super) rasterize: wgpu::ComputePipeline,
    pub(super) rasterize_backward: wgpu::ComputePipeline,
    pub(super) project_backward: wgpu::ComputePipeline,
}

/// The wgpu rasterizer backend.
pub struct GpuBackend {
    device: Device,
    pipelines: Pipelines,
    shading: ShadePipelines,
    atomics: AtomicsMode,
    walk: Walk,
}

/// What the forward pass keeps (on the device) for the backward pass.
struct Saved {
    num_surfels: usize,
    camera: Camera,
    settings: RasterSettings,
    raw: wgpu::Buffer,
    proj: wgpu::Buffer,
    /// One per band, top to bottom.
    bands: Vec<BandSaved>,
}

/// The forward state of one band: its parameters, sorted entries, tile ranges and per-pixel
/// buffers (G-buffers, final transmittance, contributor counts), all for the band's rows only.
struct BandSaved {
    band: Band,
    params: wgpu::Buffer,
    entries: wgpu::Buffer,
    ranges: wgpu::Buffer,
    gbuf: wgpu::Buffer,
    final_t: wgpu::Buffer,
    contrib: wgpu::Buffer,
}

/// What every band of one forward pass shares: the view, and the surfels on the device (raw and
/// projected; the projection is the same for every band).
struct Frame<'a> {
    camera: &'a Camera,
    settings: &'a RasterSettings,
    surfels: u32,
    /// [`varying_depth_bits`] of the surfels.
    depth_bits: u32,
    raw: &'a wgpu::Buffer,
    proj: &'a wgpu::Buffer,
}

/// What the forward pass of one band brings back.
struct BandResult {
    saved: BandSaved,
    gbuf: Vec<f32>,
    evals: Vec<u32>,
    tile_counts: Vec<u32>,
}

/// The forward pass of one band: done, or its entries exceed the binding limit.
enum BandOutcome {
    Done(Box<BandResult>),
    TooManyEntries(u64),
}

impl SavedForward for Saved {
    const NOT_THIS_BACKEND: &'static str = "not a gpu forward result";
    fn scene(&self) -> (usize, &Camera, &RasterSettings) {
        (self.num_surfels, &self.camera, &self.settings)
    }
}

impl GpuBackend {
    /// Compiles the kernels on `ctx`'s device; float atomics where the device has them.
    pub fn new(ctx: GpuContext) -> Result<Self, GpuError> {
        Self::with_options(ctx, GpuOptions::default())
    }

    pub fn with_options(ctx: GpuContext, options: GpuOptions) -> Result<Self, GpuError> {
        let atomics = if ctx.has_float_atomics() && !options.force_compare_exchange {
            AtomicsMode::Float
        } else {
            AtomicsMode::CompareExchange
        };
        let walk = if ctx.has_subgroups() && !options.force_own_walk {
            Walk::Subgroup
        } else {
            Walk::OwnEntries
        };
        let device = Device::new(ctx, options.max_binding_bytes, options.profile);
        let atomic_src = match atomics {
            AtomicsMode::Float => ATOMIC_FLOAT,
            AtomicsMode::CompareExchange => ATOMIC_CAS,
        };
        let walk_src = match walk {
            Walk::OwnEntries => WALK_OWN,
            Walk::Subgroup => WALK_SUBGROUP,
        };
        let pipelines = device.compile_all(|d| Pipelines {
            project: d.pipeline("project", &[COMMON, PROJECT], "project"),
            emit: d.pipeline("emit", &[COMMON, BIN], "emit"),
            tile_ranges: d.pipeline("tile_ranges", &[COMMON, BIN], "tile_ranges"),
            radix_count: d.pipeline("radix_count", &[RADIX_SORT], "radix_count"),
            radix_scan: d.pipeline("radix_scan", &[RADIX_SORT], "radix_scan"),
            radix_scatter: d.pipeline("radix_scatter", &[RADIX_SORT], "radix_scatter"),
            rasterize: d.pipeline("rasterize", &[COMMON, TILE_LIST, RASTERIZE], "rasterize"),
            rasterize_backward: d.pipeline(
                "rasterize_backward",
                &[COMMON, TILE_LIST, RASTERIZE_BACKWARD, atomic_src, walk_src],
                "rasterize_backward",
            ),
            project_backward: d.pipeline(
                "project_backward",
                &[COMMON, PROJECT_BACKWARD],
                "project_backward",
            ),
        })?;
        let shading = ShadePipelines::compile(&device, atomic_src)?;
        Ok(GpuBackend {
            device,
            pipelines,
            shading,
            atomics,
            walk,
        })
    }

    pub fn context(&self) -> &GpuContext {
        self.device.context()
    }

    pub fn atomics(&self) -> AtomicsMode {
        self.atomics
    }

    pub fn walk(&self) -> Walk {
        self.walk
    }

    /// The device and its helpers.
    pub(super) fn device(&self) -> &Device {
        &self.device
    }

    /// The rasterization kernels.
    pub(super) fn raster(&self) -> &Pipelines {
        &self.pipelines
    }

    /// The PolarDR shading kernels.
    pub(super) fn shading(&self) -> &ShadePipelines {
        &self.shading
    }

    /// One workgroup per tile of `band`.
    fn dispatch_tiles(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        label: &'static str,
        pipeline: &wgpu::ComputePipeline,
        group: &wgpu::BindGroup,
        camera: &Camera,
        band: Band,
    ) {
        let mut pass = self.device.begin_pass(encoder, label);
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, group, &[]);
        pass.dispatch_workgroups(camera.width.div_ceil(TILE), band.tile_rows(), 1);
    }

    fn forward_impl(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError> {
        let n = surfels.len();
        let n32 = u32::try_from(n)
            .map_err(|_| RasterError::Gpu(format!("{n} surfels exceed the u32 index range")))?;
        let (w, h) = (camera.width as usize, camera.height as usize);
        // Every buffer is checked as it is created; the backward pass's per-surfel sums are
        // checked now so that a render the backward pass could not handle fails at once.
        self.device
            .check_size("gradient sums", n as u64 * NUM_ACC * 4)?;
        // The largest per-pixel buffers (G-buffers forward, upstream gradient backward) decide
        // how many tile rows a band may have.
        let tile_row_bytes = u64::from(camera.width) * u64::from(TILE) * NUM_OUT as u64 * 4;
        self.device
            .check_size("g-buffers (one tile row)", tile_row_bytes)?;
        let rows_per_band =
            (self.device.binding_limit() / tile_row_bytes).min(u64::from(u32::MAX)) as u32;
        let tile_rows = camera.height.div_ceil(TILE);
        // A stack with the top band last, so bands are popped top to bottom.
        let mut pending: Vec<Band> = (0..tile_rows)
            .step_by(rows_per_band as usize)
            .map(|first| Band {
                first,
                end: (first + rows_per_band).min(tile_rows),
            })
            .rev()
            .collect();

        let raw_buf = {
            let _span = info_span!("upload", surfels = n).entered();
            self.device
                .storage_init("raw surfels", bytemuck::cast_slice(&raw_surfels(surfels)))?
        };
        let proj_buf = self.device.storage(
            "projected surfels",
            n as u64 * PROJ_BYTES,
            wgpu::BufferUsages::empty(),
        )?;

        // Bands top to bottom; one whose entries exceed the limit is split in two.
        let frame = Frame {
            camera,
            settings,
            surfels: n32,
            depth_bits: varying_depth_bits(surfels, camera, settings.near),
            raw: &raw_buf,
            proj: &proj_buf,
        };
        let mut done: Vec<BandResult> = Vec::new();
        while let Some(band) = pending.pop() {
            let _span = info_span!("band", first = band.first, end = band.end).entered();
            match self.forward_band(&frame, band)? {
                BandOutcome::Done(result) => done.push(*result),
                BandOutcome::TooManyEntries(total) if band.tile_rows() == 1 => {
                    return Err(self
                        .device
                        .too_large("tile entries (one tile row)", total * ENTRY_BYTES)
                        .into());
                }
                BandOutcome::TooManyEntries(_) => {
                    let (top, bottom) = band.halves();
                    pending.push(bottom);
                    pending.push(top);
                }
            }
        }

        let _span = info_span!("readback").entered();
        let mut gb = GBuffers::zeros(w, h);
        let mut visible = vec![false; n];
        let mut tile_entries = 0usize;
        let mut pixel_evaluations = 0u64;
        for result in &done {
            let first_pixel = (result.saved.band.first * TILE) as usize * w;
            for (j, px) in result.gbuf.chunks_exact(NUM_OUT).enumerate() {
                let k = first_pixel + j;
                let v = |c: usize| f64::from(px[c]);
                gb.alpha[k] = v(0);
                gb.depth[k] = v(1);
                gb.normal[k] = [v(2), v(3), v(4)];
                gb.albedo[k] = [v(5), v(6), v(7)];
                gb.roughness[k] = v(8);
                gb.ior[k] = v(9);
            }
            for (seen, &c) in visible.iter_mut().zip(&result.tile_counts) {
                *seen |= c > 0;
            }
            tile_entries += result
                .tile_counts
                .iter()
                .map(|&c| c as usize)
                .sum::<usize>();
            pixel_evaluations += result.evals.iter().map(|&e| u64::from(e)).sum::<u64>();
        }
        drop(_span);
        {
            let _span = info_span!("depth_normal").entered();
            gb.depth_normal =
                depth_normals(camera, &gb.depth, &gb.alpha, settings.normalize_alpha_min);
        }
        Ok(Rasterized {
            gbuffers: gb,
            stats: RasterStats {
                visible_surfels: visible.iter().filter(|&&v| v).count(),
                tile_entries,
                pixel_evaluations,
            },
            saved: Box::new(Saved {
                num_surfels: n,
                camera: *camera,
                settings: *settings,
                raw: raw_buf,
                proj: proj_buf,
                bands: done.into_iter().map(|r| r.saved).collect(),
            }),
        })
    }

    /// Projects the surfels for `band` (the projection is the same for every band; the tile
    /// counts are the band's), bins and sorts the band's entries and rasterizes its tiles.
    fn forward_band(&self, frame: &Frame, band: Band) -> Result<BandOutcome, RasterError> {
        let device = self.device.wgpu();
        let (camera, settings) = (frame.camera, frame.settings);
        let (raw_buf, proj_buf) = (frame.raw, frame.proj);
        let n = frame.surfels as usize;
        let pixels = u64::from(camera.width) * u64::from(band.pixel_rows(camera.height));
        let tiles = camera.width.div_ceil(TILE) * band.tile_rows();
        let params = ParamsGpu::new(camera, settings, frame.surfels, band);
        let params_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("params"),
            contents: bytemuck::bytes_of(&params),
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });

        // Projection and the band's tile counts.
        let counts_buf =
            self.device
                .storage("tile counts", n as u64 * 4, wgpu::BufferUsages::COPY_SRC)?;
        let counts: Vec<u32> = {
            let _span = info_span!("project", surfels = n).entered();
            let mut encoder = device.create_command_encoder(&Default::default());
            let group = self.device.bind(
                &self.pipelines.project,
                &[
                    (0, &params_buf),
                    (1, raw_buf),
                    (2, proj_buf),
                    (3, &counts_buf),
                ],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "project",
                &self.pipelines.project,
                &group,
                n as u64,
            )?;
            let out = self
                .device
                .submit_and_read(encoder, &[(&counts_buf, n as u64 * 4)])?;
            bytemuck::pod_collect_to_vec(&out[0])
        };

        // Host exclusive scan of the tile counts. Entries that fit the binding limit (a u32 of
        // bytes) also fit the u32 offsets.
        let total: u64 = counts.iter().map(|&c| u64::from(c)).sum();
        if total * ENTRY_BYTES > self.device.binding_limit() {
            return Ok(BandOutcome::TooManyEntries(total));
        }
        let offsets: Vec<u32> = {
            let _span = info_span!("scan").entered();
            counts
                .iter()
                .scan(0u32, |next, &c| {
                    let offset = *next;
                    *next += c;
                    Some(offset)
                })
                .collect()
        };

        let count_buf = self
            .device
            .storage_init("entry count", bytemuck::bytes_of(&(total as u32)))?;
        let offsets_buf = self
            .device
            .storage_init("entry offsets", bytemuck::cast_slice(&offsets))?;
        let entries_buf = self.device.storage(
            "tile entries",
            total * ENTRY_BYTES,
            wgpu::BufferUsages::empty(),
        )?;
        // The radix sort's other half: each pass reads one and writes the other.
        let sorted_alt_buf = self.device.storage(
            "tile entries (sort)",
            total * ENTRY_BYTES,
            wgpu::BufferUsages::empty(),
        )?;
        let ranges_buf = self.device.storage(
            "tile ranges",
            u64::from(tiles) * 8,
            wgpu::BufferUsages::COPY_DST,
        )?;
        let gbuf_buf = self.device.storage(
            "g-buffers",
            pixels * NUM_OUT as u64 * 4,
            wgpu::BufferUsages::COPY_SRC,
        )?;
        let final_t_buf = self.device.storage(
            "final transmittance",
            pixels * 4,
            wgpu::BufferUsages::empty(),
        )?;
        let contrib_buf =
            self.device
                .storage("contributors", pixels * 4, wgpu::BufferUsages::empty())?;
        let evals_buf =
            self.device
                .storage("evaluations", pixels * 4, wgpu::BufferUsages::COPY_SRC)?;

        let mut encoder = device.create_command_encoder(&Default::default());
        let entries_buf = {
            let _span = info_span!("bin_sort", entries = total).entered();
            let group = self.device.bind(
                &self.pipelines.emit,
                &[
                    (0, &params_buf),
                    (1, proj_buf),
                    (2, &offsets_buf),
                    (3, &entries_buf),
                ],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "emit",
                &self.pipelines.emit,
                &group,
                n as u64,
            )?;
            let hist = self.device.storage(
                "radix histogram",
                total.div_ceil(RADIX_BLOCK) * (1u64 << RADIX_BITS) * 4,
                wgpu::BufferUsages::empty(),
            )?;
            let entries_buf = self.encode_sort(
                &mut encoder,
                [entries_buf, sorted_alt_buf],
                &SortInputs {
                    hist: &hist,
                    count: &count_buf,
                    bits: KeyBits {
                        depth: frame.depth_bits,
                        tile: varying_bits(0, tiles - 1),
                    },
                    dispatch: SortDispatch::Direct { total },
                },
            )?;
            encoder.clear_buffer(&ranges_buf, 0, None);
            let group = self.device.bind(
                &self.pipelines.tile_ranges,
                &[(3, &entries_buf), (4, &ranges_buf), (5, &count_buf)],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "tile_ranges",
                &self.pipelines.tile_ranges,
                &group,
                total,
            )?;
            entries_buf
        };
        let out = {
            let _span = info_span!("rasterize", entries = total).entered();
            let group = self.device.bind(
                &self.pipelines.rasterize,
                &[
                    (0, &params_buf),
                    (1, &entries_buf),
                    (2, &ranges_buf),
                    (3, proj_buf),
                    (4, &gbuf_buf),
                    (5, &final_t_buf),
                    (6, &contrib_buf),
                    (7, &evals_buf),
                ],
            );
            self.dispatch_tiles(
                &mut encoder,
                "rasterize",
                &self.pipelines.rasterize,
                &group,
                camera,
                band,
            );
            self.device.submit_and_read(
                encoder,
                &[
                    (&gbuf_buf, pixels * NUM_OUT as u64 * 4),
                    (&evals_buf, pixels * 4),
                ],
            )?
        };
        Ok(BandOutcome::Done(Box::new(BandResult {
            gbuf: bytemuck::pod_collect_to_vec(&out[0]),
            evals: bytemuck::pod_collect_to_vec(&out[1]),
            tile_counts: counts,
            saved: BandSaved {
                band,
                params: params_buf,
                entries: entries_buf,
                ranges: ranges_buf,
                gbuf: gbuf_buf,
                final_t: final_t_buf,
                contrib: contrib_buf,
            },
        })))
    }

    /// Encodes the radix sort of the entries of `buffers[0]` (as many as `inputs.count[0]`) by
    /// (tile, depth) and returns the buffer that holds the result (the passes alternate between
    /// the two). The passes cover the varying low bits of the depth, then of the tile index
    /// ([`KeyBits`]); each reads its digit from its own aligned slice of a uniform buffer.
    pub(super) fn encode_sort(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        buffers: [wgpu::Buffer; 2],
        inputs: &SortInputs,
    ) -> Result<wgpu::Buffer, GpuError> {
        let [mut keys, mut other] = buffers;
        let grid = match inputs.dispatch {
            SortDispatch::Direct { total } if total < 2 => return Ok(keys),
            SortDispatch::Direct { total } => {
                let (x, y) = self.device.workgroup_grid(total.div_ceil(RADIX_BLOCK))?;
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
        let wgpu_device = self.device.wgpu();
        let stride = u64::from(wgpu_device.limits().min_uniform_buffer_offset_alignment).max(16);
        let mut bytes = vec![0u8; passes.len() * stride as usize];
        for (i, p) in passes.iter().enumerate() {
            let at = i * stride as usize;
            bytes[at..at + 16].copy_from_slice(bytemuck::bytes_of(p));
        }
        let pass_buf = self.device.uniform("radix passes", &bytes);
        let (hist, count) = (inputs.hist, inputs.count);
        let mut compute = self.device.begin_pass(encoder, "radix sort");
        for i in 0..passes.len() {
            let pass_params = wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer: &pass_buf,
                offset: i as u64 * stride,
                size: wgpu::BufferSize::new(16),
            });
            // With `digit`, the pass parameters at binding 0 (the scan reads only the counts).
            let group = |pipeline: &wgpu::ComputePipeline,
                         digit: bool,
                         buffers: &[(u32, &wgpu::Buffer)]| {
                let mut entries = Vec::new();
                if digit {
                    entries.push(wgpu::BindGroupEntry {
                        binding: 0,
                        resource: pass_params.clone(),
                    });
                }
                entries.extend(
                    buffers
                        .iter()
                        .map(|&(binding, buffer)| wgpu::BindGroupEntry {
                            binding,
                            resource: buffer.as_entire_binding(),
                        }),
                );
                wgpu_device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: None,
                    layout: &pipeline.get_bind_group_layout(0),
                    entries: &entries,
                })
            };
            let dispatch_blocks = |compute: &mut wgpu::ComputePass| match (grid, inputs.dispatch) {
                (Some((x, y)), _) => compute.dispatch_workgroups(x, y, 1),
                (None, SortDispatch::Indirect { args, offset }) => {
                    compute.dispatch_workgroups_indirect(args, offset)
                }
                (None, SortDispatch::Direct { .. }) => unreachable!("direct sorts have a grid"),
            };
            compute.set_pipeline(&self.pipelines.radix_count);
            compute.set_bind_group(
                0,
                &group(
                    &self.pipelines.radix_count,
                    true,
                    &[(1, &keys), (3, hist), (4, count)],
                ),
                &[],
            );
            dispatch_blocks(&mut compute);
            compute.set_pipeline(&self.pipelines.radix_scan);
            compute.set_bind_group(
                0,
                &group(&self.pipelines.radix_scan, false, &[(3, hist), (4, count)]),
                &[],
            );
            compute.dispatch_workgroups(1, 1, 1);
            compute.set_pipeline(&self.pipelines.radix_scatter);
            compute.set_bind_group(
                0,
                &group(
                    &self.pipelines.radix_scatter,
                    true,
                    &[(1, &keys), (2, &other), (3, hist), (4, count)],
                ),
                &[],
            );
            dispatch_blocks(&mut compute);
            std::mem::swap(&mut keys, &mut other);
        }
        Ok(keys)
    }

    fn backward_impl(
        &self,
        saved: &Saved,
        camera: &Camera,
        settings: &RasterSettings,
        gb: &GBuffers,
        upstream: &GBufferGrads,
    ) -> Result<RasterGrads, RasterError> {
        let n = saved.num_surfels;
        let (w, h) = (gb.width, gb.height);
        let eps = settings.normalize_alpha_min;
        let depth_grad = depth_upstream(camera, gb, upstream, eps);
        let up: Vec<f32> = (0..w * h)
            .flat_map(|k| {
                let n3 = upstream.normal[k];
                let a3 = upstream.albedo[k];
                [
                    upstream.alpha[k],
                    depth_grad[k],
                    n3[0],
                    n3[1],
                    n3[2],
                    a3[0],
                    a3[1],
                    a3[2],
                    upstream.roughness[k],
                    upstream.ior[k],
                ]
                .map(|v| v as f32)
            })
            .collect();
        // Newly created buffers are zero-initialized.
        let acc_buf = self.device.storage(
            "gradient sums",
            n as u64 * NUM_ACC * 4,
            wgpu::BufferUsages::empty(),
        )?;
        let raw_grad_bytes = n as u64 * NUM_RAW_GRAD as u64 * 4;
        let out_buf = self.device.storage(
            "raw gradients",
            raw_grad_bytes,
            wgpu::BufferUsages::COPY_SRC,
        )?;

        let mut encoder = self
            .device
            .wgpu()
            .create_command_encoder(&Default::default());
        // Every band adds into the same per-surfel sums: the projection is the same in all.
        for band in &saved.bands {
            let _span = info_span!("rasterize_backward", first = band.band.first).entered();
            let band_up = band.band.rows_of(&up, camera.height, w * NUM_OUT);
            let up_buf = self
                .device
                .storage_init("upstream gradient", bytemuck::cast_slice(band_up))?;
            let group = self.device.bind(
                &self.pipelines.rasterize_backward,
                &[
                    (0, &band.params),
                    (1, &band.entries),
                    (2, &band.ranges),
                    (3, &saved.proj),
                    (4, &band.gbuf),
                    (5, &up_buf),
                    (6, &band.final_t),
                    (7, &band.contrib),
                    (8, &acc_buf),
                ],
            );
            self.dispatch_tiles(
                &mut encoder,
                "rasterize_backward",
                &self.pipelines.rasterize_backward,
                &group,
                camera,
                band.band,
            );
        }
        let out = {
            let _span = info_span!("project_backward").entered();
            // The band parts of the parameters do not enter the projection's backward pass.
            let params = &saved.bands[0].params;
            let group = self.device.bind(
                &self.pipelines.project_backward,
                &[
                    (0, params),
                    (1, &saved.raw),
                    (2, &saved.proj),
                    (3, &acc_buf),
                    (4, &out_buf),
                ],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "project_backward",
                &self.pipelines.project_backward,
                &group,
                n as u64,
            )?;
            self.device
                .submit_and_read(encoder, &[(&out_buf, raw_grad_bytes)])?
        };
        let vals: Vec<f32> = bytemuck::pod_collect_to_vec(&out[0]);
        let mut grads = SurfelGrads::zeros(n);
        let mut mean2d = vec![0.0; n];
        for (i, g) in vals.chunks_exact(NUM_RAW_GRAD).enumerate() {
            let v = |c: usize| f64::from(g[c]);
            grads.position[i] = [v(0), v(1), v(2)];
            grads.log_scale[i] = [v(3), v(4)];
            grads.rotation[i] = [v(5), v(6), v(7), v(8)];
            grads.opacity[i] = v(9);
            grads.albedo[i] = [v(10), v(11), v(12)];
            grads.roughness[i] = v(13);
            grads.ior[i] = v(14);
            mean2d[i] = v(15);
        }
        Ok(RasterGrads {
            surfels: grads,
            mean2d_grad_norm: mean2d,
        })
    }
}

impl Backend for GpuBackend {
    fn name(&self) -> &'static str {
        "gpu"
    }

    fn description(&self) -> String {
        format!(
            "gpu on {}, {:?} atomics, {:?} walk",
            self.device.context().adapter_summary(),
            self.atomics,
            self.walk
        )
    }

    fn forward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError> {
        validate_inputs(surfels, camera, settings)?;
        let _span = info_span!("raster_forward", backend = "gpu").entered();
        self.device
            .scoped("forward", || self.forward_impl(surfels, camera, settings))
    }

    fn backward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
        forward: &Rasterized,
        upstream: &GBufferGrads,
    ) -> Result<RasterGrads, RasterError> {
        let saved: &Saved = begin_backward(surfels, camera, settings, forward, upstream)?;
        let gb = &forward.gbuffers;
        let _span = info_span!("raster_backward", backend = "gpu").entered();
        self.device.scoped("backward", || {
            self.backward_impl(saved, camera, settings, gb, upstream)
        })
    }

    fn take_stage_times(&self) -> Vec<StageTime> {
        self.device.take_stage_times()
    }

    /// On the device under the global light or GridMap; other lights with the cpu code.
    fn shade(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
    ) -> Result<StokesImage, ShadingError> {
        match device_lighting(light) {
            Some(lighting) => self.shade_on_device(camera, buffers, lighting, lut),
            None => shading::shade_image(camera, buffers, light, lut),
        }
    }

    /// The device keeps nothing between the passes: [`Self::shade`].
    fn shade_saved(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
    ) -> Result<(StokesImage, Option<SavedShading>), ShadingError> {
        Ok((self.shade(camera, buffers, light, lut)?, None))
    }

    fn shade_backward(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
        upstream: &StokesImageGrad,
    ) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
        match device_lighting(light) {
            Some(lighting) => {
                self.shade_backward_on_device(camera, buffers, lighting, lut, upstream)
            }
            None => shading::shade_image_backward(camera, buffers, light, lut, upstream),
        }
    }
}

/// The kernels' form of `light`, where they have one.
fn device_lighting(light: &dyn LightProbe) -> Option<Lighting<'_>> {
    match light.kind() {
        LightKind::Global(env) => Some(Lighting::Global(env)),
        LightKind::GridMap(grid) => Some(Lighting::GridMap(grid)),
        LightKind::Other => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;
    use rand::{Rng, SeedableRng};

    /// The gpu backend on any adapter (lavapipe in CI), or `None` with a notice outside CI.
    fn backend() -> Option<GpuBackend> {
        match GpuContext::new(crate::gpu::AdapterRequirement::Any) {
            Ok(ctx) => Some(GpuBackend::with_options(ctx, GpuOptions::default()).unwrap()),
            Err(e) => {
                assert!(
                    !crate::testing::running_in_ci(),
                    "CI=true but no adapter: {e}"
                );
                println!("skipping: no GPU adapter ({e})");
                None
            }
        }
    }

    /// Sorts binning entries (tile, depth key, surfel, unused) on the device by (tile, depth)
    /// over the given varying bits.
    fn device_sort(gpu: &GpuBackend, entries: &[[u32; 4]], bits: KeyBits) -> Vec<[u32; 4]> {
        let device = &gpu.device;
        let total = entries.len() as u64;
        let bytes = total * ENTRY_BYTES;
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
            .encode_sort(
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
        let Some(gpu) = backend() else { return };
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
    fn uniform_and_storage_structs_mirror_the_wgsl() {
        use crate::gpu::layout::assert_mirrors;
        assert_mirrors::<ParamsGpu>(&[COMMON, PROJECT]);
        assert_mirrors::<RawGpu>(&[COMMON, PROJECT]);
        assert_mirrors::<RadixPassGpu>(&[RADIX_SORT]);
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

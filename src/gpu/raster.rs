//! [`Rasterizer`]: the rasterizer's forward and backward passes as wgpu compute kernels (the
//! [`super::backend::GpuBackend`]'s `forward` and `backward`).
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
//! per-pixel buffers or tile entries would exceed them is rasterized in bands of tile rows
//! (`super::band`). The projection is the same for every band (only the tile counts and entries
//! are the band's), so the backward passes of all bands add into one set of per-surfel sums. What
//! cannot be split (the per-surfel buffers, or one tile row's entries) fails with
//! [`RasterError::Gpu`] naming the buffer. Workgroup memory: only the radix sort's (8 KiB per
//! workgroup).
//!
//! The kernels' parameters and buffer layouts are in `super::params`, the sort in `super::sort`,
//! what each kernel is compiled from and binds in `super::shaders`. The resident trainer
//! (`super::train`) runs the same kernels without the host round trips: the scan on the device,
//! the sort and the range kernels dispatched indirectly.
//!
//! The forward pass is also a building block: [`Rasterizer::rasterize_bands`] hands each band's
//! encoded work to its caller, which reads the G-buffers back (`forward`) or consumes them on the
//! device (the TSDF fusion, `super::tsdf`).
//!
//! Threading: calls on one device are serialized (a mutex, `Device::scoped`); the host-side conversions
//! are single-threaded.

use tracing::info_span;

use super::band::Band;
use super::bind_cache::Binder;
use super::device::{Device, Kernel};
use super::params::{
    raw_surfels, ParamsGpu, ENTRY_BYTES, NUM_ACC, NUM_OUT, NUM_RAW_GRAD, PROJ_BYTES, TILE,
};
use super::shaders;
use super::sort::{
    varying_bits, varying_depth_bits, KeyBits, RadixSort, SortDispatch, SortInputs, RADIX_BITS,
    RADIX_BLOCK,
};
use crate::core::camera::Camera;
use crate::core::raster::{
    depth_normals, depth_upstream, GBufferGrads, GBuffers, RasterError, RasterGrads,
    RasterSettings, RasterStats, Rasterized, SavedForward,
};
use crate::core::surfels::{SurfelGrads, Surfels};

/// The rasterization kernels (the sort's are [`RadixSort`]'s).
pub(super) struct RasterKernels {
    pub(super) project: Kernel,
    pub(super) emit: Kernel,
    pub(super) tile_ranges: Kernel,
    pub(super) rasterize: Kernel,
    pub(super) rasterize_backward: Kernel,
    pub(super) project_backward: Kernel,
}

impl RasterKernels {
    /// Compiles the kernels (inside the caller's [`Device::compile_all`]).
    pub(super) fn new(device: &Device) -> Self {
        RasterKernels {
            project: device.kernel(&shaders::PROJECT),
            emit: device.kernel(&shaders::EMIT),
            tile_ranges: device.kernel(&shaders::TILE_RANGES),
            rasterize: device.kernel(&shaders::RASTERIZE),
            rasterize_backward: device.kernel(&shaders::RASTERIZE_BACKWARD),
            project_backward: device.kernel(&shaders::PROJECT_BACKWARD),
        }
    }
}

/// The rasterizer's kernels on their device, for the calls of one pass (the backend, the TSDF
/// fusion and the resident trainer borrow them from [`super::backend::GpuBackend`]).
pub(super) struct Rasterizer<'a> {
    pub(super) device: &'a Device,
    pub(super) kernels: &'a RasterKernels,
    pub(super) sort: &'a RadixSort,
}

/// What the forward pass keeps (on the device) for the backward pass.
pub(super) struct Saved {
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
pub(super) struct BandSaved {
    pub(super) band: Band,
    params: wgpu::Buffer,
    entries: wgpu::Buffer,
    ranges: wgpu::Buffer,
    /// `NUM_OUT` values per pixel of the band's rows (α first, depth second).
    pub(super) gbuf: wgpu::Buffer,
    final_t: wgpu::Buffer,
    contrib: wgpu::Buffer,
}

/// The surfels on the device for rasterizing views of them: their raw parameters, and room for
/// their projection into one view at a time.
pub(super) struct DeviceSurfels {
    pub(super) count: u32,
    raw: wgpu::Buffer,
    proj: wgpu::Buffer,
}

/// What every band of one forward pass shares: the view, and the surfels on the device (raw and
/// projected; the projection is the same for every band).
pub(super) struct Frame<'a> {
    pub(super) camera: &'a Camera,
    pub(super) settings: &'a RasterSettings,
    pub(super) surfels: &'a DeviceSurfels,
    /// [`varying_depth_bits`] of the surfels.
    pub(super) depth_bits: u32,
}

impl<'a> Frame<'a> {
    /// `uploaded` (the device's copy of `surfels`) seen from `camera`.
    pub(super) fn new(
        camera: &'a Camera,
        settings: &'a RasterSettings,
        surfels: &Surfels,
        uploaded: &'a DeviceSurfels,
    ) -> Self {
        Frame {
            camera,
            settings,
            surfels: uploaded,
            depth_bits: varying_depth_bits(surfels, camera, settings.near),
        }
    }
}

/// What the forward pass of one band brings back.
struct BandResult {
    saved: BandSaved,
    gbuf: Vec<f32>,
    evals: Vec<u32>,
    tile_counts: Vec<u32>,
}

/// One band rasterized into `encoder`, not yet submitted: its G-buffers (in `saved`) and
/// evaluation counts are on the device once the caller submits the encoder, with whatever it
/// adds (a readback, or kernels that consume the G-buffers where they are).
pub(super) struct EncodedBand {
    pub(super) saved: BandSaved,
    pub(super) evals: wgpu::Buffer,
    pub(super) tile_counts: Vec<u32>,
    pub(super) encoder: wgpu::CommandEncoder,
}

/// The forward pass of one band: encoded, or its entries exceed the binding limit.
enum BandOutcome {
    Encoded(Box<EncodedBand>),
    TooManyEntries(u64),
}

impl SavedForward for Saved {
    const NOT_THIS_BACKEND: &'static str = "not a gpu forward result";
    fn scene(&self) -> (usize, &Camera, &RasterSettings) {
        (self.num_surfels, &self.camera, &self.settings)
    }
}

impl Rasterizer<'_> {
    /// One workgroup per tile of `band`.
    fn dispatch_tiles(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        label: &'static str,
        kernel: &Kernel,
        group: &wgpu::BindGroup,
        camera: &Camera,
        band: Band,
    ) {
        let mut pass = self.device.begin_pass(encoder, label);
        pass.set_pipeline(kernel.pipeline());
        pass.set_bind_group(0, group, &[]);
        pass.dispatch_workgroups(camera.width.div_ceil(TILE), band.tile_rows(), 1);
    }

    /// Uploads the surfels' raw parameters and makes room for their projection.
    pub(super) fn upload(&self, surfels: &Surfels) -> Result<DeviceSurfels, RasterError> {
        let n = surfels.len();
        let count = u32::try_from(n)
            .map_err(|_| RasterError::Gpu(format!("{n} surfels exceed the u32 index range")))?;
        let _span = info_span!("upload", surfels = n).entered();
        let raw = self
            .device
            .storage_init("raw surfels", bytemuck::cast_slice(&raw_surfels(surfels)))?;
        let proj = self.device.storage(
            "projected surfels",
            n as u64 * PROJ_BYTES,
            wgpu::BufferUsages::empty(),
        )?;
        Ok(DeviceSurfels { count, raw, proj })
    }

    /// Rasterizes the view of `frame` band by band, top to bottom, and hands each band's encoded
    /// work to `finish`, which submits it (with what it adds) before the next band starts. A band
    /// whose tile entries exceed the binding limit is split in two; bands are sized so that their
    /// G-buffers (and the backward pass's upstream gradient) fit it.
    pub(super) fn rasterize_bands<T>(
        &self,
        frame: &Frame,
        mut finish: impl FnMut(EncodedBand) -> Result<T, RasterError>,
    ) -> Result<Vec<T>, RasterError> {
        let camera = frame.camera;
        // The largest per-pixel buffers (G-buffers forward, upstream gradient backward) decide
        // how many tile rows a band may have.
        let tile_row_bytes = u64::from(camera.width) * u64::from(TILE) * NUM_OUT as u64 * 4;
        self.device
            .check_size("g-buffers (one tile row)", tile_row_bytes)?;
        let rows_per_band =
            (self.device.binding_limit() / tile_row_bytes).min(u64::from(u32::MAX)) as u32;
        // A stack with the top band last, so bands are popped top to bottom.
        let mut pending: Vec<Band> = Band::split(camera.height, rows_per_band)
            .into_iter()
            .rev()
            .collect();
        let mut done = Vec::new();
        while let Some(band) = pending.pop() {
            let _span = info_span!("band", first = band.first, end = band.end).entered();
            match self.forward_band(frame, band)? {
                BandOutcome::Encoded(encoded) => done.push(finish(*encoded)?),
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
        Ok(done)
    }

    pub(super) fn forward_impl(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError> {
        let n = surfels.len();
        let (w, h) = (camera.width as usize, camera.height as usize);
        // Every buffer is checked as it is created; the backward pass's per-surfel sums are
        // checked now so that a render the backward pass could not handle fails at once.
        self.device
            .check_size("gradient sums", n as u64 * NUM_ACC * 4)?;
        let uploaded = self.upload(surfels)?;
        let frame = Frame::new(camera, settings, surfels, &uploaded);
        let done = self.rasterize_bands(&frame, |encoded| {
            let pixels =
                u64::from(camera.width) * u64::from(encoded.saved.band.pixel_rows(camera.height));
            let out = {
                let _span = info_span!("submit_and_read").entered();
                self.device.submit_and_read(
                    encoded.encoder,
                    &[
                        (&encoded.saved.gbuf, pixels * NUM_OUT as u64 * 4),
                        (&encoded.evals, pixels * 4),
                    ],
                )?
            };
            Ok(BandResult {
                gbuf: bytemuck::pod_collect_to_vec(&out[0]),
                evals: bytemuck::pod_collect_to_vec(&out[1]),
                tile_counts: encoded.tile_counts,
                saved: encoded.saved,
            })
        })?;

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
                gb.depth_sq[k] = v(10);
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
        let DeviceSurfels { raw, proj, .. } = uploaded;
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
                raw,
                proj,
                bands: done.into_iter().map(|r| r.saved).collect(),
            }),
        })
    }

    /// Projects the surfels for `band` (the projection is the same for every band; the tile
    /// counts are the band's), then encodes the binning and sorting of the band's entries and
    /// the rasterization of its tiles (not submitted).
    fn forward_band(&self, frame: &Frame, band: Band) -> Result<BandOutcome, RasterError> {
        let device = self.device.wgpu();
        let (camera, settings) = (frame.camera, frame.settings);
        let (raw_buf, proj_buf) = (&frame.surfels.raw, &frame.surfels.proj);
        let n = frame.surfels.count as usize;
        let pixels = u64::from(camera.width) * u64::from(band.pixel_rows(camera.height));
        let tiles = camera.width.div_ceil(TILE) * band.tile_rows();
        let params = ParamsGpu::new(camera, settings, frame.surfels.count, band);
        let params_buf = self.device.uniform("params", bytemuck::bytes_of(&params));

        // Projection and the band's tile counts.
        let counts_buf =
            self.device
                .storage("tile counts", n as u64 * 4, wgpu::BufferUsages::COPY_SRC)?;
        let counts: Vec<u32> = {
            let _span = info_span!("project", surfels = n).entered();
            let mut encoder = device.create_command_encoder(&Default::default());
            let group = self.device.bind(
                &self.kernels.project,
                &[
                    ("params", &params_buf),
                    ("raw", raw_buf),
                    ("proj", proj_buf),
                    ("tile_counts", &counts_buf),
                ],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "project",
                &self.kernels.project,
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
                &self.kernels.emit,
                &[
                    ("params", &params_buf),
                    ("proj", proj_buf),
                    ("offsets", &offsets_buf),
                    ("entries", &entries_buf),
                ],
            );
            self.device
                .dispatch_1d(&mut encoder, "emit", &self.kernels.emit, &group, n as u64)?;
            let hist = self.device.storage(
                "radix histogram",
                total.div_ceil(RADIX_BLOCK) * (1u64 << RADIX_BITS) * 4,
                wgpu::BufferUsages::empty(),
            )?;
            let entries_buf = self.sort.encode(
                Binder::Fresh(self.device),
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
                &self.kernels.tile_ranges,
                &[
                    ("entries", &entries_buf),
                    ("ranges", &ranges_buf),
                    ("entry_count", &count_buf),
                ],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "tile_ranges",
                &self.kernels.tile_ranges,
                &group,
                total,
            )?;
            entries_buf
        };
        {
            let _span = info_span!("rasterize", entries = total).entered();
            let group = self.device.bind(
                &self.kernels.rasterize,
                &[
                    ("params", &params_buf),
                    ("entries", &entries_buf),
                    ("ranges", &ranges_buf),
                    ("proj", proj_buf),
                    ("gbuf", &gbuf_buf),
                    ("final_t", &final_t_buf),
                    ("contrib", &contrib_buf),
                    ("evals", &evals_buf),
                ],
            );
            self.dispatch_tiles(
                &mut encoder,
                "rasterize",
                &self.kernels.rasterize,
                &group,
                camera,
                band,
            );
        }
        Ok(BandOutcome::Encoded(Box::new(EncodedBand {
            evals: evals_buf,
            tile_counts: counts,
            encoder,
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

    pub(super) fn backward_impl(
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
                    upstream.depth_sq[k],
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
                &self.kernels.rasterize_backward,
                &[
                    ("params", &band.params),
                    ("entries", &band.entries),
                    ("ranges", &band.ranges),
                    ("proj", &saved.proj),
                    ("gbuf", &band.gbuf),
                    ("upstream", &up_buf),
                    ("final_t", &band.final_t),
                    ("contrib", &band.contrib),
                    ("grad_acc", &acc_buf),
                ],
            );
            self.dispatch_tiles(
                &mut encoder,
                "rasterize_backward",
                &self.kernels.rasterize_backward,
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
                &self.kernels.project_backward,
                &[
                    ("params", params),
                    ("raw", &saved.raw),
                    ("proj", &saved.proj),
                    ("grad_acc", &acc_buf),
                    ("raw_grads", &out_buf),
                ],
            );
            self.device.dispatch_1d(
                &mut encoder,
                "project_backward",
                &self.kernels.project_backward,
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
            // The kernels do not reduce the pose gradient (pose refinement is host-only).
            pose: None,
        })
    }
}

//! The fast host engine: the rasterizer of [`super::cpu`] (same G-buffers, same gradients, same
//! skip rules) with its per-pixel loops in f32 SIMD, eight pixels of a tile row at a time.
//!
//! Pipeline (each stage in a `tracing` span): `project` (rayon over surfels, the f64
//! [`project::project`] of the reference, plus each surfel's plane scale, see
//! [`tile::PlaneFrame`]), `bin` (surfels sorted once by centre depth, ties by index, then appended
//! to every 16×16 tile their pixel box touches, so each tile's list is front to back; each surfel
//! also records where its entries went), `rasterize` (rayon over tiles: a tile converts its
//! surfels into tile-local f32 [`tile::TileSplat`]s in a per-thread buffer and composites them,
//! [`tile::forward_tile`], into its own slice of tile-major sums), `assemble` (rayon over image
//! rows: α-normalization in f64) and `depth_normal` (the shared f64 [`super::depth_normals`]).
//! The tiles are always 16×16 whatever `RasterSettings::tile_size` says: the output does not
//! depend on the tile size.
//!
//! Backward: the depth-normal gradient is chained into the depth gradient (f64), then each tile
//! replays its list back to front ([`tile::backward_tile`], rayon over tiles) and writes one
//! [`tile::LocalGrad`] per (tile, surfel) entry to its own slice; then, rayon over surfels, each
//! surfel sums its entries in tile order (f64) and [`project::project_backward`] chains them to
//! the raw parameters. Every sum has a fixed order and nothing is shared between threads (no
//! atomics), so the results are bit-identical run to run and for any number of threads.
//!
//! Both tile loops hand out tiles one at a time (`with_max_len(1)`): a tile's cost follows the
//! object, not its index, and rayon's adaptive split alone left runs of about 80 tiles that one
//! thread finished while the other waited.
//!
//! Precision: the per-pixel arithmetic is f32 on tile-local coordinates; projection, the
//! per-surfel sums of the backward pass and everything outside the tiles are f64. The parity
//! tests (`tests/fast_parity.rs`) hold it to the reference at the gpu backend's tolerances.

mod lanes;
pub mod tile;

use rayon::prelude::*;
use tracing::info_span;

use self::tile::{
    BackwardScratch, ForwardScratch, LocalGrad, PixelConsts, PixelUpstream, PlaneFrame, Splat,
    TileOutput, DEPTH_SQ, NUM_SUMS, TILE, TILE_PIXELS,
};
use super::project::{self, Activations, ProjectionCamera};
use super::tiles::TileGrid;
use super::{
    begin_backward, chain_to_raw, depth_normals, depth_upstream, unnormalize_upstream,
    validate_inputs, GBufferGrads, GBuffers, RasterError, RasterGrads, RasterSettings, RasterStats,
    Rasterized, SavedForward,
};
use crate::core::camera::Camera;
use crate::core::filled::filled;
use crate::core::surfels::Surfels;

/// Which compiled copy of the tile kernels runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SimdPath {
    /// Compiled for the build's baseline target (SSE2 on x86-64, NEON on aarch64).
    Portable,
    /// x86-64 with AVX2 (256-bit lanes); only where the running CPU has it.
    Avx2,
}

impl SimdPath {
    /// The widest path this CPU runs.
    pub fn detect() -> Self {
        if Self::Avx2.is_available() {
            Self::Avx2
        } else {
            Self::Portable
        }
    }

    /// Whether this CPU runs the path.
    pub fn is_available(self) -> bool {
        match self {
            SimdPath::Portable => true,
            #[cfg(target_arch = "x86_64")]
            SimdPath::Avx2 => is_x86_feature_detected!("avx2"),
            #[cfg(not(target_arch = "x86_64"))]
            SimdPath::Avx2 => false,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            SimdPath::Portable => "portable SIMD",
            SimdPath::Avx2 => "AVX2",
        }
    }
}

/// The f32 SIMD host backend.
#[derive(Clone, Copy, Debug)]
pub struct FastBackend {
    path: SimdPath,
}

impl Default for FastBackend {
    fn default() -> Self {
        FastBackend::new()
    }
}

impl FastBackend {
    /// The backend on the widest SIMD path this CPU has.
    pub fn new() -> Self {
        FastBackend {
            path: SimdPath::detect(),
        }
    }

    /// The backend on `path`, or `None` where this CPU lacks it.
    pub fn with_path(path: SimdPath) -> Option<Self> {
        path.is_available().then_some(FastBackend { path })
    }

    pub fn path(&self) -> SimdPath {
        self.path
    }
}

/// What the backward pass keeps of a visible surfel's projection: the frame its splat was made in
/// and the activated values the projection's backward reads, with the sort key: 88 bytes a
/// surfel against a whole [`project::Projected`]'s 208 (the projection and binning are bound by
/// the memory they move).
#[derive(Clone, Copy, Debug)]
struct Kept {
    frame: PlaneFrame,
    activations: Activations,
    /// The centre depth's bits (the sort key; depths are > near ≥ 0, so the bits order like
    /// the values).
    depth_bits: u64,
}

/// Visible surfels binned into tiles.
struct Bins {
    /// Per surfel, what the backward keeps of its projection (`None`: culled).
    kept: Vec<Option<Kept>>,
    /// The visible surfels in depth order (front to back, ties by index).
    splats: Vec<Splat>,
    /// Per tile `t`, entries `tile_offsets[t]..tile_offsets[t + 1]`, front to back.
    tile_offsets: Vec<usize>,
    /// Entry → index into `splats`.
    entries: Vec<u32>,
    /// Slots of the backward pass's per-entry gradients, grouped by surfel: surfel `i` owns
    /// slots `surfel_slots[i]..surfel_slots[i + 1]`, one per tile it touches, in tile order.
    surfel_slots: Vec<usize>,
    /// Entry → its slot (a permutation of `0..entries.len()`).
    entry_slots: Vec<usize>,
}

impl Bins {
    fn tile_range(&self, t: usize) -> std::ops::Range<usize> {
        self.tile_offsets[t]..self.tile_offsets[t + 1]
    }

    /// Copies tile `t`'s splats, front to back, into `buf` (contiguous for the per-pixel loops;
    /// read in increasing address order, as a tile's list follows the depth order).
    fn gather(&self, t: usize, buf: &mut Vec<Splat>) {
        buf.clear();
        buf.extend(
            self.entries[self.tile_range(t)]
                .iter()
                .map(|&r| self.splats[r as usize]),
        );
    }
}

/// Projects every surfel and bins the visible ones into tiles, front to back.
fn project_and_bin(
    surfels: &Surfels,
    camera: &Camera,
    settings: &RasterSettings,
    grid: &TileGrid,
) -> Bins {
    let cam = ProjectionCamera::new(camera);
    // Per surfel: what the backward keeps (and the sort key), the splat.
    let (kept, splats_by_index): (Vec<Option<Kept>>, Vec<Splat>) = {
        let _span = info_span!("project", surfels = surfels.len()).entered();
        (0..surfels.len())
            .into_par_iter()
            .map(|i| match project::project(surfels, i, &cam, settings) {
                None => (None, Splat::default()),
                Some(p) => {
                    let frame = PlaneFrame::of(&p);
                    let kept = Kept {
                        frame,
                        activations: p.activations(),
                        depth_bits: p.view_depth.to_bits(),
                    };
                    (Some(kept), Splat::in_frame(&p, &frame))
                }
            })
            .unzip()
    };
    let _span = info_span!("bin").entered();
    // Sorted by centre depth, ties by index: the order is deterministic.
    let mut keys: Vec<(u64, u32)> = kept
        .iter()
        .enumerate()
        .filter_map(|(i, k)| k.as_ref().map(|k| (k.depth_bits, i as u32)))
        .collect();
    keys.par_sort_unstable();
    let splats: Vec<Splat> = keys
        .par_iter()
        .map(|&(_, i)| splats_by_index[i as usize])
        .collect();
    drop(splats_by_index);
    let mut counts = vec![0usize; grid.count() + 1];
    let mut surfel_slots = vec![0usize; surfels.len() + 1];
    for (&(_, i), sp) in keys.iter().zip(&splats) {
        let [tx0, ty0, tx1, ty1] = grid.tiles_of(sp.rect);
        surfel_slots[i as usize + 1] = (tx1 - tx0) * (ty1 - ty0);
        for ty in ty0..ty1 {
            for count in &mut counts[ty * grid.nx + tx0 + 1..ty * grid.nx + tx1 + 1] {
                *count += 1;
            }
        }
    }
    for t in 0..grid.count() {
        counts[t + 1] += counts[t];
    }
    for i in 0..surfels.len() {
        surfel_slots[i + 1] += surfel_slots[i];
    }
    let offsets = counts;
    let mut cursor = offsets.clone();
    let total = offsets[grid.count()];
    let mut entries = vec![0u32; total];
    let mut entry_slots = vec![0usize; total];
    for (rank, (&(_, i), sp)) in keys.iter().zip(&splats).enumerate() {
        let [tx0, ty0, tx1, ty1] = grid.tiles_of(sp.rect);
        let mut slot = surfel_slots[i as usize];
        for ty in ty0..ty1 {
            for tx in tx0..tx1 {
                let t = ty * grid.nx + tx;
                entries[cursor[t]] = rank as u32;
                entry_slots[cursor[t]] = slot;
                cursor[t] += 1;
                slot += 1;
            }
        }
    }
    Bins {
        kept,
        splats,
        tile_offsets: offsets,
        entries,
        surfel_slots,
        entry_slots,
    }
}

/// Writes [`LocalGrad`]s into a slice from several threads at once, each thread to slots no
/// other thread touches (the backward pass's scatter into [`Bins::entry_slots`]).
struct SlotWriter<'a> {
    ptr: *mut LocalGrad,
    len: usize,
    _slots: std::marker::PhantomData<&'a mut [LocalGrad]>,
}

// SAFETY: the writer only hands out writes through `write`, whose callers guarantee that no two
// threads write the same slot and that nobody reads the slice while the writer lives (it borrows
// the slice mutably for its lifetime).
unsafe impl Sync for SlotWriter<'_> {}

impl<'a> SlotWriter<'a> {
    fn new(slots: &'a mut [LocalGrad]) -> Self {
        SlotWriter {
            ptr: slots.as_mut_ptr(),
            len: slots.len(),
            _slots: std::marker::PhantomData,
        }
    }

    /// Writes `slot` (bounds-checked).
    ///
    /// # Safety
    /// No other thread may write `slot` while this writer lives.
    unsafe fn write(&self, slot: usize, value: LocalGrad) {
        assert!(slot < self.len, "slot {slot} out of {}", self.len);
        // SAFETY: in bounds (checked above) of a slice borrowed mutably for 'a; exclusive per
        // the caller's guarantee.
        unsafe { self.ptr.add(slot).write(value) };
    }
}

/// What the forward pass keeps for the backward pass.
struct Saved {
    num_surfels: usize,
    camera: Camera,
    settings: RasterSettings,
    bins: Bins,
    grid: TileGrid,
    /// Tile-major (`tile * TILE_PIXELS + local`) final transmittance and number of list entries
    /// up to and including the last one composited.
    final_transmittance: Vec<f64>,
    contributors: Vec<u32>,
}

impl SavedForward for Saved {
    const NOT_THIS_BACKEND: &'static str = "not a fast forward result";
    fn scene(&self) -> (usize, &Camera, &RasterSettings) {
        (self.num_surfels, &self.camera, &self.settings)
    }
}

/// Writes the α-normalized G-buffers of image rows from the tile-major sums.
fn assemble(gb: &mut GBuffers, grid: &TileGrid, sums: &[f32], eps: f64) {
    let w = grid.width;
    (
        gb.alpha.par_chunks_mut(w),
        gb.depth.par_chunks_mut(w),
        gb.normal.par_chunks_mut(w),
        gb.albedo.par_chunks_mut(w),
        gb.roughness.par_chunks_mut(w),
        gb.ior.par_chunks_mut(w),
        gb.depth_sq.par_chunks_mut(w),
    )
        .into_par_iter()
        .enumerate()
        .for_each(
            |(y, (alpha, depth, normal, albedo, roughness, ior, depth_sq))| {
                let (ty, ly) = (y / TILE, y % TILE);
                for x in 0..w {
                    let t = ty * grid.nx + x / TILE;
                    let li = ly * TILE + x % TILE;
                    let s = |f: usize| f64::from(sums[(t * NUM_SUMS + f) * TILE_PIXELS + li]);
                    let a = s(0);
                    alpha[x] = a;
                    if a > eps {
                        let inv = 1.0 / a;
                        depth[x] = s(1) * inv;
                        normal[x] = [s(2) * inv, s(3) * inv, s(4) * inv];
                        albedo[x] = [s(5) * inv, s(6) * inv, s(7) * inv];
                        roughness[x] = s(8) * inv;
                        ior[x] = s(9) * inv;
                        depth_sq[x] = s(DEPTH_SQ) * inv;
                    }
                }
            },
        );
}

impl FastBackend {
    /// What [`crate::core::engine::Backend::description`] says of this engine.
    pub fn description(&self) -> String {
        format!(
            "fast ({} threads, f32 {})",
            rayon::current_num_threads(),
            self.path.name()
        )
    }

    /// The forward pass ([`crate::core::engine::Backend::forward`]).
    pub fn forward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError> {
        validate_inputs(surfels, camera, settings)?;
        let _span = info_span!("raster_forward", backend = "fast").entered();
        let (w, h) = (camera.width as usize, camera.height as usize);
        let grid = TileGrid::new(w, h, TILE);
        let bins = project_and_bin(surfels, camera, settings, &grid);
        let consts = PixelConsts::new(settings);

        let n = grid.count();
        let mut sums = filled(n * NUM_SUMS * TILE_PIXELS, 0.0f32);
        let mut final_transmittance = filled(n * TILE_PIXELS, 1.0f64);
        let mut contributors = filled(n * TILE_PIXELS, 0u32);
        let evaluations: u64 = {
            let _span = info_span!("rasterize", entries = bins.entries.len()).entered();
            (
                sums.par_chunks_mut(NUM_SUMS * TILE_PIXELS),
                final_transmittance.par_chunks_mut(TILE_PIXELS),
                contributors.par_chunks_mut(TILE_PIXELS),
            )
                .into_par_iter()
                .enumerate()
                .with_max_len(1)
                .map_init(
                    || (Vec::new(), ForwardScratch::default()),
                    |(list, scratch), (t, (sums, transmittance, contributors))| {
                        bins.gather(t, list);
                        let out = TileOutput {
                            sums,
                            transmittance,
                            contributors,
                        };
                        let bounds = grid.bounds(t).map(|v| v as u32);
                        tile::forward_tile(self.path, list, bounds, &consts, scratch, out)
                    },
                )
                .sum()
        };

        let mut gb = GBuffers::zeros(w, h);
        let eps = settings.normalize_alpha_min;
        {
            let _span = info_span!("assemble").entered();
            assemble(&mut gb, &grid, &sums, eps);
        }
        drop(sums);
        {
            let _span = info_span!("depth_normal").entered();
            gb.depth_normal = depth_normals(camera, &gb.depth, &gb.alpha, eps);
        }
        let stats = RasterStats {
            visible_surfels: bins.splats.len(),
            tile_entries: bins.entries.len(),
            pixel_evaluations: evaluations,
        };
        Ok(Rasterized {
            gbuffers: gb,
            stats,
            saved: Box::new(Saved {
                num_surfels: surfels.len(),
                camera: *camera,
                settings: *settings,
                bins,
                grid,
                final_transmittance,
                contributors,
            }),
        })
    }

    /// The backward pass ([`crate::core::engine::Backend::backward`]).
    pub fn backward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
        forward: &Rasterized,
        upstream: &GBufferGrads,
    ) -> Result<RasterGrads, RasterError> {
        let saved: &Saved = begin_backward(surfels, camera, settings, forward, upstream)?;
        let gb = &forward.gbuffers;
        let _span = info_span!("raster_backward", backend = "fast").entered();
        let eps = settings.normalize_alpha_min;

        let depth_grad = depth_upstream(camera, gb, upstream, eps);

        let grid = saved.grid;
        let consts = PixelConsts::new(settings);
        let bins = &saved.bins;
        // One gradient slot per (tile, surfel) entry, grouped by surfel: each tile scatters its
        // entries' gradients to their slots, so that each surfel then reads its own contiguously.
        let mut slot_grads = vec![LocalGrad::default(); bins.entries.len()];
        {
            let _span = info_span!("rasterize_backward").entered();
            let slots = SlotWriter::new(&mut slot_grads);
            (0..grid.count())
                .into_par_iter()
                .with_max_len(1)
                .for_each_init(
                    || (Vec::new(), BackwardScratch::default(), Vec::new()),
                    |(list, scratch, local), t| {
                        let base = t * TILE_PIXELS;
                        let contributors = &saved.contributors[base..base + TILE_PIXELS];
                        if contributors.iter().all(|&c| c == 0) {
                            return;
                        }
                        bins.gather(t, list);
                        scratch.clear();
                        let [x0, y0, x1, y1] = grid.bounds(t);
                        for y in y0..y1 {
                            for x in x0..x1 {
                                let li = (y - y0) * TILE + x - x0;
                                let k = y * gb.width + x;
                                let pixel = pixel_upstream(gb, upstream, &depth_grad, k, eps);
                                scratch.pixel(
                                    li,
                                    &PixelUpstream {
                                        transmittance: saved.final_transmittance[base + li],
                                        contributors: contributors[li],
                                        ..pixel
                                    },
                                );
                            }
                        }
                        local.clear();
                        local.resize(list.len(), LocalGrad::default());
                        let bounds = [x0, y0, x1, y1].map(|v| v as u32);
                        tile::backward_tile(self.path, list, bounds, &consts, scratch, local);
                        let own_slots = &bins.entry_slots[bins.tile_range(t)];
                        for (&slot, g) in own_slots.iter().zip(local.iter()) {
                            // SAFETY: `entry_slots` is a permutation of the entries (`project_and_bin`
                            // hands out each slot once, to one entry) and this tile alone owns the
                            // entries of `tile_range(t)`, so no other thread writes this slot, and
                            // nothing reads the slots until the parallel loop has ended.
                            unsafe { slots.write(slot, *g) };
                        }
                    },
                );
        }

        // Per surfel, its entries in tile order: a fixed order, no shared writes.
        Ok(chain_to_raw(
            surfels,
            camera,
            &bins.kept,
            |kept| kept.activations,
            |i, kept| {
                let mut sum = LocalGrad::<f64>::default();
                for g in &slot_grads[bins.surfel_slots[i]..bins.surfel_slots[i + 1]] {
                    sum.add(g);
                }
                sum.to_projected(&kept.frame)
            },
        ))
    }
}

/// Pixel `k`'s effective `dL/dα` and `dL/d(sum)` (the α-normalization undone, as in the
/// reference); transmittance and contributors are left for the caller.
fn pixel_upstream(
    gb: &GBuffers,
    upstream: &GBufferGrads,
    depth_grad: &[f64],
    k: usize,
    eps: f64,
) -> PixelUpstream {
    let (g_alpha, g_sums) = unnormalize_upstream(gb, upstream, depth_grad, k, eps);
    PixelUpstream {
        g_alpha,
        g_sums,
        transmittance: 1.0,
        contributors: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// Pairing the rows of narrow boxes changes which vector holds a pixel, not its arithmetic:
    /// every tile's sums, transmittance and counts are the same bits as walking rows.
    #[test]
    fn the_paired_walk_composites_the_same_bits_as_rows() {
        let (w, h) = (96, 80);
        let camera = Camera::look_at(w, h, 0.9, DVec3::new(0.4, -3.2, 0.9), DVec3::ZERO, DVec3::Z);
        let mut surfels = crate::pipeline::bench::shell_surfels(3000, 5);
        // Opaque enough that pixels near the stopping threshold occur.
        surfels.opacity.iter_mut().for_each(|o| *o = 3.0);
        let settings = RasterSettings::default();
        let grid = TileGrid::new(w as usize, h as usize, TILE);
        let bins = project_and_bin(&surfels, &camera, &settings, &grid);
        let consts = PixelConsts::new(&settings);
        let (mut narrow, mut wide, mut nearly_opaque) = (0, 0, 0);
        let mut list = Vec::new();
        for t in 0..grid.count() {
            bins.gather(t, &mut list);
            let bounds = grid.bounds(t).map(|v| v as u32);
            let run = |walk| {
                let mut sums = vec![0.0f32; NUM_SUMS * TILE_PIXELS];
                let mut transmittance = vec![0.0f64; TILE_PIXELS];
                let mut contributors = vec![0u32; TILE_PIXELS];
                let out = TileOutput {
                    sums: &mut sums,
                    transmittance: &mut transmittance,
                    contributors: &mut contributors,
                };
                let mut scratch = ForwardScratch::default();
                let evaluations =
                    tile::forward_body(&list, bounds, &consts, &mut scratch, out, walk);
                (sums, transmittance, contributors, evaluations)
            };
            let rows = run(tile::Walk::Rows);
            let paired = run(tile::Walk::PairNarrowRows);
            let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&rows.0), bits(&paired.0), "tile {t}");
            assert_eq!(rows.1, paired.1, "tile {t}");
            assert_eq!((&rows.2, rows.3), (&paired.2, paired.3), "tile {t}");
            nearly_opaque += rows.1.iter().filter(|&&v| v < 1e-3).count();
            for sp in &list {
                let (x0, x1) = (sp.rect[0].max(bounds[0]), sp.rect[2].min(bounds[2]));
                if x1 - x0 <= 4 {
                    narrow += 1;
                } else {
                    wide += 1;
                }
            }
        }
        assert!(narrow > 100 && wide > 100, "narrow {narrow}, wide {wide}");
        assert!(nearly_opaque > 0, "some pixels are nearly opaque");
    }

    /// Every entry has its own slot, among its surfel's contiguous slots.
    #[test]
    fn entry_slots_are_a_permutation_grouped_by_surfel() {
        let camera = Camera::look_at(
            70,
            50,
            0.8,
            DVec3::new(0.5, -3.0, 0.6),
            DVec3::ZERO,
            DVec3::Z,
        );
        let surfels = crate::pipeline::bench::shell_surfels(400, 3);
        let settings = RasterSettings::default();
        let grid = TileGrid::new(70, 50, TILE);
        let bins = project_and_bin(&surfels, &camera, &settings, &grid);
        let total = bins.entries.len();
        assert!(total > bins.splats.len(), "some surfels span several tiles");
        let mut seen = vec![false; total];
        for &slot in &bins.entry_slots {
            assert!(
                !std::mem::replace(&mut seen[slot], true),
                "slot {slot} twice"
            );
        }
        assert_eq!(bins.surfel_slots[surfels.len()], total);
        // Splat of each surfel index, to map entries (depth ranks) back to surfels.
        let cam = ProjectionCamera::new(&camera);
        let splat_of =
            |i: usize| project::project(&surfels, i, &cam, &settings).map(|p| Splat::new(&p));
        let index_of = |sp: &Splat| {
            (0..surfels.len())
                .find(|&i| splat_of(i).as_ref() == Some(sp))
                .unwrap()
        };
        for t in 0..grid.count() {
            for e in bins.tile_range(t) {
                let i = index_of(&bins.splats[bins.entries[e] as usize]);
                let slot = bins.entry_slots[e];
                assert!((bins.surfel_slots[i]..bins.surfel_slots[i + 1]).contains(&slot));
            }
        }
    }
}

//! The f64 cpu reference rasterizer: tile-based forward compositing and its hand-written backward.
//!
//! Pipeline (each stage in a `tracing` span): `project` (rayon over surfels, [`project::project`]),
//! `bin` (surfels sorted once by centre view depth, then appended sequentially to every 16×16 tile
//! their pixel box touches, so each tile's list is already front-to-back), `rasterize` (rayon over
//! tiles; a tile first copies its surfels into a per-thread contiguous buffer, then loops over them
//! with the pixels of each surfel's box inner, so a small surfel only visits its own pixels; each
//! pixel keeps its transmittance and its 10 running sums), `depth_normal`.
//!
//! Backward: the upstream gradient on the depth normals is chained into the depth buffer, the
//! α-normalization is undone per pixel (`dL/dS = g/α`, `dL/dα −= Σ g·out/α`), then each tile
//! replays its list back to front from the saved final transmittance and per-pixel count of
//! composited entries (rayon over tiles). Per pixel only two numbers are carried: `T` and
//! `B = Σ_{j>i} w_j (dL/dα + Σ_c dL/dS_c v_{j,c})`, which gives
//! `dL/dα_i = T_i (dL/dα + Σ_c dL/dS_c v_{i,c}) − B / (1 − α_i)`. Gradients are summed per (tile,
//! surfel) entry in registers and written to the tile's own slice of one buffer, then reduced per
//! surfel in a fixed order
//! (deterministic, no atomics or locks), and chained to raw parameters by
//! [`project::project_backward`] (rayon over surfels).

use rayon::prelude::*;
use tracing::info_span;

use super::project::{self, Projected, ProjectedGrad, ProjectionCamera, NUM_FEATURES};
use super::tiles::TileGrid;
use super::{
    begin_backward, chain_to_raw, depth_normals, depth_upstream, unnormalize_upstream,
    validate_inputs, GBufferGrads, GBuffers, RasterError, RasterGrads, RasterSettings, RasterStats,
    Rasterized, SavedForward, NUM_PIXEL_SUMS,
};
use crate::core::camera::Camera;
use crate::core::surfels::Surfels;

/// Running sums per pixel ([`NUM_PIXEL_SUMS`]): α, depth, the features of
/// [`Projected::features`], the squared depth.
const NUM_SUMS: usize = NUM_PIXEL_SUMS;
/// Where the squared depth's sum sits.
const DEPTH_SQ: usize = NUM_SUMS - 1;

/// The rayon cpu backend.
#[derive(Clone, Copy, Debug, Default)]
pub struct CpuBackend;

/// What the forward pass keeps for the backward pass.
struct Saved {
    num_surfels: usize,
    camera: Camera,
    settings: RasterSettings,
    bins: Bins,
    tiles: TileGrid,
    /// Tile-major (`tile * tile_size² + local`) final transmittance and number of list entries
    /// up to and including the last one composited.
    final_transmittance: Vec<f64>,
    contributors: Vec<u32>,
}

impl SavedForward for Saved {
    const NOT_THIS_BACKEND: &'static str = "not a cpu forward result";
    fn scene(&self) -> (usize, &Camera, &RasterSettings) {
        (self.num_surfels, &self.camera, &self.settings)
    }
}

/// Visible surfels binned into tiles.
struct Bins {
    /// Per surfel, its projection (`None`: culled).
    projected: Vec<Option<Projected>>,
    /// Number of projected surfels.
    visible: usize,
    /// Per tile `t`, entries `tile_offsets[t]..tile_offsets[t + 1]`, front to back.
    tile_offsets: Vec<usize>,
    /// Entry → surfel index.
    entries: Vec<u32>,
}

impl Bins {
    fn tile_range(&self, t: usize) -> std::ops::Range<usize> {
        self.tile_offsets[t]..self.tile_offsets[t + 1]
    }

    /// Copies tile `t`'s projected surfels, front to back, into `buf`: the per-pixel loops then
    /// stream contiguous memory (reading them through `entries` there was dominated by cache
    /// misses).
    fn gather(&self, t: usize, buf: &mut Vec<Projected>) {
        buf.clear();
        buf.extend(
            self.entries[self.tile_range(t)]
                .iter()
                .filter_map(|&i| self.projected[i as usize]),
        );
    }
}

/// Per-pixel constants of the compositing.
#[derive(Clone, Copy, Debug)]
struct PixelConsts {
    lowpass: bool,
    inv_sigma2: f64,
    near: f64,
    alpha_min: f64,
    alpha_max: f64,
}

impl PixelConsts {
    fn new(s: &RasterSettings) -> Self {
        PixelConsts {
            lowpass: s.lowpass_sigma_px > 0.0,
            inv_sigma2: 1.0 / (s.lowpass_sigma_px * s.lowpass_sigma_px),
            near: s.near,
            alpha_min: s.alpha_min,
            alpha_max: s.alpha_max,
        }
    }
}

/// One surfel evaluated at one pixel centre.
#[derive(Clone, Copy, Debug)]
struct Hit {
    alpha: f64,
    /// Gaussian weight G.
    g: f64,
    /// α hit the `alpha_max` clamp.
    clamped: bool,
    /// ρ came from the surfel plane (else from the screen-space low-pass filter).
    use3d: bool,
    /// Plane coordinates, `1/p.z`, the plane point's homogeneous x and y, and the depth.
    s: f64,
    t: f64,
    inv: f64,
    px: f64,
    py: f64,
    z: f64,
    /// Pixel minus projected centre.
    dx: f64,
    dy: f64,
}

/// Evaluates surfel `p` at pixel centre `(x, y)`; `None` when it is skipped (intersection not
/// beyond `near`, `α < alpha_min`). Forward and backward call this same function, so they skip the
/// same pairs.
#[inline(always)]
fn evaluate(p: &Projected, x: f64, y: f64, c: &PixelConsts) -> Option<Hit> {
    let q = &p.q;
    let px = q[0] * x + q[1] * y + q[2];
    let py = q[3] * x + q[4] * y + q[5];
    let pz = q[6] * x + q[7] * y + q[8];
    let dx = x - p.mean[0];
    let dy = y - p.mean[1];
    let rho2 = if c.lowpass {
        (dx * dx + dy * dy) * c.inv_sigma2
    } else {
        f64::INFINITY
    };
    // Cheap rejection without the division: both ρ_3d = (px² + py²) / pz² and ρ_2d beyond the
    // cut (also rejects NaN).
    let num = px * px + py * py;
    if rho2 > p.rho_cut && (num > p.rho_cut * (pz * pz) || num.is_nan()) {
        return None;
    }
    let inv = 1.0 / pz;
    let s = px * inv;
    let t = py * inv;
    let rho3 = s * s + t * t;
    // NaN ρ_3d (ray parallel to a degenerate plane) takes the filter branch.
    let use3d = rho3 <= rho2;
    let rho = if use3d { rho3 } else { rho2 };
    // rho_cut is finite, so this also rejects ρ = ∞ and NaN.
    if rho.is_nan() || rho > p.rho_cut {
        return None;
    }
    // Depth: the ray–plane intersection, or the centre's depth where the filter wins (a surfel
    // seen edge-on has its plane through the camera centre: every intersection is at z = 0).
    let z = if use3d {
        let z = p.det * inv;
        if !(z > c.near && z < f64::INFINITY) {
            return None;
        }
        z
    } else {
        p.view_depth
    };
    let g = (-0.5 * rho).exp();
    let oa = p.opacity * g;
    let clamped = oa > c.alpha_max;
    let alpha = if clamped { c.alpha_max } else { oa };
    if alpha < c.alpha_min {
        return None;
    }
    Some(Hit {
        alpha,
        g,
        clamped,
        use3d,
        s,
        t,
        inv,
        px,
        py,
        z,
        dx,
        dy,
    })
}

/// Forward result of one tile, tile-local pixel order.
struct TileForward {
    sums: Vec<[f64; NUM_SUMS]>,
    transmittance: Vec<f64>,
    contributors: Vec<u32>,
    evaluations: u64,
}

fn forward_tile(
    grid: &TileGrid,
    tile: usize,
    list: &[Projected],
    consts: &PixelConsts,
    transmittance_min: f64,
) -> TileForward {
    let n = grid.pixels();
    let [x0, y0, x1, y1] = grid.bounds(tile);
    let mut out = TileForward {
        sums: vec![[0.0; NUM_SUMS]; n],
        transmittance: vec![1.0; n],
        contributors: vec![0; n],
        evaluations: 0,
    };
    let mut done = vec![false; n];
    let live_pixels = (x1 - x0) * (y1 - y0);
    let mut n_done = 0;
    for (k, p) in list.iter().enumerate() {
        let rx0 = (p.rect[0] as usize).max(x0);
        let ry0 = (p.rect[1] as usize).max(y0);
        let rx1 = (p.rect[2] as usize).min(x1);
        let ry1 = (p.rect[3] as usize).min(y1);
        for y in ry0..ry1 {
            let yf = y as f64 + 0.5;
            let row = (y - y0) * grid.size;
            for x in rx0..rx1 {
                let li = row + x - x0;
                if done[li] {
                    continue;
                }
                out.evaluations += 1;
                let Some(hit) = evaluate(p, x as f64 + 0.5, yf, consts) else {
                    continue;
                };
                let t = out.transmittance[li];
                let next_t = t * (1.0 - hit.alpha);
                if next_t < transmittance_min {
                    done[li] = true;
                    n_done += 1;
                    continue;
                }
                let w = hit.alpha * t;
                let sums = &mut out.sums[li];
                sums[0] += w;
                sums[1] += w * hit.z;
                for f in 0..NUM_FEATURES {
                    sums[2 + f] += w * p.features[f];
                }
                sums[DEPTH_SQ] += w * hit.z * hit.z;
                out.transmittance[li] = next_t;
                out.contributors[li] = k as u32 + 1;
            }
        }
        if n_done == live_pixels {
            break;
        }
    }
    out
}

/// Projects every surfel and bins the visible ones into tiles, front to back.
fn project_and_bin(
    surfels: &Surfels,
    camera: &Camera,
    settings: &RasterSettings,
    grid: &TileGrid,
) -> Bins {
    let cam = ProjectionCamera::new(camera);
    let projected: Vec<Option<Projected>> = {
        let _span = info_span!("project", surfels = surfels.len()).entered();
        (0..surfels.len())
            .into_par_iter()
            .map(|i| project::project(surfels, i, &cam, settings))
            .collect()
    };
    let _span = info_span!("bin").entered();
    // Sort by centre depth; depths are > near ≥ 0, so their bit patterns order like the values.
    // Ties are broken by index: the order is deterministic.
    let mut keys: Vec<(u64, u32)> = projected
        .iter()
        .enumerate()
        .filter_map(|(i, p)| p.as_ref().map(|p| (p.view_depth.to_bits(), i as u32)))
        .collect();
    keys.par_sort_unstable();
    let rect_of = |i: u32| projected[i as usize].as_ref().map(|p| p.rect);
    let mut counts = vec![0usize; grid.count() + 1];
    for &(_, i) in &keys {
        if let Some(rect) = rect_of(i) {
            let [tx0, ty0, tx1, ty1] = grid.tiles_of(rect);
            for ty in ty0..ty1 {
                for tx in tx0..tx1 {
                    counts[ty * grid.nx + tx + 1] += 1;
                }
            }
        }
    }
    for t in 0..grid.count() {
        counts[t + 1] += counts[t];
    }
    let offsets = counts;
    let mut cursor = offsets.clone();
    let mut entries = vec![0u32; offsets[grid.count()]];
    for &(_, i) in &keys {
        if let Some(rect) = rect_of(i) {
            let [tx0, ty0, tx1, ty1] = grid.tiles_of(rect);
            for ty in ty0..ty1 {
                for tx in tx0..tx1 {
                    let t = ty * grid.nx + tx;
                    entries[cursor[t]] = i;
                    cursor[t] += 1;
                }
            }
        }
    }
    Bins {
        visible: keys.len(),
        projected,
        tile_offsets: offsets,
        entries,
    }
}

impl CpuBackend {
    /// What [`crate::core::engine::Backend::description`] says of this engine.
    pub fn description(&self) -> String {
        format!("cpu ({} threads)", rayon::current_num_threads())
    }

    /// The forward pass ([`crate::core::engine::Backend::forward`]).
    pub fn forward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError> {
        validate_inputs(surfels, camera, settings)?;
        let _span = info_span!("raster_forward", backend = "cpu").entered();
        let (w, h) = (camera.width as usize, camera.height as usize);
        let grid = TileGrid::new(w, h, settings.tile_size as usize);
        let bins = project_and_bin(surfels, camera, settings, &grid);
        let consts = PixelConsts::new(settings);

        let tiles: Vec<TileForward> = {
            let _span = info_span!("rasterize", entries = bins.entries.len()).entered();
            (0..grid.count())
                .into_par_iter()
                .map_init(Vec::new, |list, t| {
                    bins.gather(t, list);
                    forward_tile(&grid, t, list, &consts, settings.transmittance_min)
                })
                .collect()
        };

        let mut gb = GBuffers::zeros(w, h);
        let eps = settings.normalize_alpha_min;
        let npix = grid.pixels();
        let mut final_transmittance = vec![1.0; grid.count() * npix];
        let mut contributors = vec![0u32; grid.count() * npix];
        let mut evaluations = 0;
        for (t, tile) in tiles.iter().enumerate() {
            evaluations += tile.evaluations;
            final_transmittance[t * npix..(t + 1) * npix].copy_from_slice(&tile.transmittance);
            contributors[t * npix..(t + 1) * npix].copy_from_slice(&tile.contributors);
            let [x0, y0, x1, y1] = grid.bounds(t);
            for y in y0..y1 {
                for x in x0..x1 {
                    let s = &tile.sums[(y - y0) * grid.size + x - x0];
                    let k = y * w + x;
                    let a = s[0];
                    gb.alpha[k] = a;
                    if a > eps {
                        let inv = 1.0 / a;
                        gb.depth[k] = s[1] * inv;
                        gb.normal[k] = [s[2] * inv, s[3] * inv, s[4] * inv];
                        gb.albedo[k] = [s[5] * inv, s[6] * inv, s[7] * inv];
                        gb.roughness[k] = s[8] * inv;
                        gb.ior[k] = s[9] * inv;
                        gb.depth_sq[k] = s[DEPTH_SQ] * inv;
                    }
                }
            }
        }
        {
            let _span = info_span!("depth_normal").entered();
            gb.depth_normal = depth_normals(camera, &gb.depth, &gb.alpha, eps);
        }
        let stats = RasterStats {
            visible_surfels: bins.visible,
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
                tiles: grid,
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
        let _span = info_span!("raster_backward", backend = "cpu").entered();
        let eps = settings.normalize_alpha_min;

        let depth_grad = depth_upstream(camera, gb, upstream, eps);

        let grid = saved.tiles;
        let consts = PixelConsts::new(settings);
        let bins = &saved.bins;
        // One gradient slot per (tile, surfel) entry; each tile writes its own slice.
        let mut entry_grads = vec![ProjectedGrad::default(); bins.entries.len()];
        {
            let _span = info_span!("rasterize_backward").entered();
            let mut slices: Vec<&mut [ProjectedGrad]> = Vec::with_capacity(grid.count());
            let mut rest = entry_grads.as_mut_slice();
            for t in 0..grid.count() {
                let (head, tail) = rest.split_at_mut(bins.tile_range(t).len());
                slices.push(head);
                rest = tail;
            }
            slices
                .into_par_iter()
                .enumerate()
                .for_each_init(Vec::new, |list, (t, out)| {
                    bins.gather(t, list);
                    backward_tile(saved, t, list, gb, upstream, &depth_grad, &consts, eps, out)
                });
        }

        // Reduction per surfel in entry order: deterministic, no shared writes. (Streaming the
        // entries and scattering measured faster than gathering each surfel's entries.)
        let mut per_surfel = vec![ProjectedGrad::default(); surfels.len()];
        for (g, &i) in entry_grads.iter().zip(&bins.entries) {
            per_surfel[i as usize].add(g);
        }
        drop(entry_grads);
        Ok(chain_to_raw(
            surfels,
            camera,
            &bins.projected,
            Projected::activations,
            |i, _| per_surfel[i],
        ))
    }
}

/// Back-to-front replay of one tile; returns the gradient of each entry of the tile's list.
#[allow(clippy::too_many_arguments)]
fn backward_tile(
    saved: &Saved,
    tile: usize,
    list: &[Projected],
    gb: &GBuffers,
    upstream: &GBufferGrads,
    depth_grad: &[f64],
    consts: &PixelConsts,
    eps: f64,
    grads: &mut [ProjectedGrad],
) {
    let grid = &saved.tiles;
    let npix = grid.pixels();
    let base = tile * npix;
    let contributors = &saved.contributors[base..base + npix];
    let max_contrib = contributors.iter().copied().max().unwrap_or(0) as usize;
    if max_contrib == 0 {
        return;
    }
    let [x0, y0, x1, y1] = grid.bounds(tile);
    let w = gb.width;

    // Per pixel: dL/dα (effective), dL/d(sum) for depth and the features, T and B.
    let mut g_alpha = vec![0.0; npix];
    let mut g_sums = vec![[0.0; NUM_SUMS - 1]; npix];
    let mut trans = saved.final_transmittance[base..base + npix].to_vec();
    let mut b_acc = vec![0.0; npix];
    for y in y0..y1 {
        for x in x0..x1 {
            let li = (y - y0) * grid.size + x - x0;
            let k = y * w + x;
            (g_alpha[li], g_sums[li]) = unnormalize_upstream(gb, upstream, depth_grad, k, eps);
        }
    }

    for k in (0..max_contrib).rev() {
        let p = &list[k];
        let rx0 = (p.rect[0] as usize).max(x0);
        let ry0 = (p.rect[1] as usize).max(y0);
        let rx1 = (p.rect[2] as usize).min(x1);
        let ry1 = (p.rect[3] as usize).min(y1);
        let mut acc = ProjectedGrad::default();
        for y in ry0..ry1 {
            let yf = y as f64 + 0.5;
            let row = (y - y0) * grid.size;
            for x in rx0..rx1 {
                let li = row + x - x0;
                if k >= contributors[li] as usize {
                    continue;
                }
                let xf = x as f64 + 0.5;
                let Some(hit) = evaluate(p, xf, yf, consts) else {
                    continue;
                };
                let one_minus = 1.0 - hit.alpha;
                let t_i = trans[li] / one_minus;
                let weight = hit.alpha * t_i;
                let gs = &g_sums[li];
                let mut u = g_alpha[li] + gs[0] * hit.z;
                for f in 0..NUM_FEATURES {
                    u += gs[1 + f] * p.features[f];
                    acc.features[f] += weight * gs[1 + f];
                }
                let g_depth_sq = gs[DEPTH_SQ - 1];
                u += g_depth_sq * hit.z * hit.z;
                let d_alpha = t_i * u - b_acc[li] / one_minus;
                b_acc[li] += weight * u;
                trans[li] = t_i;

                // α = min(alpha_max, o G), G = exp(−ρ/2).
                let g_rho = if hit.clamped {
                    0.0
                } else {
                    acc.opacity += hit.g * d_alpha;
                    -0.5 * hit.g * p.opacity * d_alpha
                };
                let gz = weight * (gs[0] + 2.0 * hit.z * g_depth_sq);
                if !hit.use3d {
                    // Filter branch: ρ_2d around the projected centre, z = centre depth. The
                    // plane quantities (s, t, 1/p.z) may be huge or infinite here: not touched.
                    let c = -2.0 * consts.inv_sigma2 * g_rho;
                    acc.mean[0] += c * hit.dx;
                    acc.mean[1] += c * hit.dy;
                    acc.view_depth += gz;
                    continue;
                }
                // Plane branch: ρ = s² + t², s = px · inv, t = py · inv, z = det · inv,
                // inv = 1 / pz.
                let gs_ = 2.0 * hit.s * g_rho;
                let gt_ = 2.0 * hit.t * g_rho;
                acc.det += hit.inv * gz;
                let g_inv = hit.px * gs_ + hit.py * gt_ + p.det * gz;
                let gp = [hit.inv * gs_, hit.inv * gt_, -hit.inv * hit.inv * g_inv];
                for (row, g) in acc.q.chunks_exact_mut(3).zip(gp) {
                    row[0] += g * xf;
                    row[1] += g * yf;
                    row[2] += g;
                }
            }
        }
        grads[k] = acc;
    }
}

//! The fast engine's per-tile kernels: forward compositing and the back-to-front backward replay of
//! one 16×16 tile, in f32, eight pixels of a tile row at a time ([`F32x8`]).
//!
//! Threading: one call handles one tile on the calling thread; the caller runs tiles in parallel
//! ([`super::FastBackend`]). Each kernel is compiled twice, portable (SSE2 on x86-64, NEON on
//! aarch64) and, on x86-64, with AVX2 enabled; [`SimdPath`] picks one at run time. Both compute the
//! same bits (no fused operations, see [`super::lanes`]).
//!
//! A tile's list holds its surfels front to back as [`Splat`]s, whose ray–plane rows and centre
//! are rebased on the first pixel of the surfel's box (in f64, before the cast to f32, see
//! [`PlaneFrame`]), so the per-pixel arithmetic works on offsets within the box and small plane
//! values, not on absolute pixel positions whose f32 products would cancel. For one surfel, each row of its (tile-clipped) pixel
//! box is walked in groups of 8 lanes starting at the box's left edge; lanes beyond the box are
//! masked. Per-pixel state is stored tile-row-major with [`LANES`] values of padding at the end,
//! so a group that runs past the tile's right edge reads the next row's first pixels (or the
//! padding) and writes them back unchanged.
//!
//! [`evaluate`] applies the skip rules of the f64 reference ([`crate::core::raster::cpu`]) lane by lane:
//! outside the α cut (`ρ > rho_cut` or NaN), an intersection not beyond `near` where the plane
//! wins over the low-pass filter, `α < alpha_min`; α is clamped to `alpha_max`; a pixel stops
//! before the surfel that would bring its transmittance below `transmittance_min`. Forward and
//! backward call it alike, so they skip the same pairs.

use super::lanes::{exp, F32x8, F64x8, Mask8, LANES};
use super::SimdPath;
use crate::core::raster::project::{Projected, ProjectedGrad, NUM_FEATURES};
use crate::core::raster::{RasterSettings, NUM_PIXEL_SUMS};

/// Tile edge in pixels.
pub const TILE: usize = 16;
/// Pixels of a tile.
pub const TILE_PIXELS: usize = TILE * TILE;
/// Per-pixel state arrays: a tile plus one group of padding.
const PADDED: usize = TILE_PIXELS + LANES;
/// Running sums per pixel: α, depth, the features of [`Projected::features`], the squared depth.
pub const NUM_SUMS: usize = NUM_PIXEL_SUMS;
/// Where the squared depth's sum sits.
pub const DEPTH_SQ: usize = NUM_SUMS - 1;
/// Per-pixel upstream gradients of the backward replay: depth, the features, the squared depth.
const NUM_PIXEL_GRADS: usize = NUM_SUMS - 1;

/// One surfel's projection as the per-pixel loops read it: f32, in the surfel's own frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Splat {
    /// Rows `(a, b, c)` of the ray–plane map: `p_k = a u + b v + c` at the pixel `(u, v)` pixels
    /// right of and below the anchor (the box's first pixel), i.e. `λ Q` rebased on the anchor's
    /// centre ([`PlaneFrame`]).
    pub plane: [[f32; 3]; 3],
    /// `λ det(M)`: the intersection depth is `det / p_z`.
    pub det: f32,
    /// Projected centre relative to the anchor's centre.
    pub mean: [f32; 2],
    pub opacity: f32,
    /// At most `f32::MAX`, so `ρ ≤ rho_cut` rejects `ρ = ∞`.
    pub rho_cut: f32,
    pub view_depth: f32,
    pub features: [f32; NUM_FEATURES],
    /// Pixel box `[x0, y0, x1, y1)` in the image, never empty; `(x0, y0)` is the anchor.
    pub rect: [u32; 4],
}

/// How a surfel's `Q` and `det` are scaled and rebased: `λ` (a power of two, exact) brings
/// `max |Q|` near 1 so that neither overflows nor underflows f32 (`s`, `t` and the depth are
/// invariant under a common scale of `Q` and `det`), and the anchor pixel's centre `origin`
/// becomes `(0, 0)`, so the per-pixel products work on offsets within the surfel's box, not on
/// absolute pixel coordinates whose f32 products would cancel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneFrame {
    pub scale: f64,
    pub origin: [f64; 2],
}

impl PlaneFrame {
    /// The frame of projection `p`.
    pub fn of(p: &Projected) -> Self {
        let largest = p.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        // 2^−e for the binary exponent e of the largest entry (|e| ≤ 1023 for finite values
        // that are normal; the scale is clamped to the normal range).
        let scale = if largest > 0.0 && largest.is_finite() {
            let exponent = ((largest.to_bits() >> 52) & 0x7ff) as i64 - 1023;
            f64::from_bits(((1023 - exponent).clamp(1, 2046) as u64) << 52)
        } else {
            1.0
        };
        PlaneFrame {
            scale,
            origin: [p.rect[0] as f64 + 0.5, p.rect[1] as f64 + 0.5],
        }
    }
}

impl Splat {
    /// `p` in its frame ([`PlaneFrame::of`]).
    pub fn new(p: &Projected) -> Self {
        let PlaneFrame { scale, origin } = PlaneFrame::of(p);
        let [ox, oy] = origin;
        let q = &p.q;
        let row = |k: usize| {
            let (a, b, c) = (q[3 * k], q[3 * k + 1], q[3 * k + 2]);
            [
                (scale * a) as f32,
                (scale * b) as f32,
                (scale * (a * ox + b * oy + c)) as f32,
            ]
        };
        Splat {
            plane: [row(0), row(1), row(2)],
            det: (scale * p.det) as f32,
            mean: [(p.mean[0] - ox) as f32, (p.mean[1] - oy) as f32],
            opacity: p.opacity as f32,
            rho_cut: p.rho_cut.min(f32::MAX as f64) as f32,
            view_depth: p.view_depth as f32,
            features: p.features.map(|f| f as f32),
            rect: p.rect,
        }
    }

    /// The part of the box inside a tile with pixel bounds `tile` (`[x0, y0, x1, y1)`), in tile
    /// pixels, and the tile's first pixel in the surfel's frame (exact: integers below 2²⁴).
    #[inline(always)]
    fn in_tile(&self, tile: [u32; 4]) -> ([usize; 4], [f32; 2]) {
        let r = self.rect;
        let local = [
            r[0].clamp(tile[0], tile[2]) - tile[0],
            r[1].clamp(tile[1], tile[3]) - tile[1],
            r[2].clamp(tile[0], tile[2]) - tile[0],
            r[3].clamp(tile[1], tile[3]) - tile[1],
        ];
        let offset = [tile[0] as f32 - r[0] as f32, tile[1] as f32 - r[1] as f32];
        (local.map(|v| v as usize), offset)
    }
}

/// Thresholds of the per-pixel loops, f32.
#[derive(Clone, Copy, Debug)]
pub struct PixelConsts {
    lowpass: bool,
    inv_sigma2: f32,
    near: f32,
    alpha_min: f32,
    alpha_max: f32,
    /// `1 − alpha_max` in f64, the reference's factor for a clamped α.
    one_minus_alpha_max: f64,
    transmittance_min: f64,
}

impl PixelConsts {
    pub fn new(s: &RasterSettings) -> Self {
        PixelConsts {
            lowpass: s.lowpass_sigma_px > 0.0,
            inv_sigma2: (1.0 / (s.lowpass_sigma_px * s.lowpass_sigma_px)) as f32,
            near: s.near as f32,
            alpha_min: s.alpha_min as f32,
            alpha_max: s.alpha_max as f32,
            one_minus_alpha_max: 1.0 - s.alpha_max,
            transmittance_min: s.transmittance_min,
        }
    }
}

/// What one tile row contributes to [`evaluate`] for one surfel.
struct RowConsts {
    /// `b_k ly + c_k` of the three plane rows.
    p: [f32; 3],
    dy: f32,
    dy2: f32,
    ly: f32,
}

impl RowConsts {
    #[inline(always)]
    /// Row `v` of the surfel's frame.
    fn new(sp: &Splat, v: f32) -> Self {
        let lyf = v;
        let dy = lyf - sp.mean[1];
        RowConsts {
            p: sp.plane.map(|r| r[1] * lyf + r[2]),
            dy,
            dy2: dy * dy,
            ly: lyf,
        }
    }
}

/// One surfel evaluated at 8 pixel centres; lanes outside `ok` hold garbage (maybe NaN).
struct Hit {
    ok: Mask8,
    alpha: F32x8,
    /// Gaussian weight G.
    g: F32x8,
    /// α hit the `alpha_max` clamp.
    clamped: Mask8,
    /// ρ came from the surfel plane (else from the screen-space low-pass filter).
    use3d: Mask8,
    s: F32x8,
    t: F32x8,
    inv: F32x8,
    px: F32x8,
    py: F32x8,
    z: F32x8,
    dx: F32x8,
}

/// Evaluates `sp` at the pixel centres `lx` of one row for the `alive` lanes (the lane version
/// of the reference's `evaluate`, with the same cheap rejection before the division; the order
/// of the other tests differs, the lanes kept do not). `None` when no lane passes the cheap test.
#[inline(always)]
fn evaluate(sp: &Splat, row: &RowConsts, lx: F32x8, alive: Mask8, c: &PixelConsts) -> Option<Hit> {
    let [r0, r1, r2] = sp.plane;
    let px = lx * r0[0] + row.p[0];
    let py = lx * r1[0] + row.p[1];
    let pz = lx * r2[0] + row.p[2];
    let dx = lx - sp.mean[0];
    let rho2 = if c.lowpass {
        (dx * dx + row.dy2) * c.inv_sigma2
    } else {
        F32x8::splat(f32::INFINITY)
    };
    // Both ρ_3d = (px² + py²) / pz² and ρ_2d beyond the cut (also rejects NaN).
    let cut = F32x8::splat(sp.rho_cut);
    let num = px * px + py * py;
    let candidates = alive.and(rho2.le(cut).or(num.le(cut * (pz * pz))));
    if !candidates.any() {
        return None;
    }
    let inv = F32x8::splat(1.0) / pz;
    let s = px * inv;
    let t = py * inv;
    let rho3 = s * s + t * t;
    // NaN ρ_3d (ray parallel to a degenerate plane) takes the filter branch.
    let use3d = rho3.le(rho2);
    let rho = use3d.select(rho3, rho2);
    // rho_cut is finite, so this also rejects ρ = ∞ and NaN.
    let inside = candidates.and(rho.le(cut));
    let z_plane = inv * sp.det;
    let beyond_near = z_plane
        .gt(F32x8::splat(c.near))
        .and(z_plane.lt(F32x8::splat(f32::INFINITY)));
    let ok = inside.and_not(use3d.and_not(beyond_near));
    let z = use3d.select(z_plane, F32x8::splat(sp.view_depth));
    let g = exp(rho * -0.5);
    let oa = g * sp.opacity;
    let clamped = oa.gt(F32x8::splat(c.alpha_max));
    let alpha = clamped.select(F32x8::splat(c.alpha_max), oa);
    let ok = ok.and_not(alpha.lt(F32x8::splat(c.alpha_min)));
    Some(Hit {
        ok,
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
    })
}

/// `1 − α` in f64, with the reference's exact factor where α is clamped.
#[inline(always)]
fn one_minus_alpha(hit: &Hit, c: &PixelConsts) -> F64x8 {
    let unclamped = F64x8::splat(1.0) - F64x8::from_f32(hit.alpha);
    hit.clamped
        .select_f64(F64x8::splat(c.one_minus_alpha_max), unclamped)
}

/// Per-thread state of [`forward_tile`], reused from tile to tile.
pub struct ForwardScratch {
    trans: Vec<f64>,
    done: Vec<u32>,
    contrib: Vec<u32>,
    /// `NUM_SUMS` arrays of `PADDED`.
    sums: Vec<f32>,
}

impl Default for ForwardScratch {
    fn default() -> Self {
        ForwardScratch {
            trans: vec![1.0; PADDED],
            done: vec![0; PADDED],
            contrib: vec![0; PADDED],
            sums: vec![0.0; NUM_SUMS * PADDED],
        }
    }
}

/// One tile's forward result, tile-local row-major pixels.
pub struct TileOutput<'a> {
    /// `NUM_SUMS` arrays of `TILE_PIXELS`: α, depth, features.
    pub sums: &'a mut [f32],
    pub transmittance: &'a mut [f64],
    /// Per pixel, the number of list entries up to and including the last one composited.
    pub contributors: &'a mut [u32],
}

/// Composites `list` (front to back) into the tile with pixel bounds `tile` (`[x0, y0, x1, y1)`,
/// clipped to the image); returns the (pixel, surfel) pairs evaluated.
pub fn forward_tile(
    path: SimdPath,
    list: &[Splat],
    tile: [u32; 4],
    consts: &PixelConsts,
    scratch: &mut ForwardScratch,
    out: TileOutput,
) -> u64 {
    match path {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `SimdPath::Avx2` is only ever constructed after `is_x86_feature_detected!`
        // ("avx2") returned true ([`SimdPath::detect`], [`SimdPath::is_available`]), so the CPU
        // running this has every feature the function is compiled with.
        SimdPath::Avx2 => unsafe { forward_tile_avx2(list, tile, consts, scratch, out) },
        _ => forward_body(list, tile, consts, scratch, out),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn forward_tile_avx2(
    list: &[Splat],
    tile: [u32; 4],
    consts: &PixelConsts,
    scratch: &mut ForwardScratch,
    out: TileOutput,
) -> u64 {
    forward_body(list, tile, consts, scratch, out)
}

#[inline(always)]
fn forward_body(
    list: &[Splat],
    tile: [u32; 4],
    c: &PixelConsts,
    s: &mut ForwardScratch,
    out: TileOutput,
) -> u64 {
    s.trans.fill(1.0);
    s.done.fill(0);
    s.contrib.fill(0);
    s.sums.fill(0.0);
    let t_min = F64x8::splat(c.transmittance_min);
    let live_pixels = ((tile[2] - tile[0]) * (tile[3] - tile[1])) as usize;
    let mut evaluations = 0u64;
    let mut n_done = 0usize;
    for (k, sp) in list.iter().enumerate() {
        let ([rx0, ry0, rx1, ry1], [ox, oy]) = sp.in_tile(tile);
        let entry_count = [k as u32 + 1; LANES];
        let features = sp.features.map(F32x8::splat);
        for ly in ry0..ry1 {
            let row = RowConsts::new(sp, ly as f32 + oy);
            for lx in (rx0..rx1).step_by(LANES) {
                let base = ly * TILE + lx;
                let alive = Mask8::first(rx1 - lx).and_not(Mask8::nonzero(&s.done[base..]));
                if !alive.any() {
                    continue;
                }
                evaluations += u64::from(alive.count());
                let lxv = F32x8::ramp(lx as f32 + ox);
                let Some(hit) = evaluate(sp, &row, lxv, alive, c) else {
                    continue;
                };
                let valid = hit.ok;
                if !valid.any() {
                    continue;
                }
                let t = F64x8::load(&s.trans[base..]);
                let next_t = t * one_minus_alpha(&hit, c);
                let stop = valid.and(next_t.lt(t_min));
                if stop.any() {
                    let done = Mask8(std::array::from_fn(|l| s.done[base + l])).or(stop);
                    s.done[base..base + LANES].copy_from_slice(&done.0);
                    n_done += stop.count() as usize;
                }
                let comp = valid.and_not(stop);
                if !comp.any() {
                    continue;
                }
                let w = (hit.alpha * t.to_f32()).and(comp);
                let add = |sums: &mut [f32], f: usize, v: F32x8| {
                    let slot = &mut sums[f * PADDED + base..];
                    (F32x8::load(slot) + v).store(slot);
                };
                add(&mut s.sums, 0, w);
                add(&mut s.sums, 1, (w * hit.z).and(comp));
                for (f, feature) in features.iter().enumerate() {
                    add(&mut s.sums, 2 + f, w * *feature);
                }
                add(&mut s.sums, DEPTH_SQ, (w * hit.z * hit.z).and(comp));
                comp.select_f64(next_t, t).store(&mut s.trans[base..]);
                let counts = comp.select_u32(entry_count, &s.contrib[base..]);
                s.contrib[base..base + LANES].copy_from_slice(&counts);
            }
        }
        if n_done == live_pixels {
            break;
        }
    }
    for f in 0..NUM_SUMS {
        out.sums[f * TILE_PIXELS..(f + 1) * TILE_PIXELS]
            .copy_from_slice(&s.sums[f * PADDED..f * PADDED + TILE_PIXELS]);
    }
    out.transmittance.copy_from_slice(&s.trans[..TILE_PIXELS]);
    out.contributors.copy_from_slice(&s.contrib[..TILE_PIXELS]);
    evaluations
}

/// Gradient of one tile's loss with respect to one [`Splat`] (in the surfel's frame): `f32` per
/// (tile, surfel) entry, `f64` for a surfel's sum over its entries.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LocalGrad<T = f32> {
    /// Per plane row: `Σ g_p u`, `Σ g_p v`, `Σ g_p` (`(u, v)`: the pixel in the surfel's frame).
    pub plane: [[T; 3]; 3],
    pub det: T,
    pub mean: [T; 2],
    pub opacity: T,
    pub view_depth: T,
    pub features: [T; NUM_FEATURES],
}

impl LocalGrad<f64> {
    /// Adds one entry's gradient.
    pub fn add(&mut self, g: &LocalGrad) {
        for (row, r) in self.plane.iter_mut().zip(&g.plane) {
            for (a, b) in row.iter_mut().zip(r) {
                *a += f64::from(*b);
            }
        }
        self.det += f64::from(g.det);
        self.mean[0] += f64::from(g.mean[0]);
        self.mean[1] += f64::from(g.mean[1]);
        self.opacity += f64::from(g.opacity);
        self.view_depth += f64::from(g.view_depth);
        for (a, b) in self.features.iter_mut().zip(&g.features) {
            *a += f64::from(*b);
        }
    }

    /// The gradient on the surfel's [`Projected`] values, for a splat made in `frame`.
    pub fn to_projected(&self, frame: &PlaneFrame) -> ProjectedGrad {
        let [ox, oy] = frame.origin;
        let l = frame.scale;
        let mut q = [0.0; 9];
        for (k, &[ga, gb, gc]) in self.plane.iter().enumerate() {
            // p_k = λ (q_k0 (u + ox) + q_k1 (v + oy) + q_k2).
            q[3 * k] = l * (ga + ox * gc);
            q[3 * k + 1] = l * (gb + oy * gc);
            q[3 * k + 2] = l * gc;
        }
        ProjectedGrad {
            q,
            det: l * self.det,
            mean: self.mean,
            opacity: self.opacity,
            features: self.features,
            view_depth: self.view_depth,
        }
    }
}

/// Per-thread state of [`backward_tile`]: the per-pixel quantities of the replay, which the
/// caller fills ([`Self::pixel`]) before each tile.
pub struct BackwardScratch {
    /// Effective `dL/dα` per pixel.
    g_alpha: Vec<f32>,
    /// `NUM_PIXEL_GRADS` arrays: `dL/d(sum)` of depth and the features (upstream / α).
    g_sums: Vec<f32>,
    trans: Vec<f64>,
    contrib: Vec<u32>,
    /// `B = Σ_{j>i} w_j (dL/dα + Σ_c dL/dS_c v_{j,c})`.
    b_acc: Vec<f32>,
}

impl Default for BackwardScratch {
    fn default() -> Self {
        BackwardScratch {
            g_alpha: vec![0.0; PADDED],
            g_sums: vec![0.0; NUM_PIXEL_GRADS * PADDED],
            trans: vec![0.0; PADDED],
            contrib: vec![0; PADDED],
            b_acc: vec![0.0; PADDED],
        }
    }
}

/// The upstream quantities of one pixel for [`BackwardScratch::pixel`].
pub struct PixelUpstream {
    pub g_alpha: f64,
    pub g_sums: [f64; NUM_PIXEL_GRADS],
    pub transmittance: f64,
    pub contributors: u32,
}

impl BackwardScratch {
    /// Clears every pixel (no contributors).
    pub fn clear(&mut self) {
        self.g_alpha.fill(0.0);
        self.g_sums.fill(0.0);
        self.trans.fill(0.0);
        self.contrib.fill(0);
        self.b_acc.fill(0.0);
    }

    /// Sets tile-local pixel `li`.
    pub fn pixel(&mut self, li: usize, p: &PixelUpstream) {
        self.g_alpha[li] = p.g_alpha as f32;
        for (c, g) in p.g_sums.iter().enumerate() {
            self.g_sums[c * PADDED + li] = *g as f32;
        }
        self.trans[li] = p.transmittance;
        self.contrib[li] = p.contributors;
    }
}

/// Replays the list of the tile with pixel bounds `tile` back to front from the state [`BackwardScratch::pixel`] set; writes
/// the gradient of each entry to `grads` (entries no pixel composited stay untouched).
pub fn backward_tile(
    path: SimdPath,
    list: &[Splat],
    tile: [u32; 4],
    consts: &PixelConsts,
    scratch: &mut BackwardScratch,
    grads: &mut [LocalGrad],
) {
    match path {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: as in `forward_tile`: `SimdPath::Avx2` exists only where AVX2 was detected.
        SimdPath::Avx2 => unsafe { backward_tile_avx2(list, tile, consts, scratch, grads) },
        _ => backward_body(list, tile, consts, scratch, grads),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn backward_tile_avx2(
    list: &[Splat],
    tile: [u32; 4],
    consts: &PixelConsts,
    scratch: &mut BackwardScratch,
    grads: &mut [LocalGrad],
) {
    backward_body(list, tile, consts, scratch, grads)
}

/// Lane accumulators of one entry's [`LocalGrad`].
#[derive(Default)]
struct GradLanes {
    plane: [[F32x8; 3]; 3],
    det: F32x8,
    mean: [F32x8; 2],
    opacity: F32x8,
    view_depth: F32x8,
    features: [F32x8; NUM_FEATURES],
}

impl GradLanes {
    #[inline(always)]
    fn reduce(&self) -> LocalGrad {
        LocalGrad {
            plane: self.plane.map(|r| r.map(F32x8::sum)),
            det: self.det.sum(),
            mean: self.mean.map(F32x8::sum),
            opacity: self.opacity.sum(),
            view_depth: self.view_depth.sum(),
            features: self.features.map(F32x8::sum),
        }
    }
}

#[inline(always)]
fn backward_body(
    list: &[Splat],
    tile: [u32; 4],
    c: &PixelConsts,
    s: &mut BackwardScratch,
    grads: &mut [LocalGrad],
) {
    let max_contrib = s.contrib[..TILE_PIXELS].iter().copied().max().unwrap_or(0) as usize;
    let lowpass_scale = -2.0 * c.inv_sigma2;
    for k in (0..max_contrib.min(list.len())).rev() {
        let sp = &list[k];
        let ([rx0, ry0, rx1, ry1], [ox, oy]) = sp.in_tile(tile);
        let features = sp.features.map(F32x8::splat);
        let mut acc = GradLanes::default();
        for ly in ry0..ry1 {
            let row = RowConsts::new(sp, ly as f32 + oy);
            let lyv = F32x8::splat(row.ly);
            for lx in (rx0..rx1).step_by(LANES) {
                let base = ly * TILE + lx;
                let alive =
                    Mask8::first(rx1 - lx).and(Mask8::greater(&s.contrib[base..], k as u32));
                if !alive.any() {
                    continue;
                }
                let lxv = F32x8::ramp(lx as f32 + ox);
                let Some(hit) = evaluate(sp, &row, lxv, alive, c) else {
                    continue;
                };
                let valid = hit.ok;
                if !valid.any() {
                    continue;
                }
                let one_minus_64 = one_minus_alpha(&hit, c);
                let one_minus = one_minus_64.to_f32();
                let trans = F64x8::load(&s.trans[base..]);
                let b_acc = F32x8::load(&s.b_acc[base..]);
                let t_i_64 = trans / one_minus_64;
                let t_i = t_i_64.to_f32();
                let weight = hit.alpha * t_i;
                let gs = |f: usize| F32x8::load(&s.g_sums[f * PADDED + base..]);
                let g_depth = gs(0);
                let mut u = F32x8::load(&s.g_alpha[base..]) + g_depth * hit.z;
                for (f, feature) in features.iter().enumerate() {
                    let g = gs(1 + f);
                    u += g * *feature;
                    acc.features[f] += (weight * g).and(valid);
                }
                let g_depth_sq = gs(DEPTH_SQ - 1);
                u += g_depth_sq * hit.z * hit.z;
                let d_alpha = t_i * u - b_acc / one_minus;
                valid
                    .select(b_acc + weight * u, b_acc)
                    .store(&mut s.b_acc[base..]);
                valid.select_f64(t_i_64, trans).store(&mut s.trans[base..]);

                // α = min(alpha_max, o G), G = exp(−ρ/2).
                let free = valid.and_not(hit.clamped);
                acc.opacity += (hit.g * d_alpha).and(free);
                let g_rho = (hit.g * sp.opacity * d_alpha * -0.5).and(free);
                let gz = weight * (g_depth + g_depth_sq * hit.z * 2.0);
                // Filter branch: ρ_2d around the projected centre, z = centre depth.
                let filter = valid.and_not(hit.use3d);
                if filter.any() {
                    let cf = g_rho * lowpass_scale;
                    acc.mean[0] += (cf * hit.dx).and(filter);
                    acc.mean[1] += (cf * row.dy).and(filter);
                    acc.view_depth += gz.and(filter);
                }
                // Plane branch: ρ = s² + t², s = px · inv, t = py · inv, z = det · inv.
                let plane = valid.and(hit.use3d);
                if plane.any() {
                    let g_s = hit.s * g_rho * 2.0;
                    let g_t = hit.t * g_rho * 2.0;
                    acc.det += (hit.inv * gz).and(plane);
                    let g_inv = hit.px * g_s + hit.py * g_t + gz * sp.det;
                    let gp = [
                        (hit.inv * g_s).and(plane),
                        (hit.inv * g_t).and(plane),
                        (-(hit.inv * hit.inv) * g_inv).and(plane),
                    ];
                    for (r, g) in acc.plane.iter_mut().zip(gp) {
                        r[0] += g * lxv;
                        r[1] += g * lyv;
                        r[2] += g;
                    }
                }
            }
        }
        grads[k] = acc.reduce();
    }
}

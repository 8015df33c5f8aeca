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
//! values, not on absolute pixel positions whose f32 products would cancel. For one surfel, its
//! (tile-clipped) pixel box is walked in [`Group`]s of 8 lanes starting at the box's left edge:
//! one row per group, or, in the forward pass, two rows of a box at most four pixels wide; lanes
//! beyond the box are masked. Per-pixel state is stored tile-row-major with [`LANES`] values of
//! padding at the end, so a group that runs past the tile's right edge reads the next row's first
//! pixels (or the padding) and writes them back unchanged. A pixel's arithmetic does not depend
//! on the group that holds it, so the forward's G-buffers are the same bits either way.
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
        Self::in_frame(p, &PlaneFrame::of(p))
    }

    /// `p` in `frame`, which must be [`PlaneFrame::of`]`(p)` (for a caller that keeps it).
    pub fn in_frame(p: &Projected, frame: &PlaneFrame) -> Self {
        let PlaneFrame { scale, origin } = *frame;
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
        let local =
            |k: usize, axis: usize| (r[k].clamp(tile[axis], tile[axis + 2]) - tile[axis]) as usize;
        let offset = [tile[0] as f32 - r[0] as f32, tile[1] as f32 - r[1] as f32];
        // No `array::map` in a kernel (see `super::lanes`).
        ([local(0, 0), local(1, 1), local(2, 0), local(3, 1)], offset)
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

/// Lanes in half a vector: a [`Group`]'s run of pixels within one row.
const HALF: usize = LANES / 2;

/// The eight pixels one vector holds: two runs of [`HALF`] tile-local pixels, lanes 0–3 from
/// `first` and lanes 4–7 from `second`: the row's next four pixels (`second = first + 4`,
/// [`Walk::Rows`]) or the same four pixels of the next row (`second = first + TILE`, a box at most
/// four pixels wide under [`Walk::PairNarrowRows`]). Pixels of a run beyond the box are read and
/// written back unchanged (lanes outside `inside`), which the padding of the per-pixel arrays
/// allows.
struct Group {
    first: usize,
    second: usize,
    /// Lanes whose pixel is inside the surfel's (tile-clipped) box.
    inside: Mask8,
    /// Each lane's pixel centre in the surfel's frame ([`PlaneFrame`]).
    x: F32x8,
    y: F32x8,
}

impl Group {
    /// Row `ly` of the tile from column `lx`, `width` pixels of it in the box.
    #[inline(always)]
    fn row(ly: usize, lx: usize, width: usize, [ox, oy]: [f32; 2]) -> Self {
        let first = ly * TILE + lx;
        Group {
            first,
            second: first + HALF,
            inside: Mask8::first(width),
            x: F32x8::ramp(lx as f32 + ox),
            y: F32x8::splat(ly as f32 + oy),
        }
    }

    /// Columns `lx..lx + width` (`width ≤ 4`) of rows `ly` and, where `both`, `ly + 1`.
    #[inline(always)]
    fn two_rows(ly: usize, lx: usize, width: usize, both: bool, [ox, oy]: [f32; 2]) -> Self {
        let first = ly * TILE + lx;
        // A last, unpaired row leaves lanes 4–7 on the next pixels of its own row (masked).
        let second = if both { first + TILE } else { first + HALF };
        let inside = Mask8(std::array::from_fn(|l| {
            if l % HALF < width && (l < HALF || both) {
                u32::MAX
            } else {
                0
            }
        }));
        let x0 = lx as f32 + ox;
        let y0 = ly as f32 + oy;
        Group {
            first,
            second,
            inside,
            x: F32x8(std::array::from_fn(|l| x0 + (l % HALF) as f32)),
            y: F32x8(std::array::from_fn(|l| y0 + (l / HALF) as f32)),
        }
    }

    /// The lanes' values of a per-pixel array.
    #[inline(always)]
    fn load<T: Copy>(&self, values: &[T]) -> [T; LANES] {
        let (a, b) = (
            &values[self.first..][..HALF],
            &values[self.second..][..HALF],
        );
        std::array::from_fn(|l| if l < HALF { a[l] } else { b[l - HALF] })
    }

    /// The lanes' values of a per-pixel f32 array.
    #[inline(always)]
    fn vector(&self, values: &[f32]) -> F32x8 {
        F32x8(self.load(values))
    }

    /// Adds `v` to a per-pixel array.
    #[inline(always)]
    fn add(&self, v: F32x8, values: &mut [f32]) {
        self.store(&(self.vector(values) + v).0, values);
    }

    /// Writes the lanes back to a per-pixel array.
    #[inline(always)]
    fn store<T: Copy>(&self, lanes: &[T; LANES], values: &mut [T]) {
        values[self.first..][..HALF].copy_from_slice(&lanes[..HALF]);
        values[self.second..][..HALF].copy_from_slice(&lanes[HALF..]);
    }
}

/// How a kernel walks a surfel's box.
///
/// Most surfels of a trained model cover a few pixels (the knot at 20,000 surfels: boxes of
/// about 4.6 × 4.6 pixels within a tile), so one row fills about half of a vector's lanes. The
/// forward pass pairs the rows of narrow boxes: about a fifth less time in its tile loops on a
/// knot step. The backward pass gained nothing from it (measured back to back; its groups carry
/// 22 lane accumulators in memory, and the entry's reduction does not shrink) and walks rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Walk {
    /// One row per group.
    Rows,
    /// Boxes at most [`HALF`] pixels wide two rows per group, wider ones one row per group.
    PairNarrowRows,
}

/// The [`Group`]s of a surfel's tile-local box `[x0, y0, x1, y1)`, row by row from the top.
struct Groups {
    rect: [usize; 4],
    /// The tile's first pixel in the surfel's frame.
    offset: [f32; 2],
    /// Two rows per group: the box is at most [`HALF`] pixels wide.
    two_rows: bool,
    /// The next group's first pixel.
    ly: usize,
    lx: usize,
}

impl Groups {
    #[inline(always)]
    fn new(rect: [usize; 4], offset: [f32; 2], walk: Walk) -> Self {
        Groups {
            rect,
            offset,
            two_rows: walk == Walk::PairNarrowRows && rect[2] - rect[0] <= HALF,
            ly: rect[1],
            lx: rect[0],
        }
    }
}

impl Iterator for Groups {
    type Item = Group;

    #[inline(always)]
    fn next(&mut self) -> Option<Group> {
        let [rx0, _, rx1, ry1] = self.rect;
        let (ly, lx) = (self.ly, self.lx);
        if ly >= ry1 {
            return None;
        }
        if self.two_rows {
            self.ly += 2;
            Some(Group::two_rows(
                ly,
                lx,
                rx1 - rx0,
                ly + 1 < ry1,
                self.offset,
            ))
        } else {
            self.lx += LANES;
            if self.lx >= rx1 {
                self.lx = rx0;
                self.ly += 1;
            }
            Some(Group::row(ly, lx, rx1 - lx, self.offset))
        }
    }
}

/// What a [`Group`]'s rows contribute to [`evaluate`] for one surfel.
struct RowConsts {
    /// `b_k y + c_k` of the three plane rows.
    p: [F32x8; 3],
    dy: F32x8,
    dy2: F32x8,
}

impl RowConsts {
    #[inline(always)]
    fn new(sp: &Splat, group: &Group) -> Self {
        let y = group.y;
        let dy = y - sp.mean[1];
        // Written out, not `sp.plane.map(..)` (see `super::lanes` on `array::map`): that was
        // three SSE calls per group, and the two stores after them held 13% of the backward
        // kernel's samples.
        let [r0, r1, r2] = &sp.plane;
        RowConsts {
            p: [y * r0[1] + r0[2], y * r1[1] + r1[2], y * r2[1] + r2[2]],
            dy,
            dy2: dy * dy,
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
    /// Per pixel, a lane mask: all ones once the pixel has stopped.
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
        _ => forward_body(list, tile, consts, scratch, out, Walk::PairNarrowRows),
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
    forward_body(list, tile, consts, scratch, out, Walk::PairNarrowRows)
}

#[inline(always)]
pub(super) fn forward_body(
    list: &[Splat],
    tile: [u32; 4],
    c: &PixelConsts,
    s: &mut ForwardScratch,
    out: TileOutput,
    walk: Walk,
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
        let (in_tile, offset) = sp.in_tile(tile);
        let entry_count = [k as u32 + 1; LANES];
        let features = F32x8::splat_each(&sp.features);
        for group in Groups::new(in_tile, offset, walk) {
            let done = Mask8(group.load(&s.done));
            let alive = group.inside.and_not(done);
            if !alive.any() {
                continue;
            }
            evaluations += u64::from(alive.count());
            let row = RowConsts::new(sp, &group);
            let Some(hit) = evaluate(sp, &row, group.x, alive, c) else {
                continue;
            };
            let valid = hit.ok;
            if !valid.any() {
                continue;
            }
            let t = F64x8(group.load(&s.trans));
            let next_t = t * one_minus_alpha(&hit, c);
            let stop = valid.and(next_t.lt(t_min));
            if stop.any() {
                group.store(&done.or(stop).0, &mut s.done);
                n_done += stop.count() as usize;
            }
            let comp = valid.and_not(stop);
            if !comp.any() {
                continue;
            }
            let w = (hit.alpha * t.to_f32()).and(comp);
            let sums = &mut s.sums;
            group.add(w, &mut sums[..PADDED]);
            group.add((w * hit.z).and(comp), &mut sums[PADDED..]);
            for (f, feature) in features.iter().enumerate() {
                group.add(w * *feature, &mut sums[(2 + f) * PADDED..]);
            }
            group.add(
                (w * hit.z * hit.z).and(comp),
                &mut sums[DEPTH_SQ * PADDED..],
            );
            group.store(&comp.select_f64(next_t, t).0, &mut s.trans);
            let counts = comp.select_u32(entry_count, &group.load(&s.contrib));
            group.store(&counts, &mut s.contrib);
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
            plane: std::array::from_fn(|k| std::array::from_fn(|i| self.plane[k][i].sum())),
            det: self.det.sum(),
            mean: std::array::from_fn(|i| self.mean[i].sum()),
            opacity: self.opacity.sum(),
            view_depth: self.view_depth.sum(),
            features: std::array::from_fn(|f| self.features[f].sum()),
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
        let (in_tile, offset) = sp.in_tile(tile);
        let features = F32x8::splat_each(&sp.features);
        let mut acc = GradLanes::default();
        for group in Groups::new(in_tile, offset, Walk::Rows) {
            let alive = group
                .inside
                .and(Mask8::greater(&group.load(&s.contrib), k as u32));
            if !alive.any() {
                continue;
            }
            let row = RowConsts::new(sp, &group);
            let Some(hit) = evaluate(sp, &row, group.x, alive, c) else {
                continue;
            };
            let valid = hit.ok;
            if !valid.any() {
                continue;
            }
            let one_minus_64 = one_minus_alpha(&hit, c);
            let one_minus = one_minus_64.to_f32();
            let trans = F64x8(group.load(&s.trans));
            let b_acc = group.vector(&s.b_acc);
            let t_i_64 = trans / one_minus_64;
            let t_i = t_i_64.to_f32();
            let weight = hit.alpha * t_i;
            let g_sums = &s.g_sums;
            let g_depth = group.vector(g_sums);
            let mut u = group.vector(&s.g_alpha) + g_depth * hit.z;
            for (f, feature) in features.iter().enumerate() {
                let g = group.vector(&g_sums[(1 + f) * PADDED..]);
                u += g * *feature;
                acc.features[f] += (weight * g).and(valid);
            }
            let g_depth_sq = group.vector(&g_sums[(DEPTH_SQ - 1) * PADDED..]);
            u += g_depth_sq * hit.z * hit.z;
            let d_alpha = t_i * u - b_acc / one_minus;
            group.store(&valid.select(b_acc + weight * u, b_acc).0, &mut s.b_acc);
            group.store(&valid.select_f64(t_i_64, trans).0, &mut s.trans);

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
                    r[0] += g * group.x;
                    r[1] += g * group.y;
                    r[2] += g;
                }
            }
        }
        grads[k] = acc.reduce();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every box in a tile, under both walks: the inside lanes hold each pixel of the box once,
    /// at its centre in the surfel's frame, and no lane reaches past the padded arrays.
    #[test]
    fn groups_hold_every_pixel_of_a_box_once() {
        let offset = [-3.0, 5.0];
        let mut paired = 0;
        for walk in [Walk::Rows, Walk::PairNarrowRows] {
            for (x0, x1) in (0..TILE).flat_map(|a| (a + 1..=TILE).map(move |b| (a, b))) {
                for (y0, y1) in (0..TILE).flat_map(|a| (a + 1..=TILE).map(move |b| (a, b))) {
                    let mut seen = vec![0u32; PADDED];
                    for g in Groups::new([x0, y0, x1, y1], offset, walk) {
                        assert!(g.first + HALF <= PADDED && g.second + HALF <= PADDED);
                        paired += usize::from(g.second == g.first + TILE);
                        for l in 0..LANES {
                            let pixel = if l < HALF {
                                g.first + l
                            } else {
                                g.second + l - HALF
                            };
                            if g.inside.0[l] == 0 {
                                continue;
                            }
                            let (x, y) = (pixel % TILE, pixel / TILE);
                            assert!((x0..x1).contains(&x) && (y0..y1).contains(&y));
                            assert_eq!(g.x.0[l], x as f32 + offset[0]);
                            assert_eq!(g.y.0[l], y as f32 + offset[1]);
                            seen[pixel] += 1;
                        }
                    }
                    let area = (x1 - x0) * (y1 - y0);
                    assert_eq!(
                        seen.iter().sum::<u32>() as usize,
                        area,
                        "{x0} {y0} {x1} {y1}"
                    );
                    assert!(seen.iter().all(|&n| n <= 1));
                }
            }
        }
        assert!(paired > 0, "narrow boxes are paired");
    }
}

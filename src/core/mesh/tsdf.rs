//! TSDF fusion of z-depth maps (METHOD.md §8, the 2DGS recipe) and mesh extraction.
//!
//! Every voxel centre is projected into every view. Where the view sees a surface at that pixel,
//! `sdf = depth(pixel) − z` (difference of OpenCV z-depths along the viewing axis); voxels more than
//! one truncation distance behind the surface are not updated, the others receive
//! `tsdf = min(sdf / trunc, 1)`. Where the view sees background (depth 0, alpha < 0.5 or depth
//! beyond `depth_max`) at all four pixels around the projection, the voxel is free space and
//! receives `+1`, which carves the visual hull. Values are averaged with unit weights; voxels no view
//! observed stay unknown and block marching cubes. Depth is bilinearly interpolated when the four
//! neighbouring pixels see a continuous surface, else the nearest pixel is used; a voxel whose
//! nearest pixel is background but some neighbour is not gets no vote from that view. A pixel may
//! also be unknown (NaN depth): rendered depth whose composited surfaces spread along the ray by
//! more than the truncation and a few pixel footprints ([`fusion_depth`]: a sparse patch blended
//! with the far wall behind it); a voxel with an unknown pixel among its four gets no vote from
//! that view.
//!
//! Only 8³-voxel blocks near back-projected surface pixels are fused (a conservative band that
//! provably holds every cell marching cubes could triangulate, so the result equals dense fusion).
//! Threading: rayon over views (preparation, block marking) then over active blocks; each block
//! loops over the views with camera coordinates updated incrementally (one division per voxel and
//! view) and reads a per-view table of precomputed interpolation cells.

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use super::marching_cubes::{marching_cubes, ScalarGrid};
use super::{MeshError, TriangleMesh};
use crate::core::camera::Camera;

/// One depth map to fuse.
#[derive(Clone, Copy, Debug)]
pub struct DepthView<'a> {
    pub camera: &'a Camera,
    /// OpenCV z-depth per pixel, row-major, 0 = no surface, NaN = unknown (no vote: a pixel
    /// whose composited surfaces lie too far apart to stand for one, [`fusion_depth`]).
    pub depth: &'a [f64],
    /// Accumulated opacity per pixel; pixels below 0.5 count as background.
    pub alpha: Option<&'a [f64]>,
}

/// Resolution and truncation of the fusion grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TsdfParams {
    /// Voxels along the longest side of the bounding box (the grid adds a margin of
    /// `MARGIN_VOXELS` voxels on every side).
    pub resolution: usize,
    /// SDF truncation distance in voxels (2DGS: 5).
    pub truncation_voxels: f64,
    /// Depths beyond this count as background.
    pub depth_max: f64,
    /// Which rendered pixels vote (those a fusion renders itself: [`GridLayout::pixels`]).
    pub pixels: DepthPixels,
}

/// Which opaque pixels of a rendered depth map vote in a fusion that renders its own depth
/// (`pipeline::mesh_extraction`, the gpu backend's fusion).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DepthPixels {
    /// Every opaque pixel, at its mean depth: GridMap's tracing mesh, for which a hole (a mirror
    /// ray escaping, a probe seeing through) matters and a sheet inside the object, which no
    /// probe or mirror ray reaches, does not.
    #[default]
    All,
    /// Pixels whose composited depths spread less than the truncation or a few footprints
    /// ([`fusion_depth`]); the others are unknown: the deliverable mesh, without the sheets that
    /// pixels seen through a sparse patch carve inside the object.
    Coherent,
}

/// Voxels added around the bounds so that a surface touching them still closes.
pub const MARGIN_VOXELS: usize = 2;

impl TsdfParams {
    /// 2DGS defaults: SDF truncation of 5 voxels, no depth limit.
    pub fn new(resolution: usize) -> Self {
        TsdfParams {
            resolution,
            truncation_voxels: 5.0,
            depth_max: f64::INFINITY,
            pixels: DepthPixels::All,
        }
    }

    /// Defaults with the depth limit derived from the object: 2DGS truncates depth at twice the
    /// scene radius to drop far background; here any depth beyond the far side of the bounds'
    /// circumscribed sphere (camera distance to the centre + radius, worst view) is background.
    /// It depends on the cameras' positions only, not on what they see, so a fusion that renders
    /// its depth maps elsewhere (on a device, [`crate::core::engine::Backend::fuse_depth`]) gets
    /// the same limit as the host's from the same cameras.
    pub fn automatic<'a>(
        resolution: usize,
        cameras: impl IntoIterator<Item = &'a Camera>,
        bounds: (DVec3, DVec3),
    ) -> Self {
        let centre = 0.5 * (bounds.0 + bounds.1);
        let radius = 0.5 * (bounds.1 - bounds.0).length();
        let farthest = cameras
            .into_iter()
            .map(|camera| camera.origin().distance(centre))
            .fold(0.0, f64::max);
        TsdfParams {
            depth_max: farthest + radius,
            ..TsdfParams::new(resolution)
        }
    }
}

/// Edge of the cubic voxel blocks that fusion allocates around observed surface points.
const BLOCK: usize = 8;

/// Bilinear-interpolation cell between four pixel centres: `[d00, d10, d01, d11]` (x fastest).
/// `BACKGROUND` when all four see background, NaN when the cell is unusable (mixed, or a depth
/// jump larger than the truncation); else the four depths. Stored as f32 to halve cache traffic
/// (depths of a few units keep ~1e-6 precision, far below a voxel).
type Cell = [f32; 4];
const BACKGROUND: f32 = -1.0;

/// A view prepared for fast projection: world-to-camera in OpenCV axes, the cleaned depth map
/// (0 = background) and its interpolation cells.
struct PreparedView {
    rotation: DMat3,
    translation: DVec3,
    camera: Camera,
    width: usize,
    height: usize,
    depth: Vec<f64>,
    cells: Vec<Cell>,
}

impl PreparedView {
    fn new(
        view: &DepthView,
        index: usize,
        depth_max: f64,
        max_jump: f64,
    ) -> Result<Self, MeshError> {
        let cam = view.camera;
        let expected = cam.num_pixels();
        let check = |what, actual: usize| {
            if actual == expected {
                Ok(())
            } else {
                Err(MeshError::ViewSize {
                    view: index,
                    what,
                    expected,
                    actual,
                })
            }
        };
        check("depth", view.depth.len())?;
        if let Some(alpha) = view.alpha {
            check("alpha", alpha.len())?;
        }
        let depth: Vec<f64> = view
            .depth
            .iter()
            .enumerate()
            .map(|(p, &d)| {
                let opaque = view.alpha.is_none_or(|a| a[p] >= 0.5);
                if opaque && d.is_nan() {
                    f64::NAN
                } else if opaque && d.is_finite() && d > 0.0 && d <= depth_max {
                    d
                } else {
                    0.0
                }
            })
            .collect();
        let (w, h) = (cam.width as usize, cam.height as usize);
        let mut cells = Vec::with_capacity(w * h);
        for y0 in 0..h {
            let y1 = (y0 + 1).min(h - 1);
            for x0 in 0..w {
                let x1 = (x0 + 1).min(w - 1);
                let d = [
                    depth[y0 * w + x0],
                    depth[y0 * w + x1],
                    depth[y1 * w + x0],
                    depth[y1 * w + x1],
                ];
                let surfaces = d.iter().filter(|&&z| z > 0.0).count();
                let lo = d.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = d.iter().copied().fold(0.0, f64::max);
                let unknown = d.iter().any(|z| z.is_nan());
                cells.push(if unknown {
                    [f32::NAN; 4]
                } else if surfaces == 0 {
                    [BACKGROUND; 4]
                } else if surfaces == 4 && hi - lo <= max_jump {
                    d.map(|z| z as f32)
                } else {
                    [f32::NAN; 4]
                });
            }
        }
        let (rotation, translation) = cam.world_to_camera_opencv();
        Ok(PreparedView {
            rotation,
            translation,
            camera: *cam,
            width: w,
            height: h,
            depth,
            cells,
        })
    }

    /// Marks the blocks that may hold a voxel whose cell has a negative corner: every voxel that
    /// receives a negative sdf from a view lies within `(d + 2·trunc)·0.71/f + 2·trunc·‖d_cam‖`
    /// of one of the four valid pixels it interpolates (depth spread ≤ trunc, half a pixel
    /// diagonal sideways), and its cell's other corners within √3 voxels of it.
    fn mark_blocks(&self, grid: &GridLayout, marked: &mut [bool]) {
        let trunc = grid.truncation;
        let blocks = grid.blocks();
        let cam = &self.camera;
        let f_min = cam.fx.min(cam.fy);
        let dcam_max = [
            (0.0, 0.0),
            (cam.width as f64, 0.0),
            (0.0, cam.height as f64),
            (cam.width as f64, cam.height as f64),
        ]
        .iter()
        .map(|&(u, v)| cam.camera_dir(u, v).length())
        .fold(0.0, f64::max);
        let rotation_cv = cam.rotation_opencv();
        let origin = cam.origin();
        let mut last = None;
        for j in 0..self.height {
            for i in 0..self.width {
                let d = self.depth[j * self.width + i];
                // Background (0) and unknown (NaN) pixels mark nothing.
                if d.is_nan() || d <= 0.0 {
                    continue;
                }
                let p = origin + rotation_cv * (cam.camera_dir(i as f64 + 0.5, j as f64 + 0.5) * d);
                let r = (d + 2.0 * trunc) * std::f64::consts::FRAC_1_SQRT_2 / f_min
                    + 2.0 * trunc * dcam_max
                    + 1.8 * grid.voxel;
                let lo = ((p - r - grid.origin) / grid.voxel).ceil();
                let hi = ((p + r - grid.origin) / grid.voxel).floor();
                let range = |a: usize| {
                    let last = grid.dims[a] as f64 - 1.0;
                    if hi[a] < 0.0 || lo[a] > last {
                        None
                    } else {
                        Some((
                            lo[a].max(0.0) as usize / BLOCK,
                            hi[a].min(last) as usize / BLOCK,
                        ))
                    }
                };
                let (Some(bx), Some(by), Some(bz)) = (range(0), range(1), range(2)) else {
                    continue;
                };
                // Neighbouring pixels mostly mark the same blocks.
                if last == Some((bx, by, bz)) {
                    continue;
                }
                last = Some((bx, by, bz));
                for bk in bz.0..=bz.1 {
                    for bj in by.0..=by.1 {
                        let row = (bk * blocks[1] + bj) * blocks[0];
                        marked[row + bx.0..=row + bx.1].fill(true);
                    }
                }
            }
        }
    }
}

/// How one view sees a whole block of voxels.
enum BlockClass {
    /// Every voxel would be skipped (unknown pixels or more than `trunc` behind the surface).
    Skipped,
    /// Every voxel would receive exactly +1 (background or more than `trunc` in front).
    Free,
    /// Voxels must be visited one by one.
    Mixed,
}

impl PreparedView {
    /// Classifies the block whose voxel centres span `base + a·edges[0] + b·edges[1] + c·edges[2]`
    /// (camera coordinates, a, b, c ∈ [0, 1]) from the cells its projection covers. Exact: it
    /// answers `Skipped` or `Free` only when the per-voxel rule gives that for every voxel.
    fn classify_block(&self, base: DVec3, edges: [DVec3; 3], trunc: f64) -> BlockClass {
        let cam = &self.camera;
        let (mut z_lo, mut z_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut u_lo, mut u_hi, mut v_lo, mut v_hi) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for corner in 0..8 {
            let mut c = base;
            for (a, e) in edges.iter().enumerate() {
                if corner & (1 << a) != 0 {
                    c += *e;
                }
            }
            if c.z <= 1e-6 {
                return BlockClass::Mixed;
            }
            let u = cam.fx * c.x / c.z + cam.cx;
            let v = cam.fy * c.y / c.z + cam.cy;
            (z_lo, z_hi) = (z_lo.min(c.z), z_hi.max(c.z));
            (u_lo, u_hi, v_lo, v_hi) = (u_lo.min(u), u_hi.max(u), v_lo.min(v), v_hi.max(v));
        }
        // A small pad absorbs rounding differences with the incremental per-voxel projection.
        const PAD: f64 = 1e-3;
        let (w, h) = (self.width as f64, self.height as f64);
        if u_lo - PAD < 0.0 || v_lo - PAD < 0.0 || u_hi + PAD >= w || v_hi + PAD >= h {
            return BlockClass::Mixed;
        }
        let (z_lo, z_hi) = (z_lo * (1.0 - 1e-9), z_hi * (1.0 + 1e-9));
        let cell = |x: f64| (x - 0.5).max(0.0) as usize;
        let (x0, x1) = (cell(u_lo - PAD), cell(u_hi + PAD).min(self.width - 1));
        let (y0, y1) = (cell(v_lo - PAD), cell(v_hi + PAD).min(self.height - 1));
        let (mut all_free, mut all_skipped) = (true, true);
        for y in y0..=y1 {
            for c in &self.cells[y * self.width + x0..=y * self.width + x1] {
                if c[0] == BACKGROUND {
                    all_skipped = false;
                } else if c[0].is_nan() {
                    all_free = false;
                } else {
                    let lo = c.iter().copied().fold(f32::INFINITY, f32::min) as f64;
                    let hi = c.iter().copied().fold(0.0f32, f32::max) as f64;
                    all_free &= lo - z_hi >= trunc;
                    all_skipped &= hi - z_lo < -trunc;
                }
                if !all_free && !all_skipped {
                    return BlockClass::Mixed;
                }
            }
        }
        if all_skipped {
            BlockClass::Skipped
        } else {
            BlockClass::Free
        }
    }
}

/// The fusion grid over some bounds at some [`TsdfParams`]: voxel centres at
/// `origin + voxel · (i, j, k)` for `(i, j, k) < dims` (the bounds plus [`MARGIN_VOXELS`] on every
/// side), with the truncation distance and the depth limit in world units. Every fusion builds
/// its grid from this one layout: the host's [`fuse_tsdf`] and a backend's own
/// ([`crate::core::engine::Backend::fuse_depth`]), so both give the same dims, origin and spacing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridLayout {
    /// Voxels along x, y and z (x fastest in the grid's arrays).
    pub dims: [usize; 3],
    /// Centre of voxel (0, 0, 0).
    pub origin: DVec3,
    /// Voxel edge (the grid's spacing).
    pub voxel: f64,
    /// SDF truncation distance: `truncation_voxels · voxel`. It also bounds the depth spread of
    /// the four pixels that bilinear interpolation may mix.
    pub truncation: f64,
    /// Depths beyond this count as background (may be +∞).
    pub depth_max: f64,
    /// Which rendered pixels vote.
    pub pixels: DepthPixels,
}

impl GridLayout {
    /// The grid of `params` over `bounds`, after checking both: finite bounds with a positive
    /// extent on every axis, a resolution in 2..=4096, a positive truncation and depth limit.
    pub fn new(bounds: (DVec3, DVec3), params: &TsdfParams) -> Result<Self, MeshError> {
        let (lo, hi) = bounds;
        let extent = hi - lo;
        if !(lo.is_finite() && hi.is_finite() && extent.min_element() > 0.0) {
            return Err(MeshError::InvalidBounds { min: lo, max: hi });
        }
        if !(2..=4096).contains(&params.resolution) {
            return Err(MeshError::InvalidParameter {
                name: "resolution",
                value: params.resolution as f64,
                reason: "must be between 2 and 4096",
            });
        }
        if !(params.truncation_voxels.is_finite() && params.truncation_voxels > 0.0) {
            return Err(MeshError::InvalidParameter {
                name: "truncation_voxels",
                value: params.truncation_voxels,
                reason: "must be positive",
            });
        }
        if params.depth_max.is_nan() || params.depth_max <= 0.0 {
            return Err(MeshError::InvalidParameter {
                name: "depth_max",
                value: params.depth_max,
                reason: "must be positive",
            });
        }
        let voxel = extent.max_element() / params.resolution as f64;
        Ok(GridLayout {
            dims: [0, 1, 2].map(|a| (extent[a] / voxel).ceil() as usize + 2 * MARGIN_VOXELS),
            origin: lo - DVec3::splat((MARGIN_VOXELS as f64 - 0.5) * voxel),
            voxel,
            truncation: params.truncation_voxels * voxel,
            depth_max: params.depth_max,
            pixels: params.pixels,
        })
    }

    /// Voxels in the grid.
    pub fn voxel_count(&self) -> usize {
        self.dims.iter().product()
    }

    /// The fused grid with this layout: `values` and `known` per voxel, x fastest.
    pub fn scalar_grid(&self, values: Vec<f32>, known: Vec<bool>) -> ScalarGrid {
        ScalarGrid {
            dims: self.dims,
            origin: self.origin,
            spacing: self.voxel,
            values,
            known,
        }
    }

    /// Blocks of `BLOCK`³ voxels along each axis (the last ones may be partial).
    fn blocks(&self) -> [usize; 3] {
        self.dims.map(|d| d.div_ceil(BLOCK))
    }
}

/// Running sums of one block, indexed x fastest with the block's own size.
struct BlockSums {
    size: [usize; 3],
    sum: [f64; BLOCK * BLOCK * BLOCK],
    count: [u32; BLOCK * BLOCK * BLOCK],
}

impl BlockSums {
    fn slot(&self, i: usize, j: usize, k: usize) -> usize {
        (k * self.size[1] + j) * self.size[0] + i
    }
}

/// A view's camera-space frame of one block: voxel (i, j, k) of the block sits at
/// `base + i·step[0] + j·step[1] + k·step[2]`.
struct BlockFrame<'a> {
    view: &'a PreparedView,
    base: DVec3,
    step: [DVec3; 3],
    trunc: f64,
}

impl BlockFrame<'_> {
    /// Fuses the sub-box of voxels `start .. start + size` (block-local): whole sub-boxes the view
    /// sees uniformly in one step, mixed ones split in halves down to 2 voxels, then voxel by voxel.
    fn fuse(&self, start: [usize; 3], size: [usize; 3], sums: &mut BlockSums) {
        let corner = self.base
            + start[0] as f64 * self.step[0]
            + start[1] as f64 * self.step[1]
            + start[2] as f64 * self.step[2];
        let edges = [0, 1, 2].map(|a| self.step[a] * (size[a] - 1) as f64);
        match self.view.classify_block(corner, edges, self.trunc) {
            BlockClass::Skipped => return,
            BlockClass::Free => {
                for k in start[2]..start[2] + size[2] {
                    for j in start[1]..start[1] + size[1] {
                        let row = sums.slot(start[0], j, k);
                        sums.sum[row..row + size[0]]
                            .iter_mut()
                            .for_each(|s| *s += 1.0);
                        sums.count[row..row + size[0]]
                            .iter_mut()
                            .for_each(|c| *c += 1);
                    }
                }
                return;
            }
            BlockClass::Mixed => {}
        }
        if size.iter().any(|&s| s > 4) {
            let halves = size.map(|s| if s > 4 { [s / 2, s - s / 2] } else { [s, 0] });
            for part in 0..8usize {
                let pick = |a: usize| (part >> a) & 1;
                let sub = [0, 1, 2].map(|a| halves[a][pick(a)]);
                if sub.contains(&0) {
                    continue;
                }
                let sub_start = [0, 1, 2].map(|a| start[a] + pick(a) * halves[a][0]);
                self.fuse(sub_start, sub, sums);
            }
            return;
        }
        let view = self.view;
        let cam = &view.camera;
        let (w, h) = (view.width as f64, view.height as f64);
        for k in start[2]..start[2] + size[2] {
            for j in start[1]..start[1] + size[1] {
                for i in start[0]..start[0] + size[0] {
                    let c = self.base
                        + i as f64 * self.step[0]
                        + j as f64 * self.step[1]
                        + k as f64 * self.step[2];
                    if c.z <= 1e-9 {
                        continue;
                    }
                    let inv_z = 1.0 / c.z;
                    let u = cam.fx * c.x * inv_z + cam.cx;
                    let v = cam.fy * c.y * inv_z + cam.cy;
                    if !(u >= 0.0 && u < w && v >= 0.0 && v < h) {
                        continue;
                    }
                    let x = (u - 0.5).max(0.0);
                    let y = (v - 0.5).max(0.0);
                    let (x0, y0) = (x as usize, y as usize);
                    let cell = view.cells[y0 * view.width + x0];
                    let tsdf = if cell[0] == BACKGROUND {
                        1.0
                    } else if cell[0].is_nan() {
                        continue;
                    } else {
                        let (fx, fy) = ((x - x0 as f64).min(1.0), (y - y0 as f64).min(1.0));
                        let [d00, d10, d01, d11] = cell.map(f64::from);
                        let top = d00 + fx * (d10 - d00);
                        let bottom = d01 + fx * (d11 - d01);
                        let sdf = top + fy * (bottom - top) - c.z;
                        if sdf < -self.trunc {
                            continue;
                        }
                        (sdf / self.trunc).min(1.0)
                    };
                    let slot = sums.slot(i, j, k);
                    sums.sum[slot] += tsdf;
                    sums.count[slot] += 1;
                }
            }
        }
    }
}

/// Fuses every view into one block of voxels starting at voxel `start` with `size` voxels per
/// axis; returns the averaged tsdf per voxel (x fastest), NaN where no view observed it.
fn fuse_block(
    views: &[PreparedView],
    grid: &GridLayout,
    start: [usize; 3],
    size: [usize; 3],
    trunc: f64,
) -> Vec<f32> {
    let mut sums = BlockSums {
        size,
        sum: [0.0; BLOCK * BLOCK * BLOCK],
        count: [0; BLOCK * BLOCK * BLOCK],
    };
    let corner =
        grid.origin + grid.voxel * DVec3::new(start[0] as f64, start[1] as f64, start[2] as f64);
    for view in views {
        let frame = BlockFrame {
            view,
            base: view.rotation * corner + view.translation,
            step: [
                view.rotation.x_axis,
                view.rotation.y_axis,
                view.rotation.z_axis,
            ]
            .map(|a| a * grid.voxel),
            trunc,
        };
        frame.fuse([0; 3], size, &mut sums);
    }
    let n = size[0] * size[1] * size[2];
    (0..n)
        .map(|p| {
            if sums.count[p] > 0 {
                (sums.sum[p] / sums.count[p] as f64) as f32
            } else {
                f32::NAN
            }
        })
        .collect()
}

/// The fused grid: tsdf values at voxel centres (negative inside) and which voxels were observed.
/// Only blocks of `BLOCK`³ voxels near observed surface points are fused (the others cannot touch
/// a cell with a negative corner, so marching cubes gives the same surface as a dense fusion); the
/// rest stay unknown. Values are stored as f32 (they lie in [−1, 1]).
pub fn fuse_tsdf(
    views: &[DepthView],
    bounds: (DVec3, DVec3),
    params: &TsdfParams,
) -> Result<ScalarGrid, MeshError> {
    let _span = tracing::info_span!(
        "tsdf_fusion",
        views = views.len(),
        resolution = params.resolution
    )
    .entered();
    if views.is_empty() {
        return Err(MeshError::NoViews);
    }
    let grid = GridLayout::new(bounds, params)?;
    let (dims, trunc) = (grid.dims, grid.truncation);
    let prepared = views
        .par_iter()
        .enumerate()
        .map(|(i, v)| PreparedView::new(v, i, grid.depth_max, trunc))
        .collect::<Result<Vec<_>, _>>()?;

    let blocks = grid.blocks();
    let block_count = blocks.iter().product::<usize>();
    let marked = prepared
        .par_iter()
        .fold(
            || vec![false; block_count],
            |mut marked, view| {
                view.mark_blocks(&grid, &mut marked);
                marked
            },
        )
        .reduce(
            || vec![false; block_count],
            |mut a, b| {
                a.iter_mut().zip(&b).for_each(|(x, y)| *x |= *y);
                a
            },
        );
    let active: Vec<usize> = (0..block_count).filter(|&b| marked[b]).collect();
    tracing::debug!(active = active.len(), total = block_count, "tsdf blocks");
    let [bx, by, _] = blocks;
    let fused: Vec<(usize, Vec<f32>)> = active
        .par_iter()
        .map(|&b| {
            let block = [b % bx, (b / bx) % by, b / (bx * by)];
            let start = block.map(|x| x * BLOCK);
            let size = [0, 1, 2].map(|a| BLOCK.min(dims[a] - start[a]));
            (b, fuse_block(&prepared, &grid, start, size, trunc))
        })
        .collect();

    let [nx, ny, _] = dims;
    let mut values = vec![0f32; grid.voxel_count()];
    let mut known = vec![false; grid.voxel_count()];
    for (b, block_values) in fused {
        let block = [b % bx, (b / bx) % by, b / (bx * by)];
        let start = block.map(|x| x * BLOCK);
        let size = [0, 1, 2].map(|a| BLOCK.min(dims[a] - start[a]));
        let mut slot = 0;
        for k in 0..size[2] {
            for j in 0..size[1] {
                let row = ((start[2] + k) * ny + start[1] + j) * nx + start[0];
                for i in 0..size[0] {
                    let value = block_values[slot];
                    slot += 1;
                    if !value.is_nan() {
                        values[row + i] = value;
                        known[row + i] = true;
                    }
                }
            }
        }
    }
    Ok(grid.scalar_grid(values, known))
}

/// Fuses the depth maps into a TSDF over `bounds` ([`fuse_tsdf`]) and extracts its surface
/// ([`mesh_from_grid`]).
pub fn extract_mesh(
    views: &[DepthView],
    bounds: (DVec3, DVec3),
    params: &TsdfParams,
) -> Result<TriangleMesh, MeshError> {
    let _span = tracing::info_span!("extract_mesh").entered();
    mesh_from_grid(&fuse_tsdf(views, bounds, params)?)
}

/// The surface of a fused grid: marching cubes on its zero level set, the largest connected
/// component, and area-weighted vertex normals pointing outward (towards positive TSDF).
/// [`MeshError::NoSurface`] when the grid has no zero crossing.
pub fn mesh_from_grid(grid: &ScalarGrid) -> Result<TriangleMesh, MeshError> {
    let mut mesh = marching_cubes(grid);
    if mesh.triangles.is_empty() {
        return Err(MeshError::NoSurface);
    }
    mesh.keep_largest_component();
    mesh.compute_vertex_normals();
    Ok(mesh)
}

/// Exact z-depth maps of a sphere seen by `cameras` (0 where the pixel-centre ray misses). Used by
/// the tests and the benchmark as ground truth that needs no renderer.
pub fn sphere_depth_maps(cameras: &[Camera], centre: DVec3, radius: f64) -> Vec<Vec<f64>> {
    cameras
        .par_iter()
        .map(|cam| {
            let (w, h) = (cam.width, cam.height);
            let o = cam.origin();
            let forward = cam.forward();
            let mut depth = vec![0.0; cam.num_pixels()];
            for j in 0..h {
                for i in 0..w {
                    let d = cam.pixel_dir(i, j);
                    let oc = o - centre;
                    let b = oc.dot(d);
                    let disc = b * b - (oc.length_squared() - radius * radius);
                    if disc >= 0.0 {
                        let s = -b - disc.sqrt();
                        if s > 0.0 {
                            depth[(j * w + i) as usize] = (s * d).dot(forward);
                        }
                    }
                }
            }
            depth
        })
        .collect()
}

/// Depth spread, in pixel footprints at the pixel's depth, that one surface seen at pixel
/// resolution may have (a tilted surface, overlapping surfels): trained models' pixels spread
/// 1.1–1.5 footprints at the median, 3.0–4.6 at the 90th percentile, 4.0–6.1 at the 95th (the
/// default models of the shared captures and the creature; the tail holds the mixed pixels).
pub const SURFACE_SPREAD_FOOTPRINTS: f64 = 4.0;

/// Standard deviation of the depths composited into a pixel, from its α-normalized mean `depth`
/// and second moment `depth_sq` (0 where rounding makes the variance negative).
pub fn depth_spread(depth: f64, depth_sq: f64) -> f64 {
    (depth_sq - depth * depth).max(0.0).sqrt()
}

/// A rendered depth map of `camera` prepared for fusion: the α-normalized `depth`, NaN
/// (unknown) where the surfaces composited into a pixel spread along its ray (their standard
/// deviation, from the α-normalized second moment `depth_sq`) by more than `truncation` and more
/// than [`SURFACE_SPREAD_FOOTPRINTS`] pixel footprints. Such a pixel blends a surface with what
/// lies behind it — the far wall seen through a sparse patch, or the background past an
/// occluding edge — and its mean depth lies on neither: fused, it would carve free space behind
/// the surface (an interior sheet in the mesh) or vote for a floating one.
pub fn fusion_depth(camera: &Camera, depth: &[f64], depth_sq: &[f64], truncation: f64) -> Vec<f64> {
    let per_depth = SURFACE_SPREAD_FOOTPRINTS / camera.fx.min(camera.fy);
    depth
        .iter()
        .zip(depth_sq)
        .map(|(&d, &d2)| {
            if depth_spread(d, d2) > truncation.max(per_depth * d) {
                f64::NAN
            } else {
                d
            }
        })
        .collect()
}

/// One [`DepthView`] per camera with the rendered `(depth, alpha)` maps of the same index.
pub fn rendered_depth_views<'a>(
    cameras: &'a [Camera],
    maps: &'a [(Vec<f64>, Vec<f64>)],
) -> Vec<DepthView<'a>> {
    cameras
        .iter()
        .zip(maps)
        .map(|(camera, (depth, alpha))| DepthView {
            camera,
            depth,
            alpha: Some(alpha),
        })
        .collect()
}

/// One [`DepthView`] per camera with the depth map of the same index, every view with `alpha`.
pub(crate) fn depth_views<'a>(
    cameras: &'a [Camera],
    depths: &'a [Vec<f64>],
    alpha: Option<&'a [f64]>,
) -> Vec<DepthView<'a>> {
    cameras
        .iter()
        .zip(depths)
        .map(|(camera, depth)| DepthView {
            camera,
            depth,
            alpha,
        })
        .collect()
}

/// A sphere of `radius` at the origin seen by cameras around it (40° field of view), with its exact
/// depth maps: the ground truth of the fusion tests and the extraction benchmark.
pub(crate) struct AnalyticSphere {
    pub radius: f64,
    pub cameras: Vec<Camera>,
    pub depths: Vec<Vec<f64>>,
}

impl AnalyticSphere {
    /// `views` cameras of `image_size`² pixels on a Fibonacci sphere of radius `distance`.
    pub fn new(radius: f64, views: usize, distance: f64, image_size: u32) -> Self {
        let cameras = cameras_around(views, distance, image_size, 40f64.to_radians());
        let depths = sphere_depth_maps(&cameras, DVec3::ZERO, radius);
        AnalyticSphere {
            radius,
            cameras,
            depths,
        }
    }

    /// The depth views to fuse, every one with `alpha`.
    pub fn views<'a>(&'a self, alpha: Option<&'a [f64]>) -> Vec<DepthView<'a>> {
        depth_views(&self.cameras, &self.depths, alpha)
    }

    /// Largest |‖v‖ − radius| over the vertices of `mesh`.
    pub fn worst_radial_error(&self, mesh: &TriangleMesh) -> f64 {
        mesh.vertices
            .iter()
            .map(|v| (DVec3::from_array(*v).length() - self.radius).abs())
            .fold(0.0, f64::max)
    }
}

/// `count` cameras on a Fibonacci sphere of radius `distance` around the origin, looking at it.
pub fn cameras_around(count: usize, distance: f64, size: u32, fov_x_rad: f64) -> Vec<Camera> {
    cameras_around_point(count, DVec3::ZERO, distance, size, fov_x_rad)
}

/// `count` square cameras of `size`² pixels on a Fibonacci sphere of radius `distance` around
/// `centre`, looking at it.
pub fn cameras_around_point(
    count: usize,
    centre: DVec3,
    distance: f64,
    size: u32,
    fov_x_rad: f64,
) -> Vec<Camera> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..count)
        .map(|n| {
            let z = 1.0 - 2.0 * (n as f64 + 0.5) / count as f64;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * n as f64;
            let eye = centre + distance * DVec3::new(r * phi.cos(), r * phi.sin(), z);
            let up = if z.abs() > 0.9 { DVec3::Y } else { DVec3::Z };
            Camera::look_at(size, size, fov_x_rad, eye, centre, up)
        })
        .collect()
}

/// Plain references for the fusion tests (here and the device's, `crate::gpu`).
#[cfg(test)]
pub(crate) mod reference {
    use super::*;

    /// Z-depth maps of a union of spheres (0 where every sphere is missed).
    pub(crate) fn spheres_depth(cameras: &[Camera], spheres: &[(DVec3, f64)]) -> Vec<Vec<f64>> {
        let per_sphere: Vec<Vec<Vec<f64>>> = spheres
            .iter()
            .map(|&(c, r)| sphere_depth_maps(cameras, c, r))
            .collect();
        (0..cameras.len())
            .map(|v| {
                (0..cameras[v].num_pixels())
                    .map(|p| {
                        per_sphere
                            .iter()
                            .map(|maps| maps[v][p])
                            .filter(|&d| d > 0.0)
                            .fold(0.0, |a: f64, d| if a == 0.0 { d } else { a.min(d) })
                    })
                    .collect()
            })
            .collect()
    }

    /// Marks rows 30–37 of every fourth view (views 2, 6, …) unknown (NaN depth): a band across
    /// surfaces, silhouettes and background that must give no vote.
    pub(crate) fn with_unknown_band(depths: &mut [Vec<f64>], width: usize) {
        for depth in depths.iter_mut().skip(2).step_by(4) {
            depth[30 * width..38 * width].fill(f64::NAN);
        }
    }

    /// Dense fusion written plainly from the rules in the module doc: every voxel, every view,
    /// `Camera::project`, raw depth pixels.
    pub(crate) fn dense_reference(
        views: &[DepthView],
        bounds: (DVec3, DVec3),
        params: &TsdfParams,
    ) -> ScalarGrid {
        let extent = bounds.1 - bounds.0;
        let voxel = extent.max_element() / params.resolution as f64;
        let dims = [0, 1, 2].map(|a| (extent[a] / voxel).ceil() as usize + 2 * MARGIN_VOXELS);
        let origin = bounds.0 - DVec3::splat((MARGIN_VOXELS as f64 - 0.5) * voxel);
        let trunc = params.truncation_voxels * voxel;
        let mut values = Vec::new();
        let mut known = Vec::new();
        for k in 0..dims[2] {
            for j in 0..dims[1] {
                for i in 0..dims[0] {
                    let p = origin + voxel * DVec3::new(i as f64, j as f64, k as f64);
                    let (mut sum, mut count) = (0.0, 0);
                    for view in views {
                        let cam = view.camera;
                        let (w, h) = (cam.width as usize, cam.height as usize);
                        let Some((u, v, z)) = cam.project(p) else {
                            continue;
                        };
                        if !(u >= 0.0 && u < w as f64 && v >= 0.0 && v < h as f64) {
                            continue;
                        }
                        let depth_at = |x: usize, y: usize| {
                            let d = view.depth[y * w + x];
                            let opaque = view.alpha.is_none_or(|a| a[y * w + x] >= 0.5);
                            if opaque && d.is_nan() {
                                f64::NAN
                            } else if opaque && d > 0.0 && d <= params.depth_max {
                                d
                            } else {
                                0.0
                            }
                        };
                        let (x, y) = ((u - 0.5).max(0.0), (v - 0.5).max(0.0));
                        let (x0, y0) = (x.floor() as usize, y.floor() as usize);
                        let (x1, y1) = ((x0 + 1).min(w - 1), (y0 + 1).min(h - 1));
                        let d = [
                            depth_at(x0, y0),
                            depth_at(x1, y0),
                            depth_at(x0, y1),
                            depth_at(x1, y1),
                        ];
                        if d.iter().any(|z| z.is_nan()) {
                            continue;
                        }
                        if d.iter().all(|&z| z == 0.0) {
                            sum += 1.0;
                            count += 1;
                            continue;
                        }
                        let spread = d.iter().copied().fold(0.0, f64::max)
                            - d.iter().copied().fold(f64::INFINITY, f64::min);
                        if d.contains(&0.0) || spread > trunc {
                            continue;
                        }
                        let d = d.map(|z| z as f32 as f64);
                        let (fx, fy) = ((x - x0 as f64).min(1.0), (y - y0 as f64).min(1.0));
                        let depth = (1.0 - fy) * ((1.0 - fx) * d[0] + fx * d[1])
                            + fy * ((1.0 - fx) * d[2] + fx * d[3]);
                        let sdf = depth - z;
                        if sdf >= -trunc {
                            sum += (sdf / trunc).min(1.0);
                            count += 1;
                        }
                    }
                    values.push(if count > 0 {
                        (sum / count as f64) as f32
                    } else {
                        0.0
                    });
                    known.push(count > 0);
                }
            }
        }
        ScalarGrid {
            dims,
            origin,
            spacing: voxel,
            values,
            known,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::reference::{dense_reference, spheres_depth, with_unknown_band};
    use super::*;
    use std::collections::HashMap;

    #[test]
    fn analytic_sphere_depth_fuses_into_a_closed_accurate_sphere() {
        let sphere = AnalyticSphere::new(0.8, 20, 3.0, 128);
        let views = sphere.views(None);
        let bounds = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let params = TsdfParams::automatic(64, &sphere.cameras, bounds);
        let mesh = extract_mesh(&views, bounds, &params).unwrap();
        let voxel = 2.0 / 64.0;
        let worst = sphere.worst_radial_error(&mesh);
        assert!(
            worst < 0.5 * voxel,
            "worst radial error {worst} (voxel {voxel})"
        );
        assert!(mesh.triangles.len() > 1000);
        let mut edges = HashMap::new();
        for t in &mesh.triangles {
            for e in 0..3 {
                let (a, b) = (t[e], t[(e + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        assert!(
            edges.values().all(|&n| n == 2),
            "an edge is not shared by exactly 2 triangles"
        );
        assert!(mesh.has_normals());
        for (v, n) in mesh.vertices.iter().zip(&mesh.normals) {
            let (v, n) = (DVec3::from_array(*v), DVec3::from_array(*n));
            assert!(
                n.dot(v.normalize()) > 0.9,
                "normal {n} at {v} is not outward"
            );
        }
    }

    #[test]
    fn background_alpha_carves_and_far_depth_is_ignored() {
        // A view whose alpha says "background everywhere" removes the surface its depth shows.
        let sphere = AnalyticSphere::new(0.5, 12, 3.0, 64);
        let transparent = vec![0.0; sphere.cameras[0].num_pixels()];
        let bounds = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let fused = |alpha: Option<&[f64]>| {
            fuse_tsdf(&sphere.views(alpha), bounds, &TsdfParams::new(32)).unwrap()
        };
        let solid = fused(None);
        // The voxel centre nearest (0.4, 0, 0) lies 0.09 inside the surface, within truncation.
        let index = |p: DVec3| {
            let [i, j, k] = ((p - solid.origin) / solid.spacing).round().to_array();
            (k as usize * solid.dims[1] + j as usize) * solid.dims[0] + i as usize
        };
        let inside = index(DVec3::new(0.4, 0.0, 0.0));
        assert!(solid.known[inside] && solid.values[inside] < -0.1);
        let outside = index(DVec3::new(0.8, 0.0, 0.0));
        assert!(solid.known[outside] && solid.values[outside] == 1.0);
        let carved = fused(Some(&transparent));
        assert!(carved
            .values
            .iter()
            .zip(&carved.known)
            .all(|(v, k)| !k || *v == 1.0));
        let views = sphere.views(None);
        let mut params = TsdfParams::new(32);
        params.depth_max = 1.0; // every sphere depth (≈ 2.5) is beyond it
        assert!(matches!(
            extract_mesh(&views, bounds, &params),
            Err(MeshError::NoSurface)
        ));
    }

    #[test]
    fn unknown_pixels_give_no_vote() {
        let sphere = AnalyticSphere::new(0.5, 12, 3.0, 64);
        let bounds = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let params = TsdfParams::new(32);
        let views = sphere.views(None);
        let unknown = vec![f64::NAN; sphere.cameras[0].num_pixels()];
        let mut with_unknown = views.clone();
        with_unknown[0].depth = &unknown;
        let (a, b) = (
            fuse_tsdf(&with_unknown, bounds, &params).unwrap(),
            fuse_tsdf(&views[1..], bounds, &params).unwrap(),
        );
        assert_eq!(a.known, b.known);
        assert!(a.known.iter().filter(|&&k| k).count() > 1000);
        assert!(a
            .values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| x.to_bits() == y.to_bits() || x.is_nan() && y.is_nan()));
    }

    #[test]
    fn depths_that_spread_beyond_the_limit_become_unknown() {
        // Focal length 100 px: four footprints are 0.04 units a unit of depth.
        let camera = cameras_around(1, 3.0, 100, 2.0 * 0.5f64.atan())[0];
        assert!((camera.fx - 100.0).abs() < 1e-9);
        let depth = [2.0, 2.0, 3.0, 0.0, 5.0, 5.0];
        // Spreads 0.01, 0.5, exactly 0.1, a background pixel, and 0.19 and 0.21 at a depth
        // where four footprints (0.2) exceed the truncation.
        let depth_sq = [
            4.0 + 1e-4,
            4.0 + 0.25,
            9.0 + 0.01,
            0.0,
            25.0 + 0.0361,
            25.0 + 0.0441,
        ];
        let fused = fusion_depth(&camera, &depth, &depth_sq, 0.1 + 1e-9);
        assert_eq!(fused[0], 2.0);
        assert!(fused[1].is_nan());
        assert_eq!(fused[2], 3.0);
        assert_eq!(fused[3], 0.0);
        assert_eq!(fused[4], 5.0);
        assert!(fused[5].is_nan());
    }

    #[test]
    fn mismatched_view_sizes_and_bad_parameters_are_reported() {
        let cameras = cameras_around(1, 3.0, 16, 0.7);
        let short = vec![1.0; 10];
        let views = [DepthView {
            camera: &cameras[0],
            depth: &short,
            alpha: None,
        }];
        let bounds = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let err = fuse_tsdf(&views, bounds, &TsdfParams::new(8)).unwrap_err();
        assert!(matches!(
            err,
            MeshError::ViewSize {
                view: 0,
                expected: 256,
                actual: 10,
                ..
            }
        ));
        let flat = (DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0));
        assert!(matches!(
            fuse_tsdf(&views, flat, &TsdfParams::new(8)),
            Err(MeshError::InvalidBounds { .. })
        ));
        assert!(matches!(
            fuse_tsdf(&[], bounds, &TsdfParams::new(8)),
            Err(MeshError::NoViews)
        ));
    }

    #[test]
    fn sparse_fusion_matches_a_dense_reference() {
        // Two overlapping spheres (occlusion edges, a concave crease) and a small far one; some
        // views carry an alpha map that hides part of the image, others a band of unknown pixels.
        let spheres = [
            (DVec3::new(-0.25, 0.0, 0.0), 0.5),
            (DVec3::new(0.35, 0.1, 0.05), 0.4),
            (DVec3::new(0.0, 0.0, 0.85), 0.1),
        ];
        let cameras = cameras_around(10, 3.0, 64, 40f64.to_radians());
        let mut depths = spheres_depth(&cameras, &spheres);
        with_unknown_band(&mut depths, 64);
        let alphas: Vec<Vec<f64>> = (0..cameras.len())
            .map(|v| {
                (0..64 * 64)
                    .map(|p| if v % 3 == 0 && p % 64 > 44 { 0.2 } else { 1.0 })
                    .collect()
            })
            .collect();
        let views: Vec<DepthView> = (0..cameras.len())
            .map(|v| DepthView {
                camera: &cameras[v],
                depth: &depths[v],
                alpha: (v % 3 == 0).then_some(alphas[v].as_slice()),
            })
            .collect();
        let bounds = (DVec3::new(-1.0, -0.8, -0.8), DVec3::new(1.0, 0.8, 1.0));
        let params = TsdfParams::automatic(40, &cameras, bounds);
        let fast = fuse_tsdf(&views, bounds, &params).unwrap();
        let reference = dense_reference(&views, bounds, &params);
        assert_eq!(fast.dims, reference.dims);
        let mut compared = 0;
        for idx in 0..fast.values.len() {
            if fast.known[idx] {
                assert!(reference.known[idx]);
                assert!(
                    (fast.values[idx] - reference.values[idx]).abs() < 1e-5,
                    "voxel {idx}"
                );
                compared += 1;
            } else if reference.known[idx] {
                assert!(
                    reference.values[idx] >= 0.0,
                    "voxel {idx} negative but not fused"
                );
            }
        }
        assert!(compared > 5000, "only {compared} voxels fused");
        let a = marching_cubes(&fast);
        let b = marching_cubes(&reference);
        assert!(a.triangles.len() > 500);
        assert_eq!(a.triangles, b.triangles);
        for (p, q) in a.vertices.iter().zip(&b.vertices) {
            assert!(DVec3::from_array(*p).distance(DVec3::from_array(*q)) < 1e-6);
        }
        // The far small sphere is its own component; extraction keeps only the big pair.
        let mesh = extract_mesh(&views, bounds, &params).unwrap();
        assert!(mesh.triangles.len() < a.triangles.len());
        assert!(mesh.vertices.iter().all(|v| v[2] < 0.6));
    }

    #[test]
    fn ground_truth_knot_depth_fuses_close_to_the_knot_mesh() {
        use crate::core::camera::{CameraConvention, Intrinsics};
        use glam::DMat4;
        let Some(shared) = crate::testing::shared_data_dir() else {
            return;
        };
        let data = shared.join("knot");
        let text = std::fs::read_to_string(data.join("transforms_train.json")).unwrap();
        let meta: serde_json::Value = serde_json::from_str(&text).unwrap();
        let number = |key: &str| meta[key].as_f64().unwrap();
        let intrinsics = Intrinsics {
            width: number("w") as u32,
            height: number("h") as u32,
            fx: number("fl_x"),
            fy: number("fl_y"),
            cx: number("cx"),
            cy: number("cy"),
        };
        let frames = meta["frames"].as_array().unwrap();
        let mut cameras = Vec::new();
        let mut depths = Vec::new();
        for frame in frames {
            let rows: Vec<Vec<f64>> =
                serde_json::from_value(frame["transform_matrix"].clone()).unwrap();
            let c2w =
                DMat4::from_cols_array_2d(&[0, 1, 2, 3].map(|c| [0, 1, 2, 3].map(|r| rows[r][c])));
            cameras.push(Camera::new(intrinsics, c2w, CameraConvention::OpenGL));
            let path = data.join(frame["depth_path"].as_str().unwrap());
            let (image, _) = crate::formats::image_io::read_image(&path).unwrap();
            depths.push(
                image
                    .data
                    .iter()
                    .step_by(image.channels)
                    .map(|&d| d as f64)
                    .collect::<Vec<f64>>(),
            );
        }
        let views = depth_views(&cameras, &depths, None);
        let bounds = (DVec3::splat(-1.1), DVec3::splat(1.1));
        let params = TsdfParams::automatic(128, &cameras, bounds);
        let mesh = extract_mesh(&views, bounds, &params).unwrap();
        let gt = TriangleMesh::read_ply(&data.join("mesh.ply")).unwrap();
        let voxel = 2.2 / 128.0;
        let forward = super::super::chamfer_l1_with(&mesh, &gt, 50_000, 0).unwrap();
        let backward = super::super::chamfer_l1_with(&gt, &mesh, 50_000, 0).unwrap();
        println!("knot: {} triangles, chamfer pred→gt {forward:.5}, gt→pred {backward:.5}, voxel {voxel:.5}", mesh.triangles.len());
        assert!(forward < 0.1 * voxel, "pred→gt {forward}");
        assert!(backward < 0.1 * voxel, "gt→pred {backward} (holes?)");
    }
}

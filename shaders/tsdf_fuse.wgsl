// TSDF fusion of rendered depth on the device (after common.wgsl), a port in f32 of the host's
// `core::mesh::tsdf` (its module doc states the rules). Two kernels, run per view:
//
// `prepare_depth` turns one band of the rasterizer's G-buffers into the view's cleaned depth map
// (`fusion_depth` and `PreparedView::new`): when only coherent pixels vote, a pixel with α ≥ 0.5
// whose composited depths spread (standard deviation, from the second moment) more than
// max_spread and spread_per_depth × depth is unknown (−1); else it keeps its z-depth where
// 0 < depth ≤ depth_max; every other pixel is background (0). One thread per pixel of the band.
//
// `fuse_view` adds the view's vote into every voxel's running sum and count (`BlockFrame::fuse`
// voxel by voxel): the voxel centre is projected; outside the image, or behind the camera, no
// vote. The four pixels around the projection (clamped at the last row and column) decide: any
// unknown → no vote; all background → +1 (free space); all surface with a depth spread ≤
// truncation → bilinear depth, sdf = depth − z, no vote when sdf < −truncation, else
// min(sdf / truncation, 1); any other mix → no vote. One thread per voxel (x fastest), one dispatch per view: each voxel has one thread per
// dispatch and dispatches run in order, so the sums need no atomics, and only one view's depth
// map is on the device at a time. 256-thread workgroups on a 2-D grid (`linear_index`).

struct DepthBand {
    // First pixel of the band in the view (row-major) and its pixel count.
    pixel_first: u32,
    pixels: u32,
    // Values per pixel of the G-buffers (α at 0, depth at 1, its second moment at 10).
    gbuf_stride: u32,
    // Depths beyond this are background (the largest f32 not above the host's limit).
    depth_max: f32,
    // 1 to trust only the coherent pixels (`DepthPixels::Coherent`), 0 for every pixel.
    coherent_only: u32,
    // Then a pixel whose depths spread more than both of these is unknown: the grid's
    // truncation, and SURFACE_SPREAD_FOOTPRINTS pixel footprints (this factor times its depth).
    max_spread: f32,
    spread_per_depth: f32,
    pad0: u32,
}

struct FuseView {
    // Camera-space (OpenCV) position of voxel (0, 0, 0), and the camera-space steps of one voxel
    // along the grid's x, y and z.
    base: vec4<f32>,
    step_x: vec4<f32>,
    step_y: vec4<f32>,
    step_z: vec4<f32>,
    // Focal lengths and principal point in pixels.
    fx: f32,
    fy: f32,
    cx: f32,
    cy: f32,
    // Image size in pixels.
    width: u32,
    height: u32,
    // Voxels along x, y and z.
    dims_x: u32,
    dims_y: u32,
    dims_z: u32,
    // Truncation distance (world units): of the sdf, and of the depth spread bilinear
    // interpolation may mix.
    truncation: f32,
    pad0: u32,
    pad1: u32,
}

@group(0) @binding(0) var<uniform> fuse: FuseView;
// The view's cleaned z-depth per pixel, row-major, 0 = background, −1 = unknown.
@group(0) @binding(1) var<storage, read> view_depth: array<f32>;
// Per voxel: the sum of the views' votes and their number.
@group(0) @binding(2) var<storage, read_write> tsdf_sum: array<f32>;
@group(0) @binding(3) var<storage, read_write> tsdf_count: array<u32>;
@group(0) @binding(4) var<uniform> depth_band: DepthBand;
// One band of the rasterizer's G-buffers (NUM_OUT values per pixel).
@group(0) @binding(5) var<storage, read> band_gbuf: array<f32>;
// The view's cleaned depth map, written band by band.
@group(0) @binding(6) var<storage, read_write> clean_depth: array<f32>;

@compute @workgroup_size(256)
fn prepare_depth(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let p = linear_index(gid, nwg);
    if p >= depth_band.pixels {
        return;
    }
    let alpha = band_gbuf[p * depth_band.gbuf_stride];
    let depth = band_gbuf[p * depth_band.gbuf_stride + 1u];
    let depth_sq = band_gbuf[p * depth_band.gbuf_stride + 10u];
    let spread = sqrt(max(depth_sq - depth * depth, 0.0));
    let surface = alpha >= 0.5 && depth > 0.0 && depth <= depth_band.depth_max;
    var clean = select(0.0, depth, surface);
    let spread_limit = max(depth_band.max_spread, depth_band.spread_per_depth * depth);
    if depth_band.coherent_only != 0u && alpha >= 0.5 && spread > spread_limit {
        clean = -1.0;
    }
    clean_depth[depth_band.pixel_first + p] = clean;
}

@compute @workgroup_size(256)
fn fuse_view(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let index = linear_index(gid, nwg);
    if index >= fuse.dims_x * fuse.dims_y * fuse.dims_z {
        return;
    }
    let i = index % fuse.dims_x;
    let j = (index / fuse.dims_x) % fuse.dims_y;
    let k = index / (fuse.dims_x * fuse.dims_y);
    let c = fuse.base.xyz + f32(i) * fuse.step_x.xyz + f32(j) * fuse.step_y.xyz
        + f32(k) * fuse.step_z.xyz;
    if c.z <= 1e-9 {
        return;
    }
    let inv_z = 1.0 / c.z;
    let u = fuse.fx * c.x * inv_z + fuse.cx;
    let v = fuse.fy * c.y * inv_z + fuse.cy;
    let w = fuse.width;
    if !(u >= 0.0 && u < f32(w) && v >= 0.0 && v < f32(fuse.height)) {
        return;
    }
    let x = max(u - 0.5, 0.0);
    let y = max(v - 0.5, 0.0);
    let x0 = u32(x);
    let y0 = u32(y);
    let x1 = min(x0 + 1u, w - 1u);
    let y1 = min(y0 + 1u, fuse.height - 1u);
    let d00 = view_depth[y0 * w + x0];
    let d10 = view_depth[y0 * w + x1];
    let d01 = view_depth[y1 * w + x0];
    let d11 = view_depth[y1 * w + x1];
    if min(min(d00, d10), min(d01, d11)) < 0.0 {
        return;
    }
    let surfaces = u32(d00 > 0.0) + u32(d10 > 0.0) + u32(d01 > 0.0) + u32(d11 > 0.0);
    let trunc = fuse.truncation;
    var tsdf = 1.0;
    if surfaces != 0u {
        let lo = min(min(d00, d10), min(d01, d11));
        let hi = max(max(d00, d10), max(d01, d11));
        if surfaces != 4u || hi - lo > trunc {
            return;
        }
        let fx = min(x - f32(x0), 1.0);
        let fy = min(y - f32(y0), 1.0);
        let top = d00 + fx * (d10 - d00);
        let bottom = d01 + fx * (d11 - d01);
        let sdf = top + fy * (bottom - top) - c.z;
        if sdf < -trunc {
            return;
        }
        tsdf = min(sdf / trunc, 1.0);
    }
    tsdf_sum[index] += tsdf;
    tsdf_count[index] += 1u;
}

// Per-surfel projection and culling (a port of `project` in src/raster/project.rs, in f32).
// Threading: one thread per surfel, 256-thread workgroups on a 2-D grid (see `linear_index`).
// Writes the surfel's `Proj` (rect empty when culled) and the number of 8×8 tiles its pixel box
// touches (0 when culled), which the host scans into the offsets of the binning pass.
// The box is the exact α-cut box of the cpu backend widened by one pixel on each side, so f32
// rounding of the conic extents cannot drop a pixel the cpu backend would draw.

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> raw: array<Raw>;
@group(0) @binding(2) var<storage, read_write> proj: array<Proj>;
@group(0) @binding(3) var<storage, read_write> tile_counts: array<u32>;

fn finite(v: f32) -> bool {
    return abs(v) <= BIG;
}

// Screen interval of the tangent lines of the conic with dual entries c00, c02, c22;
// z = 0 when unbounded.
fn conic_extent(c00: f32, c02: f32, c22: f32) -> vec3<f32> {
    if !(c22 < 0.0) {
        return vec3<f32>(0.0, 0.0, 0.0);
    }
    let disc = sqrt(max(c02 * c02 - c00 * c22, 0.0));
    let r0 = (c02 + disc) / c22;
    let r1 = (c02 - disc) / c22;
    if !(finite(r0) && finite(r1)) {
        return vec3<f32>(0.0, 0.0, 0.0);
    }
    return vec3<f32>(min(r0, r1), max(r0, r1), 1.0);
}

// First and one-past-last pixel whose centre lies in [lo, hi], clipped to [0, n].
fn pixel_span(lo: f32, hi: f32, n: u32) -> vec2<u32> {
    let nf = f32(n);
    let first = clamp(ceil(lo - 0.5), 0.0, nf);
    let last = clamp(floor(hi - 0.5) + 1.0, 0.0, nf);
    return vec2<u32>(u32(first), u32(last));
}

@compute @workgroup_size(256)
fn project(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = linear_index(gid, nwg);
    let prm = params;
    if i >= prm.surfels {
        return;
    }
    var out: Proj;
    out.rect = vec4<u32>(0u);
    proj[i] = out;
    tile_counts[i] = 0u;

    let r = raw[i];
    let alpha_min = prm.alpha_min;
    let opacity = sigmoid(r.pos_op.w);
    if !(opacity >= alpha_min) || opacity <= 0.0 {
        return;
    }
    let geo = geometry(r, prm);
    if !(geo.c.z > prm.near) {
        return;
    }
    let m0 = geo.m0;
    let m1 = geo.m1;
    let m2 = geo.m2;
    let qx = cross(m1, m2);
    let qy = cross(m2, m0);
    let qc = cross(m0, m1);
    let det = dot(m2, qc);
    let mean = vec2<f32>(
        prm.fx * geo.c.x / geo.c.z + prm.cx,
        prm.fy * geo.c.y / geo.c.z + prm.cy,
    );
    let normal = geo.normal_sign * geo.rot[2];
    let albedo = vec3<f32>(sigmoid(r.albedo.x), sigmoid(r.albedo.y), sigmoid(r.albedo.z));
    let roughness = sigmoid(r.scale_rough_ior.z);
    let ior = 1.3 + sigmoid(r.scale_rough_ior.w);

    var rho_cut = BIG;
    if alpha_min > 0.0 {
        rho_cut = min(2.0 * log(opacity / alpha_min), BIG);
    }
    out.q0 = vec4<f32>(qx.x, qy.x, qc.x, det);
    out.q1 = vec4<f32>(qx.y, qy.y, qc.y, geo.c.z);
    out.q2 = vec4<f32>(qx.z, qy.z, qc.z, rho_cut);
    out.mean_op = vec4<f32>(mean, opacity, 0.0);
    out.f0 = vec4<f32>(normal, albedo.x);
    out.f1 = vec4<f32>(albedo.y, albedo.z, roughness, ior);
    let all_finite = finite(qx.x) && finite(qx.y) && finite(qx.z) && finite(qy.x) && finite(qy.y)
        && finite(qy.z) && finite(qc.x) && finite(qc.y) && finite(qc.z) && finite(det)
        && finite(mean.x) && finite(mean.y) && finite(normal.x) && finite(normal.y)
        && finite(normal.z);
    if !all_finite {
        return;
    }

    // Box: the α-cut disc on the surfel plane (a projected conic) united with the low-pass disc.
    let w = prm.width;
    let h = prm.height;
    let radius = sqrt(rho_cut);
    var lo = vec2<f32>(0.0, 0.0);
    var hi = vec2<f32>(f32(w), f32(h));
    let d = vec3<f32>(1.0, 1.0, -1.0 / (radius * radius));
    let c22 = dot(m2 * d, m2);
    let ex = conic_extent(dot(m0 * d, m0), dot(m0 * d, m2), c22);
    let ey = conic_extent(dot(m1 * d, m1), dot(m1 * d, m2), c22);
    if ex.z != 0.0 && ey.z != 0.0 {
        lo = vec2<f32>(ex.x, ey.x);
        hi = vec2<f32>(ex.y, ey.y);
    }
    if prm.lowpass != 0u {
        let r2d = min(prm.lowpass_sigma_px * radius, BIG);
        lo = min(lo, mean - vec2<f32>(r2d));
        hi = max(hi, mean + vec2<f32>(r2d));
    }
    let sx = pixel_span(lo.x - 1.0, hi.x + 1.0, w);
    let sy = pixel_span(lo.y - 1.0, hi.y + 1.0, h);
    if sx.x >= sx.y || sy.x >= sy.y {
        return;
    }
    out.rect = vec4<u32>(sx.x, sy.x, sx.y, sy.y);
    proj[i] = out;
    let rows = band_tile_rows(out.rect, prm);
    tile_counts[i] = ((sx.y - 1u) / TILE + 1u - sx.x / TILE) * (rows.y - rows.x);
}

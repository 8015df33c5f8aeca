// The resident trainer's per-pixel G-buffer kernels (after train_common.wgsl and
// train_params.wgsl), ports of `ShadingInputs::new` (src/render.rs) and of `depth_normals` /
// `depth_normals_backward` (src/raster/mod.rs), in f32:
//   `prepare_pixels`        the shader's inputs (α-normalized normal and roughness, albedo and IoR,
//                           the surface point back-projected from the depth), whether the pixel is
//                           shaded, and the depth-derived normal;
//   `depth_normal_backward` the gradient on the central differences dx, dy of each pixel's depth
//                           normal, from the depth–normal loss's gradient on it;
//   `assemble_upstream`     the upstream gradient of every G-buffer for the rasterizer's backward
//                           pass: the loss terms', the shader's (shaded stages) and the depth
//                           normal's, gathered back onto the depth from the neighbours' dx, dy.
// Threading: one thread per pixel (train_common.wgsl).

// Per pixel NUM_OUT values: α, depth, normal (3), albedo (3), roughness, IoR, squared depth
// (α-normalized).
@group(0) @binding(1) var<storage, read> gbuf: array<f32>;
// Per pixel three vectors: (normal, roughness), (albedo, IoR), (surface point, 0).
@group(0) @binding(2) var<storage, read_write> shade_in: array<vec4<f32>>;
// Per pixel: 1 where the pixel is shaded.
@group(0) @binding(3) var<storage, read_write> active_pixels: array<u32>;
// Per pixel: the unit depth-derived world normal (zero where undefined).
@group(0) @binding(4) var<storage, read_write> depth_normal: array<vec4<f32>>;
// Per pixel 6 values: the depth–normal loss's gradients on the normal and on the depth normal,
// before the factor λ / (valid pixels).
@group(0) @binding(5) var<storage, read> dn_grad: array<f32>;
@group(0) @binding(6) var<storage, read> status: array<u32>;
// Per pixel 6 values: gradients on dx and dy.
@group(0) @binding(7) var<storage, read_write> gdxy: array<f32>;
// Per pixel NUM_OUT values: the loss terms' upstream gradient on the G-buffers (without the depth
// normal's and the shader's parts).
@group(0) @binding(8) var<storage, read> up_partial: array<f32>;
// Per pixel 8 values: the shader's gradients on the normal, albedo, roughness and IoR.
@group(0) @binding(9) var<storage, read> shade_grads: array<f32>;
// Per pixel NUM_OUT values: the rasterizer's upstream gradient.
@group(0) @binding(10) var<storage, read_write> upstream: array<f32>;

fn alpha_at(p: u32) -> f32 {
    return gbuf[p * NUM_OUT];
}

fn depth_at(p: u32) -> f32 {
    return gbuf[p * NUM_OUT + 1u];
}

// Whether pixel p's depth normal is defined: interior, itself and its 4 neighbours covered.
fn depth_normal_defined(p: u32) -> bool {
    let w = train.width;
    let i = p % w;
    let j = p / w;
    if i < 1u || j < 1u || i + 1u >= w || j + 1u >= train.height {
        return false;
    }
    let eps = train.normalize_alpha_min;
    return alpha_at(p) > eps && alpha_at(p - 1u) > eps && alpha_at(p + 1u) > eps
        && alpha_at(p - w) > eps && alpha_at(p + w) > eps;
}

// Intermediates of one pixel's depth normal (`DepthNormalPixel`); `len` is 0 where undefined.
struct DepthNormal {
    dx: vec3<f32>,
    dy: vec3<f32>,
    v: vec3<f32>,
    sign: f32,
    len: f32,
}

fn depth_normal_at(p: u32) -> DepthNormal {
    var d: DepthNormal;
    d.len = 0.0;
    if !depth_normal_defined(p) {
        return d;
    }
    let w = train.width;
    d.dx = camera_dir(p + 1u) * depth_at(p + 1u) - camera_dir(p - 1u) * depth_at(p - 1u);
    d.dy = camera_dir(p + w) * depth_at(p + w) - camera_dir(p - w) * depth_at(p - w);
    let c = cross(d.dx, d.dy);
    d.sign = select(1.0, -1.0, dot(c, camera_dir(p)) > 0.0);
    d.v = d.sign * c;
    let len = length(d.v);
    if len > 1e-30 && len < BIG_F {
        d.len = len;
    }
    return d;
}

@compute @workgroup_size(THREADS)
fn prepare_pixels(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let p = pixel_index(gid, nwg);
    if p >= train.pixels {
        return;
    }
    let o = p * NUM_OUT;
    let depth = gbuf[o + 1u];
    let position = train.origin.xyz + to_world(camera_dir(p) * depth);
    shade_in[3u * p] = vec4<f32>(gbuf[o + 2u], gbuf[o + 3u], gbuf[o + 4u], gbuf[o + 8u]);
    shade_in[3u * p + 1u] = vec4<f32>(gbuf[o + 5u], gbuf[o + 6u], gbuf[o + 7u], gbuf[o + 9u]);
    shade_in[3u * p + 2u] = vec4<f32>(position, 0.0);
    active_pixels[p] = u32(gbuf[o] > train.shade_alpha_min);
    let d = depth_normal_at(p);
    var n = vec3<f32>(0.0);
    if d.len > 0.0 {
        n = to_world(d.v / d.len);
    }
    depth_normal[p] = vec4<f32>(n, 0.0);
}

// λ_depth_normal / (pixels where the depth–normal loss is defined), 0 when there are none.
fn depth_normal_scale() -> f32 {
    let count = bitcast<f32>(status[SUM_FIRST + SLOT_DEPTH_NORMAL_COUNT]);
    if count > 0.0 {
        return train.lambda_depth_normal / count;
    }
    return 0.0;
}

@compute @workgroup_size(THREADS)
fn depth_normal_backward(
    @builtin(global_invocation_id) gid: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
) {
    let p = pixel_index(gid, nwg);
    if p >= train.pixels {
        return;
    }
    var gdx = vec3<f32>(0.0);
    var gdy = vec3<f32>(0.0);
    let g = depth_normal_scale() * vec3<f32>(dn_grad[6u * p + 3u], dn_grad[6u * p + 4u], dn_grad[6u * p + 5u]);
    if any(g != vec3<f32>(0.0)) {
        let d = depth_normal_at(p);
        if d.len > 0.0 {
            let gc = to_camera(g);
            let n = d.v / d.len;
            let gv = d.sign * (gc - n * dot(n, gc)) / d.len;
            gdx = cross(d.dy, gv);
            gdy = cross(gv, d.dx);
        }
    }
    let o = 6u * p;
    gdxy[o] = gdx.x;
    gdxy[o + 1u] = gdx.y;
    gdxy[o + 2u] = gdx.z;
    gdxy[o + 3u] = gdy.x;
    gdxy[o + 4u] = gdy.y;
    gdxy[o + 5u] = gdy.z;
}

fn gdx_at(p: u32) -> vec3<f32> {
    return vec3<f32>(gdxy[6u * p], gdxy[6u * p + 1u], gdxy[6u * p + 2u]);
}

fn gdy_at(p: u32) -> vec3<f32> {
    return vec3<f32>(gdxy[6u * p + 3u], gdxy[6u * p + 4u], gdxy[6u * p + 5u]);
}

@compute @workgroup_size(THREADS)
fn assemble_upstream(
    @builtin(global_invocation_id) gid: vec3<u32>,
    @builtin(num_workgroups) nwg: vec3<u32>,
) {
    let p = pixel_index(gid, nwg);
    if p >= train.pixels {
        return;
    }
    let w = train.width;
    let i = p % w;
    let j = p / w;
    // dx(i, j) = P(i+1, j) − P(i−1, j): P(i, j) receives +gdx(i−1, j) − gdx(i+1, j).
    var gp = vec3<f32>(0.0);
    if i >= 1u {
        gp += gdx_at(p - 1u);
    }
    if i + 1u < w {
        gp -= gdx_at(p + 1u);
    }
    if j >= 1u {
        gp += gdy_at(p - w);
    }
    if j + 1u < train.height {
        gp -= gdy_at(p + w);
    }
    var up: array<f32, NUM_OUT>;
    for (var k = 0u; k < NUM_OUT; k++) {
        up[k] = up_partial[NUM_OUT * p + k];
    }
    up[1] += dot(camera_dir(p), gp);
    let scale = depth_normal_scale();
    for (var k = 0u; k < 3u; k++) {
        up[2u + k] += scale * dn_grad[6u * p + k];
    }
    if train.shaded != 0u && active_pixels[p] != 0u {
        // The shader's gradients: normal (3), albedo (3), roughness, IoR.
        for (var k = 0u; k < 8u; k++) {
            up[2u + k] += shade_grads[8u * p + k];
        }
    }
    for (var k = 0u; k < NUM_OUT; k++) {
        upstream[NUM_OUT * p + k] = up[k];
    }
}

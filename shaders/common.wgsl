// Shared definitions of the rasterizer kernels: the uniform parameters, the buffer layouts and the
// per-pixel evaluation of one projected surfel (a port of `evaluate` in src/raster/cpu.rs, in f32).
// No bindings and no entry points: every rasterizer kernel is compiled with this file first (the
// files of each kernel, in order, are listed in src/gpu/shaders.rs), so the forward and backward
// passes evaluate (and skip) exactly the same (pixel, surfel) pairs.

// Tile edge in pixels; the rasterization kernels run one 8×8 workgroup per tile.
const TILE: u32 = 8u;
// Per-surfel gradient accumulators: Q (9), det, mean (2), opacity, features (8), view depth.
const NUM_ACC: u32 = 22u;
// Per-pixel values of the forward output: α, depth, normal (3), albedo (3), roughness, IoR,
// squared depth (train_common.wgsl repeats it for the trainer's kernels).
const NUM_OUT: u32 = 11u;
// Finite stand-in for +∞ (WGSL has no infinity literal).
const BIG: f32 = 3.0e38;

struct Params {
    // World-to-camera rotation (columns) and translation, OpenCV axes.
    rot0: vec4<f32>,
    rot1: vec4<f32>,
    rot2: vec4<f32>,
    trans: vec4<f32>,
    // Camera centre in world coordinates.
    origin: vec4<f32>,
    // Focal lengths and principal point in pixels.
    fx: f32,
    fy: f32,
    cx: f32,
    cy: f32,
    // Image size in pixels and in tiles.
    width: u32,
    height: u32,
    tiles_x: u32,
    tiles_y: u32,
    // Surfels to project; the screen-space low-pass filter on (1) or off (0).
    surfels: u32,
    pad0: u32,
    pad1: u32,
    lowpass: u32,
    // Projection and compositing thresholds (RasterSettings).
    near: f32,
    alpha_min: f32,
    alpha_max: f32,
    transmittance_min: f32,
    // The screen-space low-pass filter's σ in pixels, and 1/σ² (0 when the filter is off).
    lowpass_sigma_px: f32,
    inv_lowpass_sigma2: f32,
    // ε of the α-normalization of the G-buffers.
    normalize_alpha_min: f32,
    pad2: f32,
    // The band of tile rows being rasterized (large images are split into bands): its tile rows
    // [band_tile_first, band_tile_end), its first pixel row and its pixel rows. Per-pixel
    // buffers and tile ranges hold the band only, indexed from its first row.
    band_tile_first: u32,
    band_tile_end: u32,
    band_pixel_first: u32,
    band_pixel_rows: u32,
}

// Raw (unactivated) surfel parameters.
struct Raw {
    // position xyz, opacity logit
    pos_op: vec4<f32>,
    // quaternion (w, x, y, z), not normalized
    quat: vec4<f32>,
    // log scale u, log scale v, roughness logit, IoR logit
    scale_rough_ior: vec4<f32>,
    // albedo logits rgb, unused
    albedo: vec4<f32>,
}

// A surfel projected into the camera (`Projected` of src/raster/project.rs).
struct Proj {
    // Rows of Q = adj(M) in xyz; w: det(M), centre view depth, ρ cut.
    q0: vec4<f32>,
    q1: vec4<f32>,
    q2: vec4<f32>,
    // projected centre (pixels), activated opacity, unused
    mean_op: vec4<f32>,
    // features: normal facing the camera (3), albedo (3), roughness, IoR
    f0: vec4<f32>,
    f1: vec4<f32>,
    // pixel box [x0, y0, x1, y1); empty (x0 == x1) when the surfel is culled
    rect: vec4<u32>,
}

// One projected surfel evaluated at one pixel centre.
struct Hit {
    ok: bool,
    alpha: f32,
    // Gaussian weight G
    g: f32,
    // α hit the alpha_max clamp
    clamped: bool,
    // ρ came from the surfel plane (else from the screen-space low-pass filter)
    use3d: bool,
    s: f32,
    t: f32,
    inv: f32,
    px: f32,
    py: f32,
    z: f32,
    dx: f32,
    dy: f32,
}

// The tile rows [lo, hi) of pixel box `r` inside the band (lo == hi when it misses the band).
fn band_tile_rows(r: vec4<u32>, prm: Params) -> vec2<u32> {
    let lo = max(r.y / TILE, prm.band_tile_first);
    let hi = min((r.w - 1u) / TILE + 1u, prm.band_tile_end);
    return vec2<u32>(lo, max(lo, hi));
}

fn rect_contains(r: vec4<u32>, x: u32, y: u32) -> bool {
    return x >= r.x && x < r.z && y >= r.y && y < r.w;
}

// Evaluates surfel `p` at pixel centre (x, y); `ok` is false when the pair is skipped
// (intersection not beyond `near`, α < alpha_min, outside the α cut).
fn evaluate(p: Proj, x: f32, y: f32, prm: Params) -> Hit {
    var h: Hit;
    h.ok = false;
    let px = p.q0.x * x + p.q0.y * y + p.q0.z;
    let py = p.q1.x * x + p.q1.y * y + p.q1.z;
    let pz = p.q2.x * x + p.q2.y * y + p.q2.z;
    let dx = x - p.mean_op.x;
    let dy = y - p.mean_op.y;
    let rho_cut = p.q2.w;
    var rho2 = BIG;
    if prm.lowpass != 0u {
        rho2 = (dx * dx + dy * dy) * prm.inv_lowpass_sigma2;
    }
    // ρ_3d = (px² + py²) / pz² within the cut, tested without the division.
    let num = px * px + py * py;
    let in3d = pz != 0.0 && num <= rho_cut * (pz * pz);
    if !in3d && !(rho2 <= rho_cut) {
        return h;
    }
    var use3d = false;
    var rho = rho2;
    var inv = 0.0;
    var s = 0.0;
    var t = 0.0;
    if in3d {
        inv = 1.0 / pz;
        s = px * inv;
        t = py * inv;
        let rho3 = s * s + t * t;
        if rho3 <= rho2 {
            use3d = true;
            rho = rho3;
        }
    }
    if !(rho <= rho_cut) {
        return h;
    }
    // Depth: the ray–plane intersection, or the centre's depth where the filter wins.
    var z = p.q1.w;
    if use3d {
        z = p.q0.w * inv;
        if !(z > prm.near && z < BIG) {
            return h;
        }
    }
    let g = exp(-0.5 * rho);
    let oa = p.mean_op.z * g;
    let clamped = oa > prm.alpha_max;
    let alpha = select(oa, prm.alpha_max, clamped);
    if alpha < prm.alpha_min {
        return h;
    }
    h.ok = true;
    h.alpha = alpha;
    h.g = g;
    h.clamped = clamped;
    h.use3d = use3d;
    h.s = s;
    h.t = t;
    h.inv = inv;
    h.px = px;
    h.py = py;
    h.z = z;
    h.dx = dx;
    h.dy = dy;
    return h;
}

fn sigmoid(x: f32) -> f32 {
    return 1.0 / (1.0 + exp(-x));
}

// Rotation matrix (columns t_u, t_v, normal) of a unit quaternion (w, x, y, z).
fn rotation_from_unit(q: vec4<f32>) -> mat3x3<f32> {
    let w = q.x;
    let x = q.y;
    let y = q.z;
    let z = q.w;
    return mat3x3<f32>(
        vec3<f32>(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)),
        vec3<f32>(2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x)),
        vec3<f32>(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)),
    );
}

// Intermediate values of the projection of one surfel, shared by the projection and its backward.
struct Geometry {
    q_norm: f32,
    q_unit: vec4<f32>,
    rot: mat3x3<f32>,
    scale: vec2<f32>,
    // Camera-space scaled tangent axes and centre.
    a: vec3<f32>,
    b: vec3<f32>,
    c: vec3<f32>,
    // Rows of M = K [a b c].
    m0: vec3<f32>,
    m1: vec3<f32>,
    m2: vec3<f32>,
    // +1 when the surfel normal already faces the camera, else −1.
    normal_sign: f32,
}

fn geometry(r: Raw, prm: Params) -> Geometry {
    var geo: Geometry;
    let p = r.pos_op.xyz;
    geo.q_norm = length(r.quat);
    geo.q_unit = r.quat / geo.q_norm;
    geo.rot = rotation_from_unit(geo.q_unit);
    geo.scale = exp(r.scale_rough_ior.xy);
    let cam_rot = mat3x3<f32>(prm.rot0.xyz, prm.rot1.xyz, prm.rot2.xyz);
    geo.a = geo.scale.x * (cam_rot * geo.rot[0]);
    geo.b = geo.scale.y * (cam_rot * geo.rot[1]);
    geo.c = cam_rot * p + prm.trans.xyz;
    geo.m2 = vec3<f32>(geo.a.z, geo.b.z, geo.c.z);
    geo.m0 = prm.fx * vec3<f32>(geo.a.x, geo.b.x, geo.c.x) + prm.cx * geo.m2;
    geo.m1 = prm.fy * vec3<f32>(geo.a.y, geo.b.y, geo.c.y) + prm.cy * geo.m2;
    geo.normal_sign = select(1.0, -1.0, dot(geo.rot[2], p - prm.origin.xyz) > 0.0);
    return geo;
}

// Index of a 1-D invocation laid out on a 2-D grid of 256-thread workgroups (a dispatch has at
// most 65535 workgroups per dimension).
fn linear_index(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.x + gid.y * nwg.x * 256u;
}

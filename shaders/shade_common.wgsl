// PolarDR shading of one pixel (a port of `forward` in src/shading/mod.rs, in f32): the BRDF
// table, and lookups in the global environment light (the prefiltered specular mip chain and the
// irradiance map(s) of a `PreparedEnv`). The light a pixel sees comes from `light_point` (what the
// light needs of the surface point, found once per pixel), `light_specular` and
// `light_irradiance`, defined by the light file compiled with this one (light_global.wgsl, or
// light_gridmap.wgsl for GridMap's local probes). Shared by shade.wgsl (forward) and
// shade_backward.wgsl; no entry points. Threading: one thread per pixel of the current chunk of
// the image, 256 per workgroup, on a 2-D grid of workgroups (`linear_index`).

const GROUP: u32 = 256u;
// The cpu clamps μ = n·o below at this value (`MIN_COS_VIEW`).
const MIN_COS_VIEW: f32 = 1e-4;
// Most IoR nodes of Fresnel-weighted irradiance maps (FRESNEL_IRRADIANCE_IORS has 5).
const MAX_IORS: u32 = 8u;

struct ShadeParams {
    // Camera-to-world rotation (columns: the OpenCV right, down, forward axes).
    rot0: vec4<f32>,
    rot1: vec4<f32>,
    rot2: vec4<f32>,
    // The camera's up vector (Stokes frames are built from it).
    up: vec4<f32>,
    // Focal lengths and principal point in pixels.
    fx: f32,
    fy: f32,
    cx: f32,
    cy: f32,
    // Image width, the first pixel of this chunk and its pixel count; BRDF table cells per axis.
    width: u32,
    first_pixel: u32,
    pixels: u32,
    lut_size: u32,
    // The light's layout: mip levels, irradiance maps, the first irradiance texel in `light`, the
    // first BRDF table value in `light`.
    levels: u32,
    irradiance_maps: u32,
    irradiance_offset: u32,
    lut_offset: u32,
    // Roughness of level 0 and of the second-to-last level; IoR nodes (irradiance maps blended
    // by IoR, `iors`).
    min_roughness: f32,
    max_roughness: f32,
    ior_nodes: u32,
    pad0: u32,
    // IoR of each irradiance map (Fresnel-weighted irradiance), 4 per vector.
    iors: array<vec4<f32>, 2>,
    // GridMap only: anchors, f32 values per probe, BVH nodes; the start offset of the mirror ray.
    grid_anchors: u32,
    grid_probe_values: u32,
    grid_nodes: u32,
    pad1: u32,
    grid_ray_offset: f32,
    pad2: f32,
    pad3: f32,
    pad4: f32,
}

@group(0) @binding(0) var<uniform> params: ShadeParams;
// RGB texels of every mip level (finest first), then of every irradiance map, then the BRDF
// table's A and B values (`j · size + i`).
@group(0) @binding(1) var<storage, read> light: array<f32>;
// Per mip level (4 values each): face size, first texel in `light`, first entry of its border
// table in `tables`, unused; then the border tables (`CubeGrid::border_table`).
@group(0) @binding(2) var<storage, read> tables: array<u32>;
// Per pixel of the chunk, three vectors: (raw normal, roughness), (albedo, IoR), (surface point, 0).
@group(0) @binding(3) var<storage, read> pixels: array<vec4<f32>>;
// Per pixel of the chunk: 1 where the pixel is shaded.
@group(0) @binding(4) var<storage, read> active_pixels: array<u32>;

fn linear_index(gid: vec3<u32>, groups: vec3<u32>) -> u32 {
    return gid.x + gid.y * groups.x * GROUP;
}

// A value with its derivatives in μ and η: (v, d/dμ, d/dη).
fn dmul(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(a.x * b.x, a.y * b.x + a.x * b.y, a.z * b.x + a.x * b.z);
}

fn ddiv(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    let inv = 1.0 / b.x;
    let v = a.x * inv;
    return vec3<f32>(v, (a.y - v * b.y) * inv, (a.z - v * b.z) * inv);
}

fn dsqrt(a: vec3<f32>) -> vec3<f32> {
    let v = sqrt(a.x);
    let k = 0.5 / v;
    return vec3<f32>(v, a.y * k, a.z * k);
}

// (x − y)/(x + y), zero when both vanish.
fn contrast(x: vec3<f32>, y: vec3<f32>) -> vec3<f32> {
    let sum = x + y;
    if abs(sum.x) < 1e-30 {
        return vec3<f32>(0.0);
    }
    return ddiv(x - y, sum);
}

struct Ratios {
    // ρ_s = R⁻/R⁺ and ρ_d = T⁻/T⁺, each (v, d/dμ, d/dη).
    spec: vec3<f32>,
    diff: vec3<f32>,
}

// Fresnel polarization ratios at cos θ = μ and index η (`polarization_ratios`).
fn polarization_ratios(mu: f32, eta: f32) -> Ratios {
    let m = vec3<f32>(mu, 1.0, 0.0);
    let e = vec3<f32>(eta, 0.0, 1.0);
    let one = vec3<f32>(1.0, 0.0, 0.0);
    let sin2_t = ddiv(one - dmul(m, m), dmul(e, e));
    var cos_t = vec3<f32>(1e-15, 0.0, 0.0);
    if 1.0 - sin2_t.x > 1e-30 {
        cos_t = dsqrt(one - sin2_t);
    }
    let ect = dmul(e, cos_t);
    let em = dmul(e, m);
    let rs = ddiv(m - ect, m + ect);
    let rp = ddiv(cos_t - em, cos_t + em);
    let a = ect + m;
    let b = em + cos_t;
    return Ratios(
        contrast(dmul(rs, rs), dmul(rp, rp)),
        contrast(dmul(b, b), dmul(a, a)),
    );
}

struct Azimuth {
    cos2: f32,
    sin2: f32,
    // [d/da, d/db] of cos 2φ and sin 2φ.
    dcos2: vec2<f32>,
    dsin2: vec2<f32>,
}

// cos 2φ, sin 2φ of the normal's azimuth from a = n·x̂, b = n·ŷ (`double_azimuth`).
fn double_azimuth(a: f32, b: f32) -> Azimuth {
    let q = a * a + b * b;
    if q < 1e-24 {
        return Azimuth(0.0, 0.0, vec2<f32>(0.0), vec2<f32>(0.0));
    }
    let q2 = q * q;
    return Azimuth(
        (a * a - b * b) / q,
        2.0 * a * b / q,
        vec2<f32>(4.0 * a * b * b / q2, -4.0 * a * a * b / q2),
        vec2<f32>(2.0 * b * (b * b - a * a) / q2, 2.0 * a * (a * a - b * b) / q2),
    );
}

struct LutSample {
    // A, B and their derivatives: (value, d/dμ, d/dr).
    a: vec3<f32>,
    b: vec3<f32>,
}

// One axis of the BRDF table: (first cell, fraction, d fraction / d coordinate).
fn lut_axis(v: f32, n: u32) -> vec3<f32> {
    let x = v * f32(n) - 0.5;
    let clamped = clamp(x, 0.0, f32(n - 1u));
    let i0 = min(floor(clamped), f32(n - 2u));
    var scale = 0.0;
    if x == clamped {
        scale = f32(n);
    }
    return vec3<f32>(i0, clamped - i0, scale);
}

fn lut_bilinear(base: u32, n: u32, mu_axis: vec3<f32>, r_axis: vec3<f32>) -> vec3<f32> {
    let i0 = u32(mu_axis.x);
    let j0 = u32(r_axis.x);
    let fx = mu_axis.y;
    let fy = r_axis.y;
    let v00 = light[base + j0 * n + i0];
    let v10 = light[base + j0 * n + i0 + 1u];
    let v01 = light[base + (j0 + 1u) * n + i0];
    let v11 = light[base + (j0 + 1u) * n + i0 + 1u];
    let value = (v00 * (1.0 - fx) + v10 * fx) * (1.0 - fy) + (v01 * (1.0 - fx) + v11 * fx) * fy;
    let d_mu = ((v10 - v00) * (1.0 - fy) + (v11 - v01) * fy) * mu_axis.z;
    let d_r = ((v01 - v00) * (1.0 - fx) + (v11 - v10) * fx) * r_axis.z;
    return vec3<f32>(value, d_mu, d_r);
}

// `BrdfLut::lookup_with_grad`.
fn lut_lookup(mu: f32, roughness: f32) -> LutSample {
    let n = params.lut_size;
    let mu_axis = lut_axis(mu, n);
    let r_axis = lut_axis(roughness, n);
    let base = params.lut_offset;
    return LutSample(
        lut_bilinear(base, n, mu_axis, r_axis),
        lut_bilinear(base + n * n, n, mu_axis, r_axis),
    );
}

// The four bilinear taps of a cube-map lookup: texel indices within `light`, weights, and the
// gradient of each weight with respect to the (unnormalized) direction.
struct Taps {
    texel: vec4<u32>,
    weight: vec4<f32>,
    grad: array<vec3<f32>, 4>,
}

// `CubeGrid::taps_with_grad` on mip level `level`, reading texels from `first` on (a level's own
// texels, or an irradiance map on the coarsest level's grid).
fn cube_taps(level: u32, first: u32, dir: vec3<f32>) -> Taps {
    let size = tables[level * 4u];
    let border = tables[level * 4u + 2u];
    // Face selection and face coordinates (`dir_to_face_uv_with_grad`).
    let a = abs(dir);
    var face = 0u;
    var major = 0u;
    var u_axis = 2u;
    var v_axis = 1u;
    var major_sign = 1.0;
    var u_sign = -1.0;
    var v_sign = -1.0;
    if a.x >= a.y && a.x >= a.z {
        if dir.x < 0.0 {
            face = 1u;
            major_sign = -1.0;
            u_sign = 1.0;
        }
    } else if a.y >= a.z {
        major = 1u;
        u_axis = 0u;
        v_axis = 2u;
        u_sign = 1.0;
        face = 2u;
        v_sign = 1.0;
        if dir.y < 0.0 {
            face = 3u;
            major_sign = -1.0;
            v_sign = -1.0;
        }
    } else {
        major = 2u;
        u_axis = 0u;
        v_axis = 1u;
        face = 4u;
        u_sign = 1.0;
        if dir.z < 0.0 {
            face = 5u;
            major_sign = -1.0;
            u_sign = -1.0;
        }
    }
    let m = major_sign * dir[major];
    let u = u_sign * dir[u_axis] / m;
    let v = v_sign * dir[v_axis] / m;
    var du = vec3<f32>(0.0);
    du[u_axis] = u_sign / m;
    du[major] = -u / dir[major];
    var dv = vec3<f32>(0.0);
    dv[v_axis] = v_sign / m;
    dv[major] = -v / dir[major];

    let s = f32(size);
    let dcx = du * (0.5 * s);
    let dcy = dv * (0.5 * s);
    let cx = clamp((u + 1.0) * 0.5 * s - 0.5, -0.5, s - 0.5);
    let cy = clamp((v + 1.0) * 0.5 * s - 0.5, -0.5, s - 0.5);
    let x0 = min(i32(floor(cx)), i32(size) - 1);
    let y0 = min(i32(floor(cy)), i32(size) - 1);
    let fx = cx - f32(x0);
    let fy = cy - f32(y0);
    // Border table over padded coordinates [−1, D]²: continues each face across its edges.
    let p = size + 2u;
    let row0 = border + (face * p + u32(y0 + 1)) * p + u32(x0 + 1);
    let row1 = row0 + p;
    var taps: Taps;
    taps.texel = vec4<u32>(tables[row0], tables[row0 + 1u], tables[row1], tables[row1 + 1u])
        + vec4<u32>(first);
    taps.weight = vec4<f32>((1.0 - fx) * (1.0 - fy), fx * (1.0 - fy), (1.0 - fx) * fy, fx * fy);
    taps.grad[0] = -dcx * (1.0 - fy) - dcy * (1.0 - fx);
    taps.grad[1] = dcx * (1.0 - fy) - dcy * fx;
    taps.grad[2] = -dcx * fy + dcy * (1.0 - fx);
    taps.grad[3] = dcx * fy + dcy * fx;
    return taps;
}

fn texel_rgb(t: u32) -> vec3<f32> {
    return vec3<f32>(light[t * 3u], light[t * 3u + 1u], light[t * 3u + 2u]);
}

fn sample_taps(taps: Taps) -> vec3<f32> {
    var sum = vec3<f32>(0.0);
    for (var k = 0u; k < 4u; k++) {
        sum += taps.weight[k] * texel_rgb(taps.texel[k]);
    }
    return sum;
}

// `level_blend`: (first level, weight of the next, d weight / d roughness).
fn level_blend(roughness: f32) -> vec3<f32> {
    let n = params.levels;
    let second_last = f32(n - 2u);
    let r_min = params.min_roughness;
    let r_max = params.max_roughness;
    var level = 0.0;
    var dlevel = 0.0;
    if roughness < r_max {
        if roughness > r_min {
            dlevel = second_last / (r_max - r_min);
            level = (roughness - r_min) * dlevel;
        }
    } else if roughness >= 1.0 {
        level = second_last + 1.0;
    } else {
        dlevel = 1.0 / (1.0 - r_max);
        level = (roughness - r_max) * dlevel + second_last;
    }
    let l0 = min(floor(level), second_last);
    return vec3<f32>(l0, level - l0, dlevel);
}

fn level_first(level: u32) -> u32 {
    return tables[level * 4u + 1u];
}

// Prefiltered radiance along `dir` (`PreparedEnv::specular`).
fn specular_light(dir: vec3<f32>, roughness: f32) -> vec3<f32> {
    let blend = level_blend(roughness);
    let l0 = u32(blend.x);
    let a = sample_taps(cube_taps(l0, level_first(l0), dir));
    let b = sample_taps(cube_taps(l0 + 1u, level_first(l0 + 1u), dir));
    return a * (1.0 - blend.y) + b * blend.y;
}

fn ior_node(k: u32) -> f32 {
    return params.iors[k / 4u][k % 4u];
}

struct IrradianceBlend {
    a: u32,
    b: u32,
    t: f32,
    dt: f32,
}

// `PrefilterPlan::irradiance_blend`: maps a and b, weight of b, d weight / d IoR. No loop bound
// (nor branch) depends on the uniform block alone: lavapipe (Mesa 22) recompiled the kernel at
// every dispatch to inline such a bound, and a dispatch then cost a compile (≈1 s).
fn irradiance_blend(ior: f32) -> IrradianceBlend {
    let nodes = params.ior_nodes;
    // The segment [k, k + 1] holding the IoR: the inner nodes at or below it (nodes ascend).
    var k = 0u;
    for (var i = 1u; i + 1u < MAX_IORS; i++) {
        k += select(0u, 1u, i + 1u < nodes && ior_node(i) <= ior);
    }
    let span = ior_node(k + 1u) - ior_node(k);
    let t = (ior - ior_node(k)) / span;
    let outside = t <= 0.0 || t >= 1.0;
    let weight = select(select(t, 1.0, t >= 1.0), 0.0, t <= 0.0);
    // A single map (or none): nothing to blend.
    let single = nodes < 2u;
    return IrradianceBlend(
        k,
        select(k + 1u, 0u, single),
        select(weight, 0.0, single),
        select(1.0 / span, 0.0, outside || single),
    );
}

// First texel of irradiance map `k` in `light` (every map is on the coarsest level's grid).
fn irradiance_first(k: u32) -> u32 {
    let coarsest = params.levels - 1u;
    let size = tables[coarsest * 4u];
    return params.irradiance_offset + k * 6u * size * size;
}

// Diffuse irradiance E_d(n) (`PreparedEnv::irradiance`).
fn irradiance_light(normal: vec3<f32>, ior: f32) -> vec3<f32> {
    let coarsest = params.levels - 1u;
    let blend = irradiance_blend(ior);
    let a = sample_taps(cube_taps(coarsest, irradiance_first(blend.a), normal));
    if blend.t == 0.0 {
        return a;
    }
    let b = sample_taps(cube_taps(coarsest, irradiance_first(blend.b), normal));
    return a * (1.0 - blend.t) + b * blend.t;
}

// The shader input of one pixel (`PixelInput`): the view direction and the Stokes frame come
// from the camera.
struct Pixel {
    position: vec3<f32>,
    normal: vec3<f32>,
    view: vec3<f32>,
    stokes_x: vec3<f32>,
    stokes_y: vec3<f32>,
    albedo: vec3<f32>,
    roughness: f32,
    ior: f32,
}

fn load_pixel(i: u32) -> Pixel {
    let p = params.first_pixel + i;
    let x = f32(p % params.width) + 0.5;
    let y = f32(p / params.width) + 0.5;
    let c = vec3<f32>((x - params.cx) / params.fx, (y - params.cy) / params.fy, 1.0);
    let d = normalize(params.rot0.xyz * c.x + params.rot1.xyz * c.y + params.rot2.xyz * c.z);
    let sx = normalize(cross(d, params.up.xyz));
    let a = pixels[3u * i];
    let b = pixels[3u * i + 1u];
    let position = pixels[3u * i + 2u].xyz;
    return Pixel(position, a.xyz, -d, sx, cross(sx, d), b.xyz, a.w, b.w);
}

// Forward intermediates kept for the backward pass (`Forward`).
struct Shaded {
    diffuse: vec3<f32>,
    specular: vec3<f32>,
    unit_normal: vec3<f32>,
    // 1/|raw normal|, 0 for a vanishing normal (no normal gradient).
    inv_length: f32,
    flip: f32,
    n: vec3<f32>,
    mu: f32,
    mu_clamped: bool,
    lut: LutSample,
    f0: f32,
    df0: f32,
    w_s: f32,
    mirror: vec3<f32>,
    // The light's view of the surface point (the backward lookups reuse it).
    light: LightPoint,
    radiance: vec3<f32>,
    // 1 − F, the transmitted fraction of the diffuse term.
    transmitted: f32,
    dfresnel_dmu: f32,
    dfresnel_df0: f32,
    irradiance: vec3<f32>,
    rho: Ratios,
    azimuth: Azimuth,
}

fn shade_pixel(px: Pixel) -> Shaded {
    var s: Shaded;
    let raw_length = length(px.normal);
    if raw_length > 1e-30 && raw_length < 3.0e38 {
        s.unit_normal = px.normal / raw_length;
        s.inv_length = 1.0 / raw_length;
    } else {
        s.unit_normal = px.view;
        s.inv_length = 0.0;
    }
    s.flip = 1.0;
    if dot(s.unit_normal, px.view) < 0.0 {
        s.flip = -1.0;
    }
    s.n = s.unit_normal * s.flip;
    let raw_mu = dot(s.n, px.view);
    s.mu_clamped = raw_mu < MIN_COS_VIEW;
    s.mu = max(raw_mu, MIN_COS_VIEW);
    let eta = px.ior;

    let k = (eta - 1.0) / (eta + 1.0);
    s.f0 = k * k;
    s.df0 = 4.0 * k / ((eta + 1.0) * (eta + 1.0));
    s.lut = lut_lookup(s.mu, px.roughness);
    s.w_s = s.f0 * s.lut.a.x + s.lut.b.x;
    s.mirror = 2.0 * s.mu * s.n - px.view;
    s.light = light_point(px.position, s.mirror);
    s.radiance = light_specular(s.light, s.mirror, px.roughness);
    s.specular = s.w_s * s.radiance;

    let one_minus_mu = 1.0 - s.mu;
    let pow4 = one_minus_mu * one_minus_mu * one_minus_mu * one_minus_mu;
    let pow5 = pow4 * one_minus_mu;
    // 1 − F = (1 − F0)(1 − x⁵) with x = 1 − μ, and 1 − x⁵ = μ(1 + x + x² + x³ + x⁴): no
    // cancellation at grazing angles, where F → 1 and 1 − F would keep few f32 digits.
    let x = one_minus_mu;
    s.transmitted = (1.0 - s.f0) * s.mu * (1.0 + x * (1.0 + x * (1.0 + x * (1.0 + x))));
    s.dfresnel_dmu = -5.0 * (1.0 - s.f0) * pow4;
    s.dfresnel_df0 = 1.0 - pow5;
    s.irradiance = light_irradiance(s.light, s.n, eta);
    s.diffuse = s.transmitted * px.albedo * s.irradiance;

    s.rho = polarization_ratios(s.mu, eta);
    s.azimuth = double_azimuth(dot(s.n, px.stokes_x), dot(s.n, px.stokes_y));
    return s;
}

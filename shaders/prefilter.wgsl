// The environment prefilter on the device (a port of src/envmap/prefilter.rs in f32), for the
// resident trainer: from the raw cube map, the activated radiance and its box-downsampled pyramid,
// every level's GGX lobe convolution and the irradiance map(s), written in the light layout of
// shade_common.wgsl; and the transpose, from a gradient in that layout back to the raw texels.
//   `activate`            radiance f(raw) and f′(raw) of the base texels;
//   `downsample`          a pyramid level from the one above (2×2 box);
//   `convolve`            one convolution of the plan, forward (out[o] = Σ_i k(n_o·d_i) ΔΩ_i
//                         src[i] / Z_o, Z the lobe's normalizer, none for irradiance) or
//                         transposed (out[i] = ΔΩ_i Σ_o k(n_o·d_i) g[o] / Z_o), optionally added
//                         into its output; 8×8 texel blocks are culled by bounding cones;
//   `pyramid_transpose`   a pyramid level's gradient added into the level above (a quarter per
//                         child texel where the size halves, all of it where it does not);
//   `raw_gradient`        the base level's gradient times f′(raw).
// Threading: one thread per output texel (or value), 256-thread workgroups on a 2-D grid.

struct ConvParams {
    // The grid: its texels (the output texels), its first texel in `dirs`/`solid_angle`, its
    // first block and its blocks.
    texels: u32,
    first_texel: u32,
    first_block: u32,
    blocks: u32,
    // The grid's first entry in `block_texels`/`block_dirs`, this convolution's first threshold
    // and first normalizer (or NO_NORMALIZER); transposed (1) or forward (0).
    first_entry: u32,
    first_threshold: u32,
    first_normalizer: u32,
    transposed: u32,
    // The kernel (0 GGX, 1 cosine, 2 Fresnel cosine), its parameter (GGX α² or the IoR) and the
    // cosine of its angular cutoff.
    kernel_kind: u32,
    pad0: u32,
    pad1: u32,
    pad2: u32,
    kernel_param: f32,
    cos_cut: f32,
    pad3: f32,
    pad4: f32,
    // The first value read in `src`, the first value written in `dst`, add into `dst` (1) or
    // overwrite it (0).
    src_first: u32,
    dst_first: u32,
    accumulate: u32,
    pad5: u32,
}

struct LevelParams {
    // Texels of the output level, its face size, the first value of the source level in
    // `pyramid`, the first value of the output level.
    texels: u32,
    face_size: u32,
    src_first: u32,
    dst_first: u32,
    // The output has the size of the source (1: copy or add all) or half of it (0).
    same_size: u32,
    pad0: u32,
    pad1: u32,
    pad2: u32,
}

const NO_NORMALIZER: u32 = 0xffffffffu;
const INV_PI: f32 = 0.31830988618;

@group(0) @binding(0) var<uniform> conv: ConvParams;
@group(0) @binding(1) var<storage, read> dirs: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> solid_angle: array<f32>;
// Per block: its bounding cone's axis (xyz), and its first entry in the grid's `block_texels`
// (a block ends where the next one starts, the grid's last at its texel count).
@group(0) @binding(3) var<storage, read> blocks: array<vec4<f32>>;
@group(0) @binding(14) var<storage, read> block_starts: array<u32>;
@group(0) @binding(4) var<storage, read> block_texels: array<u32>;
@group(0) @binding(5) var<storage, read> block_dirs: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read> thresholds: array<f32>;
@group(0) @binding(7) var<storage, read> normalizers: array<f32>;
@group(0) @binding(8) var<storage, read> src: array<f32>;
@group(0) @binding(9) var<storage, read_write> dst: array<f32>;

@group(0) @binding(10) var<uniform> level: LevelParams;
@group(0) @binding(11) var<storage, read> raw: array<f32>;
@group(0) @binding(12) var<storage, read_write> pyramid: array<f32>;
@group(0) @binding(13) var<storage, read_write> derivative: array<f32>;

fn value_index(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.x + gid.y * nwg.x * 256u;
}

// Unpolarized Fresnel reflectance at cos θ = c from air into index `ior` (`fresnel_unpolarized`).
fn fresnel_unpolarized(c_in: f32, ior: f32) -> f32 {
    let c = clamp(c_in, 0.0, 1.0);
    let ct = sqrt(max(1.0 - (1.0 - c * c) / (ior * ior), 0.0));
    let rs = (c - ior * ct) / (c + ior * ct);
    let rp = (ct - ior * c) / (ct + ior * c);
    return 0.5 * (rs * rs + rp * rp);
}

// The kernel at cos(angle) = c between unit directions n and d; `one_minus_c` = 1 − c from
// ‖n − d‖² / 2, which keeps its digits near the lobe's axis: there the GGX denominator
// cos²θ_h (α² − 1) + 1 = (1 − c) / 2 + cos²θ_h α² is tiny for sharp lobes (α² = 4e-5 at r = 0.08),
// and forming it as the f32 sum of numbers near ±1 would lose three digits.
fn kernel_weight(c: f32, one_minus_c: f32) -> f32 {
    switch conv.kernel_kind {
        case 0u: {
            let alpha2 = conv.kernel_param;
            let cos2h = 0.5 * (1.0 + c);
            let denom = 0.5 * one_minus_c + cos2h * alpha2;
            return alpha2 / (denom * denom) * c;
        }
        case 1u: {
            return c * INV_PI;
        }
        default: {
            return c * (1.0 - fresnel_unpolarized(c, conv.kernel_param)) * INV_PI;
        }
    }
}

fn normalizer(t: u32) -> f32 {
    if conv.first_normalizer == NO_NORMALIZER {
        return 1.0;
    }
    return normalizers[conv.first_normalizer + t];
}

@compute @workgroup_size(256)
fn convolve(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let o = value_index(gid, nwg);
    let texels = conv.texels;
    if o >= texels {
        return;
    }
    let transposed = conv.transposed != 0u;
    let n = dirs[conv.first_texel + o].xyz;
    let first_block = conv.first_block;
    let block_count = conv.blocks;
    let cos_cut = conv.cos_cut;
    var acc = vec3<f32>(0.0);
    for (var b = 0u; b < block_count; b++) {
        let block = blocks[first_block + b];
        if dot(n, block.xyz) < thresholds[conv.first_threshold + b] {
            continue;
        }
        let start = block_starts[first_block + b];
        var end = texels;
        if b + 1u < block_count {
            end = block_starts[first_block + b + 1u];
        }
        for (var e = start; e < end; e++) {
            let d = block_dirs[conv.first_entry + e].xyz;
            let c = dot(n, d);
            if c <= cos_cut {
                continue;
            }
            let t = block_texels[conv.first_entry + e];
            let gap = n - d;
            var w = kernel_weight(c, 0.5 * dot(gap, gap));
            if transposed {
                w /= normalizer(t);
            } else {
                w *= solid_angle[conv.first_texel + t];
            }
            let s = conv.src_first + 3u * t;
            acc += w * vec3<f32>(src[s], src[s + 1u], src[s + 2u]);
        }
    }
    if transposed {
        acc *= solid_angle[conv.first_texel + o];
    } else {
        acc /= normalizer(o);
    }
    let d = conv.dst_first + 3u * o;
    if conv.accumulate != 0u {
        acc += vec3<f32>(dst[d], dst[d + 1u], dst[d + 2u]);
    }
    dst[d] = acc.x;
    dst[d + 1u] = acc.y;
    dst[d + 2u] = acc.z;
}

// f(x) = sigmoid(x) for x ≤ 0, x + ½ above (`envmap::activate`), and f′.
@compute @workgroup_size(256)
fn activate(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = value_index(gid, nwg);
    if i >= arrayLength(&raw) {
        return;
    }
    let x = raw[i];
    if x <= 0.0 {
        let s = 1.0 / (1.0 + exp(-x));
        pyramid[i] = s;
        derivative[i] = s * (1.0 - s);
    } else {
        pyramid[i] = x + 0.5;
        derivative[i] = 1.0;
    }
}

// The output level's RGB value i from the source level: a 2×2 box (or a copy).
@compute @workgroup_size(256)
fn downsample(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = value_index(gid, nwg);
    let texels = level.texels;
    if i >= texels * 3u {
        return;
    }
    let src_first = level.src_first;
    let out = level.dst_first + i;
    if level.same_size != 0u {
        pyramid[out] = pyramid[src_first + i];
        return;
    }
    let half = level.face_size;
    let size = 2u * half;
    let t = i / 3u;
    let c = i % 3u;
    let face = t / (half * half);
    let y = (t / half) % half;
    let x = t % half;
    var sum = 0.0;
    for (var dy = 0u; dy < 2u; dy++) {
        for (var dx = 0u; dx < 2u; dx++) {
            let s = (face * size + 2u * y + dy) * size + 2u * x + dx;
            sum += 0.25 * pyramid[src_first + 3u * s + c];
        }
    }
    pyramid[out] = sum;
}

// Adds a level's gradient (at `src_first`, face size `face_size` / 2 unless `same_size`) into
// the level above it (at `dst_first`, `texels` texels, face size `face_size`).
@compute @workgroup_size(256)
fn pyramid_transpose(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = value_index(gid, nwg);
    let texels = level.texels;
    if i >= texels * 3u {
        return;
    }
    let coarse_first = level.src_first;
    let out = level.dst_first + i;
    if level.same_size != 0u {
        pyramid[out] += pyramid[coarse_first + i];
        return;
    }
    let size = level.face_size;
    let half = size / 2u;
    let t = i / 3u;
    let c = i % 3u;
    let face = t / (size * size);
    let y = (t / size) % size;
    let x = t % size;
    let parent = (face * half + y / 2u) * half + x / 2u;
    pyramid[out] += 0.25 * pyramid[coarse_first + 3u * parent + c];
}

// The base level's gradient (the first values of `pyramid`) times f′(raw), into `dst`.
@compute @workgroup_size(256)
fn raw_gradient(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = value_index(gid, nwg);
    if i >= arrayLength(&derivative) {
        return;
    }
    dst[i] = pyramid[i] * derivative[i];
}

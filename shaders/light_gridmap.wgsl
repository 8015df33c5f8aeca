// GridMap's light (a port of the `LightProbe` of src/gridmap.rs, in f32): at surface point x the
// local probes are blended with weights w_k ∝ 1/(‖x − a_k‖² + 1e-6); the diffuse irradiance is
// the blend of the probes' irradiance maps everywhere, and the specular radiance the blend of
// their mip chains where the mirror ray from x is blocked by the mesh, the global map where it
// escapes. The occlusion test walks the mesh's BVH (flattened depth first, as src/bvh.rs builds
// it) with a fixed stack, nearer child first, and Möller–Trumbore triangle tests: the ray starts
// `grid_ray_offset` along the direction, steps through up to MAX_EXITS back-facing hits, and the
// first front-facing hit means "occluded". Compiled after shade_common.wgsl (before the backward
// file when differentiating); one thread per pixel as there.

// The probes' texels in the layout of `light` (every mip level, then every irradiance map),
// texel-major: texel t of probe k at (t · anchors + k) · 3, so that a blend reads one block.
@group(0) @binding(9) var<storage, read> probes: array<f32>;
// Anchor positions (xyz).
@group(0) @binding(10) var<storage, read> anchors: array<vec4<f32>>;
// Two vectors per node: its box's min and max corners (rounded outwards; w unused).
@group(0) @binding(11) var<storage, read> bvh_nodes: array<vec4<f32>>;
// Per node: its first triangle slot (leaf) or right child (interior), and its triangle count
// (0 for an interior node, whose left child follows it).
@group(0) @binding(13) var<storage, read> bvh_links: array<vec2<u32>>;
// Six vectors per triangle slot: corner v0, edges e1 and e2, the corners' vertex normals.
@group(0) @binding(12) var<storage, read> bvh_slots: array<vec4<f32>>;

const WEIGHT_EPSILON: f32 = 1e-6;
// Back faces stepped through before a mirror ray counts as escaping.
const MAX_EXITS: u32 = 4u;
// Traversal stack entries (one per tree level; src/bvh.rs bounds the depth by 88).
const BVH_STACK: u32 = 88u;
// Hits closer than this ray parameter are ignored.
const T_MIN: f32 = 1e-9;
// Finite stand-in for +∞.
const FAR: f32 = 3.0e38;

// The anchor weights at x: w_k = inv_total / (‖x − a_k‖² + 1e-6), computed on the fly by
// `weight` (cheaper on every device than a per-thread array of 56).
struct Blend {
    x: vec3<f32>,
    inv_total: f32,
}

// The anchor and BVH node counts of the uniform block, bounded by their buffers' lengths: a loop
// bound on uniform values alone made lavapipe (Mesa 22) recompile the kernel at every dispatch to
// inline them (the node check, a branch, is kept off them as a precaution); a bound that also
// reads a buffer length keeps the kernel as compiled.
fn anchor_count() -> u32 {
    return min(params.grid_anchors, arrayLength(&anchors));
}

fn node_count() -> u32 {
    return min(params.grid_nodes, arrayLength(&bvh_links));
}

fn raw_weight(x: vec3<f32>, k: u32) -> f32 {
    let d = x - anchors[k].xyz;
    return 1.0 / (dot(d, d) + WEIGHT_EPSILON);
}

fn anchor_blend(x: vec3<f32>) -> Blend {
    var total = 0.0;
    for (var k = 0u; k < anchor_count(); k++) {
        total += raw_weight(x, k);
    }
    return Blend(x, 1.0 / total);
}

// Texel t of probe k.
fn probe_texel(t: u32, k: u32) -> vec3<f32> {
    let o = (t * params.grid_anchors + k) * 3u;
    return vec3<f32>(probes[o], probes[o + 1u], probes[o + 2u]);
}

// The blend Σ_k w_k · (texel of probe k) at each of a lookup's four taps (anchors in the outer
// loop, so each weight is computed once).
struct BlendedTaps {
    t0: vec3<f32>,
    t1: vec3<f32>,
    t2: vec3<f32>,
    t3: vec3<f32>,
}

fn blended_taps(b: Blend, taps: Taps) -> BlendedTaps {
    var out = BlendedTaps(vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0));
    for (var k = 0u; k < anchor_count(); k++) {
        let w = raw_weight(b.x, k) * b.inv_total;
        out.t0 += w * probe_texel(taps.texel.x, k);
        out.t1 += w * probe_texel(taps.texel.y, k);
        out.t2 += w * probe_texel(taps.texel.z, k);
        out.t3 += w * probe_texel(taps.texel.w, k);
    }
    return out;
}

fn blended_sample(b: Blend, taps: Taps) -> vec3<f32> {
    let v = blended_taps(b, taps);
    return taps.weight.x * v.t0 + taps.weight.y * v.t1 + taps.weight.z * v.t2
        + taps.weight.w * v.t3;
}

// Σ_k w_k E_k(dir, r).
fn blended_specular(b: Blend, dir: vec3<f32>, roughness: f32) -> vec3<f32> {
    let blend = level_blend(roughness);
    let l0 = u32(blend.x);
    let lo = blended_sample(b, cube_taps(l0, level_first(l0), dir));
    let hi = blended_sample(b, cube_taps(l0 + 1u, level_first(l0 + 1u), dir));
    return lo * (1.0 - blend.y) + hi * blend.y;
}

// Σ_k w_k E_d,k(n).
fn blended_irradiance(b: Blend, normal: vec3<f32>, ior: f32) -> vec3<f32> {
    let coarsest = params.levels - 1u;
    let blend = irradiance_blend(ior);
    let first = blended_sample(b, cube_taps(coarsest, irradiance_first(blend.a), normal));
    if blend.a == blend.b || blend.t == 0.0 {
        return first;
    }
    let second = blended_sample(b, cube_taps(coarsest, irradiance_first(blend.b), normal));
    return first * (1.0 - blend.t) + second * blend.t;
}

// 1/d per component, with ±1e30 for zero components (WGSL leaves x/0 undefined).
fn safe_inverse(d: vec3<f32>) -> vec3<f32> {
    let sign = select(vec3<f32>(1.0), vec3<f32>(-1.0), d < vec3<f32>(0.0));
    return sign / max(abs(d), vec3<f32>(1e-30));
}

// Entry distance of the ray into node i's box within (0, t_max), or −1 when it misses.
fn box_entry(i: u32, origin: vec3<f32>, inv_dir: vec3<f32>, t_max: f32) -> f32 {
    let t0 = (bvh_nodes[2u * i].xyz - origin) * inv_dir;
    let t1 = (bvh_nodes[2u * i + 1u].xyz - origin) * inv_dir;
    let lo = min(t0, t1);
    let hi = max(t0, t1);
    let near = max(max(max(lo.x, lo.y), lo.z), 0.0);
    let far = min(min(min(hi.x, hi.y), hi.z), t_max);
    return select(-1.0, near, near <= far);
}

// Möller–Trumbore against slot s: (t, u, v) with T_MIN < t < t_max, or t = −1.
fn triangle_hit(s: u32, origin: vec3<f32>, dir: vec3<f32>, t_max: f32) -> vec3<f32> {
    let miss = vec3<f32>(-1.0, 0.0, 0.0);
    let v0 = bvh_slots[6u * s].xyz;
    let e1 = bvh_slots[6u * s + 1u].xyz;
    let e2 = bvh_slots[6u * s + 2u].xyz;
    let p = cross(dir, e2);
    let det = dot(e1, p);
    if det == 0.0 || !(abs(det) < FAR) {
        return miss;
    }
    let inv_det = 1.0 / det;
    let sv = origin - v0;
    let u = dot(sv, p) * inv_det;
    if !(u >= 0.0 && u <= 1.0) {
        return miss;
    }
    let q = cross(sv, e1);
    let v = dot(dir, q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return miss;
    }
    let t = dot(e2, q) * inv_det;
    if t > T_MIN && t < t_max {
        return vec3<f32>(t, u, v);
    }
    return miss;
}

// The interpolated vertex normal at (u, v) of slot s (its geometric normal where that vanishes).
fn slot_normal(s: u32, u: f32, v: f32) -> vec3<f32> {
    let n = (1.0 - u - v) * bvh_slots[6u * s + 3u].xyz + u * bvh_slots[6u * s + 4u].xyz
        + v * bvh_slots[6u * s + 5u].xyz;
    if length(n) > 1e-30 {
        return n;
    }
    return cross(bvh_slots[6u * s + 1u].xyz, bvh_slots[6u * s + 2u].xyz);
}

// The closest hit of origin + t·dir: (normal at the hit, unnormalized; t), or t = −1.
fn closest_hit(origin: vec3<f32>, dir: vec3<f32>) -> vec4<f32> {
    var best = vec4<f32>(0.0, 0.0, 0.0, -1.0);
    if node_count() == 0u {
        return best;
    }
    let inv_dir = safe_inverse(dir);
    var t_max = FAR;
    if box_entry(0u, origin, inv_dir, t_max) < 0.0 {
        return best;
    }
    var stack: array<u32, BVH_STACK>;
    var top = 0u;
    var node = 0u;
    loop {
        let link = bvh_links[node];
        let first_or_right = link.x;
        let count = link.y;
        if count > 0u {
            for (var s = first_or_right; s < first_or_right + count; s++) {
                let h = triangle_hit(s, origin, dir, t_max);
                if h.x >= 0.0 {
                    t_max = h.x;
                    best = vec4<f32>(slot_normal(s, h.y, h.z), h.x);
                }
            }
        } else {
            let left = node + 1u;
            let right = first_or_right;
            let a = box_entry(left, origin, inv_dir, t_max);
            let b = box_entry(right, origin, inv_dir, t_max);
            if a >= 0.0 && b >= 0.0 {
                if top < BVH_STACK {
                    stack[top] = select(right, left, b < a);
                    top += 1u;
                }
                node = select(left, right, b < a);
                continue;
            }
            if a >= 0.0 {
                node = left;
                continue;
            }
            if b >= 0.0 {
                node = right;
                continue;
            }
        }
        // Pop the next node still in reach.
        var found = false;
        while top > 0u {
            top -= 1u;
            node = stack[top];
            if box_entry(node, origin, inv_dir, t_max) >= 0.0 {
                found = true;
                break;
            }
        }
        if !found {
            break;
        }
    }
    return best;
}

// Whether the mirror ray from x along dir is blocked by the mesh.
fn occluded(x: vec3<f32>, dir: vec3<f32>) -> bool {
    let len = length(dir);
    if !(len > 0.0 && len < FAR) {
        return false;
    }
    let d = dir / len;
    let offset = params.grid_ray_offset;
    var origin = x + offset * d;
    for (var e = 0u; e < MAX_EXITS; e++) {
        let hit = closest_hit(origin, d);
        if hit.w < 0.0 {
            return false;
        }
        if dot(hit.xyz, d) < 0.0 {
            return true;
        }
        origin = origin + (hit.w + offset) * d;
    }
    return false;
}

// What the light needs to know of a pixel's surface point, found once per pixel (the forward
// and backward lookups share it): the anchor weights, and whether the mirror ray is blocked.
struct LightPoint {
    blend: Blend,
    blocked: bool,
}

fn light_point(x: vec3<f32>, mirror: vec3<f32>) -> LightPoint {
    return LightPoint(anchor_blend(x), occluded(x, mirror));
}

fn light_specular(at: LightPoint, dir: vec3<f32>, roughness: f32) -> vec3<f32> {
    if at.blocked {
        return blended_specular(at.blend, dir, roughness);
    }
    return specular_light(dir, roughness);
}

fn light_irradiance(at: LightPoint, normal: vec3<f32>, ior: f32) -> vec3<f32> {
    return blended_irradiance(at.blend, normal, ior);
}

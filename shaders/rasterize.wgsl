// Forward rasterization: front-to-back compositing of each tile's sorted surfels into the
// α-normalized G-buffers (α, depth, normal, albedo, roughness, IoR, squared depth), as `forward_tile` of
// src/raster/cpu.rs does in f64.
// Threading: one workgroup of 64 threads per 8×8 tile, one thread per pixel; each thread walks
// its tile's list on its own (reading the projected surfels from global memory, no workgroup
// memory, no barriers) and stops at the surfel that would bring its transmittance below
// transmittance_min. Per pixel it also writes the final transmittance and the number of list
// entries up to the last one composited (for the backward pass), and how many surfel boxes it was
// evaluated in (the `pixel_evaluations` statistic).

@group(0) @binding(4) var<storage, read_write> gbuf: array<f32>;
@group(0) @binding(5) var<storage, read_write> final_t: array<f32>;
@group(0) @binding(6) var<storage, read_write> contrib: array<u32>;
@group(0) @binding(7) var<storage, read_write> evals: array<u32>;

@compute @workgroup_size(8, 8)
fn rasterize(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let prm = params;
    let tp = tile_pixel(wg, lid, prm);
    if !tp.inside {
        return;
    }
    let x = tp.x;
    let y = tp.y;
    let pix = tp.pix;
    let range = tp.range;
    let xf = tp.centre.x;
    let yf = tp.centre.y;
    var trans = 1.0;
    var alpha_sum = 0.0;
    var depth_sum = 0.0;
    var normal_sum = vec3<f32>(0.0);
    var albedo_sum = vec3<f32>(0.0);
    var rough_sum = 0.0;
    var ior_sum = 0.0;
    var depth_sq_sum = 0.0;
    var last = 0u;
    var n_evals = 0u;
    for (var k = range.x; k < range.y; k++) {
        let idx = entries[k].z;
        // The box alone first: most entries of a tile miss most of its pixels.
        if !rect_contains(proj[idx].rect, x, y) {
            continue;
        }
        let p = proj[idx];
        n_evals++;
        let hit = evaluate(p, xf, yf, prm);
        if !hit.ok {
            continue;
        }
        let next_t = trans * (1.0 - hit.alpha);
        if next_t < prm.transmittance_min {
            break;
        }
        let w = hit.alpha * trans;
        alpha_sum += w;
        depth_sum += w * hit.z;
        normal_sum += w * p.f0.xyz;
        albedo_sum += w * vec3<f32>(p.f0.w, p.f1.x, p.f1.y);
        rough_sum += w * p.f1.z;
        ior_sum += w * p.f1.w;
        depth_sq_sum += w * hit.z * hit.z;
        trans = next_t;
        last = k - range.x + 1u;
    }
    let o = pix * NUM_OUT;
    gbuf[o] = alpha_sum;
    var inv = 0.0;
    if alpha_sum > prm.normalize_alpha_min {
        inv = 1.0 / alpha_sum;
    }
    gbuf[o + 1u] = depth_sum * inv;
    gbuf[o + 2u] = normal_sum.x * inv;
    gbuf[o + 3u] = normal_sum.y * inv;
    gbuf[o + 4u] = normal_sum.z * inv;
    gbuf[o + 5u] = albedo_sum.x * inv;
    gbuf[o + 6u] = albedo_sum.y * inv;
    gbuf[o + 7u] = albedo_sum.z * inv;
    gbuf[o + 8u] = rough_sum * inv;
    gbuf[o + 9u] = ior_sum * inv;
    gbuf[o + 10u] = depth_sq_sum * inv;
    final_t[pix] = trans;
    contrib[pix] = last;
    evals[pix] = n_evals;
}

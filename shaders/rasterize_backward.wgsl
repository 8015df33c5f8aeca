// Backward rasterization: replays each pixel's compositing back to front (as `backward_tile` of
// src/raster/cpu.rs) and adds every (pixel, surfel) contribution to the surfel's 22 accumulators
// (Q, det, mean, opacity, features, view depth) with `add_grad`, which is a float atomic add where
// the adapter has SHADER_FLOAT32_ATOMIC and a compare-and-swap loop on the f32 bit pattern
// otherwise (appended from atomic_float.wgsl or atomic_cas.wgsl). The upstream gradient arrives
// per pixel as (α, depth, normal, albedo, roughness, IoR, squared depth) on the normalized
// buffers; the depth
// entry already includes the depth-normal chain computed on the host.
// Threading: one workgroup of 64 threads per 8×8 tile, one thread per pixel, each walking its
// tile's list back to the first entry from its last composited one, or with subgroups from the
// last one any thread of its subgroup composited (`walk_length`); no workgroup memory, no barriers.
// Per pixel only T and B = Σ_{j>i} w_j (dL/dα + Σ_c dL/dS_c v_{j,c}) are carried.

@group(0) @binding(4) var<storage, read> gbuf: array<f32>;
@group(0) @binding(5) var<storage, read> upstream: array<f32>;
@group(0) @binding(6) var<storage, read> final_t: array<f32>;
@group(0) @binding(7) var<storage, read> contrib: array<u32>;

@compute @workgroup_size(8, 8)
fn rasterize_backward(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let prm = params;
    let tp = tile_pixel(wg, lid, prm);
    let x = tp.x;
    let y = tp.y;
    let pix = select(0u, tp.pix, tp.inside);
    let n = select(0u, contrib[pix], tp.inside);
    // How far back this thread walks (walk_own.wgsl or walk_subgroup.wgsl); every thread of the
    // tile calls it, none has returned yet.
    let walk = walk_length(n);
    if n == 0u {
        return;
    }
    let range = tp.range;
    let o = pix * NUM_OUT;
    let a = gbuf[o];
    // Undo the α-normalization: dL/dS = g / α, dL/dα −= Σ g · out / α.
    var g_alpha = upstream[o];
    var g_depth = 0.0;
    var g_depth_sq = 0.0;
    var g_feat0 = vec4<f32>(0.0);
    var g_feat1 = vec4<f32>(0.0);
    if a > prm.normalize_alpha_min {
        let inv_a = 1.0 / a;
        var dot_sum = 0.0;
        for (var c = 1u; c < NUM_OUT; c++) {
            dot_sum += upstream[o + c] * gbuf[o + c];
        }
        g_alpha -= dot_sum * inv_a;
        g_depth = upstream[o + 1u] * inv_a;
        g_depth_sq = upstream[o + 10u] * inv_a;
        g_feat0 = vec4<f32>(upstream[o + 2u], upstream[o + 3u], upstream[o + 4u], upstream[o + 5u]) * inv_a;
        g_feat1 = vec4<f32>(upstream[o + 6u], upstream[o + 7u], upstream[o + 8u], upstream[o + 9u]) * inv_a;
    }
    let xf = tp.centre.x;
    let yf = tp.centre.y;
    let inv_sigma2 = prm.inv_lowpass_sigma2;
    var trans = final_t[pix];
    var b_acc = 0.0;
    for (var kk = walk; kk > 0u; kk--) {
        let e = entries[range.x + kk - 1u];
        if kk > n || !rect_contains(proj[e.z].rect, x, y) {
            continue;
        }
        let p = proj[e.z];
        let hit = evaluate(p, xf, yf, prm);
        if !hit.ok {
            continue;
        }
        let base = e.z * NUM_ACC;
        let one_minus = 1.0 - hit.alpha;
        let t_i = trans / one_minus;
        let weight = hit.alpha * t_i;
        let u = g_alpha + (g_depth + g_depth_sq * hit.z) * hit.z + dot(g_feat0, p.f0)
            + dot(g_feat1, p.f1);
        let gf0 = weight * g_feat0;
        let gf1 = weight * g_feat1;
        add_grad(base + 13u, gf0.x);
        add_grad(base + 14u, gf0.y);
        add_grad(base + 15u, gf0.z);
        add_grad(base + 16u, gf0.w);
        add_grad(base + 17u, gf1.x);
        add_grad(base + 18u, gf1.y);
        add_grad(base + 19u, gf1.z);
        add_grad(base + 20u, gf1.w);
        let d_alpha = t_i * u - b_acc / one_minus;
        b_acc += weight * u;
        trans = t_i;

        // α = min(alpha_max, o G), G = exp(−ρ/2).
        var g_rho = 0.0;
        if !hit.clamped {
            add_grad(base + 12u, hit.g * d_alpha);
            g_rho = -0.5 * hit.g * p.mean_op.z * d_alpha;
        }
        let gz = weight * (g_depth + 2.0 * hit.z * g_depth_sq);
        if !hit.use3d {
            // Filter branch: ρ_2d around the projected centre, z = the centre's depth.
            let c = -2.0 * inv_sigma2 * g_rho;
            add_grad(base + 10u, c * hit.dx);
            add_grad(base + 11u, c * hit.dy);
            add_grad(base + 21u, gz);
            continue;
        }
        // Plane branch: ρ = s² + t², s = px · inv, t = py · inv, z = det · inv, inv = 1 / pz.
        let gs = 2.0 * hit.s * g_rho;
        let gt = 2.0 * hit.t * g_rho;
        add_grad(base + 9u, hit.inv * gz);
        let g_inv = hit.px * gs + hit.py * gt + p.q0.w * gz;
        let gp = vec3<f32>(hit.inv * gs, hit.inv * gt, -hit.inv * hit.inv * g_inv);
        for (var r = 0u; r < 3u; r++) {
            add_grad(base + 3u * r, gp[r] * xf);
            add_grad(base + 3u * r + 1u, gp[r] * yf);
            add_grad(base + 3u * r + 2u, gp[r]);
        }
    }
}

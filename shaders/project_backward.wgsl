// Chains each surfel's accumulated gradient on its projected values (Q, det, mean, opacity,
// features, view depth) back to its raw parameters (a port of `project_backward` in
// src/raster/project.rs, in f32), and computes |dL/dμ|, the gradient norm with respect to a
// screen-space translation of the projected surfel.
// Threading: one thread per surfel, 256-thread workgroups on a 2-D grid. Output per surfel, 16 f32:
// position (3), log scale (2), rotation (4), opacity, albedo (3), roughness, IoR, |dL/dμ|;
// all zero for culled surfels.

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> raw: array<Raw>;
@group(0) @binding(2) var<storage, read> proj: array<Proj>;
@group(0) @binding(3) var<storage, read> grad_acc: array<f32>;
@group(0) @binding(4) var<storage, read_write> raw_grads: array<f32>;

// Gradient of Σ G_ij R_ij with respect to the unit quaternion (w, x, y, z) of R; g[j][i] = G_ij.
fn rotation_backward(q: vec4<f32>, g: mat3x3<f32>) -> vec4<f32> {
    let w = q.x;
    let x = q.y;
    let y = q.z;
    let z = q.w;
    let g00 = g[0][0];
    let g01 = g[1][0];
    let g02 = g[2][0];
    let g10 = g[0][1];
    let g11 = g[1][1];
    let g12 = g[2][1];
    let g20 = g[0][2];
    let g21 = g[1][2];
    let g22 = g[2][2];
    return 2.0 * vec4<f32>(
        -z * g01 + y * g02 + z * g10 - x * g12 - y * g20 + x * g21,
        y * g01 + z * g02 + y * g10 - 2.0 * x * g11 - w * g12 + z * g20 + w * g21 - 2.0 * x * g22,
        -2.0 * y * g00 + x * g01 + w * g02 + x * g10 + z * g12 - w * g20 + z * g21 - 2.0 * y * g22,
        -2.0 * z * g00 - w * g01 + x * g02 + w * g10 - 2.0 * z * g11 + y * g12 + x * g20 + y * g21,
    );
}

@compute @workgroup_size(256)
fn project_backward(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = linear_index(gid, nwg);
    let prm = params;
    if i >= prm.surfels {
        return;
    }
    let out = i * 16u;
    for (var k = 0u; k < 16u; k++) {
        raw_grads[out + k] = 0.0;
    }
    let p = proj[i];
    if p.rect.x >= p.rect.z {
        return;
    }
    let geo = geometry(raw[i], prm);
    let m0 = geo.m0;
    let m1 = geo.m1;
    let m2 = geo.m2;
    let qx = cross(m1, m2);
    let qy = cross(m2, m0);
    let qc = cross(m0, m1);
    let b = i * NUM_ACC;
    // Column j of Q (coefficient of x, y, 1) over the three rows of p.
    let gqx = vec3<f32>(grad_acc[b], grad_acc[b + 3u], grad_acc[b + 6u]);
    let gqy = vec3<f32>(grad_acc[b + 1u], grad_acc[b + 4u], grad_acc[b + 7u]);
    let gqc = vec3<f32>(grad_acc[b + 2u], grad_acc[b + 5u], grad_acc[b + 8u]);
    let g_det = grad_acc[b + 9u];
    let g_mean = vec2<f32>(grad_acc[b + 10u], grad_acc[b + 11u]);
    let g_opacity = grad_acc[b + 12u];
    let g_view_depth = grad_acc[b + 21u];
    // Qx = M1×M2, Qy = M2×M0, Qc = M0×M1, det = M0·Qx.
    let gm0 = cross(gqy, m2) + cross(m1, gqc) + g_det * qx;
    let gm1 = cross(m2, gqx) + cross(gqc, m0) + g_det * qy;
    let gm2 = cross(gqx, m1) + cross(m0, gqy) + g_det * qc;
    // Screen translation by δ: M0 += δx M2, M1 += δy M2, μ += δ.
    let mean2d = vec2<f32>(dot(gm0, m2) + g_mean.x, dot(gm1, m2) + g_mean.y);

    let fx = prm.fx;
    let fy = prm.fy;
    let cx = prm.cx;
    let cy = prm.cy;
    let ga = vec3<f32>(fx * gm0.x, fy * gm1.x, cx * gm0.x + cy * gm1.x + gm2.x);
    let gb = vec3<f32>(fx * gm0.y, fy * gm1.y, cx * gm0.y + cy * gm1.y + gm2.y);
    var gc = vec3<f32>(fx * gm0.z, fy * gm1.z, cx * gm0.z + cy * gm1.z + gm2.z);
    let c = geo.c;
    gc.x += fx * g_mean.x / c.z;
    gc.y += fy * g_mean.y / c.z;
    gc.z -= (fx * c.x * g_mean.x + fy * c.y * g_mean.y) / (c.z * c.z);
    gc.z += g_view_depth;

    let wt = transpose(mat3x3<f32>(prm.rot0.xyz, prm.rot1.xyz, prm.rot2.xyz));
    let position = wt * gc;
    let log_scale = vec2<f32>(dot(ga, geo.a), dot(gb, geo.b));
    let g_tu = geo.scale.x * (wt * ga);
    let g_tv = geo.scale.y * (wt * gb);
    let g_tn = geo.normal_sign * vec3<f32>(grad_acc[b + 13u], grad_acc[b + 14u], grad_acc[b + 15u]);
    let g_unit = rotation_backward(geo.q_unit, mat3x3<f32>(g_tu, g_tv, g_tn));
    let qu = geo.q_unit;
    let rotation = (g_unit - qu * dot(qu, g_unit)) / geo.q_norm;

    // sigmoid' = σ (1 − σ), from the activated values the projection kept.
    let op = p.mean_op.z;
    raw_grads[out] = position.x;
    raw_grads[out + 1u] = position.y;
    raw_grads[out + 2u] = position.z;
    raw_grads[out + 3u] = log_scale.x;
    raw_grads[out + 4u] = log_scale.y;
    raw_grads[out + 5u] = rotation.x;
    raw_grads[out + 6u] = rotation.y;
    raw_grads[out + 7u] = rotation.z;
    raw_grads[out + 8u] = rotation.w;
    raw_grads[out + 9u] = g_opacity * op * (1.0 - op);
    let alb = vec3<f32>(p.f0.w, p.f1.x, p.f1.y);
    let g_alb = vec3<f32>(grad_acc[b + 16u], grad_acc[b + 17u], grad_acc[b + 18u]);
    let d_alb = g_alb * alb * (1.0 - alb);
    raw_grads[out + 10u] = d_alb.x;
    raw_grads[out + 11u] = d_alb.y;
    raw_grads[out + 12u] = d_alb.z;
    raw_grads[out + 13u] = grad_acc[b + 19u] * p.f1.z * (1.0 - p.f1.z);
    let ior_s = p.f1.w - 1.3;
    raw_grads[out + 14u] = grad_acc[b + 20u] * ior_s * (1.0 - ior_s);
    raw_grads[out + 15u] = length(mean2d);
}

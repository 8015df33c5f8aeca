// PolarDR backward (`shade_backward` in src/shading/mod.rs): per pixel, the gradient with
// respect to the raw normal, albedo, roughness and IoR, and the light's gradient added into
// per-texel sums (`add_grad`, appended from atomic_float.wgsl or atomic_cas.wgsl, over the
// levels-then-irradiance layout of `light`). The global lookups' backward passes are here; the
// light file's backward (light_global_backward.wgsl or light_gridmap_backward.wgsl) decides which
// a pixel uses. Compiled after shade_common.wgsl and the light file; one thread per pixel of the
// chunk; the forward intermediates are recomputed.

// Per pixel of the chunk, 9 values: dL/dS0, dL/dS1, dL/dS2 (RGB each).
@group(0) @binding(5) var<storage, read> upstream: array<f32>;
// Per pixel of the chunk, 8 values: dL/d raw normal (3), albedo (3), roughness, IoR.
@group(0) @binding(6) var<storage, read_write> pixel_grads: array<f32>;

fn upstream_rgb(i: u32, slot: u32) -> vec3<f32> {
    let o = i * 9u + slot * 3u;
    return vec3<f32>(upstream[o], upstream[o + 1u], upstream[o + 2u]);
}

fn add_texel_grad(t: u32, v: vec3<f32>) {
    add_grad(t * 3u, v.x);
    add_grad(t * 3u + 1u, v.y);
    add_grad(t * 3u + 2u, v.z);
}

// Backward of sampling `taps` scaled by `scale`: adds grad_out · w · scale into the texels,
// returns (Σ w · (texel · grad_out), dL/d dir) with the sum unscaled and the direction
// gradient scaled.
fn taps_backward(taps: Taps, grad_out: vec3<f32>, scale: f32) -> vec4<f32> {
    var value = 0.0;
    var grad_dir = vec3<f32>(0.0);
    for (var k = 0u; k < 4u; k++) {
        let t = taps.texel[k];
        let v = dot(texel_rgb(t), grad_out);
        value += taps.weight[k] * v;
        grad_dir += taps.grad[k] * (v * scale);
        add_texel_grad(t, grad_out * (taps.weight[k] * scale));
    }
    return vec4<f32>(grad_dir, value);
}

// Backward of `specular_light`: (dL/d dir, dL/d roughness).
fn specular_backward(dir: vec3<f32>, roughness: f32, grad_out: vec3<f32>) -> vec4<f32> {
    let blend = level_blend(roughness);
    let l0 = u32(blend.x);
    let a = taps_backward(cube_taps(l0, level_first(l0), dir), grad_out, 1.0 - blend.y);
    let b = taps_backward(cube_taps(l0 + 1u, level_first(l0 + 1u), dir), grad_out, blend.y);
    return vec4<f32>(a.xyz + b.xyz, (b.w - a.w) * blend.z);
}

// Backward of `irradiance_light`: (dL/d normal, dL/d IoR).
fn irradiance_backward(normal: vec3<f32>, ior: f32, grad_out: vec3<f32>) -> vec4<f32> {
    let coarsest = params.levels - 1u;
    let blend = irradiance_blend(ior);
    if blend.a == blend.b {
        let a = taps_backward(cube_taps(coarsest, irradiance_first(blend.a), normal), grad_out, 1.0);
        return vec4<f32>(a.xyz, 0.0);
    }
    let a = taps_backward(
        cube_taps(coarsest, irradiance_first(blend.a), normal), grad_out, 1.0 - blend.t);
    let b = taps_backward(cube_taps(coarsest, irradiance_first(blend.b), normal), grad_out, blend.t);
    return vec4<f32>(a.xyz + b.xyz, (b.w - a.w) * blend.dt);
}

@compute @workgroup_size(256)
fn shade_backward(
    @builtin(global_invocation_id) gid: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>,
) {
    let i = linear_index(gid, groups);
    if i >= params.pixels || active_pixels[i] == 0u {
        return;
    }
    let px = load_pixel(i);
    let f = shade_pixel(px);
    let up0 = upstream_rgb(i, 0u);
    let up1 = upstream_rgb(i, 1u);
    let up2 = upstream_rgb(i, 2u);

    // Stokes assembly.
    let projected = up1 * f.azimuth.cos2 + up2 * f.azimuth.sin2;
    let g_spec = up0 - projected * f.rho.spec.x;
    let g_diff = up0 - projected * f.rho.diff.x;
    let g_rho_s = -dot(f.specular, projected);
    let g_rho_d = -dot(f.diffuse, projected);
    let polarized = f.specular * f.rho.spec.x + f.diffuse * f.rho.diff.x;
    let g_cos2 = -dot(polarized, up1);
    let g_sin2 = -dot(polarized, up2);
    let g_a = g_cos2 * f.azimuth.dcos2.x + g_sin2 * f.azimuth.dsin2.x;
    let g_b = g_cos2 * f.azimuth.dcos2.y + g_sin2 * f.azimuth.dsin2.y;
    var g_n = g_a * px.stokes_x + g_b * px.stokes_y;
    var g_mu = g_rho_s * f.rho.spec.y + g_rho_d * f.rho.diff.y;
    var g_eta = g_rho_s * f.rho.spec.z + g_rho_d * f.rho.diff.z;

    // Diffuse = (1 − F) λ E_d(n).
    let g_albedo = g_diff * f.transmitted * f.irradiance;
    let g_irradiance = g_diff * f.transmitted * px.albedo;
    let g_fresnel = -dot(g_diff, px.albedo * f.irradiance);
    let irr = light_irradiance_backward(f.light, f.n, px.ior, g_irradiance);
    g_n += irr.xyz;
    g_eta += irr.w;
    g_mu += g_fresnel * f.dfresnel_dmu;
    var g_f0 = g_fresnel * f.dfresnel_df0;

    // Specular = (F0 A + B) L_s(2μn − o, r).
    let g_ws = dot(g_spec, f.radiance);
    let spec = light_specular_backward(f.light, f.mirror, px.roughness, g_spec * f.w_s);
    let g_mirror = spec.xyz;
    var g_roughness = spec.w;
    g_f0 += g_ws * f.lut.a.x;
    let g_a_lut = g_ws * f.f0;
    let g_b_lut = g_ws;
    g_mu += g_a_lut * f.lut.a.y + g_b_lut * f.lut.b.y;
    g_roughness += g_a_lut * f.lut.a.z + g_b_lut * f.lut.b.z;
    g_n += 2.0 * f.mu * g_mirror;
    g_mu += 2.0 * dot(f.n, g_mirror);
    if !f.mu_clamped {
        g_n += g_mu * px.view;
    }
    g_eta += g_f0 * f.df0;

    // n = flip · raw / |raw|.
    let g_unit = g_n * f.flip;
    let g_raw = (g_unit - f.unit_normal * dot(f.unit_normal, g_unit)) * f.inv_length;
    let o = i * 8u;
    pixel_grads[o] = g_raw.x;
    pixel_grads[o + 1u] = g_raw.y;
    pixel_grads[o + 2u] = g_raw.z;
    pixel_grads[o + 3u] = g_albedo.x;
    pixel_grads[o + 4u] = g_albedo.y;
    pixel_grads[o + 5u] = g_albedo.z;
    pixel_grads[o + 6u] = g_roughness;
    pixel_grads[o + 7u] = g_eta;
}

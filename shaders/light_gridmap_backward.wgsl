// Backward of light_gridmap.wgsl. GridMap is not differentiated (src/gridmap.rs): the blended
// lookups pass gradients to their inputs (direction, roughness, normal, IoR) but to no light;
// an escaping mirror ray passes its gradient to the global map as the global light does.
// Compiled after shade_backward.wgsl.

// Backward of `blended_sample` scaled by `scale`: (dL/d dir scaled, Σ w · (blend · grad_out)).
fn blended_sample_backward(
    w: ptr<function, array<f32, MAX_ANCHORS>>,
    taps: Taps,
    grad_out: vec3<f32>,
    scale: f32,
) -> vec4<f32> {
    var value = 0.0;
    var grad_dir = vec3<f32>(0.0);
    for (var k = 0u; k < 4u; k++) {
        let g = dot(blended_texel(w, taps.texel[k]), grad_out);
        value += taps.weight[k] * g;
        grad_dir += taps.grad[k] * (g * scale);
    }
    return vec4<f32>(grad_dir, value);
}

fn light_specular_backward(
    x: vec3<f32>,
    dir: vec3<f32>,
    roughness: f32,
    grad_out: vec3<f32>,
) -> vec4<f32> {
    if !occluded(x, dir) {
        return specular_backward(dir, roughness, grad_out);
    }
    var w = anchor_weights(x);
    let blend = level_blend(roughness);
    let l0 = u32(blend.x);
    let a = blended_sample_backward(&w, cube_taps(l0, level_first(l0), dir), grad_out, 1.0 - blend.y);
    let b = blended_sample_backward(
        &w, cube_taps(l0 + 1u, level_first(l0 + 1u), dir), grad_out, blend.y);
    return vec4<f32>(a.xyz + b.xyz, (b.w - a.w) * blend.z);
}

fn light_irradiance_backward(
    x: vec3<f32>,
    normal: vec3<f32>,
    ior: f32,
    grad_out: vec3<f32>,
) -> vec4<f32> {
    var w = anchor_weights(x);
    let coarsest = params.light_layout.x - 1u;
    let blend = irradiance_blend(ior);
    if blend.a == blend.b || blend.t == 0.0 {
        let a = blended_sample_backward(
            &w, cube_taps(coarsest, irradiance_first(blend.a), normal), grad_out, 1.0);
        return vec4<f32>(a.xyz, 0.0);
    }
    let a = blended_sample_backward(
        &w, cube_taps(coarsest, irradiance_first(blend.a), normal), grad_out, 1.0 - blend.t);
    let b = blended_sample_backward(
        &w, cube_taps(coarsest, irradiance_first(blend.b), normal), grad_out, blend.t);
    return vec4<f32>(a.xyz + b.xyz, (b.w - a.w) * blend.dt);
}

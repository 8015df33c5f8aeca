// Backward of light_gridmap.wgsl. GridMap is not differentiated (src/gridmap.rs): the blended
// lookups pass gradients to their inputs (direction, roughness, normal, IoR) but to no light;
// an escaping mirror ray passes its gradient to the global map as the global light does.
// Compiled after shade_backward.wgsl.

// Backward of `blended_sample` scaled by `scale`: (dL/d dir scaled, Σ w · (blend · grad_out)).
fn blended_sample_backward(
    b: Blend,
    taps: Taps,
    grad_out: vec3<f32>,
    scale: f32,
) -> vec4<f32> {
    let v = blended_taps(b, taps);
    let g = vec4<f32>(dot(v.t0, grad_out), dot(v.t1, grad_out), dot(v.t2, grad_out), dot(v.t3, grad_out));
    let grad_dir = (taps.grad[0] * g.x + taps.grad[1] * g.y + taps.grad[2] * g.z
        + taps.grad[3] * g.w) * scale;
    return vec4<f32>(grad_dir, dot(taps.weight, g));
}

fn light_specular_backward(
    at: LightPoint,
    dir: vec3<f32>,
    roughness: f32,
    grad_out: vec3<f32>,
) -> vec4<f32> {
    if !at.blocked {
        return specular_backward(dir, roughness, grad_out);
    }
    let weights = at.blend;
    let blend = level_blend(roughness);
    let l0 = u32(blend.x);
    let lo = blended_sample_backward(
        weights, cube_taps(l0, level_first(l0), dir), grad_out, 1.0 - blend.y);
    let hi = blended_sample_backward(
        weights, cube_taps(l0 + 1u, level_first(l0 + 1u), dir), grad_out, blend.y);
    return vec4<f32>(lo.xyz + hi.xyz, (hi.w - lo.w) * blend.z);
}

fn light_irradiance_backward(
    at: LightPoint,
    normal: vec3<f32>,
    ior: f32,
    grad_out: vec3<f32>,
) -> vec4<f32> {
    let weights = at.blend;
    let coarsest = params.levels - 1u;
    let blend = irradiance_blend(ior);
    if blend.a == blend.b || blend.t == 0.0 {
        let first = blended_sample_backward(
            weights, cube_taps(coarsest, irradiance_first(blend.a), normal), grad_out, 1.0);
        return vec4<f32>(first.xyz, 0.0);
    }
    let first = blended_sample_backward(
        weights, cube_taps(coarsest, irradiance_first(blend.a), normal), grad_out, 1.0 - blend.t);
    let second = blended_sample_backward(
        weights, cube_taps(coarsest, irradiance_first(blend.b), normal), grad_out, blend.t);
    return vec4<f32>(first.xyz + second.xyz, (second.w - first.w) * blend.dt);
}

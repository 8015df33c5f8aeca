// Backward of light_global.wgsl: the global lookups' backward passes of shade_backward.wgsl,
// which add the light's gradient into its texel sums. Compiled after shade_backward.wgsl.

fn light_specular_backward(
    at: LightPoint,
    dir: vec3<f32>,
    roughness: f32,
    grad_out: vec3<f32>,
) -> vec4<f32> {
    return specular_backward(dir, roughness, grad_out);
}

fn light_irradiance_backward(
    at: LightPoint,
    normal: vec3<f32>,
    ior: f32,
    grad_out: vec3<f32>,
) -> vec4<f32> {
    return irradiance_backward(normal, ior, grad_out);
}

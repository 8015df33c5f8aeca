// The global environment as every pixel's light (`PreparedEnv` as a `LightProbe`): the surface
// point is ignored. Compiled after shade_common.wgsl, whose lookups it calls; threading as there.

fn light_specular(x: vec3<f32>, dir: vec3<f32>, roughness: f32) -> vec3<f32> {
    return specular_light(dir, roughness);
}

fn light_irradiance(x: vec3<f32>, normal: vec3<f32>, ior: f32) -> vec3<f32> {
    return irradiance_light(normal, ior);
}

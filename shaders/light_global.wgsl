// The global environment as every pixel's light (`PreparedEnv` as a `LightProbe`): the surface
// point is ignored. Compiled after shade_common.wgsl, whose lookups it calls; threading as there.

// What the light needs to know of a pixel's surface point: nothing (WGSL structs need a member).
struct LightPoint {
    unused: u32,
}

fn light_point(x: vec3<f32>, mirror: vec3<f32>) -> LightPoint {
    return LightPoint(0u);
}

fn light_specular(at: LightPoint, dir: vec3<f32>, roughness: f32) -> vec3<f32> {
    return specular_light(dir, roughness);
}

fn light_irradiance(at: LightPoint, normal: vec3<f32>, ior: f32) -> vec3<f32> {
    return irradiance_light(normal, ior);
}

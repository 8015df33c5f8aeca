// PolarDR forward: the Stokes vector of every shaded pixel (`shade` in src/shading/mod.rs).
// Compiled after shade_common.wgsl; one thread per pixel of the chunk.

// Per pixel of the chunk, 15 values: S0, S1, S2, diffuse, specular (RGB each); zero where the
// pixel is not shaded.
@group(0) @binding(5) var<storage, read_write> stokes: array<f32>;

fn store_rgb(i: u32, slot: u32, v: vec3<f32>) {
    let o = i * 15u + slot * 3u;
    stokes[o] = v.x;
    stokes[o + 1u] = v.y;
    stokes[o + 2u] = v.z;
}

@compute @workgroup_size(256)
fn shade(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = linear_index(gid, groups);
    if i >= params.pixels || active_pixels[i] == 0u {
        return;
    }
    let s = shade_pixel(load_pixel(i));
    let polarized = s.specular * s.rho.spec.x + s.diffuse * s.rho.diff.x;
    store_rgb(i, 0u, s.specular + s.diffuse);
    store_rgb(i, 1u, -polarized * s.azimuth.cos2);
    store_rgb(i, 2u, -polarized * s.azimuth.sin2);
    store_rgb(i, 3u, s.diffuse);
    store_rgb(i, 4u, s.specular);
}

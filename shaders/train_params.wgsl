// The step's uniform parameters and pixel indexing, shared by the resident trainer's per-pixel
// kernels (train_pixels.wgsl, train_loss.wgsl; compiled after train_common.wgsl). No entry
// points. Threading of the per-pixel kernels: one thread per pixel, 256-thread workgroups on a
// 2-D grid (`pixel_index`); per-workgroup partial sums go to `partials[slot · groups + workgroup]`.

struct TrainParams {
    // width, height, pixels, workgroups of a per-pixel kernel (partial sums per slot).
    dims: vec4<u32>,
    // shaded (PolarDR or warm-up stage: 1; plain 2DGS: 0), S1/S2 targets used (1/0), a
    // polarizer angle θ applies (1/0), unused.
    mode: vec4<u32>,
    // cos 2θ, sin 2θ, unpolarized scale k (½ for a view behind a polarizer fitted as
    // unpolarized, else 1), weight of the extra L1 on Î(θ) (partial views in the PolarDR stage).
    theta: vec4<f32>,
    // λ_ssim, λ_stokes on S1/S2 (0 when unused), λ_mask, λ_normal_smooth (0 when unused).
    weights: vec4<f32>,
    // λ_depth_normal, α-normalization ε (depth normals are defined where α > ε), α above which
    // a pixel is shaded, unused.
    weights2: vec4<f32>,
    // Camera-to-world rotation (columns: the OpenCV right, down, forward axes), camera centre.
    rot0: vec4<f32>,
    rot1: vec4<f32>,
    rot2: vec4<f32>,
    origin: vec4<f32>,
    // fx, fy, cx, cy.
    intr: vec4<f32>,
    // The normalized 1-D Gaussian window of SSIM (11 taps, σ = 1.5; `loss::ssim::gaussian_kernel`).
    gauss: array<vec4<f32>, 3>,
}

@group(0) @binding(0) var<uniform> train: TrainParams;

fn pixel_index(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.x + gid.y * nwg.x * THREADS;
}

fn workgroup_index(wg: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return wg.x + wg.y * nwg.x;
}

// Camera-space (OpenCV, z = 1) direction of pixel p's centre.
fn camera_dir(p: u32) -> vec3<f32> {
    let x = f32(p % train.dims.x) + 0.5;
    let y = f32(p / train.dims.x) + 0.5;
    return vec3<f32>((x - train.intr.z) / train.intr.x, (y - train.intr.w) / train.intr.y, 1.0);
}

fn to_world(v: vec3<f32>) -> vec3<f32> {
    return train.rot0.xyz * v.x + train.rot1.xyz * v.y + train.rot2.xyz * v.z;
}

fn to_camera(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(train.rot0.xyz, v), dot(train.rot1.xyz, v), dot(train.rot2.xyz, v));
}

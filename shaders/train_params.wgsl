// The step's uniform parameters and pixel indexing, shared by the resident trainer's per-pixel
// kernels (train_pixels.wgsl, train_loss.wgsl; compiled after train_common.wgsl). No entry
// points. Threading of the per-pixel kernels: one thread per pixel, 256-thread workgroups on a
// 2-D grid (`pixel_index`); per-workgroup partial sums go to `partials[slot · groups + workgroup]`.

struct TrainParams {
    // Image size, pixels, and workgroups of a per-pixel kernel (partial sums per slot).
    width: u32,
    height: u32,
    pixels: u32,
    groups: u32,
    // Flags (1/0): shaded (PolarDR or warm-up stage; plain 2DGS: 0), S1/S2 targets used, a
    // polarizer angle θ applies; the weight of the AoLP prior (0 when unused).
    shaded: u32,
    stokes_loss: u32,
    has_theta: u32,
    lambda_aolp: f32,
    // cos 2θ, sin 2θ, the unpolarized scale k (½ for a view behind a polarizer fitted as
    // unpolarized, else 1), the weight of the extra L1 on Î(θ) (partial views in the PolarDR
    // stage).
    cos_2theta: f32,
    sin_2theta: f32,
    unpolarized_scale: f32,
    lambda_extra_l1: f32,
    // The loss weights (λ_stokes, λ_normal_smooth and λ_depth_normal 0 when unused).
    lambda_ssim: f32,
    lambda_stokes: f32,
    lambda_mask: f32,
    lambda_normal_smooth: f32,
    lambda_depth_normal: f32,
    // α-normalization ε (depth normals are defined where α > ε), α above which a pixel is shaded.
    normalize_alpha_min: f32,
    shade_alpha_min: f32,
    // λ_distortion / radius² (0 when unused): the depth distortion in units of the object's radius.
    lambda_distortion: f32,
    // Camera-to-world rotation (columns: the OpenCV right, down, forward axes), camera centre.
    rot0: vec4<f32>,
    rot1: vec4<f32>,
    rot2: vec4<f32>,
    origin: vec4<f32>,
    // Focal lengths and principal point in pixels.
    fx: f32,
    fy: f32,
    cx: f32,
    cy: f32,
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
    let x = f32(p % train.width) + 0.5;
    let y = f32(p / train.width) + 0.5;
    return vec3<f32>((x - train.cx) / train.fx, (y - train.cy) / train.fy, 1.0);
}

fn to_world(v: vec3<f32>) -> vec3<f32> {
    return train.rot0.xyz * v.x + train.rot1.xyz * v.y + train.rot2.xyz * v.z;
}

fn to_camera(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(train.rot0.xyz, v), dot(train.rot1.xyz, v), dot(train.rot2.xyz, v));
}

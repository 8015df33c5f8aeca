// The resident trainer's parameter update (after train_common.wgsl): `adam` is one Adam step on
// every raw surfel value of an unfrozen group, a port of `Adam::step` in f32
// (m ← β1 m + (1 − β1) g, v ← β2 v + (1 − β2) g²,
// p ← p − lr · m / (1 − β1ᵗ) / (√(v / (1 − β2ᵗ)) + ε)), with the densification statistics of
// `DensifyStats::add_view`; `accumulate_light` adds the step's light gradient into the sums that
// wait for the next environment update. Both do nothing when the step's tile entries overflowed
// their buffer (the host reruns the step) and `adam` flags non-finite parameters in the status.
// Threading: one thread per surfel (`adam`) or per light value (`accumulate_light`), 256-thread
// workgroups on a 2-D grid.

struct AdamParams {
    // Surfels to update.
    surfels: u32,
    pad0: u32,
    pad1: u32,
    pad2: u32,
    // Adam's β1, β2 and ε; the densification statistics' pixel-to-NDC factor of the screen-space
    // gradient (½ max(width, height)).
    beta1: f32,
    beta2: f32,
    eps: f32,
    ndc_scale: f32,
    // Per raw value slot (the layout of `Raw`, 16 slots): learning rate, 1 / (1 − β1ᵗ),
    // 1 / (1 − β2ᵗ) of its group, and whether the group is trained this step (1) or frozen (0).
    lr: array<vec4<f32>, 4>,
    bias1: array<vec4<f32>, 4>,
    bias2: array<vec4<f32>, 4>,
    trained: array<vec4<u32>, 4>,
}

@group(0) @binding(0) var<uniform> adam_params: AdamParams;
// Per surfel 16 values in the layout of `Raw` (common.wgsl): parameters, first and second moments.
@group(0) @binding(1) var<storage, read_write> raw: array<f32>;
@group(0) @binding(2) var<storage, read_write> moment1: array<f32>;
@group(0) @binding(3) var<storage, read_write> moment2: array<f32>;
// Per surfel 16 values: the raw gradients of project_backward.wgsl (position 3, log scale 2,
// rotation 4, opacity, albedo 3, roughness, IoR, |dL/d projected centre| in pixels).
@group(0) @binding(4) var<storage, read> raw_grad: array<f32>;
@group(0) @binding(5) var<storage, read_write> grad_sum: array<f32>;
@group(0) @binding(6) var<storage, read_write> seen: array<u32>;
@group(0) @binding(7) var<storage, read_write> step_status: array<atomic<u32>>;
@group(0) @binding(8) var<storage, read> light_step: array<f32>;
@group(0) @binding(9) var<storage, read_write> light_pending: array<f32>;

// The raw gradient of each `Raw` slot (16: none).
const GRAD_OF_SLOT = array<u32, 16>(0u, 1u, 2u, 9u, 5u, 6u, 7u, 8u, 3u, 4u, 13u, 14u, 10u, 11u, 12u, 16u);
const MEAN2D_GRAD: u32 = 15u;

fn index_1d(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.x + gid.y * nwg.x * THREADS;
}

@compute @workgroup_size(THREADS)
fn adam(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = index_1d(gid, nwg);
    if i >= adam_params.surfels || atomicLoad(&step_status[STATUS_OVERFLOW]) != 0u {
        return;
    }
    let beta1 = adam_params.beta1;
    let beta2 = adam_params.beta2;
    let eps = adam_params.eps;
    var finite = true;
    for (var slot = 0u; slot < 15u; slot++) {
        let q = slot / 4u;
        let r = slot % 4u;
        if adam_params.trained[q][r] == 0u {
            continue;
        }
        let g = raw_grad[16u * i + GRAD_OF_SLOT[slot]];
        let o = 16u * i + slot;
        let m = beta1 * moment1[o] + (1.0 - beta1) * g;
        let v = beta2 * moment2[o] + (1.0 - beta2) * g * g;
        let step = adam_params.lr[q][r] * (m * adam_params.bias1[q][r])
            / (sqrt(v * adam_params.bias2[q][r]) + eps);
        let value = raw[o] - step;
        moment1[o] = m;
        moment2[o] = v;
        raw[o] = value;
        finite = finite && abs(value) <= BIG_F;
    }
    if !finite {
        atomicOr(&step_status[STATUS_NONFINITE], 1u);
    }
    let g2d = raw_grad[16u * i + MEAN2D_GRAD];
    if g2d > 0.0 {
        grad_sum[i] += g2d * adam_params.ndc_scale;
        seen[i] += 1u;
    }
}

@compute @workgroup_size(THREADS)
fn accumulate_light(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = index_1d(gid, nwg);
    if i >= arrayLength(&light_pending) || atomicLoad(&step_status[STATUS_OVERFLOW]) != 0u {
        return;
    }
    light_pending[i] += light_step[i];
}

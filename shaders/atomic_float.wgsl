// `add_grad` for adapters with SHADER_FLOAT32_ATOMIC: one native float atomic add per value.
// Appended to rasterize_backward.wgsl and shade_backward.wgsl; threading as there.

@group(0) @binding(8) var<storage, read_write> grad_acc: array<atomic<f32>>;

fn add_grad(i: u32, v: f32) {
    if v != 0.0 {
        atomicAdd(&grad_acc[i], v);
    }
}

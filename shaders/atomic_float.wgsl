// `add_grad` for adapters with SHADER_FLOAT32_ATOMIC: one native float atomic add per value.
// Part of the rasterize_backward and shade_backward kernels with float atomics
// (`Part::AddGrad` in src/gpu/shaders.rs); threading as there.

@group(0) @binding(8) var<storage, read_write> grad_acc: array<atomic<f32>>;

fn add_grad(i: u32, v: f32) {
    if v != 0.0 {
        atomicAdd(&grad_acc[i], v);
    }
}

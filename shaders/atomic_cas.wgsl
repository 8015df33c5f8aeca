// `add_grad` for adapters without float atomics: a compare-and-swap loop on the f32 bit pattern
// held in an atomic<u32> (retries until no other thread wrote in between).
// Part of the rasterize_backward and shade_backward kernels without float atomics
// (`Part::AddGrad` in src/gpu/shaders.rs); threading as there.

@group(0) @binding(8) var<storage, read_write> grad_acc: array<atomic<u32>>;

fn add_grad(i: u32, v: f32) {
    if v == 0.0 {
        return;
    }
    var old = atomicLoad(&grad_acc[i]);
    loop {
        let next = bitcast<u32>(bitcast<f32>(old) + v);
        let r = atomicCompareExchangeWeak(&grad_acc[i], old, next);
        if r.exchanged {
            break;
        }
        old = r.old_value;
    }
}

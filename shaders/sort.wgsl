// One compare-and-swap stage of a bitonic sort of the binning entries (vec4<u32>: tile, depth bits,
// surfel), ascending by (tile, depth, surfel): each tile's run is then front to back, ties broken by
// surfel index like the cpu backend. The host dispatches the stages (k = 2, 4, …, n; j = k/2, …, 1)
// in order over a power-of-two padded array; each stage reads its (k, j) from its own slice of a
// uniform buffer.
// Threading: one thread per compared pair (n/2 threads), 256-thread workgroups on a 2-D grid.

struct Stage {
    k: u32,
    j: u32,
    pairs: u32,
    unused: u32,
}

@group(0) @binding(0) var<uniform> stage: Stage;
@group(0) @binding(1) var<storage, read_write> entries: array<vec4<u32>>;

fn less(a: vec4<u32>, b: vec4<u32>) -> bool {
    if a.x != b.x {
        return a.x < b.x;
    }
    if a.y != b.y {
        return a.y < b.y;
    }
    return a.z < b.z;
}

@compute @workgroup_size(256)
fn bitonic_step(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = linear_index(gid, nwg);
    if i >= stage.pairs {
        return;
    }
    let j = stage.j;
    let lo = ((i & ~(j - 1u)) << 1u) | (i & (j - 1u));
    let hi = lo | j;
    let a = entries[lo];
    let b = entries[hi];
    let ascending = (lo & stage.k) == 0u;
    let swap = select(less(a, b), less(b, a), ascending);
    if swap {
        entries[lo] = b;
        entries[hi] = a;
    }
}

// `walk_length` for adapters without subgroup operations: each thread of rasterize_backward walks
// its own composited entries only. Appended to rasterize_backward.wgsl.

fn walk_length(n: u32) -> u32 {
    return n;
}

// `walk_length` for adapters without subgroup operations: each thread of rasterize_backward walks
// its own composited entries only. Part of the rasterize_backward kernel where the adapter has
// no subgroups (`Part::WalkLength` in src/gpu/shaders.rs).

fn walk_length(n: u32) -> u32 {
    return n;
}

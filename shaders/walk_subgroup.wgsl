// `walk_length` with subgroup operations (wgpu's SUBGROUP feature): the threads of a subgroup walk
// their tile's list in step, from the furthest entry any of them composited (each skips the
// entries beyond its own), so at every step they read the same entry and projected surfel instead
// of scattered ones. Measured on lavapipe: rasterize_backward 15–25% faster. Part of the
// rasterize_backward kernel where the adapter has subgroups (`Part::WalkLength` in
// src/gpu/shaders.rs); rasterize_backward.wgsl calls it before any thread of the subgroup returns.

fn walk_length(n: u32) -> u32 {
    return subgroupMax(n);
}

// Tile binning around the sort (radix_sort.wgsl): `emit` writes one (tile, depth, surfel) entry per
// tile of the band that a projected surfel's pixel box touches (tiles numbered from the band's
// first row), at the surfel's offset from the exclusive scan of the tile counts (on the host, or
// on the device: scan.wgsl), so entries come in surfel order; entries beyond the buffer's capacity
// are dropped (the device scan flags that, and the step is rerun with more room). After the sort,
// `tile_ranges` marks where each tile's run of entries starts and ends (the ranges buffer is
// cleared to zero first, so empty tiles are 0..0); `entry_count[0]` holds the number of entries.
// Threading: one thread per surfel (`emit`) or per entry (`tile_ranges`), 256-thread
// workgroups on a 2-D grid. Entries are vec4<u32>(tile, depth bits, surfel, 0): the centre depth is
// positive, so its f32 bit pattern orders like its value.

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> proj: array<Proj>;
@group(0) @binding(2) var<storage, read> offsets: array<u32>;
@group(0) @binding(3) var<storage, read_write> entries: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read_write> ranges: array<vec2<u32>>;
@group(0) @binding(5) var<storage, read> entry_count: array<u32>;

@compute @workgroup_size(256)
fn emit(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = linear_index(gid, nwg);
    if i >= params.surfels {
        return;
    }
    let p = proj[i];
    let r = p.rect;
    if r.x >= r.z {
        return;
    }
    let depth_bits = bitcast<u32>(p.q1.w);
    let tiles_x = params.tiles_x;
    let rows = band_tile_rows(r, params);
    let capacity = arrayLength(&entries);
    var o = offsets[i];
    for (var ty = rows.x; ty < rows.y; ty++) {
        for (var tx = r.x / TILE; tx <= (r.z - 1u) / TILE; tx++) {
            if o < capacity {
                entries[o] = vec4<u32>((ty - params.band_tile_first) * tiles_x + tx, depth_bits, i, 0u);
            }
            o++;
        }
    }
}

@compute @workgroup_size(256)
fn tile_ranges(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    let i = linear_index(gid, nwg);
    let n = min(entry_count[0], arrayLength(&entries));
    if i >= n {
        return;
    }
    let t = entries[i].x;
    if i == 0u || entries[i - 1u].x != t {
        ranges[t].x = i;
    }
    if i + 1u == n || entries[i + 1u].x != t {
        ranges[t].y = i + 1u;
    }
}

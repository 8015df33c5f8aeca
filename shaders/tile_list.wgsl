// Shared by the two rasterization kernels (rasterize.wgsl, rasterize_backward.wgsl, each compiled
// after common.wgsl and this; src/gpu/shaders.rs): the bindings of the band's sorted tile lists
// and the pixel a thread owns. Threading: one 8×8 workgroup per tile of the band, one thread per
// pixel.

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> entries: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> ranges: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> proj: array<Proj>;

// The pixel of one thread.
struct TilePixel {
    x: u32,
    y: u32,
    // Inside the image (the last tiles of a row or column may stick out).
    inside: bool,
    // Index into the band's per-pixel buffers (which hold the band's rows only).
    pix: u32,
    // The tile's run [start, end) of sorted entries.
    range: vec2<u32>,
    // Pixel centre.
    centre: vec2<f32>,
}

fn tile_pixel(wg: vec3<u32>, lid: vec3<u32>, prm: Params) -> TilePixel {
    var tp: TilePixel;
    tp.x = wg.x * TILE + lid.x;
    tp.y = (prm.band_tile_first + wg.y) * TILE + lid.y;
    tp.inside = tp.x < prm.width && tp.y < prm.height;
    tp.pix = (tp.y - prm.band_pixel_first) * prm.width + tp.x;
    tp.range = ranges[wg.y * prm.tiles_x + wg.x];
    tp.centre = vec2<f32>(f32(tp.x) + 0.5, f32(tp.y) + 0.5);
    return tp;
}

//! What the rasterization kernels read besides their inputs' values: the uniform parameters
//! (`Params` of shaders/common.wgsl: the view, the raster settings, the band), the surfels' raw
//! parameters in the kernels' layout (`Raw`), and the sizes of the kernels' per-surfel,
//! per-entry and per-pixel records. The resident trainer (`super::train`) uses the same.
//!
//! Threading: plain values, converted on the calling thread.

use bytemuck::{Pod, Zeroable};

use super::band::Band;
pub(super) use super::band::TILE;
use super::layout::wgsl_mirror;
use crate::core::camera::Camera;
use crate::core::raster::RasterSettings;
use crate::core::surfels::Surfels;

/// Per-surfel gradient accumulators (`NUM_ACC`).
pub(super) const NUM_ACC: u64 = 22;
/// Per-pixel forward outputs (`NUM_OUT`).
pub(super) const NUM_OUT: usize = 11;
/// Per-surfel raw gradient outputs of `project_backward`.
pub(super) const NUM_RAW_GRAD: usize = 16;
/// Bytes of one `Proj` (7 × vec4).
pub(super) const PROJ_BYTES: u64 = 112;
/// Bytes of one sort entry (vec4<u32>).
pub(super) const ENTRY_BYTES: u64 = 16;

wgsl_mirror! {
    /// `Params` of shaders/common.wgsl.
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    pub(super) struct ParamsGpu = "Params" {
        rot0: [f32; 4],
        rot1: [f32; 4],
        rot2: [f32; 4],
        trans: [f32; 4],
        origin: [f32; 4],
        fx: f32,
        fy: f32,
        cx: f32,
        cy: f32,
        width: u32,
        height: u32,
        tiles_x: u32,
        tiles_y: u32,
        surfels: u32,
        pad0: u32,
        pad1: u32,
        lowpass: u32,
        near: f32,
        alpha_min: f32,
        alpha_max: f32,
        transmittance_min: f32,
        lowpass_sigma_px: f32,
        inv_lowpass_sigma2: f32,
        normalize_alpha_min: f32,
        pad2: f32,
        band_tile_first: u32,
        band_tile_end: u32,
        band_pixel_first: u32,
        band_pixel_rows: u32,
    }
}

impl ParamsGpu {
    /// The parameters of a whole image of `camera` (one band).
    pub(super) fn whole_image(camera: &Camera, settings: &RasterSettings, surfels: u32) -> Self {
        Self::new(camera, settings, surfels, Band::whole(camera.height))
    }

    /// The parameters of `band` of an image of `camera`.
    pub(super) fn new(
        camera: &Camera,
        settings: &RasterSettings,
        surfels: u32,
        band: Band,
    ) -> Self {
        let (rot, trans) = camera.world_to_camera_opencv();
        let v4 = |v: glam::DVec3| [v.x as f32, v.y as f32, v.z as f32, 0.0];
        let sigma = settings.lowpass_sigma_px;
        let lowpass = sigma > 0.0;
        ParamsGpu {
            rot0: v4(rot.x_axis),
            rot1: v4(rot.y_axis),
            rot2: v4(rot.z_axis),
            trans: v4(trans),
            origin: v4(camera.origin()),
            fx: camera.fx as f32,
            fy: camera.fy as f32,
            cx: camera.cx as f32,
            cy: camera.cy as f32,
            width: camera.width,
            height: camera.height,
            tiles_x: camera.width.div_ceil(TILE),
            tiles_y: camera.height.div_ceil(TILE),
            surfels,
            pad0: 0,
            pad1: 0,
            lowpass: lowpass as u32,
            near: settings.near as f32,
            alpha_min: settings.alpha_min as f32,
            alpha_max: settings.alpha_max as f32,
            transmittance_min: settings.transmittance_min as f32,
            lowpass_sigma_px: sigma as f32,
            inv_lowpass_sigma2: if lowpass {
                (1.0 / (sigma * sigma)) as f32
            } else {
                0.0
            },
            normalize_alpha_min: settings.normalize_alpha_min as f32,
            pad2: 0.0,
            band_tile_first: band.first,
            band_tile_end: band.end,
            band_pixel_first: band.first * TILE,
            band_pixel_rows: band.pixel_rows(camera.height),
        }
    }
}

wgsl_mirror! {
    /// `Raw` of shaders/common.wgsl: a surfel's raw parameters, 16 values.
    #[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
    pub(super) struct RawGpu = "Raw" {
        pub(super) pos_op: [f32; 4],
        pub(super) quat: [f32; 4],
        pub(super) scale_rough_ior: [f32; 4],
        pub(super) albedo: [f32; 4],
    }
}

/// The surfels' raw parameters in the kernels' layout (f32).
pub(super) fn raw_surfels(surfels: &Surfels) -> Vec<RawGpu> {
    let f = |v: f64| v as f32;
    (0..surfels.len())
        .map(|i| {
            let p = surfels.position[i];
            let s = surfels.log_scale[i];
            let a = surfels.albedo[i];
            RawGpu {
                pos_op: [f(p[0]), f(p[1]), f(p[2]), f(surfels.opacity[i])],
                quat: surfels.rotation[i].map(f),
                scale_rough_ior: [f(s[0]), f(s[1]), f(surfels.roughness[i]), f(surfels.ior[i])],
                albedo: [f(a[0]), f(a[1]), f(a[2]), 0.0],
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::layout::assert_mirrors;
    use crate::gpu::shaders;

    #[test]
    fn params_and_raw_surfels_mirror_the_wgsl() {
        assert_mirrors::<ParamsGpu>(&shaders::PROJECT);
        assert_mirrors::<RawGpu>(&shaders::PROJECT);
    }
}

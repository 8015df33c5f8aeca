//! The compute engine's interface, below the rasterizer and the shader that it offers together:
//! [`Backend`] rasterizes surfels into G-buffers and back ([`crate::core::raster`]), shades
//! G-buffers with PolarDR ([`crate::core::shading`]'s host code unless the engine has its own),
//! may fuse rendered depth into a TSDF on its own device, and reports its device's stage times.
//! The host engines' implementations are in [`host`]; the gpu engine's is `gpu::GpuBackend`.

pub mod host;

use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::envmap::EnvGrad;
use crate::core::light::LightProbe;
use crate::core::loss::LossPrecision;
use crate::core::mesh::{GridLayout, ScalarGrid};
use crate::core::raster::{
    GBufferGrads, RasterError, RasterGrads, RasterSettings, Rasterized, StageTime,
};
use crate::core::shading::{
    self, GBufferGrad, SavedShading, ShadingBuffers, ShadingError, StokesImage, StokesImageGrad,
};
use crate::core::surfels::Surfels;

/// A compute engine: rasterization, shading, depth fusion.
pub trait Backend: Send + Sync {
    fn name(&self) -> &'static str;
    /// The name plus what it runs on (for logs and `phygap bench`).
    fn description(&self) -> String {
        self.name().to_string()
    }
    fn forward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError>;
    fn backward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
        forward: &Rasterized,
        upstream: &GBufferGrads,
    ) -> Result<RasterGrads, RasterError>;
    /// The TSDF of the depth and opacity of `surfels` seen from every camera, fused into `grid`
    /// on the backend's own device, so the depth maps never leave it; `None` (the default) where
    /// the backend has no such fusion, and the caller renders the views with [`Self::forward`]
    /// and fuses them on the host ([`crate::core::mesh::fuse_tsdf`]). The fusion follows the
    /// host's rules (`core::mesh::tsdf`) but is dense: every voxel some view observes is known,
    /// where the host fuses only the blocks near the surface; marching cubes gives the same
    /// surface from either.
    fn fuse_depth(
        &self,
        _surfels: &Surfels,
        _cameras: &[Camera],
        _settings: &RasterSettings,
        _grid: &GridLayout,
    ) -> Option<Result<ScalarGrid, RasterError>> {
        None
    }
    /// The precision of the losses a host step computes for this backend where the computation
    /// allows a choice (SSIM, [`crate::core::loss::ssim_in`]): f64 (the default, the reference's)
    /// unless the engine trades it for speed.
    fn loss_precision(&self) -> LossPrecision {
        LossPrecision::F64
    }
    /// Device time per stage since the last call, where the backend measures it (the gpu
    /// backend with [`crate::gpu::GpuOptions::profile`]); empty otherwise.
    fn take_stage_times(&self) -> Vec<StageTime> {
        Vec::new()
    }
    /// PolarDR shading of one view's G-buffers ([`shading::shade_image`], the default); a
    /// backend may run it on its own device.
    fn shade(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
    ) -> Result<StokesImage, ShadingError> {
        shading::shade_image(camera, buffers, light, lut)
    }
    /// [`Self::shade`] for a training step, which calls [`Self::shade_backward_saved`] next:
    /// the host's shader keeps its forward intermediates ([`shading::shade_image_saved`]) so the
    /// backward pass does not look the light up again; a backend that shades on its own device
    /// keeps nothing (`None`).
    fn shade_saved(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
    ) -> Result<(StokesImage, Option<SavedShading>), ShadingError> {
        let (image, saved) = shading::shade_image_saved(camera, buffers, light, lut)?;
        Ok((image, Some(saved)))
    }
    /// Backward of [`Self::shade_saved`]: from its intermediates where it kept them, else
    /// [`Self::shade_backward`].
    fn shade_backward_saved(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
        saved: Option<&SavedShading>,
        upstream: &StokesImageGrad,
    ) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
        match saved {
            Some(saved) => {
                shading::shade_image_backward_saved(camera, buffers, light, lut, saved, upstream)
            }
            None => self.shade_backward(camera, buffers, light, lut, upstream),
        }
    }
    /// Backward of [`Self::shade`] ([`shading::shade_image_backward`], the default).
    fn shade_backward(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
        upstream: &StokesImageGrad,
    ) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
        shading::shade_image_backward(camera, buffers, light, lut, upstream)
    }
}

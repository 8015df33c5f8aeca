//! Rendering one view of a reconstruction: rasterize surfels into G-buffers, then shade them with
//! PolarDR. Outputs are premultiplied by the rendered opacity α, as the captures are (silhouette
//! pixels are coverage-weighted, background is black).
//!
//! Used by training (forward half of a step), evaluation, `phygap render` and relighting.
//!
//! Threading: the shading inputs are gathered from the G-buffers in parallel over pixels (rayon).

use glam::DVec3;
use rayon::prelude::*;
use thiserror::Error;

use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::engine::Backend;
use crate::core::light::LightProbe;
use crate::core::raster::{GBuffers, RasterError, RasterSettings, Rasterized};
use crate::core::shading::{ShadingBuffers, ShadingError, StokesImage};
use crate::core::surfels::Surfels;

/// Pixels whose opacity is at most this are not shaded (they are background).
pub const SHADE_ALPHA_MIN: f64 = 1e-4;

#[derive(Debug, Error)]
pub enum RenderError {
    #[error(transparent)]
    Raster(#[from] RasterError),
    #[error(transparent)]
    Shading(#[from] ShadingError),
}

/// The G-buffers of a view converted to the shader's per-pixel layout, owned.
pub struct ShadingInputs {
    pub normal: Vec<DVec3>,
    pub albedo: Vec<DVec3>,
    pub position: Vec<DVec3>,
    pub active: Vec<bool>,
}

impl ShadingInputs {
    /// Surface points are back-projected from the α-normalized depth; pixels with α at most
    /// [`SHADE_ALPHA_MIN`] are inactive.
    pub fn new(g: &GBuffers, camera: &Camera) -> Self {
        let w = g.width;
        ShadingInputs {
            normal: g.normal.par_iter().map(|n| DVec3::from_array(*n)).collect(),
            albedo: g.albedo.par_iter().map(|a| DVec3::from_array(*a)).collect(),
            position: g
                .depth
                .par_iter()
                .enumerate()
                .map(|(p, &z)| {
                    let (u, v) = ((p % w) as f64 + 0.5, (p / w) as f64 + 0.5);
                    camera.backproject(u, v, z)
                })
                .collect(),
            active: g.alpha.par_iter().map(|&a| a > SHADE_ALPHA_MIN).collect(),
        }
    }

    /// Borrowed view for the shader.
    pub fn buffers<'a>(&'a self, g: &'a GBuffers) -> ShadingBuffers<'a> {
        ShadingBuffers {
            normal: &self.normal,
            albedo: &self.albedo,
            roughness: &g.roughness,
            ior: &g.ior,
            position: Some(&self.position),
            active: Some(&self.active),
        }
    }
}

/// A rendered view: G-buffers and the shaded (not yet α-premultiplied) Stokes images.
pub struct RenderedView {
    pub raster: Rasterized,
    pub inputs: ShadingInputs,
    /// Radiance of the surface at each pixel (not multiplied by α).
    pub shaded: StokesImage,
}

impl RenderedView {
    pub fn gbuffers(&self) -> &GBuffers {
        &self.raster.gbuffers
    }

    /// An RGB image of a shaded quantity premultiplied by α, interleaved f64.
    pub fn premultiplied(&self, values: &[DVec3]) -> Vec<f64> {
        values
            .iter()
            .zip(&self.raster.gbuffers.alpha)
            .flat_map(|(v, &a)| (*v * a).to_array())
            .collect()
    }
}

/// What a render needs besides the camera.
pub struct Scene<'a> {
    pub surfels: &'a Surfels,
    pub light: &'a dyn LightProbe,
    pub lut: &'a BrdfLut,
    pub backend: &'a dyn Backend,
    pub settings: RasterSettings,
}

impl Scene<'_> {
    /// Rasterizes and shades one view.
    pub fn render(&self, camera: &Camera) -> Result<RenderedView, RenderError> {
        let raster = self.backend.forward(self.surfels, camera, &self.settings)?;
        let inputs = ShadingInputs::new(&raster.gbuffers, camera);
        let shaded = self.backend.shade(
            camera,
            &inputs.buffers(&raster.gbuffers),
            self.light,
            self.lut,
        )?;
        Ok(RenderedView {
            raster,
            inputs,
            shaded,
        })
    }
}

/// Interleaves per-pixel triples into a flat RGB buffer.
pub fn flatten(values: &[DVec3]) -> Vec<f64> {
    values.iter().flat_map(|v| v.to_array()).collect()
}

//! The host engines behind [`Backend`]: the f64 reference ([`CpuBackend`]) and the f32 SIMD
//! engine ([`FastBackend`]) rasterize with [`crate::core::raster`]'s code and shade with the
//! trait's defaults (the host's PolarDR); the fast engine's steps compute SSIM in f32.

use super::Backend;
use crate::core::camera::Camera;
use crate::core::loss::LossPrecision;
use crate::core::raster::cpu::CpuBackend;
use crate::core::raster::fast::FastBackend;
use crate::core::raster::{GBufferGrads, RasterError, RasterGrads, RasterSettings, Rasterized};
use crate::core::surfels::Surfels;

/// One host engine's [`Backend`]: its name, its own forward and backward passes, and the
/// precision of its losses.
macro_rules! host_engine {
    ($engine:ty, $name:expr, $precision:expr) => {
        impl Backend for $engine {
            fn name(&self) -> &'static str {
                $name
            }

            fn loss_precision(&self) -> LossPrecision {
                $precision
            }

            fn description(&self) -> String {
                <$engine>::description(self)
            }

            fn forward(
                &self,
                surfels: &Surfels,
                camera: &Camera,
                settings: &RasterSettings,
            ) -> Result<Rasterized, RasterError> {
                <$engine>::forward(self, surfels, camera, settings)
            }

            fn backward(
                &self,
                surfels: &Surfels,
                camera: &Camera,
                settings: &RasterSettings,
                forward: &Rasterized,
                upstream: &GBufferGrads,
            ) -> Result<RasterGrads, RasterError> {
                <$engine>::backward(self, surfels, camera, settings, forward, upstream)
            }
        }
    };
}

host_engine!(CpuBackend, "cpu", LossPrecision::F64);
host_engine!(FastBackend, "fast", LossPrecision::F32);

//! [`GpuBackend`], the wgpu engine: one device and its kernel sets — the rasterizer's
//! ([`super::raster`], with the radix sort of [`super::sort`]), PolarDR's shading
//! ([`super::shade`]) and the TSDF fusion ([`super::tsdf`]) — behind the core's
//! [`Backend`] interface. Each pass takes the device and the kernels it needs by argument; the
//! resident trainer ([`super::train`]) borrows them from here too.
//!
//! Threading: calls on one backend are serialized on its device (`Device::scoped`, a mutex).

use tracing::info_span;

use super::device::{Device, DeviceMemory};
use super::raster::{RasterKernels, Rasterizer, Saved};
use super::shade::{Lighting, ShadePipelines};
use super::shaders::{AtomicsMode, Variant, Walk};
use super::sort::RadixSort;
use super::tsdf::TsdfKernels;
use super::{GpuContext, GpuError};
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::engine::Backend;
use crate::core::envmap::EnvGrad;
use crate::core::light::{LightKind, LightProbe};
use crate::core::mesh::{GridLayout, ScalarGrid};
use crate::core::raster::{
    begin_backward, validate_inputs, GBufferGrads, RasterError, RasterGrads, RasterSettings,
    Rasterized, StageTime,
};
use crate::core::shading::{
    self, GBufferGrad, SavedShading, ShadingBuffers, ShadingError, StokesImage, StokesImageGrad,
};
use crate::core::surfels::Surfels;

/// Options of [`GpuBackend::with_options`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GpuOptions {
    /// Use the compare-and-swap path even where float atomics exist (to test it).
    pub force_compare_exchange: bool,
    /// Walk each pixel's own entries in the backward pass even where subgroups exist (to test it).
    pub force_own_walk: bool,
    /// Treat buffers above this many bytes as beyond the device's binding limit (to test the
    /// splitting of large renders into bands on small scenes).
    pub max_binding_bytes: Option<u64>,
    /// Time every compute pass on the device (where the adapter has `TIMESTAMP_QUERY`), for
    /// [`Backend::take_stage_times`].
    pub profile: bool,
}

/// The wgpu engine.
pub struct GpuBackend {
    // Boxed: the backend is held in an enum beside the host engines, which are small
    // (`pipeline::backend::Engine`).
    device: Box<Device>,
    raster: Box<RasterKernels>,
    sort: Box<RadixSort>,
    shading: Box<ShadePipelines>,
    tsdf: Box<TsdfKernels>,
}

impl GpuBackend {
    /// Compiles the kernels on `ctx`'s device; float atomics where the device has them.
    pub fn new(ctx: GpuContext) -> Result<Self, GpuError> {
        Self::with_options(ctx, GpuOptions::default())
    }

    pub fn with_options(ctx: GpuContext, options: GpuOptions) -> Result<Self, GpuError> {
        let atomics = if ctx.has_float_atomics() && !options.force_compare_exchange {
            AtomicsMode::Float
        } else {
            AtomicsMode::CompareExchange
        };
        let walk = if ctx.has_subgroups() && !options.force_own_walk {
            Walk::Subgroup
        } else {
            Walk::OwnEntries
        };
        let variant = Variant { atomics, walk };
        let device = Device::new(ctx, variant, options.max_binding_bytes, options.profile);
        let (raster, sort, tsdf) = device.compile_all(|d| {
            (
                RasterKernels::new(d),
                RadixSort::new(d),
                TsdfKernels::new(d),
            )
        })?;
        let shading = ShadePipelines::compile(&device)?;
        Ok(GpuBackend {
            device: Box::new(device),
            raster: Box::new(raster),
            sort: Box::new(sort),
            shading: Box::new(shading),
            tsdf: Box::new(tsdf),
        })
    }

    pub fn context(&self) -> &GpuContext {
        self.device.context()
    }

    pub fn atomics(&self) -> AtomicsMode {
        self.device.variant().atomics
    }

    pub fn walk(&self) -> Walk {
        self.device.variant().walk
    }

    /// Buffer memory on the device now and at its peak since the backend was made.
    pub fn buffer_memory(&self) -> DeviceMemory {
        self.device.buffer_memory()
    }

    /// Host time of the resident trainer's step phases (encode, read-back, finish, submit, wait)
    /// since the last call.
    pub fn take_host_times(&self) -> Vec<StageTime> {
        self.device.take_host_times()
    }

    /// The device and its helpers.
    pub(super) fn device(&self) -> &Device {
        &self.device
    }

    /// The rasterization kernels.
    pub(super) fn raster(&self) -> &RasterKernels {
        &self.raster
    }

    /// The TSDF fusion kernels (their tests fuse with them directly).
    #[cfg(test)]
    pub(super) fn tsdf(&self) -> &TsdfKernels {
        &self.tsdf
    }

    /// The rasterizer on this device.
    fn rasterizer(&self) -> Rasterizer<'_> {
        Rasterizer {
            device: &self.device,
            kernels: &self.raster,
            sort: &self.sort,
        }
    }

    /// The radix sort of the binning entries.
    pub(super) fn sort(&self) -> &RadixSort {
        &self.sort
    }

    /// The PolarDR shading kernels.
    pub(super) fn shading(&self) -> &ShadePipelines {
        &self.shading
    }
}

impl Backend for GpuBackend {
    fn name(&self) -> &'static str {
        "gpu"
    }

    fn description(&self) -> String {
        format!(
            "gpu on {}, {:?} atomics, {:?} walk",
            self.device.context().adapter_summary(),
            self.atomics(),
            self.walk()
        )
    }

    fn forward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
    ) -> Result<Rasterized, RasterError> {
        validate_inputs(surfels, camera, settings)?;
        let _span = info_span!("raster_forward", backend = "gpu").entered();
        self.device.scoped("forward", || {
            self.rasterizer().forward_impl(surfels, camera, settings)
        })
    }

    fn backward(
        &self,
        surfels: &Surfels,
        camera: &Camera,
        settings: &RasterSettings,
        forward: &Rasterized,
        upstream: &GBufferGrads,
    ) -> Result<RasterGrads, RasterError> {
        let saved: &Saved = begin_backward(surfels, camera, settings, forward, upstream)?;
        let gb = &forward.gbuffers;
        let _span = info_span!("raster_backward", backend = "gpu").entered();
        self.device.scoped("backward", || {
            self.rasterizer()
                .backward_impl(saved, camera, settings, gb, upstream)
        })
    }

    /// Rendered and fused on the device (`super::tsdf`), unless the grid exceeds the binding
    /// limit.
    fn fuse_depth(
        &self,
        surfels: &Surfels,
        cameras: &[Camera],
        settings: &RasterSettings,
        grid: &GridLayout,
    ) -> Option<Result<ScalarGrid, RasterError>> {
        self.tsdf
            .fuse_on_device(&self.rasterizer(), surfels, cameras, settings, grid)
    }

    fn take_stage_times(&self) -> Vec<StageTime> {
        self.device.take_stage_times()
    }

    /// On the device under the global light or GridMap; other lights with the cpu code.
    fn shade(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
    ) -> Result<StokesImage, ShadingError> {
        match device_lighting(light) {
            Some(lighting) => self
                .shading
                .shade(&self.device, camera, buffers, lighting, lut),
            None => shading::shade_image(camera, buffers, light, lut),
        }
    }

    /// The device keeps nothing between the passes: [`Self::shade`].
    fn shade_saved(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
    ) -> Result<(StokesImage, Option<SavedShading>), ShadingError> {
        Ok((self.shade(camera, buffers, light, lut)?, None))
    }

    fn shade_backward(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        light: &dyn LightProbe,
        lut: &BrdfLut,
        upstream: &StokesImageGrad,
    ) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
        match device_lighting(light) {
            Some(lighting) => {
                self.shading
                    .shade_backward(&self.device, camera, buffers, lighting, lut, upstream)
            }
            None => shading::shade_image_backward(camera, buffers, light, lut, upstream),
        }
    }
}

/// The kernels' form of `light`, where they have one.
fn device_lighting(light: &dyn LightProbe) -> Option<Lighting<'_>> {
    match light.kind() {
        LightKind::Global(env) => Some(Lighting::Global(env)),
        LightKind::GridMap(grid) => Some(Lighting::GridMap(grid)),
        LightKind::Other => None,
    }
}

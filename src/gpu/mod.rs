//! The wgpu compute backend: the rasterizer of [`crate::raster`] as WGSL compute kernels
//! (`shaders/*.wgsl`), in f32 on the device.
//!
//! [`GpuContext`] opens an adapter (Vulkan, Metal or DX12, including software Vulkan such as
//! Mesa's lavapipe) and [`GpuBackend`] implements [`crate::raster::Backend`] with it:
//! projection and culling (one thread per surfel), a host exclusive scan of the per-surfel tile
//! counts, emission of (tile, depth, surfel) entries and a radix sort of them on the device,
//! per-tile ranges, forward compositing (one 8×8 workgroup per tile, one thread per pixel),
//! and the backward pass (per-pixel back-to-front replay, a subgroup's threads in step where the
//! adapter has subgroups, with float atomics or a compare-and-swap loop, then the per-surfel chain
//! to raw parameters). Images too large for the adapter's binding limit are rasterized in bands of
//! tile rows; [`GpuOptions::profile`] times every compute pass on the device. The depth-derived
//! normals and their backward are the host-side f64 helpers of [`crate::raster`], computed from
//! the downloaded depth.
//!
//! Not done on the device: the PolarDR shading and the loss (they stay on the cpu), and data does
//! not stay on the device across iterations (surfels are uploaded on every forward pass and the
//! G-buffers and gradients are downloaded; only the forward state the backward pass needs stays on
//! the device between the two).

mod context;
mod device;
mod profile;
mod raster;
mod shade;
mod train;

pub use context::{is_software, list_adapters, AdapterRequirement, AdapterSummary, GpuContext};
pub use raster::{AtomicsMode, GpuBackend, GpuOptions, Walk};
pub use train::{DeviceStep, DeviceStepResult, DeviceTrainer};

use thiserror::Error;

/// What to install when no adapter exists at all.
pub const INSTALL_HINT: &str = "on Debian/Ubuntu install a Vulkan driver, e.g. the software one: \
     `apt-get install mesa-vulkan-drivers` (or use `--backend cpu`)";

/// Errors of opening or using the gpu backend.
#[derive(Debug, Error)]
pub enum GpuError {
    #[error("no Vulkan, Metal or DX12 adapter found (backends tried: {backends}); {hint}")]
    NoAdapter {
        backends: String,
        hint: &'static str,
    },
    #[error("no hardware gpu adapter found, only software ones ({software})")]
    OnlySoftware { software: String },
    #[error("could not open a device on adapter {adapter}: {message}")]
    RequestDevice { adapter: String, message: String },
    #[error("the gpu kernels failed to compile on adapter {adapter}: {message}")]
    Shader { adapter: String, message: String },
    #[error(
        "buffer `{name}` needs {bytes} bytes, more than the device allows ({limit} bytes, \
         max_storage_buffer_binding_size); use fewer surfels, a smaller image or `--backend cpu`"
    )]
    BufferTooLarge {
        name: String,
        bytes: u64,
        limit: u64,
    },
    /// A device error (validation, out of memory, a failed readback), naming what was running.
    #[error("{0}")]
    Device(String),
}

impl From<GpuError> for crate::raster::RasterError {
    fn from(e: GpuError) -> Self {
        crate::raster::RasterError::Gpu(e.to_string())
    }
}

impl From<GpuError> for crate::shading::ShadingError {
    fn from(e: GpuError) -> Self {
        crate::shading::ShadingError::Gpu(e.to_string())
    }
}

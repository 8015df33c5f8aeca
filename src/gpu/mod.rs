//! The wgpu compute backend: the rasterizer of [`crate::core::raster`], PolarDR shading and whole
//! training steps as WGSL compute kernels (`shaders/*.wgsl`), in f32 on the device.
//!
//! [`GpuContext`] opens an adapter (Vulkan, Metal or DX12, including software Vulkan such as
//! Mesa's lavapipe) and [`GpuBackend`] implements [`crate::core::engine::Backend`] with it:
//! projection and culling (one thread per surfel), an exclusive scan of the per-surfel tile
//! counts, emission of (tile, depth, surfel) entries and a radix sort of them on the device,
//! per-tile ranges, forward compositing (one 8×8 workgroup per tile, one thread per pixel),
//! and the backward pass (per-pixel back-to-front replay, a subgroup's threads in step where the
//! adapter has subgroups, with float atomics or a compare-and-swap loop, then the per-surfel chain
//! to raw parameters). Images too large for the adapter's binding limit are rasterized in bands of
//! tile rows; [`GpuOptions::profile`] times every compute pass on the device. Its `shade` and
//! `shade_backward` run PolarDR on the device under the global light or GridMap (`shade` module).
//! These per-call passes upload their inputs and read their outputs back: they serve rendering,
//! evaluation, mesh extraction, and training steps on the host.
//!
//! [`DeviceTrainer`] runs whole training steps on the device instead (`train` module): surfels,
//! Adam moments, densification statistics, every view's target and the light stay there between
//! steps; a step reads back a few dozen words (loss sums, the polarizer angle's gradient, the
//! tile-entry count and two flags), and the state comes back only when the training loop needs
//! it on the host. The training loop uses it whenever the run's backend is this one.
//!
//! GridMap's mesh is fused on the device too (`tsdf`, [`crate::core::engine::Backend::fuse_depth`]):
//! the training views' depth is rendered and fused into a TSDF grid there, and only the grid
//! comes back for marching cubes. Still on the host: the environment map's prefilter and its
//! transpose (every `envmap_prefilter_interval` steps), marching cubes and GridMap's probe
//! rendering (every `gridmap_interval` / `mesh_interval` steps), densification and evaluation.
//!
//! Modules: `shaders` (the table of kernels: what each is compiled from and binds), `device`
//! (compiling, binding, dispatching, reading back), `layout` (the Rust mirrors of the WGSL
//! structs), `params` (the rasterizer's parameters and buffer layouts), `band` (tile-row bands
//! of large images), `sort` (the radix sort), `raster` ([`GpuBackend`]), `light` (lights laid
//! out for the kernels), `shade` (PolarDR), `prefilter` (the environment prefilter), `train`
//! ([`DeviceTrainer`]), `tsdf` (TSDF fusion of rendered depth), `profile` (pass timings),
//! `context` (adapters).

mod backend;
mod band;
mod bind_cache;
mod context;
mod device;
mod layout;
mod light;
mod params;
mod prefilter;
mod profile;
mod raster;
mod readback;
mod shade;
mod shaders;
mod sort;
mod train;
mod tsdf;

pub use backend::{GpuBackend, GpuOptions};
pub use bind_cache::BindCounts;
pub use context::{is_software, list_adapters, AdapterRequirement, AdapterSummary, GpuContext};
pub use device::DeviceMemory;
pub use shaders::{AtomicsMode, Walk};
pub use train::{DeviceStep, DeviceStepResult, DeviceTrainer};

use thiserror::Error;

/// The gpu backend on any adapter (lavapipe in CI), or `None` with a notice outside CI, for the
/// unit tests of the gpu modules.
#[cfg(test)]
pub(crate) fn test_backend() -> Option<GpuBackend> {
    match GpuContext::new(AdapterRequirement::Any) {
        Ok(ctx) => Some(GpuBackend::with_options(ctx, GpuOptions::default()).unwrap()),
        Err(e) => {
            assert!(
                !crate::testing::running_in_ci(),
                "CI=true but no adapter: {e}"
            );
            println!("skipping: no GPU adapter ({e})");
            None
        }
    }
}

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

impl From<GpuError> for crate::core::raster::RasterError {
    fn from(e: GpuError) -> Self {
        crate::core::raster::RasterError::Gpu(e.to_string())
    }
}

impl From<GpuError> for crate::core::shading::ShadingError {
    fn from(e: GpuError) -> Self {
        crate::core::shading::ShadingError::Gpu(e.to_string())
    }
}

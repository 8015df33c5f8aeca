//! Choosing the compute backend (`--backend auto|cpu|fast|gpu`).
//!
//! `cpu` is the rayon f64 reference; `fast` the same computation in f32 SIMD on the host. `gpu`
//! opens any Vulkan/Metal/DX12 adapter, software ones such as lavapipe included, and fails with
//! what to install when there is none. `auto` takes the gpu backend only on a real (non-software)
//! adapter and falls back to fast otherwise, so a machine with only lavapipe trains on the
//! (faster there) host.

use thiserror::Error;
use tracing::info;

use crate::config::BackendChoice;
use crate::gpu::{AdapterRequirement, GpuBackend, GpuContext, GpuError, GpuOptions};
use crate::raster::cpu::CpuBackend;
use crate::raster::fast::FastBackend;
use crate::raster::Backend;

#[derive(Debug, Error)]
pub enum BackendError {
    #[error("the gpu backend is unavailable: {0}")]
    Gpu(#[from] GpuError),
}

/// The backend for a choice.
pub fn select(choice: BackendChoice) -> Result<Box<dyn Backend>, BackendError> {
    select_with(choice, GpuOptions::default())
}

/// The backend for a choice, with `options` for the gpu backend.
pub fn select_with(
    choice: BackendChoice,
    options: GpuOptions,
) -> Result<Box<dyn Backend>, BackendError> {
    let gpu = |ctx| GpuBackend::with_options(ctx, options);
    match choice {
        BackendChoice::Cpu => Ok(Box::new(CpuBackend)),
        BackendChoice::Fast => Ok(Box::new(FastBackend::new())),
        BackendChoice::Gpu => Ok(Box::new(gpu(GpuContext::new(AdapterRequirement::Any)?)?)),
        BackendChoice::Auto => match GpuContext::new(AdapterRequirement::Hardware).and_then(gpu) {
            Ok(gpu) => Ok(Box::new(gpu)),
            Err(e) => {
                info!("backend auto: using fast ({e})");
                Ok(Box::new(FastBackend::new()))
            }
        },
    }
}

/// What a choice resolves to on this machine, as `phygap info` prints it: `Ok("gpu on …")`,
/// `Ok("cpu (… threads)")` or `Ok("fast (… threads, f32 AVX2)")`, or the error the choice would
/// fail with.
pub fn describe(choice: BackendChoice) -> Result<String, BackendError> {
    let gpu = |req| GpuContext::new(req).map(|ctx| format!("gpu on {}", ctx.adapter_summary()));
    match choice {
        BackendChoice::Cpu => Ok(CpuBackend.description()),
        BackendChoice::Fast => Ok(FastBackend::new().description()),
        BackendChoice::Gpu => Ok(gpu(AdapterRequirement::Any)?),
        BackendChoice::Auto => Ok(gpu(AdapterRequirement::Hardware)
            .unwrap_or_else(|e| format!("{}; {e}", FastBackend::new().description()))),
    }
}

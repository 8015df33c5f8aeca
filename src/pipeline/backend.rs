//! Choosing the compute backend (`--backend auto|cpu|fast|gpu`).
//!
//! `cpu` is the rayon f64 reference; `fast` the same computation in f32 SIMD on the host. `gpu`
//! opens any Vulkan/Metal/DX12 adapter, software ones such as lavapipe included, and fails with
//! what to install when there is none. `auto` takes the gpu backend only on a real (non-software)
//! adapter and falls back to fast otherwise, so a machine with only lavapipe trains on the
//! (faster there) host.

use thiserror::Error;
use tracing::info;

use std::ops::Deref;

use crate::core::config::BackendChoice;
use crate::core::engine::Backend;
use crate::core::raster::cpu::CpuBackend;
use crate::core::raster::fast::FastBackend;
use crate::core::resolution::Resolution;
use crate::gpu::{AdapterRequirement, GpuBackend, GpuContext, GpuError, GpuOptions};

/// The engine a run computes on: each implements the rasterizer interface [`Backend`] (which
/// `Engine` dereferences to), and the gpu engine can also train whole steps on its device.
pub enum Engine {
    /// The f64 rayon reference.
    Cpu(CpuBackend),
    /// The f32 SIMD host engine.
    Fast(FastBackend),
    /// The wgpu engine.
    Gpu(GpuBackend),
}

impl Engine {
    /// The gpu engine, for the device trainer; `None` for the host engines.
    pub fn gpu(&self) -> Option<&GpuBackend> {
        match self {
            Engine::Gpu(gpu) => Some(gpu),
            Engine::Cpu(_) | Engine::Fast(_) => None,
        }
    }

    /// Pixels a view may have at the `auto` working resolution: the device's budget on a
    /// hardware GPU, the host's on the host engines and on software adapters (lavapipe runs on
    /// the same cores).
    pub fn pixel_budget(&self) -> u64 {
        match self {
            Engine::Gpu(gpu) if !gpu.context().adapter_summary().software => {
                Resolution::DEVICE_PIXEL_BUDGET
            }
            _ => Resolution::HOST_PIXEL_BUDGET,
        }
    }
}

impl Deref for Engine {
    type Target = dyn Backend;

    fn deref(&self) -> &(dyn Backend + 'static) {
        match self {
            Engine::Cpu(cpu) => cpu,
            Engine::Fast(fast) => fast,
            Engine::Gpu(gpu) => gpu,
        }
    }
}

#[derive(Debug, Error)]
pub enum BackendError {
    #[error("the gpu backend is unavailable: {0}")]
    Gpu(#[from] GpuError),
}

/// The backend for a choice.
pub fn select(choice: BackendChoice) -> Result<Engine, BackendError> {
    select_with(choice, GpuOptions::default())
}

/// The backend for a choice, with `options` for the gpu backend.
pub fn select_with(choice: BackendChoice, options: GpuOptions) -> Result<Engine, BackendError> {
    let gpu = |ctx| GpuBackend::with_options(ctx, options);
    match choice {
        BackendChoice::Cpu => Ok(Engine::Cpu(CpuBackend)),
        BackendChoice::Fast => Ok(Engine::Fast(FastBackend::new())),
        BackendChoice::Gpu => Ok(Engine::Gpu(gpu(GpuContext::new(AdapterRequirement::Any)?)?)),
        BackendChoice::Auto => match GpuContext::new(AdapterRequirement::Hardware).and_then(gpu) {
            Ok(gpu) => Ok(Engine::Gpu(gpu)),
            Err(e) => {
                info!("backend auto: using fast ({e})");
                Ok(Engine::Fast(FastBackend::new()))
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

//! Choosing the compute backend (`--backend auto|cpu|gpu`).

use thiserror::Error;

use crate::config::BackendChoice;
use crate::raster::cpu::CpuBackend;
use crate::raster::Backend;

#[derive(Debug, Error)]
pub enum BackendError {
    #[error("the gpu backend is not available in this build yet; use `--backend cpu` (or `auto`)")]
    GpuUnavailable,
}

/// The backend for a choice: `auto` and `cpu` give the rayon reference backend.
pub fn select(choice: BackendChoice) -> Result<Box<dyn Backend>, BackendError> {
    match choice {
        BackendChoice::Auto | BackendChoice::Cpu => Ok(Box::new(CpuBackend)),
        BackendChoice::Gpu => Err(BackendError::GpuUnavailable),
    }
}

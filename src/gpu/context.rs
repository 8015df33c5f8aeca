//! Adapter discovery and device creation for the gpu backend.
//!
//! Backends: Vulkan, Metal and DX12 (wgpu's primary backends; GL is not built in, so a missing
//! Vulkan driver cannot silently fall back to it), or the set named by the `WGPU_BACKEND`
//! environment variable (e.g. `vulkan`). Adapters are ranked discrete > integrated > virtual >
//! other > cpu. A software adapter is one whose device type is `Cpu` or whose name is a known
//! software rasterizer (llvmpipe/lavapipe, SwiftShader, WARP).
//!
//! Threading: discovery and device creation block the calling thread (`pollster`); a
//! [`GpuContext`] is shared by reference, and its users serialize their work on it
//! (`super::device`).

use std::fmt;

use tracing::info;

use super::{GpuError, INSTALL_HINT};

/// Which adapters [`GpuContext::new`] may open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AdapterRequirement {
    /// Any Vulkan/Metal/DX12 adapter, software ones included (`--backend gpu`).
    Any,
    /// Only real gpus (`--backend auto`).
    Hardware,
}

/// One adapter as `phygap info` prints it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AdapterSummary {
    pub name: String,
    /// wgpu backend (`Vulkan`, `Metal`, `Dx12`).
    pub backend: String,
    /// `DiscreteGpu`, `IntegratedGpu`, `VirtualGpu`, `Cpu` or `Other`.
    pub device_type: String,
    pub driver: String,
    pub software: bool,
    /// The adapter offers `SHADER_FLOAT32_ATOMIC` (native float atomics in the backward pass).
    pub float_atomics: bool,
    /// The adapter offers `SUBGROUP` (subgroups walk their tile lists in step in the backward pass).
    pub subgroups: bool,
}

impl fmt::Display for AdapterSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}, {:?}{}{})",
            self.name,
            self.backend,
            self.device_type,
            if self.driver.is_empty() {
                String::new()
            } else {
                format!(", driver {}", self.driver)
            },
            if self.software { ", software" } else { "" }
        )
    }
}

/// True for software rasterizers (lavapipe, SwiftShader, WARP) and any `Cpu` device.
pub fn is_software(info: &wgpu::AdapterInfo) -> bool {
    let name = info.name.to_lowercase();
    info.device_type == wgpu::DeviceType::Cpu
        || [
            "llvmpipe",
            "lavapipe",
            "softpipe",
            "swiftshader",
            "basic render",
        ]
        .iter()
        .any(|s| name.contains(s))
}

fn backends() -> wgpu::Backends {
    wgpu::Backends::from_env().unwrap_or(wgpu::Backends::PRIMARY)
}

fn instance() -> wgpu::Instance {
    wgpu::Instance::new(&wgpu::InstanceDescriptor {
        backends: backends(),
        ..Default::default()
    })
}

fn rank(t: wgpu::DeviceType) -> u8 {
    match t {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Other => 3,
        wgpu::DeviceType::Cpu => 4,
    }
}

fn summary(adapter: &wgpu::Adapter) -> AdapterSummary {
    let info = adapter.get_info();
    AdapterSummary {
        software: is_software(&info),
        name: info.name,
        backend: format!("{:?}", info.backend),
        device_type: format!("{:?}", info.device_type),
        driver: [info.driver, info.driver_info]
            .into_iter()
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join(" "),
        float_atomics: adapter
            .features()
            .contains(wgpu::Features::SHADER_FLOAT32_ATOMIC),
        subgroups: adapter.features().contains(wgpu::Features::SUBGROUP),
    }
}

fn sorted_adapters(instance: &wgpu::Instance) -> Vec<wgpu::Adapter> {
    let mut adapters = instance.enumerate_adapters(backends());
    adapters.sort_by_key(|a| {
        let info = a.get_info();
        (is_software(&info), rank(info.device_type))
    });
    adapters
}

/// Every adapter of the enabled backends, best first.
pub fn list_adapters() -> Vec<AdapterSummary> {
    sorted_adapters(&instance()).iter().map(summary).collect()
}

/// An open device: the adapter it came from, the device and its queue.
pub struct GpuContext {
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    summary: AdapterSummary,
}

impl GpuContext {
    /// Opens the best adapter that meets `requirement`, with the adapter's own limits, and
    /// `SHADER_FLOAT32_ATOMIC`, `SUBGROUP` and `TIMESTAMP_QUERY` where it has them.
    pub fn new(requirement: AdapterRequirement) -> Result<Self, GpuError> {
        let instance = instance();
        let adapters = sorted_adapters(&instance);
        let Some(adapter) = adapters
            .into_iter()
            .find(|a| requirement == AdapterRequirement::Any || !is_software(&a.get_info()))
        else {
            let all = list_adapters();
            return Err(if all.is_empty() {
                GpuError::NoAdapter {
                    backends: format!("{:?}", backends()),
                    hint: INSTALL_HINT,
                }
            } else {
                GpuError::OnlySoftware {
                    software: all
                        .iter()
                        .map(|a| a.name.clone())
                        .collect::<Vec<_>>()
                        .join(", "),
                }
            });
        };
        let summary = summary(&adapter);
        // Native float atomics and subgroups for the backward pass; timestamps for
        // `GpuOptions::profile`.
        let required_features = adapter.features()
            & (wgpu::Features::SHADER_FLOAT32_ATOMIC
                | wgpu::Features::SUBGROUP
                | wgpu::Features::TIMESTAMP_QUERY);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("phygap"),
            required_features,
            required_limits: adapter.limits(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        }))
        .map_err(|e| GpuError::RequestDevice {
            adapter: summary.name.clone(),
            message: e.to_string(),
        })?;
        info!(adapter = %summary, "opened gpu device");
        Ok(GpuContext {
            adapter,
            device,
            queue,
            summary,
        })
    }

    /// The adapter this context runs on.
    pub fn adapter_summary(&self) -> &AdapterSummary {
        &self.summary
    }

    /// The adapter's wgpu info (backend, device type, driver).
    pub fn adapter_info(&self) -> wgpu::AdapterInfo {
        self.adapter.get_info()
    }

    /// True when the device was opened with native float atomics.
    pub fn has_float_atomics(&self) -> bool {
        self.device
            .features()
            .contains(wgpu::Features::SHADER_FLOAT32_ATOMIC)
    }

    /// True when the device was opened with subgroup operations.
    pub fn has_subgroups(&self) -> bool {
        self.device.features().contains(wgpu::Features::SUBGROUP)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(name: &str, device_type: wgpu::DeviceType) -> wgpu::AdapterInfo {
        wgpu::AdapterInfo {
            name: name.into(),
            vendor: 0,
            device: 0,
            device_type,
            driver: String::new(),
            driver_info: String::new(),
            backend: wgpu::Backend::Vulkan,
        }
    }

    #[test]
    fn software_adapters_are_recognized_by_type_or_name() {
        use wgpu::DeviceType::*;
        assert!(is_software(&info("llvmpipe (LLVM 15.0.6, 256 bits)", Cpu)));
        assert!(is_software(&info("SwiftShader Device (Subzero)", Other)));
        assert!(is_software(&info(
            "Microsoft Basic Render Driver",
            IntegratedGpu
        )));
        assert!(!is_software(&info("NVIDIA H100 80GB HBM3", DiscreteGpu)));
        assert!(!is_software(&info(
            "AMD Radeon Graphics (RADV GFX1103_R1)",
            IntegratedGpu
        )));
    }

    #[test]
    fn adapters_rank_discrete_first_and_cpu_last() {
        use wgpu::DeviceType::*;
        let mut types = [Cpu, Other, DiscreteGpu, VirtualGpu, IntegratedGpu];
        types.sort_by_key(|&t| rank(t));
        assert_eq!(types, [DiscreteGpu, IntegratedGpu, VirtualGpu, Other, Cpu]);
    }
}

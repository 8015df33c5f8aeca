//! The environment prefilter on the device (`shaders/prefilter.wgsl`), an f32 port of
//! [`crate::core::envmap::PreparedEnv::new`] and [`crate::core::envmap::PreparedEnv::backward`] for the
//! resident trainer: the learned cube map goes up raw, its prefiltered light is written straight
//! into the light buffer the shading kernels read, and the light's gradient comes back through
//! the transposed convolutions as a gradient on the raw texels. A plan's geometry (texel
//! directions and solid angles, the 8×8 culling blocks) and its convolutions (kernels, cutoffs,
//! culling thresholds, normalizers) go up once.
//!
//! Threading: one thread per output texel (convolutions) or value (activation, pyramid), in
//! dispatches encoded into the caller's command encoder.

use std::sync::Arc;

use bytemuck::{Pod, Zeroable};

use super::device::{Device, Kernel};
use super::layout::wgsl_mirror;
use super::shaders;
use super::GpuError;
use crate::core::envmap::prefilter::{ConvolutionTable, Kernel as Lobe};
use crate::core::envmap::{CubeMap, PrefilterPlan};

/// `NO_NORMALIZER` of prefilter.wgsl.
const NO_NORMALIZER: u32 = u32::MAX;
/// Culling thresholds are lowered by this much, so f32 rounding never culls a block the f64
/// prefilter keeps.
const THRESHOLD_SLACK: f64 = 1e-5;

wgsl_mirror! {
    /// `ConvParams` of prefilter.wgsl.
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    struct ConvParamsGpu = "ConvParams" {
        texels: u32,
        first_texel: u32,
        first_block: u32,
        blocks: u32,
        first_entry: u32,
        first_threshold: u32,
        first_normalizer: u32,
        transposed: u32,
        kernel_kind: u32,
        pad0: u32,
        pad1: u32,
        pad2: u32,
        kernel_param: f32,
        cos_cut: f32,
        pad3: f32,
        pad4: f32,
        src_first: u32,
        dst_first: u32,
        accumulate: u32,
        pad5: u32,
    }
}

wgsl_mirror! {
    /// `LevelParams` of prefilter.wgsl.
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    struct LevelParamsGpu = "LevelParams" {
        texels: u32,
        face_size: u32,
        src_first: u32,
        dst_first: u32,
        same_size: u32,
        pad0: u32,
        pad1: u32,
        pad2: u32,
    }
}

pub(super) struct PrefilterKernels {
    convolve: Kernel,
    activate: Kernel,
    downsample: Kernel,
    pyramid_transpose: Kernel,
    raw_gradient: Kernel,
}

impl PrefilterKernels {
    fn compile(device: &Device) -> Result<Self, GpuError> {
        device.compile_all(|d| PrefilterKernels {
            convolve: d.kernel(&shaders::CONVOLVE),
            activate: d.kernel(&shaders::ACTIVATE),
            downsample: d.kernel(&shaders::DOWNSAMPLE),
            pyramid_transpose: d.kernel(&shaders::PYRAMID_TRANSPOSE),
            raw_gradient: d.kernel(&shaders::RAW_GRADIENT),
        })
    }
}

/// One convolution: its forward and transposed parameters and texel count.
struct Conv {
    forward: wgpu::Buffer,
    transposed: wgpu::Buffer,
    texels: u64,
}

/// One pyramid level: its texel count, and the parameters that make it from the level above
/// (forward) and add its gradient into that level (backward); none for the base level.
struct Level {
    texels: u64,
    from_above: Option<(wgpu::Buffer, wgpu::Buffer)>,
}

/// A plan on the device, with the buffers of one prefilter.
pub(super) struct DevicePrefilter {
    plan: Arc<PrefilterPlan>,
    kernels: PrefilterKernels,
    dirs: wgpu::Buffer,
    solid_angle: wgpu::Buffer,
    blocks: wgpu::Buffer,
    block_starts: wgpu::Buffer,
    block_texels: wgpu::Buffer,
    block_dirs: wgpu::Buffer,
    thresholds: wgpu::Buffer,
    normalizers: wgpu::Buffer,
    levels: Vec<Level>,
    specular: Vec<Conv>,
    irradiance: Vec<Conv>,
    /// The raw base texels, the activated pyramid and its gradient, f′(raw), the raw gradient.
    raw: wgpu::Buffer,
    pyramid: wgpu::Buffer,
    pyramid_grad: wgpu::Buffer,
    derivative: wgpu::Buffer,
    raw_grad: wgpu::Buffer,
}

fn kernel_code(kernel: Lobe) -> (u32, f32) {
    match kernel {
        Lobe::Ggx { alpha2 } => (0, alpha2 as f32),
        Lobe::Cosine => (1, 0.0),
        Lobe::FresnelCosine { ior } => (2, ior as f32),
    }
}

impl DevicePrefilter {
    /// Uploads `plan`'s geometry and convolutions.
    pub(super) fn new(device: &Device, plan: Arc<PrefilterPlan>) -> Result<Self, GpuError> {
        let kernels = PrefilterKernels::compile(device)?;
        let f32s = |v: &mut Vec<f32>, values: &[f64]| v.extend(values.iter().map(|&x| x as f32));
        // Every grid's tables, concatenated; per grid its first texel, block and block entry.
        let (mut dirs, mut solid, mut blocks, mut block_texels, mut block_dirs) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut block_starts: Vec<u32> = Vec::new();
        let mut grid_first = Vec::new();
        for grid in &plan.grids {
            grid_first.push((
                solid.len() as u32,
                (blocks.len() / 4) as u32,
                block_texels.len() as u32,
            ));
            dirs.extend(
                grid.dirs
                    .iter()
                    .flat_map(|d| [d.x as f32, d.y as f32, d.z as f32, 0.0]),
            );
            f32s(&mut solid, &grid.solid_angle);
            for b in &grid.blocks {
                blocks.extend([b.center.x as f32, b.center.y as f32, b.center.z as f32, 0.0]);
                block_starts.push(b.start as u32);
            }
            block_texels.extend_from_slice(&grid.block_texels);
            block_dirs.extend(
                grid.block_dirs
                    .iter()
                    .flat_map(|d| [d.x as f32, d.y as f32, d.z as f32, 0.0]),
            );
        }
        let (mut thresholds, mut normalizers) = (Vec::new(), Vec::new());
        let mut conv_params = |table: ConvolutionTable, level: usize| {
            let grid = &plan.grids[level];
            let (texel0, block0, entry0) = grid_first[level];
            let threshold0 = thresholds.len() as u32;
            thresholds.extend(
                table
                    .thresholds
                    .iter()
                    .map(|&t| (t - THRESHOLD_SLACK) as f32),
            );
            let normalizer0 = match table.normalizer {
                Some(z) => {
                    let first = normalizers.len() as u32;
                    f32s(&mut normalizers, z);
                    first
                }
                None => NO_NORMALIZER,
            };
            let (kind, parameter) = kernel_code(table.kernel);
            let texels = grid.num_texels() as u32;
            let params = |transposed: u32| ConvParamsGpu {
                texels,
                first_texel: texel0,
                first_block: block0,
                blocks: grid.blocks.len() as u32,
                first_entry: entry0,
                first_threshold: threshold0,
                first_normalizer: normalizer0,
                transposed,
                kernel_kind: kind,
                kernel_param: parameter,
                cos_cut: table.cos_cut as f32,
                ..ConvParamsGpu::zeroed()
            };
            (params(0), params(1), u64::from(texels))
        };
        let mut specular_params = Vec::new();
        for level in 0..plan.num_levels() {
            specular_params.push(conv_params(plan.specular_convolution(level), level));
        }
        let last = plan.num_levels() - 1;
        let mut irradiance_params = Vec::new();
        for map in 0..plan.num_irradiance_maps() {
            irradiance_params.push(conv_params(plan.irradiance_convolution(map), last));
        }

        // Where each level lives: in the pyramid, and in the light layout.
        let level_texels: Vec<u64> = plan.grids.iter().map(|g| g.num_texels() as u64).collect();
        let pyramid_first: Vec<u64> = level_texels
            .iter()
            .scan(0, |next, &t| {
                let first = *next;
                *next += 3 * t;
                Some(first)
            })
            .collect();
        let pyramid_values: u64 = level_texels.iter().sum::<u64>() * 3;
        let to_u32 = |v: u64| v as u32;
        let light_first = pyramid_first.clone();
        let irradiance_first = pyramid_values;
        let irradiance_values = level_texels[last] * 3;
        let uniform = |name: &str, bytes: &[u8]| device.uniform(name, bytes);
        let specular = specular_params
            .into_iter()
            .enumerate()
            .map(|(level, (mut forward, mut transposed, texels))| {
                // Forward: pyramid level → light level; transposed: light gradient level →
                // pyramid gradient level.
                forward.src_first = to_u32(pyramid_first[level]);
                forward.dst_first = to_u32(light_first[level]);
                transposed.src_first = to_u32(light_first[level]);
                transposed.dst_first = to_u32(pyramid_first[level]);
                Conv {
                    forward: uniform("prefilter level", bytemuck::bytes_of(&forward)),
                    transposed: uniform(
                        "prefilter level (transposed)",
                        bytemuck::bytes_of(&transposed),
                    ),
                    texels,
                }
            })
            .collect();
        let irradiance = irradiance_params
            .into_iter()
            .enumerate()
            .map(|(map, (mut forward, mut transposed, texels))| {
                let light = irradiance_first + map as u64 * irradiance_values;
                forward.src_first = to_u32(pyramid_first[last]);
                forward.dst_first = to_u32(light);
                // The transposed irradiance adds into the coarsest level's gradient.
                transposed.src_first = to_u32(light);
                transposed.dst_first = to_u32(pyramid_first[last]);
                transposed.accumulate = 1;
                Conv {
                    forward: uniform("prefilter irradiance", bytemuck::bytes_of(&forward)),
                    transposed: uniform(
                        "prefilter irradiance (transposed)",
                        bytemuck::bytes_of(&transposed),
                    ),
                    texels,
                }
            })
            .collect();
        let levels = (0..plan.num_levels())
            .map(|l| Level {
                texels: level_texels[l],
                from_above: (l > 0).then(|| {
                    let same = u32::from(plan.grids[l].size == plan.grids[l - 1].size);
                    let down = LevelParamsGpu {
                        texels: to_u32(level_texels[l]),
                        face_size: plan.grids[l].size as u32,
                        src_first: to_u32(pyramid_first[l - 1]),
                        dst_first: to_u32(pyramid_first[l]),
                        same_size: same,
                        ..LevelParamsGpu::zeroed()
                    };
                    let up = LevelParamsGpu {
                        texels: to_u32(level_texels[l - 1]),
                        face_size: plan.grids[l - 1].size as u32,
                        src_first: to_u32(pyramid_first[l]),
                        dst_first: to_u32(pyramid_first[l - 1]),
                        same_size: same,
                        ..LevelParamsGpu::zeroed()
                    };
                    (
                        uniform("pyramid level", bytemuck::bytes_of(&down)),
                        uniform("pyramid level (transposed)", bytemuck::bytes_of(&up)),
                    )
                }),
            })
            .collect();
        let base_values = level_texels[0] * 3;
        let copy = wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST;
        let slice = |v: &[f32]| bytemuck::cast_slice::<f32, u8>(v).to_vec();
        Ok(DevicePrefilter {
            kernels,
            dirs: device.storage_init("prefilter directions", &slice(&dirs))?,
            solid_angle: device.storage_init("prefilter solid angles", &slice(&solid))?,
            blocks: device.storage_init("prefilter blocks", &slice(&blocks))?,
            block_starts: device.storage_init(
                "prefilter block starts",
                bytemuck::cast_slice(&block_starts),
            )?,
            block_texels: device.storage_init(
                "prefilter block texels",
                bytemuck::cast_slice(&block_texels),
            )?,
            block_dirs: device.storage_init("prefilter block directions", &slice(&block_dirs))?,
            thresholds: device.storage_init("prefilter thresholds", &slice(&thresholds))?,
            normalizers: device.storage_init("prefilter normalizers", &slice(&normalizers))?,
            levels,
            specular,
            irradiance,
            raw: device.storage("environment raw", base_values * 4, copy)?,
            pyramid: device.storage("environment pyramid", pyramid_values * 4, copy)?,
            pyramid_grad: device.storage(
                "environment pyramid gradient",
                pyramid_values * 4,
                copy,
            )?,
            derivative: device.storage(
                "environment activation derivative",
                base_values * 4,
                copy,
            )?,
            raw_grad: device.storage("environment raw gradient", base_values * 4, copy)?,
            plan,
        })
    }

    /// The plan this prefilter was built for.
    pub(super) fn plan(&self) -> &Arc<PrefilterPlan> {
        &self.plan
    }

    /// One convolution dispatch from `src` into `dst`.
    fn convolve(
        &self,
        device: &Device,
        encoder: &mut wgpu::CommandEncoder,
        params: &wgpu::Buffer,
        texels: u64,
        src: &wgpu::Buffer,
        dst: &wgpu::Buffer,
    ) -> Result<(), GpuError> {
        let k = &self.kernels;
        let group = device.bind(
            &k.convolve,
            &[
                ("conv", params),
                ("dirs", &self.dirs),
                ("solid_angle", &self.solid_angle),
                ("blocks", &self.blocks),
                ("block_starts", &self.block_starts),
                ("block_texels", &self.block_texels),
                ("block_dirs", &self.block_dirs),
                ("thresholds", &self.thresholds),
                ("normalizers", &self.normalizers),
                ("src", src),
                ("dst", dst),
            ],
        );
        device.dispatch_1d(encoder, "prefilter", &k.convolve, &group, texels)
    }

    /// Encodes the prefilter of `cube` (written now) into the first values of `light` (the
    /// light layout: every level, then every irradiance map).
    pub(super) fn encode_forward(
        &self,
        device: &Device,
        encoder: &mut wgpu::CommandEncoder,
        cube: &CubeMap,
        light: &wgpu::Buffer,
    ) -> Result<(), GpuError> {
        let raw: Vec<f32> = cube.raw.iter().map(|&v| v as f32).collect();
        device
            .queue()
            .write_buffer(&self.raw, 0, bytemuck::cast_slice(&raw));
        let k = &self.kernels;
        let group = device.bind(
            &k.activate,
            &[
                ("raw", &self.raw),
                ("pyramid", &self.pyramid),
                ("derivative", &self.derivative),
            ],
        );
        device.dispatch_1d(encoder, "activate", &k.activate, &group, raw.len() as u64)?;
        for level in &self.levels {
            if let Some((down, _)) = &level.from_above {
                let group = device.bind(
                    &k.downsample,
                    &[("level", down), ("pyramid", &self.pyramid)],
                );
                device.dispatch_1d(
                    encoder,
                    "downsample",
                    &k.downsample,
                    &group,
                    level.texels * 3,
                )?;
            }
        }
        for conv in self.specular.iter().chain(&self.irradiance) {
            self.convolve(
                device,
                encoder,
                &conv.forward,
                conv.texels,
                &self.pyramid,
                light,
            )?;
        }
        Ok(())
    }

    /// Encodes the transpose of the prefilter applied to `grad` (in the light layout) and the
    /// activation's derivative; [`Self::raw_gradient`] holds the result.
    pub(super) fn encode_backward(
        &self,
        device: &Device,
        encoder: &mut wgpu::CommandEncoder,
        grad: &wgpu::Buffer,
    ) -> Result<(), GpuError> {
        let k = &self.kernels;
        for conv in self.specular.iter().chain(&self.irradiance) {
            self.convolve(
                device,
                encoder,
                &conv.transposed,
                conv.texels,
                grad,
                &self.pyramid_grad,
            )?;
        }
        for l in (1..self.levels.len()).rev() {
            if let Some((_, up)) = &self.levels[l].from_above {
                let group = device.bind(
                    &k.pyramid_transpose,
                    &[("level", up), ("pyramid", &self.pyramid_grad)],
                );
                let values = self.levels[l - 1].texels * 3;
                device.dispatch_1d(
                    encoder,
                    "pyramid_transpose",
                    &k.pyramid_transpose,
                    &group,
                    values,
                )?;
            }
        }
        let group = device.bind(
            &k.raw_gradient,
            &[
                ("dst", &self.raw_grad),
                ("pyramid", &self.pyramid_grad),
                ("derivative", &self.derivative),
            ],
        );
        device.dispatch_1d(
            encoder,
            "raw_gradient",
            &k.raw_gradient,
            &group,
            self.levels[0].texels * 3,
        )
    }

    /// The raw gradient of the last [`Self::encode_backward`]: one f32 per raw value.
    pub(super) fn raw_gradient(&self) -> (&wgpu::Buffer, u64) {
        (&self.raw_grad, self.levels[0].texels * 3 * 4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prefilter_params_mirror_the_wgsl() {
        crate::gpu::layout::assert_mirrors::<ConvParamsGpu>(&shaders::CONVOLVE);
        crate::gpu::layout::assert_mirrors::<LevelParamsGpu>(&shaders::DOWNSAMPLE);
    }
}

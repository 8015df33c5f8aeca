//! PolarDR shading on the device: [`GpuBackend`]'s `shade` and `shade_backward` under the global
//! environment light (`shaders/shade_common.wgsl`, `shade.wgsl`, `shade_backward.wgsl`), in f32,
//! a port of [`crate::shading`].
//!
//! Per call the light goes up as one f32 buffer (every prefiltered mip level and irradiance map
//! of the [`PreparedEnv`], then the BRDF table) with the cube grids' border tables beside it, and
//! the G-buffers as two vectors per pixel; the view direction and Stokes frame of each pixel are
//! computed on the device from the camera. The forward pass reads back the Stokes images; the
//! backward pass reads back the per-pixel gradients and the light's gradient. Lights that depend
//! on the surface point (GridMap) are not handled here: [`GpuBackend`] shades them with the cpu
//! code.
//!
//! Threading: one thread per pixel, 256 per workgroup. The backward pass adds the light's
//! gradient into per-texel sums with float atomics or a compare-and-swap loop
//! ([`super::AtomicsMode`]), so the order of its sums, and their last bits, vary between runs.
//! Limits: an image whose per-pixel buffers exceed the binding limit is shaded in chunks of
//! pixels; a light that exceeds it fails with [`ShadingError::Gpu`] naming the buffer.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;
use tracing::info_span;

use super::device::Device;
use super::raster::GpuBackend;
use super::GpuError;
use crate::brdf_lut::BrdfLut;
use crate::camera::Camera;
use crate::envmap::{EnvGrad, PreparedEnv};
use crate::shading::{GBufferGrad, ShadingBuffers, ShadingError, StokesImage, StokesImageGrad};

const SHADE_COMMON: &str = include_str!("../../shaders/shade_common.wgsl");
const SHADE: &str = include_str!("../../shaders/shade.wgsl");
const SHADE_BACKWARD: &str = include_str!("../../shaders/shade_backward.wgsl");

/// The shading kernels.
pub(super) struct ShadePipelines {
    shade: wgpu::ComputePipeline,
    shade_backward: wgpu::ComputePipeline,
}

impl ShadePipelines {
    /// Compiles the kernels; `atomics` is the `add_grad` source the backward pass adds the
    /// light's gradient with.
    pub(super) fn compile(device: &Device, atomics: &str) -> Result<Self, GpuError> {
        device.compile_all(|d| ShadePipelines {
            shade: d.pipeline("shade", &[SHADE_COMMON, SHADE], "shade"),
            shade_backward: d.pipeline(
                "shade_backward",
                &[SHADE_COMMON, SHADE_BACKWARD, atomics],
                "shade_backward",
            ),
        })
    }
}

/// IoR nodes the kernels' parameters hold (`MAX_IORS`).
const MAX_IORS: usize = 8;
/// f32 values per pixel of the Stokes images (the largest per-pixel buffer) and of the input
/// gradients.
const STOKES_FLOATS: u64 = 15;
const GRAD_FLOATS: u64 = 8;

/// `ShadeParams` of shade_common.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct ShadeParamsGpu {
    rot: [[f32; 4]; 3],
    up: [f32; 4],
    intr: [f32; 4],
    dims: [u32; 4],
    light_layout: [u32; 4],
    rough: [f32; 4],
    iors: [[f32; 4]; 2],
}

fn v4(v: DVec3) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, 0.0]
}

/// A light and BRDF table laid out for the kernels.
struct DeviceLight {
    /// RGB texels of every level, then of every irradiance map; then the table's A and B.
    values: Vec<f32>,
    /// Per level: face size, first texel, first border entry, 0; then the border tables.
    tables: Vec<u32>,
    /// Texels of each level, in order.
    level_texels: Vec<usize>,
    /// Texels of each irradiance map.
    irradiance_texels: usize,
    /// Values of the texels (levels and irradiance maps), the length of the gradient sums.
    texel_values: usize,
    params: ShadeParamsGpu,
}

impl DeviceLight {
    fn new(env: &PreparedEnv, lut: &BrdfLut) -> Result<Self, ShadingError> {
        let plan = env.plan();
        if plan.irradiance_iors.len() > MAX_IORS {
            return Err(ShadingError::Gpu(format!(
                "{} irradiance IoR nodes, the kernels take at most {MAX_IORS}",
                plan.irradiance_iors.len()
            )));
        }
        if lut.size < 2 {
            return Err(ShadingError::Gpu(format!(
                "BRDF table of {} cells per axis, need at least 2",
                lut.size
            )));
        }
        let levels = plan.num_levels();
        let level_texels: Vec<usize> = plan.grids.iter().map(|g| g.num_texels()).collect();
        let mut tables = vec![0u32; levels * 4];
        let mut first_texel = 0;
        for (l, grid) in plan.grids.iter().enumerate() {
            let border_first = tables.len();
            tables.extend_from_slice(grid.border_table());
            tables[l * 4..l * 4 + 4].copy_from_slice(&[
                grid.size as u32,
                first_texel as u32,
                border_first as u32,
                0,
            ]);
            first_texel += level_texels[l];
        }
        let irradiance_first = first_texel;
        let irradiance_texels = plan.irradiance_grid().num_texels();
        let mut values: Vec<f32> = env
            .levels
            .iter()
            .chain(&env.irradiance)
            .flatten()
            .map(|&v| v as f32)
            .collect();
        let texel_values = values.len();
        let lut_first = values.len();
        values.extend(lut.a.iter().chain(&lut.b).map(|&v| v as f32));
        let mut iors = [[0.0f32; 4]; 2];
        for (k, &ior) in plan.irradiance_iors.iter().enumerate() {
            iors[k / 4][k % 4] = ior as f32;
        }
        let params = ShadeParamsGpu {
            rot: [[0.0; 4]; 3],
            up: [0.0; 4],
            intr: [0.0; 4],
            dims: [0, 0, 0, lut.size as u32],
            light_layout: [
                levels as u32,
                env.irradiance.len() as u32,
                irradiance_first as u32,
                lut_first as u32,
            ],
            rough: [
                plan.spec.min_roughness as f32,
                plan.spec.max_roughness as f32,
                plan.irradiance_iors.len() as f32,
                0.0,
            ],
            iors,
        };
        Ok(DeviceLight {
            values,
            tables,
            level_texels,
            irradiance_texels,
            texel_values,
            params,
        })
    }

    /// The kernels' parameters for `pixels` pixels of `camera` from `first_pixel` on.
    fn params(&self, camera: &Camera, first_pixel: usize, pixels: usize) -> ShadeParamsGpu {
        let r = camera.rotation_opencv();
        ShadeParamsGpu {
            rot: [v4(r.x_axis), v4(r.y_axis), v4(r.z_axis)],
            up: v4(camera.up()),
            intr: [
                camera.fx as f32,
                camera.fy as f32,
                camera.cx as f32,
                camera.cy as f32,
            ],
            dims: [
                camera.width,
                first_pixel as u32,
                pixels as u32,
                self.params.dims[3],
            ],
            ..self.params
        }
    }

    /// Splits the per-texel gradient sums into an [`EnvGrad`] (levels, then irradiance maps).
    fn env_grad(&self, sums: &[f32], maps: usize) -> EnvGrad {
        let mut rest = sums;
        let mut take = |texels: usize| {
            let (head, tail) = rest.split_at(texels * 3);
            rest = tail;
            head.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>()
        };
        let levels = self.level_texels.iter().map(|&t| take(t)).collect();
        let irradiance = (0..maps).map(|_| take(self.irradiance_texels)).collect();
        EnvGrad { levels, irradiance }
    }
}

/// Ranges of at most `limit_pixels` pixels covering `pixels`.
fn chunks(pixels: usize, limit_pixels: usize) -> impl Iterator<Item = std::ops::Range<usize>> {
    let step = limit_pixels.max(1);
    (0..pixels)
        .step_by(step)
        .map(move |start| start..(start + step).min(pixels))
}

impl GpuBackend {
    /// Pixels per chunk: as many as the largest per-pixel buffer (the Stokes images) allows.
    fn shade_chunk_pixels(&self) -> usize {
        (self.device().binding_limit() / (STOKES_FLOATS * 4)) as usize
    }

    /// The inputs of the pixels in `range`: two vectors each, and the active flags.
    fn pixel_inputs(
        buffers: &ShadingBuffers,
        range: std::ops::Range<usize>,
    ) -> (Vec<[f32; 4]>, Vec<u32>) {
        let mut inputs = Vec::with_capacity(range.len() * 2);
        let mut active = Vec::with_capacity(range.len());
        for p in range {
            let n = buffers.normal[p];
            let a = buffers.albedo[p];
            inputs.push([
                n.x as f32,
                n.y as f32,
                n.z as f32,
                buffers.roughness[p] as f32,
            ]);
            inputs.push([a.x as f32, a.y as f32, a.z as f32, buffers.ior[p] as f32]);
            active.push(u32::from(buffers.is_active(p)));
        }
        (inputs, active)
    }

    fn light_buffers(&self, light: &DeviceLight) -> Result<(wgpu::Buffer, wgpu::Buffer), GpuError> {
        Ok((
            self.device()
                .storage_init("light", bytemuck::cast_slice(&light.values))?,
            self.device()
                .storage_init("light tables", bytemuck::cast_slice(&light.tables))?,
        ))
    }

    fn params_buffer(&self, params: &ShadeParamsGpu) -> wgpu::Buffer {
        self.device()
            .uniform("shade params", bytemuck::bytes_of(params))
    }

    /// PolarDR forward under the global light `env` on the device.
    pub(super) fn shade_on_device(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        env: &PreparedEnv,
        lut: &BrdfLut,
    ) -> Result<StokesImage, ShadingError> {
        let pixels = camera.num_pixels();
        buffers.check(pixels)?;
        let _span = info_span!("shade_image", backend = "gpu").entered();
        let light = DeviceLight::new(env, lut)?;
        let mut out = StokesImage {
            width: camera.width as usize,
            height: camera.height as usize,
            s0: Vec::with_capacity(pixels),
            s1: Vec::with_capacity(pixels),
            s2: Vec::with_capacity(pixels),
            diffuse: Vec::with_capacity(pixels),
            specular: Vec::with_capacity(pixels),
        };
        self.device().scoped("shade", || -> Result<(), GpuError> {
            let (light_buf, tables_buf) = self.light_buffers(&light)?;
            for range in chunks(pixels, self.shade_chunk_pixels()) {
                let n = range.len() as u64;
                let params = self.params_buffer(&light.params(camera, range.start, range.len()));
                let (inputs, active) = Self::pixel_inputs(buffers, range);
                let inputs_buf = self
                    .device()
                    .storage_init("shading inputs", bytemuck::cast_slice(&inputs))?;
                let active_buf = self
                    .device()
                    .storage_init("active pixels", bytemuck::cast_slice(&active))?;
                let stokes_buf = self.device().storage(
                    "stokes",
                    n * STOKES_FLOATS * 4,
                    wgpu::BufferUsages::COPY_SRC,
                )?;
                let pipeline = &self.shading().shade;
                let group = self.device().bind(
                    pipeline,
                    &[
                        (0, &params),
                        (1, &light_buf),
                        (2, &tables_buf),
                        (3, &inputs_buf),
                        (4, &active_buf),
                        (5, &stokes_buf),
                    ],
                );
                let mut encoder = self
                    .device()
                    .wgpu()
                    .create_command_encoder(&Default::default());
                self.device()
                    .dispatch_1d(&mut encoder, "shade", pipeline, &group, n)?;
                let data = self
                    .device()
                    .submit_and_read(encoder, &[(&stokes_buf, n * STOKES_FLOATS * 4)])?;
                let values: Vec<f32> = bytemuck::pod_collect_to_vec(&data[0]);
                for v in values.chunks_exact(STOKES_FLOATS as usize) {
                    let rgb = |k: usize| {
                        DVec3::new(v[3 * k].into(), v[3 * k + 1].into(), v[3 * k + 2].into())
                    };
                    out.s0.push(rgb(0));
                    out.s1.push(rgb(1));
                    out.s2.push(rgb(2));
                    out.diffuse.push(rgb(3));
                    out.specular.push(rgb(4));
                }
            }
            Ok(())
        })?;
        Ok(out)
    }

    /// PolarDR backward under the global light `env` on the device.
    pub(super) fn shade_backward_on_device(
        &self,
        camera: &Camera,
        buffers: &ShadingBuffers,
        env: &PreparedEnv,
        lut: &BrdfLut,
        upstream: &StokesImageGrad,
    ) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
        let pixels = camera.num_pixels();
        buffers.check(pixels)?;
        upstream.check(pixels)?;
        let _span = info_span!("shade_image_backward", backend = "gpu").entered();
        let light = DeviceLight::new(env, lut)?;
        let mut grads = GBufferGrad {
            normal: Vec::with_capacity(pixels),
            albedo: Vec::with_capacity(pixels),
            roughness: Vec::with_capacity(pixels),
            ior: Vec::with_capacity(pixels),
        };
        let sums = self
            .device()
            .scoped("shade backward", || -> Result<Vec<f32>, GpuError> {
                let (light_buf, tables_buf) = self.light_buffers(&light)?;
                let sums_bytes = light.texel_values as u64 * 4;
                let sums_buf = self.device().storage(
                    "light gradient",
                    sums_bytes,
                    wgpu::BufferUsages::COPY_SRC,
                )?;
                let chunk_list: Vec<_> = chunks(pixels, self.shade_chunk_pixels()).collect();
                let last = chunk_list.len().saturating_sub(1);
                let mut sums = Vec::new();
                for (c, range) in chunk_list.into_iter().enumerate() {
                    let n = range.len() as u64;
                    let params =
                        self.params_buffer(&light.params(camera, range.start, range.len()));
                    let (inputs, active) = Self::pixel_inputs(buffers, range.clone());
                    let up: Vec<f32> = range
                        .flat_map(|p| [upstream.s0[p], upstream.s1[p], upstream.s2[p]])
                        .flat_map(|v| [v.x as f32, v.y as f32, v.z as f32])
                        .collect();
                    let inputs_buf = self
                        .device()
                        .storage_init("shading inputs", bytemuck::cast_slice(&inputs))?;
                    let active_buf = self
                        .device()
                        .storage_init("active pixels", bytemuck::cast_slice(&active))?;
                    let up_buf = self
                        .device()
                        .storage_init("stokes gradient", bytemuck::cast_slice(&up))?;
                    let grad_buf = self.device().storage(
                        "shading input gradient",
                        n * GRAD_FLOATS * 4,
                        wgpu::BufferUsages::COPY_SRC,
                    )?;
                    let pipeline = &self.shading().shade_backward;
                    let group = self.device().bind(
                        pipeline,
                        &[
                            (0, &params),
                            (1, &light_buf),
                            (2, &tables_buf),
                            (3, &inputs_buf),
                            (4, &active_buf),
                            (5, &up_buf),
                            (6, &grad_buf),
                            (8, &sums_buf),
                        ],
                    );
                    let mut encoder = self
                        .device()
                        .wgpu()
                        .create_command_encoder(&Default::default());
                    self.device().dispatch_1d(
                        &mut encoder,
                        "shade backward",
                        pipeline,
                        &group,
                        n,
                    )?;
                    let mut reads = vec![(&grad_buf, n * GRAD_FLOATS * 4)];
                    if c == last {
                        reads.push((&sums_buf, sums_bytes));
                    }
                    let data = self.device().submit_and_read(encoder, &reads)?;
                    let values: Vec<f32> = bytemuck::pod_collect_to_vec(&data[0]);
                    for v in values.chunks_exact(GRAD_FLOATS as usize) {
                        let d = |k: usize| f64::from(v[k]);
                        grads.normal.push(DVec3::new(d(0), d(1), d(2)));
                        grads.albedo.push(DVec3::new(d(3), d(4), d(5)));
                        grads.roughness.push(d(6));
                        grads.ior.push(d(7));
                    }
                    if c == last {
                        sums = bytemuck::pod_collect_to_vec(&data[1]);
                    }
                }
                Ok(sums)
            })?;
        let env_grad = if pixels == 0 {
            env.zero_grad()
        } else {
            light.env_grad(&sums, env.irradiance.len())
        };
        Ok((grads, env_grad))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chunks_cover_every_pixel_once() {
        let ranges: Vec<_> = chunks(10, 4).collect();
        assert_eq!(ranges, vec![0..4, 4..8, 8..10]);
        assert_eq!(chunks(0, 4).count(), 0);
        assert_eq!(chunks(3, 0).collect::<Vec<_>>(), vec![0..1, 1..2, 2..3]);
    }
}

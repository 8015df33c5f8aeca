//! PolarDR shading on the device: [`super::GpuBackend`]'s `shade` and `shade_backward` in f32, a port
//! of [`crate::core::shading`] (`shaders/shade_common.wgsl`, `shade.wgsl`, `shade_backward.wgsl`),
//! under the global environment (`light_global*.wgsl`) or GridMap's local probes over it
//! (`light_gridmap*.wgsl`: anchor weights, blended probe lookups and the occlusion test of mirror
//! rays against the mesh's BVH). Lights of other kinds are shaded by the cpu code.
//!
//! A light goes up as the f32 buffers of `super::light`; the resident trainer ([`super::train`])
//! keeps them on the device, `shade` uploads them per call. Per pixel the kernels read three
//! vectors: (raw normal, roughness), (albedo, IoR), (surface point); the view direction and
//! Stokes frame come from the camera. The forward pass writes the Stokes images; the backward
//! pass writes the per-pixel gradients and adds the global light's gradient into per-texel sums.
//!
//! Threading: one thread per pixel, 256 per workgroup. The backward pass adds the light's
//! gradient with float atomics or a compare-and-swap loop ([`super::AtomicsMode`]), so the order
//! of its sums, and their last bits, vary between runs. Limits: an image whose per-pixel buffers
//! exceed the binding limit is shaded in chunks of pixels; a light that exceeds it fails with
//! [`ShadingError::Gpu`] naming the buffer.

use glam::DVec3;
use tracing::info_span;

use super::device::{Device, Kernel};
use super::light::{v4, HostLight, HostProbes, ProbeBuffers};
use super::shaders;
use super::GpuError;
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::envmap::{EnvGrad, PreparedEnv};
use crate::core::gridmap::GridMap;
use crate::core::shading::{
    GBufferGrad, ShadingBuffers, ShadingError, StokesImage, StokesImageGrad,
};

/// Vectors per pixel of the shading inputs.
pub(super) const INPUT_VECTORS: u64 = 3;
/// f32 values per pixel of the Stokes images (S0, S1, S2, diffuse, specular; RGB each).
pub(super) const STOKES_FLOATS: u64 = 15;
/// f32 values per pixel of the input gradients (normal, albedo, roughness, IoR).
pub(super) const GRAD_FLOATS: u64 = 8;

/// The forward and backward kernels under one kind of light.
pub(super) struct LightPipelines {
    pub(super) forward: Kernel,
    pub(super) backward: Kernel,
}

/// The shading kernels, per kind of light.
pub(super) struct ShadePipelines {
    pub(super) global: LightPipelines,
    pub(super) gridmap: LightPipelines,
}

impl ShadePipelines {
    /// Compiles the kernels.
    pub(super) fn compile(device: &Device) -> Result<Self, GpuError> {
        device.compile_all(|d| ShadePipelines {
            global: LightPipelines {
                forward: d.kernel(&shaders::SHADE_GLOBAL),
                backward: d.kernel(&shaders::SHADE_BACKWARD_GLOBAL),
            },
            gridmap: LightPipelines {
                forward: d.kernel(&shaders::SHADE_GRIDMAP),
                backward: d.kernel(&shaders::SHADE_BACKWARD_GRIDMAP),
            },
        })
    }

    /// The kernels for `lighting`.
    pub(super) fn for_lighting(&self, lighting: Lighting) -> &LightPipelines {
        match lighting {
            Lighting::Global(_) => &self.global,
            Lighting::GridMap(_) => &self.gridmap,
        }
    }
}

/// A light the kernels evaluate.
#[derive(Clone, Copy)]
pub(super) enum Lighting<'a> {
    Global(&'a PreparedEnv),
    GridMap(&'a GridMap),
}

impl<'a> Lighting<'a> {
    /// The global environment (GridMap's escaping rays use it and receive its gradient).
    pub(super) fn global(self) -> &'a PreparedEnv {
        match self {
            Lighting::Global(env) => env,
            Lighting::GridMap(grid) => grid.global(),
        }
    }

    /// GridMap's probes laid out for the kernels (none for the global light).
    fn probes(self) -> Result<Option<HostProbes>, ShadingError> {
        match self {
            Lighting::Global(_) => Ok(None),
            Lighting::GridMap(grid) => HostProbes::new(grid).map(Some),
        }
    }
}

/// Ranges of at most `limit_pixels` pixels covering `pixels`.
fn chunks(pixels: usize, limit_pixels: usize) -> impl Iterator<Item = std::ops::Range<usize>> {
    let step = limit_pixels.max(1);
    (0..pixels)
        .step_by(step)
        .map(move |start| start..(start + step).min(pixels))
}

/// The inputs of the pixels in `range`: three vectors each, and the active flags.
fn pixel_inputs(
    buffers: &ShadingBuffers,
    range: std::ops::Range<usize>,
) -> (Vec<[f32; 4]>, Vec<u32>) {
    let mut inputs = Vec::with_capacity(range.len() * INPUT_VECTORS as usize);
    let mut active = Vec::with_capacity(range.len());
    for p in range {
        let n = buffers.normal[p];
        let a = buffers.albedo[p];
        let x = buffers.position.map_or(DVec3::ZERO, |q| q[p]);
        inputs.push([
            n.x as f32,
            n.y as f32,
            n.z as f32,
            buffers.roughness[p] as f32,
        ]);
        inputs.push([a.x as f32, a.y as f32, a.z as f32, buffers.ior[p] as f32]);
        inputs.push(v4(x));
        active.push(u32::from(buffers.is_active(p)));
    }
    (inputs, active)
}

/// Pixels per chunk: as many as the largest per-pixel buffer (the Stokes images) allows.
fn chunk_pixels(device: &Device) -> usize {
    (device.binding_limit() / (STOKES_FLOATS * 4)) as usize
}

impl ShadePipelines {
    /// PolarDR forward under `lighting` on `device`.
    pub(super) fn shade(
        &self,
        device: &Device,
        camera: &Camera,
        buffers: &ShadingBuffers,
        lighting: Lighting,
        lut: &BrdfLut,
    ) -> Result<StokesImage, ShadingError> {
        let pixels = camera.num_pixels();
        buffers.check(pixels)?;
        let _span = info_span!("shade_image", backend = "gpu").entered();
        let light = HostLight::new(lighting.global(), lut)?;
        let probes = lighting.probes()?;
        let mut out = StokesImage {
            width: camera.width as usize,
            height: camera.height as usize,
            s0: Vec::with_capacity(pixels),
            s1: Vec::with_capacity(pixels),
            s2: Vec::with_capacity(pixels),
            diffuse: Vec::with_capacity(pixels),
            specular: Vec::with_capacity(pixels),
        };
        let kernel = &self.for_lighting(lighting).forward;
        device.scoped("shade", || -> Result<(), GpuError> {
            let light_buffers = light.upload(device)?;
            let probe_buffers = probes.as_ref().map(|p| p.upload(device)).transpose()?;
            for range in chunks(pixels, chunk_pixels(device)) {
                let n = range.len() as u64;
                let params = light.params(camera, range.start, range.len(), probe_buffers.as_ref());
                let params = device.uniform("shade params", bytemuck::bytes_of(&params));
                let (inputs, active) = pixel_inputs(buffers, range);
                let inputs =
                    device.storage_init("shading inputs", bytemuck::cast_slice(&inputs))?;
                let active = device.storage_init("active pixels", bytemuck::cast_slice(&active))?;
                let stokes = device.storage(
                    "stokes",
                    n * STOKES_FLOATS * 4,
                    wgpu::BufferUsages::COPY_SRC,
                )?;
                let mut bindings = vec![
                    ("params", &params),
                    ("pixels", &inputs),
                    ("active_pixels", &active),
                    ("stokes", &stokes),
                ];
                bindings.extend(light_buffers.bindings());
                bindings.extend(probe_buffers.iter().flat_map(ProbeBuffers::bindings));
                let group = device.bind(kernel, &bindings);
                let mut encoder = device.wgpu().create_command_encoder(&Default::default());
                device.dispatch_1d(&mut encoder, "shade", kernel, &group, n)?;
                let data = device.submit_and_read(encoder, &[(&stokes, n * STOKES_FLOATS * 4)])?;
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

    /// PolarDR backward under `lighting` on `device`.
    pub(super) fn shade_backward(
        &self,
        device: &Device,
        camera: &Camera,
        buffers: &ShadingBuffers,
        lighting: Lighting,
        lut: &BrdfLut,
        upstream: &StokesImageGrad,
    ) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
        let pixels = camera.num_pixels();
        buffers.check(pixels)?;
        upstream.check(pixels)?;
        let _span = info_span!("shade_image_backward", backend = "gpu").entered();
        let light = HostLight::new(lighting.global(), lut)?;
        let probes = lighting.probes()?;
        let mut grads = GBufferGrad {
            normal: Vec::with_capacity(pixels),
            albedo: Vec::with_capacity(pixels),
            roughness: Vec::with_capacity(pixels),
            ior: Vec::with_capacity(pixels),
        };
        let kernel = &self.for_lighting(lighting).backward;
        let sums = device.scoped("shade backward", || -> Result<Vec<f32>, GpuError> {
            let light_buffers = light.upload(device)?;
            let probe_buffers = probes.as_ref().map(|p| p.upload(device)).transpose()?;
            let sums_bytes = light.gradient_bytes();
            let sums =
                device.storage("light gradient", sums_bytes, wgpu::BufferUsages::COPY_SRC)?;
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            for range in chunks(pixels, chunk_pixels(device)) {
                let n = range.len() as u64;
                let params = light.params(camera, range.start, range.len(), probe_buffers.as_ref());
                let params = device.uniform("shade params", bytemuck::bytes_of(&params));
                let (inputs, active) = pixel_inputs(buffers, range.clone());
                let up: Vec<f32> = range
                    .flat_map(|p| [upstream.s0[p], upstream.s1[p], upstream.s2[p]])
                    .flat_map(|v| [v.x as f32, v.y as f32, v.z as f32])
                    .collect();
                let inputs =
                    device.storage_init("shading inputs", bytemuck::cast_slice(&inputs))?;
                let active = device.storage_init("active pixels", bytemuck::cast_slice(&active))?;
                let up = device.storage_init("stokes gradient", bytemuck::cast_slice(&up))?;
                let pixel_grads = device.storage(
                    "shading input gradient",
                    n * GRAD_FLOATS * 4,
                    wgpu::BufferUsages::COPY_SRC,
                )?;
                let mut bindings = vec![
                    ("params", &params),
                    ("pixels", &inputs),
                    ("active_pixels", &active),
                    ("upstream", &up),
                    ("pixel_grads", &pixel_grads),
                    ("grad_acc", &sums),
                ];
                bindings.extend(light_buffers.bindings());
                bindings.extend(probe_buffers.iter().flat_map(ProbeBuffers::bindings));
                let group = device.bind(kernel, &bindings);
                device.dispatch_1d(&mut encoder, "shade backward", kernel, &group, n)?;
                let data =
                    device.submit_and_read(encoder, &[(&pixel_grads, n * GRAD_FLOATS * 4)])?;
                encoder = device.wgpu().create_command_encoder(&Default::default());
                let values: Vec<f32> = bytemuck::pod_collect_to_vec(&data[0]);
                for v in values.chunks_exact(GRAD_FLOATS as usize) {
                    let d = |k: usize| f64::from(v[k]);
                    grads.normal.push(DVec3::new(d(0), d(1), d(2)));
                    grads.albedo.push(DVec3::new(d(3), d(4), d(5)));
                    grads.roughness.push(d(6));
                    grads.ior.push(d(7));
                }
            }
            let data = device.submit_and_read(encoder, &[(&sums, sums_bytes)])?;
            Ok(bytemuck::pod_collect_to_vec(&data[0]))
        })?;
        Ok((grads, light.env_grad(&sums)))
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

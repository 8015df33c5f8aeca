//! PolarDR shading on the device: [`GpuBackend`]'s `shade` and `shade_backward` in f32, a port
//! of [`crate::core::shading`] (`shaders/shade_common.wgsl`, `shade.wgsl`, `shade_backward.wgsl`),
//! under the global environment (`light_global*.wgsl`) or GridMap's local probes over it
//! (`light_gridmap*.wgsl`: anchor weights, blended probe lookups and the occlusion test of mirror
//! rays against the mesh's BVH). Lights of other kinds are shaded by the cpu code.
//!
//! A light goes up as f32 buffers: [`LightBuffers`] hold every prefiltered mip level and
//! irradiance map of the global [`PreparedEnv`] followed by the BRDF table, and the cube grids'
//! border tables; [`ProbeBuffers`] hold GridMap's probes (each in the global map's layout),
//! anchors, BVH nodes and triangle slots. The resident trainer ([`super::train`]) keeps them on
//! the device; `shade` uploads them per call.
//! Per pixel the kernels read three vectors: (raw normal, roughness), (albedo, IoR), (surface
//! point); the view direction and Stokes frame come from the camera. The forward pass writes the
//! Stokes images; the backward pass writes the per-pixel gradients and adds the global light's
//! gradient into per-texel sums.
//!
//! Threading: one thread per pixel, 256 per workgroup. The backward pass adds the light's
//! gradient with float atomics or a compare-and-swap loop ([`super::AtomicsMode`]), so the order
//! of its sums, and their last bits, vary between runs. Limits: an image whose per-pixel buffers
//! exceed the binding limit is shaded in chunks of pixels; a light that exceeds it fails with
//! [`ShadingError::Gpu`] naming the buffer.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;
use tracing::info_span;

use super::device::{Device, Kernel};
use super::layout::wgsl_mirror;
use super::raster::GpuBackend;
use super::shaders;
use super::GpuError;
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::envmap::{EnvGrad, PrefilterPlan, PreparedEnv};
use crate::core::gridmap::GridMap;
use crate::core::shading::{
    GBufferGrad, ShadingBuffers, ShadingError, StokesImage, StokesImageGrad,
};

/// IoR nodes the kernels' parameters hold (`MAX_IORS`).
const MAX_IORS: usize = 8;
/// Anchors the GridMap kernels hold (`MAX_ANCHORS`).
const MAX_ANCHORS: usize = 56;
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

wgsl_mirror! {
    /// `ShadeParams` of shade_common.wgsl.
    #[derive(Clone, Copy, Debug, Pod, Zeroable)]
    pub(super) struct ShadeParamsGpu = "ShadeParams" {
        rot0: [f32; 4],
        rot1: [f32; 4],
        rot2: [f32; 4],
        up: [f32; 4],
        fx: f32,
        fy: f32,
        cx: f32,
        cy: f32,
        width: u32,
        first_pixel: u32,
        pixels: u32,
        lut_size: u32,
        levels: u32,
        irradiance_maps: u32,
        irradiance_offset: u32,
        lut_offset: u32,
        min_roughness: f32,
        max_roughness: f32,
        ior_nodes: u32,
        pad0: u32,
        iors: [[f32; 4]; 2],
        grid_anchors: u32,
        grid_probe_values: u32,
        grid_nodes: u32,
        pad1: u32,
        grid_ray_offset: f32,
        pad2: f32,
        pad3: f32,
        pad4: f32,
    }
}

fn v4(v: DVec3) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, 0.0]
}

/// A light and the BRDF table laid out for the kernels, on the host.
pub(super) struct HostLight {
    /// RGB texels of every level, then of every irradiance map; then the table's A and B.
    values: Vec<f32>,
    /// Per level: face size, first texel, first border entry, 0; then the border tables.
    tables: Vec<u32>,
    /// Texels of each level, in order.
    level_texels: Vec<usize>,
    /// Texels of each irradiance map.
    irradiance_texels: usize,
    irradiance_maps: usize,
    /// Values of the texels (levels and irradiance maps), the length of the gradient sums.
    texel_values: usize,
    params: ShadeParamsGpu,
}

/// GridMap's probes (texel-major: every probe's RGB of texel 0, then of texel 1, ...), anchors
/// and BVH laid out for the kernels.
pub(super) struct HostProbes {
    values: Vec<f32>,
    anchors: Vec<[f32; 4]>,
    nodes: Vec<[f32; 4]>,
    links: Vec<[u32; 2]>,
    slots: Vec<[f32; 4]>,
    grid: GridCounts,
}

/// GridMap's part of the kernels' parameters.
#[derive(Clone, Copy, Debug)]
struct GridCounts {
    anchors: u32,
    probe_values: u32,
    nodes: u32,
    ray_offset: f32,
}

/// Lays out every texel of `env` (levels, then irradiance maps) as f32.
fn texel_values(env: &PreparedEnv) -> impl Iterator<Item = f32> + '_ {
    env.levels
        .iter()
        .chain(&env.irradiance)
        .flatten()
        .map(|&v| v as f32)
}

impl HostProbes {
    /// GridMap's part of its light; the global part is a [`HostLight`] of `grid.global()`.
    pub(super) fn new(grid: &GridMap) -> Result<Self, ShadingError> {
        let texel_values_per_probe = texel_values(grid.global()).count();
        let anchors = grid.anchors();
        if anchors.len() > MAX_ANCHORS {
            return Err(ShadingError::Gpu(format!(
                "{} GridMap anchors, the kernels take at most {MAX_ANCHORS}",
                anchors.len()
            )));
        }
        let k_count = anchors.len();
        let mut values = vec![0.0f32; k_count * texel_values_per_probe];
        for k in 0..k_count {
            let local = grid.local(k);
            if local.plan().spec != grid.global().plan().spec {
                return Err(ShadingError::Gpu(
                    "a GridMap probe is prefiltered with another plan than the global map".into(),
                ));
            }
            // Texel-major: a texel's RGB of every probe together, as a blend reads them.
            for (i, v) in texel_values(local).enumerate() {
                let (texel, c) = (i / 3, i % 3);
                values[(texel * k_count + k) * 3 + c] = v;
            }
        }
        // Boxes rounded outwards, so f32 rounding cannot make a ray miss a box the f64 tree's
        // ray enters.
        let widen = |v: DVec3, sign: f64| {
            let out = v + sign * (v.abs() + DVec3::ONE) * 1e-6;
            [out.x as f32, out.y as f32, out.z as f32]
        };
        let mut nodes = Vec::new();
        let mut links = Vec::new();
        for n in grid.bvh().flat_nodes() {
            let lo = widen(n.min, -1.0);
            let hi = widen(n.max, 1.0);
            nodes.push([lo[0], lo[1], lo[2], 0.0]);
            nodes.push([hi[0], hi[1], hi[2], 0.0]);
            links.push([n.first_or_right, n.count]);
        }
        let slots = grid
            .bvh()
            .slots()
            .flat_map(|(corner_edges, normals)| corner_edges.into_iter().chain(normals).map(v4))
            .collect();
        let counts = GridCounts {
            anchors: anchors.len() as u32,
            probe_values: texel_values_per_probe as u32,
            nodes: (nodes.len() / 2) as u32,
            ray_offset: grid.ray_offset() as f32,
        };
        Ok(HostProbes {
            values,
            anchors: anchors.iter().map(|&a| v4(a)).collect(),
            nodes,
            links,
            slots,
            grid: counts,
        })
    }

    /// Uploads the probes.
    pub(super) fn upload(&self, device: &Device) -> Result<ProbeBuffers, GpuError> {
        Ok(ProbeBuffers {
            buffers: [
                device.storage_init("GridMap probes", bytemuck::cast_slice(&self.values))?,
                device.storage_init("GridMap anchors", bytemuck::cast_slice(&self.anchors))?,
                device.storage_init("GridMap BVH nodes", bytemuck::cast_slice(&self.nodes))?,
                device.storage_init("GridMap BVH triangles", bytemuck::cast_slice(&self.slots))?,
                device.storage_init("GridMap BVH links", bytemuck::cast_slice(&self.links))?,
            ],
            grid: self.grid,
        })
    }
}

/// GridMap's probes, anchors, BVH nodes, triangle slots and node links on the device.
pub(super) struct ProbeBuffers {
    buffers: [wgpu::Buffer; 5],
    grid: GridCounts,
}

impl ProbeBuffers {
    /// The probes' bindings.
    pub(super) fn bindings(&self) -> impl Iterator<Item = (&'static str, &wgpu::Buffer)> {
        ["probes", "anchors", "bvh_nodes", "bvh_slots", "bvh_links"]
            .into_iter()
            .zip(self.buffers.iter())
    }
}

impl ShadeParamsGpu {
    /// These parameters with GridMap's counts and ray offset.
    pub(super) fn with_probes(self, probes: &ProbeBuffers) -> Self {
        let grid = probes.grid;
        ShadeParamsGpu {
            grid_anchors: grid.anchors,
            grid_probe_values: grid.probe_values,
            grid_nodes: grid.nodes,
            grid_ray_offset: grid.ray_offset,
            ..self
        }
    }
}

impl HostLight {
    /// The global light `env` and the BRDF table.
    pub(super) fn new(env: &PreparedEnv, lut: &BrdfLut) -> Result<Self, ShadingError> {
        let mut light = Self::layout(env.plan(), lut)?;
        for (v, e) in light.values.iter_mut().zip(texel_values(env)) {
            *v = e;
        }
        Ok(light)
    }

    /// The layout of a light prefiltered with `plan`, and the BRDF table, with every texel zero
    /// (the device prefilter writes them: `super::prefilter`).
    pub(super) fn layout(plan: &PrefilterPlan, lut: &BrdfLut) -> Result<Self, ShadingError> {
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
        let irradiance_maps = plan.num_irradiance_maps();
        let texel_values = (first_texel + irradiance_maps * irradiance_texels) * 3;
        let mut values = vec![0.0f32; texel_values];
        let lut_first = values.len();
        values.extend(lut.a.iter().chain(&lut.b).map(|&v| v as f32));
        let mut iors = [[0.0f32; 4]; 2];
        for (k, &ior) in plan.irradiance_iors.iter().enumerate() {
            iors[k / 4][k % 4] = ior as f32;
        }
        let params = ShadeParamsGpu {
            lut_size: lut.size as u32,
            levels: levels as u32,
            irradiance_maps: irradiance_maps as u32,
            irradiance_offset: irradiance_first as u32,
            lut_offset: lut_first as u32,
            min_roughness: plan.spec.min_roughness as f32,
            max_roughness: plan.spec.max_roughness as f32,
            ior_nodes: plan.irradiance_iors.len() as u32,
            iors,
            ..ShadeParamsGpu::zeroed()
        };
        Ok(HostLight {
            values,
            tables,
            level_texels,
            irradiance_texels,
            irradiance_maps,
            texel_values,
            params,
        })
    }

    /// Bytes of the global light's gradient sums (one f32 per texel value).
    pub(super) fn gradient_bytes(&self) -> u64 {
        self.texel_values as u64 * 4
    }

    /// The kernels' parameters for `pixels` pixels of `camera` from `first_pixel` on, with
    /// GridMap's `probes` where they light the view.
    pub(super) fn params(
        &self,
        camera: &Camera,
        first_pixel: usize,
        pixels: usize,
        probes: Option<&ProbeBuffers>,
    ) -> ShadeParamsGpu {
        let r = camera.rotation_opencv();
        let params = ShadeParamsGpu {
            rot0: v4(r.x_axis),
            rot1: v4(r.y_axis),
            rot2: v4(r.z_axis),
            up: v4(camera.up()),
            fx: camera.fx as f32,
            fy: camera.fy as f32,
            cx: camera.cx as f32,
            cy: camera.cy as f32,
            width: camera.width,
            first_pixel: first_pixel as u32,
            pixels: pixels as u32,
            ..self.params
        };
        match probes {
            Some(p) => params.with_probes(p),
            None => params,
        }
    }

    /// Splits the per-texel gradient sums into an [`EnvGrad`] (levels, then irradiance maps).
    pub(super) fn env_grad(&self, sums: &[f32]) -> EnvGrad {
        let mut rest = sums;
        let mut take = |texels: usize| {
            let (head, tail) = rest.split_at(texels * 3);
            rest = tail;
            head.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>()
        };
        let levels = self.level_texels.iter().map(|&t| take(t)).collect();
        let irradiance = (0..self.irradiance_maps)
            .map(|_| take(self.irradiance_texels))
            .collect();
        EnvGrad { levels, irradiance }
    }

    /// Uploads the light.
    pub(super) fn upload(&self, device: &Device) -> Result<LightBuffers, GpuError> {
        Ok(LightBuffers {
            values: device.storage_init("light", bytemuck::cast_slice(&self.values))?,
            tables: device.storage_init("light tables", bytemuck::cast_slice(&self.tables))?,
        })
    }

    /// Whether `other` has the same layout (its gradient sums are interchangeable).
    pub(super) fn same_layout(&self, other: &HostLight) -> bool {
        self.values.len() == other.values.len() && self.tables == other.tables
    }
}

/// The global light and the BRDF table on the device.
pub(super) struct LightBuffers {
    values: wgpu::Buffer,
    tables: wgpu::Buffer,
}

impl LightBuffers {
    /// The texel values (every level, then every irradiance map) followed by the BRDF table.
    pub(super) fn values(&self) -> &wgpu::Buffer {
        &self.values
    }

    /// The light's bindings.
    pub(super) fn bindings(&self) -> [(&'static str, &wgpu::Buffer); 2] {
        [("light", &self.values), ("tables", &self.tables)]
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

impl GpuBackend {
    /// Pixels per chunk: as many as the largest per-pixel buffer (the Stokes images) allows.
    fn shade_chunk_pixels(&self) -> usize {
        (self.device().binding_limit() / (STOKES_FLOATS * 4)) as usize
    }

    /// PolarDR forward under `lighting` on the device.
    pub(super) fn shade_on_device(
        &self,
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
        let device = self.device();
        let kernel = &self.shading().for_lighting(lighting).forward;
        device.scoped("shade", || -> Result<(), GpuError> {
            let light_buffers = light.upload(device)?;
            let probe_buffers = probes.as_ref().map(|p| p.upload(device)).transpose()?;
            for range in chunks(pixels, self.shade_chunk_pixels()) {
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

    /// PolarDR backward under `lighting` on the device.
    pub(super) fn shade_backward_on_device(
        &self,
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
        let device = self.device();
        let kernel = &self.shading().for_lighting(lighting).backward;
        let sums = device.scoped("shade backward", || -> Result<Vec<f32>, GpuError> {
            let light_buffers = light.upload(device)?;
            let probe_buffers = probes.as_ref().map(|p| p.upload(device)).transpose()?;
            let sums_bytes = light.gradient_bytes();
            let sums =
                device.storage("light gradient", sums_bytes, wgpu::BufferUsages::COPY_SRC)?;
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            for range in chunks(pixels, self.shade_chunk_pixels()) {
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
    fn shade_params_mirror_the_wgsl() {
        crate::gpu::layout::assert_mirrors::<ShadeParamsGpu>(&shaders::SHADE_GLOBAL);
    }

    #[test]
    fn chunks_cover_every_pixel_once() {
        let ranges: Vec<_> = chunks(10, 4).collect();
        assert_eq!(ranges, vec![0..4, 4..8, 8..10]);
        assert_eq!(chunks(0, 4).count(), 0);
        assert_eq!(chunks(3, 0).collect::<Vec<_>>(), vec![0..1, 1..2, 2..3]);
    }
}

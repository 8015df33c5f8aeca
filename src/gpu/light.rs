//! A light laid out for the shading kernels (`shaders/shade_common.wgsl`, `light_*.wgsl`), and
//! the kernels' uniform parameters, of which the light fixes most.
//!
//! [`HostLight`] lays out every prefiltered mip level and irradiance map of the global
//! [`PreparedEnv`] as f32 texels, followed by the BRDF table, with the cube grids' border tables;
//! [`HostProbes`] lays out GridMap's probes (each in the global map's layout, texel-major),
//! anchors, BVH nodes and triangle slots. Their `upload`s put them on the device
//! ([`LightBuffers`], [`ProbeBuffers`]), where `super::shade` binds them per call and the resident
//! trainer (`super::train`) keeps them between steps.
//!
//! Threading: host-side conversions on the calling thread.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use super::device::Device;
use super::layout::wgsl_mirror;
use super::GpuError;
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::envmap::{EnvGrad, PrefilterPlan, PreparedEnv};
use crate::core::gridmap::GridMap;
use crate::core::shading::ShadingError;

/// IoR nodes the kernels' parameters hold (`MAX_IORS`).
const MAX_IORS: usize = 8;
/// Anchors the GridMap kernels hold (`MAX_ANCHORS`).
const MAX_ANCHORS: usize = crate::core::gridmap::MAX_ANCHORS;

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

/// A 3-vector as the kernels' vec4 (w = 0).
pub(super) fn v4(v: DVec3) -> [f32; 4] {
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
        let probes = grid.probe_texels();
        if probes.plan().spec != grid.global().plan().spec {
            return Err(ShadingError::Gpu(
                "the GridMap probes are prefiltered with another plan than the global map".into(),
            ));
        }
        // Texel-major like the host's probes (a texel's RGB of every probe together, as a blend
        // reads them), over the levels and then the irradiance maps of one probe.
        let values = probes
            .levels
            .iter()
            .chain(&probes.irradiance)
            .flatten()
            .map(|&v| v as f32)
            .collect();
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shade_params_mirror_the_wgsl() {
        crate::gpu::layout::assert_mirrors::<ShadeParamsGpu>(&crate::gpu::shaders::SHADE_GLOBAL);
    }
}

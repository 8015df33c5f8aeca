//! TSDF fusion of rendered depth on the device ([`TsdfKernels::fuse_on_device`], behind
//! [`crate::core::engine::Backend::fuse_depth`]): every view's depth and opacity are rasterized
//! by the forward kernels (`super::raster`, band by band), each band's G-buffers are turned into
//! the view's cleaned depth map (`prepare_depth`), and the view's votes are added into per-voxel
//! sums and counts over the whole grid (`fuse_view`, shaders/tsdf_fuse.wgsl). Only the sums and
//! counts come back; the host divides them into the [`ScalarGrid`] that marching cubes reads.
//!
//! The rules are the host's (`core::mesh::tsdf`), in f32; the grid's layout is the host's
//! [`GridLayout`]. Unlike the host, which fuses only the blocks near the surface, the device
//! fuses every voxel, so voxels far from the surface that some view observes are known here and
//! unknown there; marching cubes finds the same cells with a negative corner in both.
//!
//! Threading: one dispatch per view with one thread per voxel, the views in order. Each voxel has
//! one thread per dispatch and dispatches run in submission order, so the sums need no atomics;
//! and only one view's depth map is on the device at a time (looping over every view inside one
//! thread per voxel would need all of them at once, beyond the binding limit for a few hundred
//! training views). Calls on one backend are serialized by the device's lock.

use glam::DVec3;
use tracing::info_span;

use super::band::Band;
use super::device::{Device, Kernel};
use super::layout::wgsl_mirror;
use super::params::{NUM_OUT, TILE};
use super::raster::{Frame, Rasterizer};
use super::shaders;
use super::GpuError;
use crate::core::camera::Camera;
use crate::core::mesh::{DepthPixels, GridLayout, ScalarGrid, SURFACE_SPREAD_FOOTPRINTS};
use crate::core::raster::{validate_inputs, RasterError, RasterSettings};
use crate::core::surfels::Surfels;

wgsl_mirror! {
    /// `DepthBand` of shaders/tsdf_fuse.wgsl: one band of a view's G-buffers to clean.
    #[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
    struct DepthBandGpu = "DepthBand" {
        pixel_first: u32,
        pixels: u32,
        gbuf_stride: u32,
        depth_max: f32,
        coherent_only: u32,
        max_spread: f32,
        spread_per_depth: f32,
        pad0: u32,
    }
}

wgsl_mirror! {
    /// `FuseView` of shaders/tsdf_fuse.wgsl: one view seen from the grid.
    #[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
    struct FuseViewGpu = "FuseView" {
        base: [f32; 4],
        step_x: [f32; 4],
        step_y: [f32; 4],
        step_z: [f32; 4],
        fx: f32,
        fy: f32,
        cx: f32,
        cy: f32,
        width: u32,
        height: u32,
        dims_x: u32,
        dims_y: u32,
        dims_z: u32,
        truncation: f32,
        pad0: u32,
        pad1: u32,
    }
}

/// The largest f32 not above `x` (> 0; `f32::MAX` for larger values and +∞), so that an f32
/// compares with it by `≤` or `>` exactly as with `x`: the device cleans and splits depth at the
/// host's limits to the bit.
fn f32_at_most(x: f64) -> f32 {
    let nearest = x.min(f64::from(f32::MAX)) as f32;
    if f64::from(nearest) > x {
        f32::from_bits(nearest.to_bits() - 1)
    } else {
        nearest
    }
}

impl FuseViewGpu {
    /// `camera` seen from `grid`: the camera-space (OpenCV) voxel origin and steps, in f64 then
    /// rounded (as the host's `BlockFrame` computes them).
    fn new(camera: &Camera, grid: &GridLayout) -> Self {
        let (rotation, translation) = camera.world_to_camera_opencv();
        let v4 = |v: DVec3| [v.x as f32, v.y as f32, v.z as f32, 0.0];
        let [dims_x, dims_y, dims_z] = grid.dims.map(|d| d as u32);
        FuseViewGpu {
            base: v4(rotation * grid.origin + translation),
            step_x: v4(rotation.x_axis * grid.voxel),
            step_y: v4(rotation.y_axis * grid.voxel),
            step_z: v4(rotation.z_axis * grid.voxel),
            fx: camera.fx as f32,
            fy: camera.fy as f32,
            cx: camera.cx as f32,
            cy: camera.cy as f32,
            width: camera.width,
            height: camera.height,
            dims_x,
            dims_y,
            dims_z,
            truncation: f32_at_most(grid.truncation),
            pad0: 0,
            pad1: 0,
        }
    }
}

/// The fusion kernels.
pub(super) struct TsdfKernels {
    prepare_depth: Kernel,
    fuse_view: Kernel,
}

impl TsdfKernels {
    /// Compiles the kernels (inside the caller's [`Device::compile_all`]).
    pub(super) fn new(device: &Device) -> Self {
        TsdfKernels {
            prepare_depth: device.kernel(&shaders::PREPARE_DEPTH),
            fuse_view: device.kernel(&shaders::FUSE_VIEW),
        }
    }
}

/// A grid being fused on the device: its layout and the per-voxel sums and counts of the votes.
struct Fusion<'a> {
    device: &'a Device,
    kernels: &'a TsdfKernels,
    grid: &'a GridLayout,
    voxels: u64,
    sums: wgpu::Buffer,
    counts: wgpu::Buffer,
}

impl<'a> Fusion<'a> {
    /// An empty grid (no votes) of `grid`'s layout.
    fn new(
        device: &'a Device,
        kernels: &'a TsdfKernels,
        grid: &'a GridLayout,
    ) -> Result<Self, GpuError> {
        let voxels = grid.voxel_count() as u64;
        let sums = device.storage("tsdf sums", voxels * 4, wgpu::BufferUsages::COPY_SRC)?;
        let counts = device.storage("tsdf counts", voxels * 4, wgpu::BufferUsages::COPY_SRC)?;
        Ok(Fusion {
            device,
            kernels,
            grid,
            voxels,
            sums,
            counts,
        })
    }

    /// A zeroed depth map of `camera`, for [`Self::prepare_band`] to fill.
    fn depth_map(&self, camera: &Camera) -> Result<wgpu::Buffer, GpuError> {
        self.device.storage(
            "view depth",
            camera.num_pixels() as u64 * 4,
            wgpu::BufferUsages::empty(),
        )
    }

    /// Encodes the cleaning of `band`'s G-buffers (`NUM_OUT` values per pixel of the band's
    /// rows) into its rows of the view's depth map.
    fn prepare_band(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        band: Band,
        gbuf: &wgpu::Buffer,
        depth: &wgpu::Buffer,
    ) -> Result<(), GpuError> {
        let pixels = camera.width * band.pixel_rows(camera.height);
        let params = DepthBandGpu {
            pixel_first: band.first * TILE * camera.width,
            pixels,
            gbuf_stride: NUM_OUT as u32,
            depth_max: f32_at_most(self.grid.depth_max),
            coherent_only: u32::from(self.grid.pixels == DepthPixels::Coherent),
            max_spread: self.grid.truncation as f32,
            spread_per_depth: (SURFACE_SPREAD_FOOTPRINTS / camera.fx.min(camera.fy)) as f32,
            pad0: 0,
        };
        let params = self
            .device
            .uniform("depth band", bytemuck::bytes_of(&params));
        let kernel = &self.kernels.prepare_depth;
        let group = self.device.bind(
            kernel,
            &[
                ("depth_band", &params),
                ("band_gbuf", gbuf),
                ("clean_depth", depth),
            ],
        );
        self.device
            .dispatch_1d(encoder, "prepare_depth", kernel, &group, u64::from(pixels))
    }

    /// Encodes the votes of the view `camera` sees as `depth` (cleaned) into every voxel.
    fn add_view(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        depth: &wgpu::Buffer,
    ) -> Result<(), GpuError> {
        let params = FuseViewGpu::new(camera, self.grid);
        let params = self
            .device
            .uniform("fuse view", bytemuck::bytes_of(&params));
        let kernel = &self.kernels.fuse_view;
        let group = self.device.bind(
            kernel,
            &[
                ("fuse", &params),
                ("view_depth", depth),
                ("tsdf_sum", &self.sums),
                ("tsdf_count", &self.counts),
            ],
        );
        self.device
            .dispatch_1d(encoder, "fuse_view", kernel, &group, self.voxels)
    }

    /// Reads the sums and counts back into the averaged grid (unknown where no view voted).
    fn read(self) -> Result<ScalarGrid, GpuError> {
        let _span = info_span!("readback", voxels = self.voxels).entered();
        let encoder = self
            .device
            .wgpu()
            .create_command_encoder(&Default::default());
        let bytes = self.voxels * 4;
        let out = self
            .device
            .submit_and_read(encoder, &[(&self.sums, bytes), (&self.counts, bytes)])?;
        let sums: Vec<f32> = bytemuck::pod_collect_to_vec(&out[0]);
        let counts: Vec<u32> = bytemuck::pod_collect_to_vec(&out[1]);
        let values = sums
            .iter()
            .zip(&counts)
            .map(|(&sum, &count)| if count > 0 { sum / count as f32 } else { 0.0 })
            .collect();
        let known = counts.iter().map(|&count| count > 0).collect();
        Ok(self.grid.scalar_grid(values, known))
    }
}

impl TsdfKernels {
    /// The TSDF of `surfels`' depth and opacity seen from every camera, rendered by `raster` and
    /// fused into `grid` on its device; `None` where the grid's per-voxel sums exceed the binding
    /// limit (or the u32 voxel index), and the host fuses instead.
    pub(super) fn fuse_on_device(
        &self,
        raster: &Rasterizer,
        surfels: &Surfels,
        cameras: &[Camera],
        settings: &RasterSettings,
        grid: &GridLayout,
    ) -> Option<Result<ScalarGrid, RasterError>> {
        let voxels = grid.voxel_count() as u64;
        if voxels * 4 > raster.device.binding_limit() || voxels > u64::from(u32::MAX) {
            tracing::info!(
                voxels,
                "the TSDF grid exceeds the device's binding limit: fusing on the host"
            );
            return None;
        }
        let _span = info_span!("tsdf_fusion", backend = "gpu", views = cameras.len()).entered();
        Some(raster.device.scoped("tsdf fusion", || {
            self.fuse(raster, surfels, cameras, settings, grid)
        }))
    }

    fn fuse(
        &self,
        raster: &Rasterizer,
        surfels: &Surfels,
        cameras: &[Camera],
        settings: &RasterSettings,
        grid: &GridLayout,
    ) -> Result<ScalarGrid, RasterError> {
        for camera in cameras {
            validate_inputs(surfels, camera, settings)?;
        }
        let device = raster.device;
        let fusion = Fusion::new(device, self, grid)?;
        let uploaded = raster.upload(surfels)?;
        for camera in cameras {
            let _span = info_span!("view").entered();
            let depth = fusion.depth_map(camera)?;
            let frame = Frame::new(camera, settings, surfels, &uploaded);
            raster.rasterize_bands(&frame, |mut encoded| {
                let band = encoded.saved.band;
                let gbuf = &encoded.saved.gbuf;
                fusion.prepare_band(&mut encoded.encoder, camera, band, gbuf, &depth)?;
                device.queue().submit([encoded.encoder.finish()]);
                Ok(())
            })?;
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            fusion.add_view(&mut encoder, camera, &depth)?;
            device.queue().submit([encoder.finish()]);
        }
        Ok(fusion.read()?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::engine::Backend;
    use crate::core::mesh::tsdf_reference::{dense_reference, spheres_depth, with_unknown_band};
    use crate::core::mesh::{
        cameras_around, chamfer_l1_with, fuse_tsdf, fusion_depth, marching_cubes,
        rendered_depth_views, sphere_depth_maps, DepthView, TriangleMesh, TsdfParams,
    };
    use crate::gpu::layout::assert_mirrors;
    use crate::gpu::GpuBackend;

    #[test]
    fn fusion_params_mirror_the_wgsl() {
        assert_mirrors::<DepthBandGpu>(&shaders::PREPARE_DEPTH);
        assert_mirrors::<FuseViewGpu>(&shaders::FUSE_VIEW);
    }

    #[test]
    fn f32_limits_compare_like_the_f64_ones() {
        for x in [0.1, 1.0 / 3.0, 2.5, 1e-3 * std::f64::consts::PI] {
            let limit = f32_at_most(x);
            assert!(f64::from(limit) <= x);
            let above = f32::from_bits(limit.to_bits() + 1);
            assert!(
                f64::from(above) > x,
                "{x}: {limit} is not the largest below"
            );
        }
        assert_eq!(f32_at_most(0.5), 0.5);
        assert_eq!(f32_at_most(f64::INFINITY), f32::MAX);
    }

    /// Fuses `views` on the device through both kernels: each view's depth and alpha are laid out
    /// as G-buffers (`NUM_OUT` values per pixel, in bands of `band_rows` tile rows), cleaned
    /// band by band and fused.
    fn device_fusion(
        gpu: &GpuBackend,
        views: &[DepthView],
        grid: &GridLayout,
        band_rows: u32,
    ) -> ScalarGrid {
        let device = gpu.device();
        let fusion = Fusion::new(device, gpu.tsdf(), grid).unwrap();
        for view in views {
            let camera = view.camera;
            let gbuf: Vec<f32> = (0..camera.num_pixels())
                .flat_map(|p| {
                    let mut px = [0f32; NUM_OUT];
                    px[0] = view.alpha.map_or(1.0, |a| a[p] as f32);
                    px[1] = view.depth[p] as f32;
                    if view.depth[p].is_nan() {
                        // Unknown on the host: in G-buffers, depths spread far apart about a
                        // mean inside the grid (where a vote would show).
                        (px[1], px[10]) = (3.0, 1e6);
                    }
                    px
                })
                .collect();
            let depth = fusion.depth_map(camera).unwrap();
            let mut encoder = device.wgpu().create_command_encoder(&Default::default());
            for band in Band::split(camera.height, band_rows) {
                let rows = band.rows_of(&gbuf, camera.height, camera.width as usize * NUM_OUT);
                let buffer = device
                    .storage_init("band g-buffers", bytemuck::cast_slice(rows))
                    .unwrap();
                fusion
                    .prepare_band(&mut encoder, camera, band, &buffer, &depth)
                    .unwrap();
            }
            fusion.add_view(&mut encoder, camera, &depth).unwrap();
            device.queue().submit([encoder.finish()]);
        }
        fusion.read().unwrap()
    }

    /// How the device's grid compares with a dense reference fusion over every voxel.
    #[derive(Debug)]
    struct GridComparison {
        voxels: usize,
        /// Voxels known in one grid and not the other.
        known_differs: usize,
        /// Voxels known in both.
        both_known: usize,
        /// Of those, voxels whose values differ by more than 1e-4, and the largest difference.
        value_differs: usize,
        worst_value: f32,
    }

    fn compare(device: &ScalarGrid, reference: &ScalarGrid) -> GridComparison {
        assert_eq!(device.dims, reference.dims);
        assert_eq!(device.origin, reference.origin);
        assert_eq!(device.spacing, reference.spacing);
        let mut c = GridComparison {
            voxels: device.values.len(),
            known_differs: 0,
            both_known: 0,
            value_differs: 0,
            worst_value: 0.0,
        };
        for v in 0..c.voxels {
            match (device.known[v], reference.known[v]) {
                (true, true) => {
                    c.both_known += 1;
                    let diff = (device.values[v] - reference.values[v]).abs();
                    c.worst_value = c.worst_value.max(diff);
                    c.value_differs += usize::from(diff > 1e-4);
                }
                (false, false) => {}
                _ => c.known_differs += 1,
            }
        }
        c
    }

    /// Symmetric sampled Chamfer-L1 distance between two meshes.
    fn chamfer(a: &TriangleMesh, b: &TriangleMesh) -> f64 {
        let ab = chamfer_l1_with(a, b, 20_000, 1).unwrap();
        let ba = chamfer_l1_with(b, a, 20_000, 2).unwrap();
        0.5 * (ab + ba)
    }

    /// The device's fusion against the f64 dense reference (every voxel, the same rules) and the
    /// host's sparse fusion (its marching-cubes surface): the known flags agree on ≥ 99.9 % of all
    /// voxels, the values within 1e-4 on ≥ 99.9 % of the voxels both know, the host never knows
    /// a voxel the device does not, and the marching-cubes meshes lie within 0.1 % of a voxel of
    /// each other (symmetric Chamfer-L1).
    fn assert_matches_host(
        gpu: &GpuBackend,
        views: &[DepthView],
        bounds: (DVec3, DVec3),
        params: &TsdfParams,
        band_rows: u32,
    ) {
        let grid = GridLayout::new(bounds, params).unwrap();
        let device = device_fusion(gpu, views, &grid, band_rows);
        let reference = dense_reference(views, bounds, params);
        let c = compare(&device, &reference);
        println!("{c:?}");
        assert!(c.both_known > 10_000, "{c:?}");
        assert!(c.known_differs as f64 <= 1e-3 * c.voxels as f64, "{c:?}");
        assert!(
            c.value_differs as f64 <= 1e-3 * c.both_known as f64,
            "{c:?}"
        );
        let host = fuse_tsdf(views, bounds, params).unwrap();
        let host_only = (0..host.known.len())
            .filter(|&v| host.known[v] && !device.known[v])
            .count();
        assert!(
            host_only as f64 <= 1e-3 * c.voxels as f64,
            "{host_only} voxels only the host knows"
        );
        let (device_mesh, host_mesh) = (marching_cubes(&device), marching_cubes(&host));
        assert!(host_mesh.triangles.len() > 500);
        let distance = chamfer(&device_mesh, &host_mesh);
        println!(
            "triangles: device {}, host {}; Chamfer {distance:.2e} (voxel {:.2e})",
            device_mesh.triangles.len(),
            host_mesh.triangles.len(),
            grid.voxel
        );
        assert!(distance < 1e-3 * grid.voxel, "Chamfer {distance}");
    }

    #[test]
    fn device_fusion_of_a_sphere_matches_the_host() {
        let Some(gpu) = crate::gpu::test_backend() else {
            return;
        };
        let cameras = cameras_around(16, 3.0, 96, 40f64.to_radians());
        let depths = sphere_depth_maps(&cameras, DVec3::new(0.05, -0.1, 0.0), 0.8);
        let views: Vec<DepthView> = cameras
            .iter()
            .zip(&depths)
            .map(|(camera, depth)| DepthView {
                camera,
                depth,
                alpha: None,
            })
            .collect();
        let bounds = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let params = TsdfParams::automatic(48, &cameras, bounds);
        assert_matches_host(&gpu, &views, bounds, &params, 1 << 16);
    }

    #[test]
    fn device_fusion_of_spheres_with_background_and_partial_alpha_matches_the_host() {
        let Some(gpu) = crate::gpu::test_backend() else {
            return;
        };
        // Two overlapping spheres (occlusion edges, a concave crease), a small far one, and a
        // view limit that drops it from some views; every third view's alpha hides a strip of the
        // objects, and a strip of others' is exactly at the 0.5 threshold (surface); every fourth
        // view has a band of unknown pixels; the G-buffers come in bands of 3 tile rows.
        let spheres = [
            (DVec3::new(-0.25, 0.0, 0.0), 0.5),
            (DVec3::new(0.35, 0.1, 0.05), 0.4),
            (DVec3::new(0.0, 0.0, 0.85), 0.1),
        ];
        let size = 72;
        let cameras = cameras_around(12, 3.0, size, 40f64.to_radians());
        let mut depths = spheres_depth(&cameras, &spheres);
        with_unknown_band(&mut depths, size as usize);
        let alphas: Vec<Vec<f64>> = (0..cameras.len())
            .map(|v| {
                (0..cameras[v].num_pixels())
                    .map(|p| match p % size as usize {
                        x if v % 3 == 0 && x > 40 => 0.2,
                        x if v % 3 == 1 && (25..35).contains(&x) => 0.5,
                        _ => 0.9,
                    })
                    .collect()
            })
            .collect();
        let views: Vec<DepthView> = (0..cameras.len())
            .map(|v| DepthView {
                camera: &cameras[v],
                depth: &depths[v],
                alpha: Some(&alphas[v]),
            })
            .collect();
        let bounds = (DVec3::new(-1.0, -0.8, -0.8), DVec3::new(1.0, 0.8, 1.0));
        let mut params = TsdfParams::automatic(44, &cameras, bounds);
        params.depth_max = 3.4;
        // The device sees the unknown band only as G-buffer pixels whose depths spread.
        params.pixels = DepthPixels::Coherent;
        assert_matches_host(&gpu, &views, bounds, &params, 3);
    }

    /// The whole device path (rasterize, clean, fuse) against the host's fusion of the same
    /// backend's G-buffers read back: the same known flags wherever the host fused, values within
    /// 1e-4 there on ≥ 99.9 % of voxels, and marching cubes gives the same surface.
    #[test]
    fn rendered_depth_fused_on_the_device_matches_the_host_fusion_of_the_same_render() {
        let Some(gpu) = crate::gpu::test_backend() else {
            return;
        };
        let surfels = crate::testing::sphere_surfels(
            DVec3::new(0.1, 0.0, -0.1),
            0.7,
            3000,
            DVec3::splat(0.5),
        );
        let cameras = cameras_around(10, 2.6, 80, 40f64.to_radians());
        let settings = RasterSettings::default();
        let bounds = (DVec3::splat(-0.8), DVec3::new(1.0, 0.8, 0.7));
        let params = TsdfParams {
            pixels: DepthPixels::Coherent,
            ..TsdfParams::automatic(40, &cameras, bounds)
        };
        let grid = GridLayout::new(bounds, &params).unwrap();
        let device = gpu
            .fuse_depth(&surfels, &cameras, &settings, &grid)
            .expect("the grid fits")
            .unwrap();
        let maps: Vec<_> = cameras
            .iter()
            .map(|camera| {
                let g = crate::core::engine::Backend::forward(&gpu, &surfels, camera, &settings)
                    .unwrap()
                    .gbuffers;
                (
                    fusion_depth(camera, &g.depth, &g.depth_sq, grid.truncation),
                    g.alpha,
                )
            })
            .collect();
        let host = fuse_tsdf(&rendered_depth_views(&cameras, &maps), bounds, &params).unwrap();
        let (mut fused, mut flags_differ, mut values_differ) = (0, 0, 0);
        for v in 0..host.known.len() {
            if host.known[v] {
                fused += 1;
                flags_differ += usize::from(!device.known[v]);
                values_differ += usize::from(
                    device.known[v] && (device.values[v] - host.values[v]).abs() > 1e-4,
                );
            }
        }
        println!("host fused {fused}: flags differ {flags_differ}, values differ {values_differ}");
        assert!(fused > 5000);
        assert!(flags_differ as f64 <= 1e-3 * fused as f64);
        assert!(values_differ as f64 <= 1e-3 * fused as f64);
        let (device_mesh, host_mesh) = (marching_cubes(&device), marching_cubes(&host));
        assert!(host_mesh.triangles.len() > 500);
        let distance = chamfer(&device_mesh, &host_mesh);
        println!("Chamfer {distance:.2e} (voxel {:.2e})", grid.voxel);
        assert!(distance < 1e-3 * grid.voxel, "Chamfer {distance}");
    }
}

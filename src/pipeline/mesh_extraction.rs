//! Triangle mesh of a set of surfels (METHOD.md §8): render α-normalized depth and opacity from a set
//! of cameras (the training cameras), fuse them into a TSDF over the surfels' robust extent
//! ([`TsdfParams::automatic`]: 5-voxel truncation, depth limited to the far side of the bounds;
//! a deliverable leaves out the pixels whose depths spread beyond the truncation and a few
//! footprints, [`DepthPixels::Coherent`]),
//! run marching cubes and keep the largest component. A model's deliverable mesh also has its holes
//! closed and is smoothed by bilateral normal filtering ([`extract_deliverable`]); the export's glTF
//! gets it simplified to a triangle budget ([`simplify_deliverable`]). Used by `phygap mesh`, the
//! export, the evaluation's Chamfer distance and GridMap (training and rendering; its tracing mesh
//! is the raw one).
//!
//! A deliverable's grid is as fine as its views ([`MeshResolution::FromViews`],
//! [`footprint_resolution`]): a voxel about the footprint of a pixel at the object's distance from
//! the training cameras (median over the cameras of the object centre's depth over the focal
//! length, in pixels of the resolution the depth is rendered at), so between 64 and 256 voxels
//! along the object's longest side; finer voxels than the pixels only leave holes where the
//! coherent-depth test rejects a pixelated surface. An explicit resolution
//! ([`MeshResolution::Voxels`], `phygap mesh --resolution`) overrides it.
//!
//! On a backend with its own fusion ([`Backend::fuse_depth`]: the gpu one) the depth maps are
//! rendered and fused on the device and only the grid comes back; marching cubes runs on the host.
//!
//! Threading: views are rasterized one after the other (the backend parallelizes each); fusion and
//! marching cubes are parallel inside [`crate::core::mesh`] (or the fusion on the device).

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use crate::core::camera::Camera;
use crate::core::engine::Backend;
use crate::core::mesh::{
    cameras_around_point, fuse_tsdf, fusion_depth, mesh_from_grid, rendered_depth_views,
    DepthPixels, GridLayout, MeshError, Simplification, SimplifyTarget, SmoothParams, TriangleMesh,
    TsdfParams,
};
use crate::core::raster::{RasterError, RasterSettings};
use crate::core::surfels::{sigmoid, Surfels};
use crate::io::model::Model;
use crate::pipeline::backend::{self, BackendError};

/// Most voxels along the longest side that a deliverable's grid gets from its views
/// ([`MeshResolution::FromViews`]); also the resolution of the scorecard's Chamfer mesh before
/// the views chose it.
pub const MAX_MESH_RESOLUTION: usize = 256;

/// Fewest voxels along the longest side that a deliverable's grid gets from its views, however
/// coarse they are (below it a voxel rounds off more than the views lose).
pub const MIN_MESH_RESOLUTION: usize = 64;

/// How fine a deliverable's TSDF grid is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshResolution {
    /// A voxel about the size of a pixel's footprint at the object ([`footprint_resolution`]),
    /// between [`MIN_MESH_RESOLUTION`] and [`MAX_MESH_RESOLUTION`] voxels along the longest side.
    FromViews,
    /// This many voxels along the longest side of the object, whatever the views.
    Voxels(usize),
}

/// Resolution of `phygap mesh`, the export and the scorecard: chosen from the views.
pub const DEFAULT_MESH_RESOLUTION: MeshResolution = MeshResolution::FromViews;

/// Resolution of the meshes GridMap traces against (training and rendering use the same, so a
/// model renders with the lighting it was trained with).
pub const GRIDMAP_MESH_RESOLUTION: usize = 128;

/// Surfels at least this opaque define the extent of the object.
const EXTENT_MIN_OPACITY: f64 = 0.1;
/// Fraction of the surfel centres ignored at each end of every axis (floaters).
const EXTENT_TRIM: f64 = 0.002;
/// Padding added on every side of the trimmed extent, as a fraction of its diagonal.
const EXTENT_PADDING: f64 = 0.05;

/// Cameras placed around the object when a model carries no training cameras.
const ORBIT_VIEWS: usize = 48;
const ORBIT_SIZE: u32 = 128;

#[derive(Debug, Error)]
pub enum MeshingError {
    #[error("cannot extract a mesh: the model has no surfels")]
    NoSurfels,
    #[error("cannot extract a mesh: no cameras to render depth from")]
    NoCameras,
    #[error("mesh file {0}: unknown extension (use .ply or .obj)")]
    UnknownExtension(PathBuf),
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error(transparent)]
    Raster(#[from] RasterError),
    #[error(transparent)]
    Backend(#[from] BackendError),
}

/// The object's extent from its surfel centres: surfels with opacity ≥ 0.1 (all when there are too
/// few), each axis trimmed by 0.2% at both ends against floaters, padded by 5% of the diagonal.
pub fn surfel_bounds(surfels: &Surfels) -> Option<(DVec3, DVec3)> {
    let opaque: Vec<DVec3> = (0..surfels.len())
        .filter(|&i| sigmoid(surfels.opacity[i]) >= EXTENT_MIN_OPACITY)
        .map(|i| DVec3::from_array(surfels.position[i]))
        .collect();
    let points: Vec<DVec3> = if opaque.len() >= 8 {
        opaque
    } else {
        surfels
            .position
            .iter()
            .map(|p| DVec3::from_array(*p))
            .collect()
    };
    let points: Vec<DVec3> = points.into_iter().filter(|p| p.is_finite()).collect();
    if points.is_empty() {
        return None;
    }
    let trim = ((points.len() as f64) * EXTENT_TRIM).floor() as usize;
    let mut lo = DVec3::ZERO;
    let mut hi = DVec3::ZERO;
    for axis in 0..3 {
        let mut values: Vec<f64> = points.iter().map(|p| p[axis]).collect();
        values.sort_by(f64::total_cmp);
        lo[axis] = values[trim];
        hi[axis] = values[values.len() - 1 - trim];
    }
    let pad = EXTENT_PADDING * (hi - lo).length().max(1e-6);
    Some((lo - DVec3::splat(pad), hi + DVec3::splat(pad)))
}

/// Cameras on a Fibonacci sphere around the surfels' extent (3 radii away, 40° field of view),
/// for models saved without their training cameras.
pub fn orbit_cameras(surfels: &Surfels) -> Vec<Camera> {
    let Some((lo, hi)) = surfel_bounds(surfels) else {
        return Vec::new();
    };
    let centre = 0.5 * (lo + hi);
    let radius = 0.5 * (hi - lo).length();
    cameras_around_point(
        ORBIT_VIEWS,
        centre,
        3.0 * radius,
        ORBIT_SIZE,
        40f64.to_radians(),
    )
}

/// Renders depth and opacity of `surfels` from every camera and extracts the surface at a TSDF
/// resolution of `resolution` voxels along the longest side of [`surfel_bounds`]. A backend that
/// fuses on its own device ([`Backend::fuse_depth`], the gpu one) renders and fuses there and
/// only the grid comes back; otherwise the views' depth maps are rendered with
/// [`Backend::forward`] and fused on the host. Both fuse into the same [`GridLayout`] with the
/// same [`TsdfParams::automatic`] (its depth limit depends on the cameras only), trusting the
/// rendered `pixels` chosen ([`DepthPixels`]: all for GridMap's tracing mesh, the coherent ones
/// for a deliverable).
pub fn mesh_from_surfels(
    surfels: &Surfels,
    cameras: &[Camera],
    backend: &dyn Backend,
    settings: &RasterSettings,
    resolution: usize,
    pixels: DepthPixels,
) -> Result<TriangleMesh, MeshingError> {
    let _span =
        tracing::info_span!("mesh_from_surfels", views = cameras.len(), resolution).entered();
    let bounds = surfel_bounds(surfels).ok_or(MeshingError::NoSurfels)?;
    if cameras.is_empty() {
        return Err(MeshingError::NoCameras);
    }
    let params = TsdfParams {
        pixels,
        ..TsdfParams::automatic(resolution, cameras, bounds)
    };
    let grid = GridLayout::new(bounds, &params)?;
    let fused = match backend.fuse_depth(surfels, cameras, settings, &grid) {
        Some(fused) => fused?,
        None => {
            let mut maps = Vec::with_capacity(cameras.len());
            for camera in cameras {
                let g = backend.forward(surfels, camera, settings)?.gbuffers;
                let depth = match pixels {
                    DepthPixels::All => g.depth,
                    DepthPixels::Coherent => {
                        fusion_depth(camera, &g.depth, &g.depth_sq, grid.truncation)
                    }
                };
                maps.push((depth, g.alpha));
            }
            fuse_tsdf(&rendered_depth_views(cameras, &maps), bounds, &params)?
        }
    };
    Ok(mesh_from_grid(&fused)?)
}

/// The cameras a model's mesh is extracted from: its training cameras, else [`orbit_cameras`].
pub fn model_cameras(model: &Model) -> Vec<Camera> {
    if model.train_cameras.is_empty() {
        orbit_cameras(&model.surfels)
    } else {
        model.train_cameras.iter().map(|(_, c)| *c).collect()
    }
}

/// Voxels along the longest side of `bounds` for which a voxel is as large as a pixel's
/// footprint at the object: the median over `cameras` of the z-depth of the bounds' centre over
/// the focal length (the smaller of `fx`, `fy`, in pixels of the resolution the cameras render
/// at), rounded down and kept within [`MIN_MESH_RESOLUTION`]..=[`MAX_MESH_RESOLUTION`].
///
/// A voxel smaller than the footprint asks more of the depth than the views hold: the coherent
/// pixels' test ([`DepthPixels::Coherent`]) allows a depth spread of the truncation (5 voxels)
/// or four footprints, so finer voxels reject more of a pixelated surface, and a voxel between
/// pixel centres gets the bilinear depth of a cell wider than itself. On the quickstart's sphere
/// (96-pixel views, footprint 0.030) 256 voxels (0.0088) left 45 % of the surface unobserved,
/// 74 voxels 11 %. `None` without cameras or bounds in front of them.
pub fn footprint_resolution(cameras: &[Camera], bounds: (DVec3, DVec3)) -> Option<usize> {
    let centre = 0.5 * (bounds.0 + bounds.1);
    let longest = (bounds.1 - bounds.0).max_element();
    let mut footprints: Vec<f64> = cameras
        .iter()
        .map(|camera| camera.to_camera(centre).z / camera.fx.min(camera.fy))
        .filter(|footprint| footprint.is_finite() && *footprint > 0.0)
        .collect();
    if footprints.is_empty() || !(longest.is_finite() && longest > 0.0) {
        return None;
    }
    footprints.sort_by(f64::total_cmp);
    let median = footprints[footprints.len() / 2];
    let voxels = (longest / median).floor();
    Some((voxels.min(MAX_MESH_RESOLUTION as f64) as usize).max(MIN_MESH_RESOLUTION))
}

/// The number of voxels along the longest side that `resolution` asks for, for these cameras
/// and bounds ([`MAX_MESH_RESOLUTION`] where the views give no footprint).
pub fn grid_resolution(
    resolution: MeshResolution,
    cameras: &[Camera],
    bounds: (DVec3, DVec3),
) -> usize {
    match resolution {
        MeshResolution::FromViews => {
            footprint_resolution(cameras, bounds).unwrap_or(MAX_MESH_RESOLUTION)
        }
        MeshResolution::Voxels(voxels) => voxels,
    }
}

/// A model's deliverable mesh and what it took to make it.
#[derive(Clone, Debug)]
pub struct Deliverable {
    /// Closed and smoothed, as dense as the TSDF grid.
    pub mesh: TriangleMesh,
    /// Edge of the TSDF voxel the mesh was extracted at (scene units).
    pub voxel: f64,
    /// Voxels along the longest side of the object ([`grid_resolution`]).
    pub resolution: usize,
    /// The first `observed_triangles` triangles of `mesh` are the observed surface, the rest
    /// the caps over its holes.
    pub observed_triangles: usize,
    /// Fraction of the closed surface's area that the cameras observed (the rest are the caps
    /// over the holes, [`TriangleMesh::close_holes`]).
    pub observed_fraction: f64,
    /// Holes closed.
    pub holes: usize,
    /// Of those, the holes whose caps follow a quadric fitted to the surface around them.
    pub holes_continued: usize,
}

/// Largest deviation the simplification may introduce, in TSDF voxels. The dense mesh lies about
/// half a voxel to a voxel from the true surface on the shared captures; an eighth of a voxel
/// keeps the simplified mesh's distance to the truth within 6 % of the dense mesh's on each of
/// them (a quarter voxel added up to 11 %, on the sphere).
pub const SIMPLIFY_ERROR_VOXELS: f64 = 0.125;

/// The mesh of a trained model (its own backend, the training cameras) at `resolution`
/// ([`grid_resolution`]), its holes closed: the surface where no camera looked is a thin-plate
/// cap that continues the surface around the hole ([`TriangleMesh::close_holes`]), so the
/// deliverable is watertight; then smoothed by bilateral
/// normal filtering ([`TriangleMesh::smooth`]), which removes the lumps a few surfels wide and
/// keeps creases.
pub fn extract_deliverable(
    model: &Model,
    resolution: MeshResolution,
) -> Result<Deliverable, MeshingError> {
    let backend = backend::select(model.config.backend)?;
    let cameras = model_cameras(model);
    let (lo, hi) = surfel_bounds(&model.surfels).ok_or(MeshingError::NoSurfels)?;
    let resolution = grid_resolution(resolution, &cameras, (lo, hi));
    let mut mesh = mesh_from_surfels(
        &model.surfels,
        &cameras,
        &*backend,
        &model.raster_settings(),
        resolution,
        DepthPixels::Coherent,
    )?;
    let voxel = (hi - lo).max_element() / resolution as f64;
    let observed = mesh.area();
    let observed_triangles = mesh.triangles.len();
    let closed = mesh.close_holes();
    if closed.holes > 0 {
        tracing::info!(
            holes = closed.holes,
            continued = closed.continued,
            triangles = closed.triangles,
            "closed the mesh's holes"
        );
    }
    let total = mesh.area();
    mesh.smooth(SmoothParams::default());
    Ok(Deliverable {
        mesh,
        voxel,
        resolution,
        observed_triangles,
        observed_fraction: if total > 0.0 { observed / total } else { 0.0 },
        holes: closed.holes,
        holes_continued: closed.continued,
    })
}

/// [`extract_deliverable`]'s mesh.
pub fn extract_from_model(
    model: &Model,
    resolution: MeshResolution,
) -> Result<TriangleMesh, MeshingError> {
    Ok(extract_deliverable(model, resolution)?.mesh)
}

/// A deliverable mesh simplified to at most `max_triangles`, and further where its detail allows
/// (quadric error up to [`SIMPLIFY_ERROR_VOXELS`] voxels, [`TriangleMesh::simplified`]).
pub fn simplify_deliverable(
    deliverable: &Deliverable,
    max_triangles: usize,
) -> (TriangleMesh, Simplification) {
    deliverable.mesh.simplified(SimplifyTarget {
        max_triangles,
        max_error: SIMPLIFY_ERROR_VOXELS * deliverable.voxel,
    })
}

/// Writes a mesh as PLY or OBJ, chosen by the file extension (case-insensitive).
pub fn write_mesh(mesh: &TriangleMesh, path: &Path) -> Result<(), MeshingError> {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("ply") => Ok(mesh.write_ply(path)?),
        Some("obj") => Ok(mesh.write_obj(path)?),
        _ => Err(MeshingError::UnknownExtension(path.to_owned())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::sphere_surfels;

    #[test]
    fn a_surfel_sphere_meshes_to_a_sphere() {
        let surfels = sphere_surfels(DVec3::new(0.2, -0.1, 0.3), 0.8, 4000, DVec3::splat(0.5));
        let cameras = orbit_cameras(&surfels);
        assert_eq!(cameras.len(), ORBIT_VIEWS);
        let backend = crate::core::raster::cpu::CpuBackend;
        let mesh = mesh_from_surfels(
            &surfels,
            &cameras,
            &backend,
            &RasterSettings::default(),
            48,
            DepthPixels::Coherent,
        )
        .unwrap();
        assert!(mesh.triangles.len() > 500);
        let centre = DVec3::new(0.2, -0.1, 0.3);
        let worst = mesh
            .vertices
            .iter()
            .map(|v| (DVec3::from_array(*v).distance(centre) - 0.8).abs())
            .fold(0.0, f64::max);
        // Surfels are flat discs with Gaussian edges; a few percent of the radius is the TSDF's
        // resolution (1.8 / 48 ≈ 0.04 per voxel).
        assert!(worst < 0.06, "largest radial error {worst}");
        let (lo, hi) = surfel_bounds(&surfels).unwrap();
        assert!((lo - (centre - DVec3::splat(0.8))).max_element() < 0.0);
        assert!((hi - (centre + DVec3::splat(0.8))).min_element() > 0.0);
    }

    /// The gpu backend renders and fuses on the device (its `fuse_depth` answers), the cpu one
    /// renders in f64 and fuses on the host; from the same surfels and cameras their meshes lie
    /// within 0.1 % of a voxel of each other (symmetric Chamfer-L1) and both within the sphere
    /// test's radial bound.
    #[test]
    fn gpu_and_cpu_backends_mesh_the_same_surfels_alike() {
        let Some(gpu) = crate::gpu::test_backend() else {
            return;
        };
        let centre = DVec3::new(0.2, -0.1, 0.3);
        let surfels = sphere_surfels(centre, 0.8, 4000, DVec3::splat(0.5));
        let cameras = orbit_cameras(&surfels);
        let settings = RasterSettings::default();
        let resolution = 48;
        let bounds = surfel_bounds(&surfels).unwrap();
        let grid =
            GridLayout::new(bounds, &TsdfParams::automatic(resolution, &cameras, bounds)).unwrap();
        assert!(gpu
            .fuse_depth(&surfels, &cameras, &settings, &grid)
            .is_some());
        let mesh = |backend: &dyn Backend| {
            mesh_from_surfels(
                &surfels,
                &cameras,
                backend,
                &settings,
                resolution,
                DepthPixels::Coherent,
            )
            .unwrap()
        };
        let device = mesh(&gpu);
        let cpu = crate::core::raster::cpu::CpuBackend;
        let host = mesh(&cpu);
        let forward = crate::core::mesh::chamfer_l1_with(&device, &host, 20_000, 1).unwrap();
        let backward = crate::core::mesh::chamfer_l1_with(&host, &device, 20_000, 2).unwrap();
        println!(
            "triangles: gpu {}, cpu {}; Chamfer {forward:.2e} / {backward:.2e}, voxel {:.2e}",
            device.triangles.len(),
            host.triangles.len(),
            grid.voxel
        );
        assert!(forward < 1e-3 * grid.voxel && backward < 1e-3 * grid.voxel);
        for mesh in [&device, &host] {
            let worst = mesh
                .vertices
                .iter()
                .map(|v| (DVec3::from_array(*v).distance(centre) - 0.8).abs())
                .fold(0.0, f64::max);
            assert!(worst < 0.06, "largest radial error {worst}");
        }
    }

    /// A sparse patch (the bottom cap's surfels at opacity 0.3) lets the far wall through: its
    /// pixels reach α ≥ 0.5 only with the far wall's share, so their mean depth lies inside the
    /// sphere. Fused as surface they carve the interior and leave a sheet inside; as unknown
    /// (the coherent pixels only: their depths spread far more than the truncation) they leave
    /// the shell alone.
    #[test]
    fn pixels_seen_through_a_sparse_patch_carve_no_interior_sheet() {
        let (centre, radius) = (DVec3::new(0.1, 0.0, -0.1), 0.8);
        let mut surfels = sphere_surfels(centre, radius, 4000, DVec3::splat(0.5));
        for i in 0..surfels.len() {
            if surfels.get(i).position.z - centre.z < -0.5 * radius {
                surfels.opacity[i] = crate::core::surfels::logit(0.3);
            }
        }
        let cameras = orbit_cameras(&surfels);
        let backend = crate::core::raster::cpu::CpuBackend;
        let settings = RasterSettings::default();
        let bottom = cameras
            .iter()
            .map(|c| backend.forward(&surfels, c, &settings).unwrap().gbuffers)
            .flat_map(|g| {
                (0..g.alpha.len())
                    .filter(|&p| g.alpha[p] >= 0.5)
                    .map(|p| crate::core::mesh::depth_spread(g.depth[p], g.depth_sq[p]))
                    .collect::<Vec<_>>()
            })
            .filter(|&spread| spread > 0.2)
            .count();
        assert!(
            bottom > 100,
            "{bottom} pixels mix the patch and the far wall"
        );
        let deepest = |pixels| {
            let mesh =
                mesh_from_surfels(&surfels, &cameras, &backend, &settings, 48, pixels).unwrap();
            mesh.vertices
                .iter()
                .map(|v| radius - DVec3::from_array(*v).distance(centre))
                .fold(0.0, f64::max)
        };
        let (coherent, all) = (deepest(DepthPixels::Coherent), deepest(DepthPixels::All));
        assert!(coherent < 0.1, "a vertex lies {coherent} inside the shell");
        // Trusting every pixel (GridMap's tracing mesh) leaves the sheet.
        assert!(all > 0.25, "the deepest vertex lies only {all} inside");
    }

    /// A voxel as large as a pixel's footprint at the object: cameras 4 units from the centre
    /// with a 40° field of view see 0.0303 a pixel at 96 pixels (the quickstart's capture), so a
    /// 2.34-unit object gets 77 voxels; at 256 pixels (footprint 0.0114) 205; views finer or
    /// coarser than the limits give 256 or 64, and an explicit resolution wins.
    #[test]
    fn the_grid_is_as_fine_as_the_views() {
        let bounds = (DVec3::splat(-1.17), DVec3::splat(1.17));
        let views = |size| cameras_around_point(24, DVec3::ZERO, 4.0, size, 40f64.to_radians());
        assert_eq!(footprint_resolution(&views(96), bounds), Some(77));
        assert_eq!(footprint_resolution(&views(256), bounds), Some(205));
        assert_eq!(
            footprint_resolution(&views(2048), bounds),
            Some(MAX_MESH_RESOLUTION)
        );
        assert_eq!(
            footprint_resolution(&views(24), bounds),
            Some(MIN_MESH_RESOLUTION)
        );
        // The same views twice as far: a footprint twice as large, half the voxels.
        let far = cameras_around_point(24, DVec3::ZERO, 8.0, 256, 40f64.to_radians());
        assert_eq!(footprint_resolution(&far, bounds), Some(102));
        assert_eq!(footprint_resolution(&[], bounds), None);
        assert_eq!(
            grid_resolution(MeshResolution::FromViews, &[], bounds),
            MAX_MESH_RESOLUTION
        );
        assert_eq!(
            grid_resolution(MeshResolution::Voxels(300), &views(96), bounds),
            300
        );
    }

    #[test]
    fn floaters_do_not_stretch_the_bounds_and_extensions_choose_the_format() {
        let mut surfels = sphere_surfels(DVec3::ZERO, 1.0, 2000, DVec3::splat(0.5));
        let mut floater = surfels.get(0);
        floater.position = DVec3::new(40.0, 0.0, 0.0);
        surfels.push_activated(&floater);
        let (_, hi) = surfel_bounds(&surfels).unwrap();
        assert!(hi.x < 1.3, "{hi}");
        let dir = tempfile::tempdir().unwrap();
        let mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 1);
        write_mesh(&mesh, &dir.path().join("m.PLY")).unwrap();
        write_mesh(&mesh, &dir.path().join("m.obj")).unwrap();
        assert_eq!(
            TriangleMesh::read_ply(&dir.path().join("m.PLY"))
                .unwrap()
                .triangles,
            mesh.triangles
        );
        assert!(matches!(
            write_mesh(&mesh, &dir.path().join("m.stl")),
            Err(MeshingError::UnknownExtension(_))
        ));
    }
}

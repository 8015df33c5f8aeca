//! Exporting a trained model's deliverables into a folder: surfels, the environment map (lat-long
//! EXR, Radiance HDR and a tone-mapped PNG preview, [`envmap_files`]), the extracted mesh, closed
//! and smoothed (`mesh.ply`, dense), the mesh simplified to the model's triangle budget with its
//! learned materials as glTF 2.0 binary (`model.glb`, [`gltf`]: materials sampled from the surfels
//! by [`materials`], baked into textures on a UV atlas by [`bake`], or per vertex), configuration,
//! metrics, and
//! S0/normal/albedo/DoLP/AoLP renders of the capture's test views. This is what the service
//! publishes as a job's artifacts and what `phygap export` writes.

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use crate::core::config::MeshMaterials;
use crate::core::envmap::EnvMapError;
use crate::core::mesh::{AtlasParams, MeshError, TriangleMesh, UvAtlas};
use crate::formats::image_io::{self, ImageError};
use crate::io::capture::{self, CaptureError};
use crate::io::model::{Model, ModelError, LATLONG_HEIGHT, TEST_CAMERAS_FILE};
use crate::pipeline::mesh_extraction::{self, MeshingError, DEFAULT_MESH_RESOLUTION};
use crate::pipeline::reconstruction::{Reconstruction, ReconstructionError};

pub mod bake;
pub mod envmap_files;
pub mod gltf;
pub mod material_mesh;
pub mod materials;

pub use envmap_files::{ENVMAP_HDR_FILE, ENVMAP_PNG_FILE};
pub use gltf::{write_glb, write_textured_glb, GlbSummary, GltfError, TexturedMesh};
pub use materials::{transfer_materials, MaterialError, VertexMaterial};

#[derive(Debug, Error)]
pub enum ExportError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Reconstruction(#[from] ReconstructionError),
    #[error(transparent)]
    Cameras(#[from] CaptureError),
    #[error(transparent)]
    Meshing(#[from] MeshingError),
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
    #[error(transparent)]
    Image(#[from] ImageError),
    #[error(transparent)]
    Materials(#[from] MaterialError),
    #[error("model.glb: {0}")]
    Gltf(#[from] GltfError),
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// Files copied as they are from the model folder (when present).
const COPIED: [&str; 5] = [
    "surfels.ply",
    ENVMAP_EXR_FILE,
    "config.json",
    METRICS_FILE,
    "model.json",
];

/// The mesh written into the export folder.
pub const MESH_FILE: &str = "mesh.ply";

/// The mesh with its learned materials, glTF 2.0 binary.
pub const GLB_FILE: &str = "model.glb";

/// The lat-long environment map (copied from the model folder, written when it lacks one).
pub const ENVMAP_EXR_FILE: &str = "envmap.exr";

/// The run's metrics (copied from the model folder); the export adds its `warnings` (a list of
/// text, e.g. why there is no mesh).
pub const METRICS_FILE: &str = "metrics.json";

/// Appends `warning` to the `warnings` of the metrics file at `path` (made if missing).
fn add_warning(path: &Path, warning: &str) -> Result<(), ExportError> {
    let io = |source| ExportError::Io {
        path: path.to_owned(),
        source,
    };
    let mut metrics = match std::fs::read(path) {
        Ok(bytes) => serde_json::from_slice::<serde_json::Value>(&bytes)
            .ok()
            .filter(serde_json::Value::is_object)
            .unwrap_or_else(|| serde_json::json!({})),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => serde_json::json!({}),
        Err(e) => return Err(io(e)),
    };
    if let Some(object) = metrics.as_object_mut() {
        let list = object
            .entry("warnings")
            .or_insert_with(|| serde_json::json!([]));
        if !list.is_array() {
            *list = serde_json::json!([]);
        }
        if let Some(list) = list.as_array_mut() {
            list.push(warning.into());
        }
    }
    let text = serde_json::to_vec_pretty(&metrics).map_err(|e| io(e.into()))?;
    std::fs::write(path, text).map_err(io)
}

/// The warnings an export left in `out_dir`'s metrics (none when it left none).
pub fn warnings(out_dir: &Path) -> Vec<String> {
    std::fs::read(out_dir.join(METRICS_FILE))
        .ok()
        .and_then(|bytes| serde_json::from_slice::<serde_json::Value>(&bytes).ok())
        .and_then(|metrics| metrics.get("warnings").cloned())
        .and_then(|list| serde_json::from_value::<Vec<String>>(list).ok())
        .unwrap_or_default()
}

/// Kinds rendered for every test camera (DoLP and AoLP: the polarization the model predicts).
const RENDERED: [&str; 5] = ["s0", "normal", "albedo", "dolp", "aolp"];

/// Texels across the diagonal of the object's bounding box that the textures aim at at most.
pub const TEXELS_ACROSS: f64 = 1024.0;

/// Texels along the mean spacing of the surfels that carry the materials: two, as many as the
/// sampling theorem asks of the detail the surfels can hold; more would only enlarge the file.
pub const TEXELS_PER_SURFEL_SPACING: f64 = 2.0;

/// Smallest and largest side of the baked textures (texels).
pub const TEXTURE_SIZES: (u32, u32) = (256, 2048);

/// The side of a texel (scene units) that the textures of `mesh`, whose materials come from
/// `surfels` surfels, aim at: the larger (the coarser) of [`TEXELS_ACROSS`] texels along its box's
/// diagonal and [`TEXELS_PER_SURFEL_SPACING`] texels along the surfels' mean spacing
/// (√(area / surfels)). `None` for a mesh without area.
pub fn target_texel(mesh: &TriangleMesh, surfels: usize) -> Option<f64> {
    let (min, max) = mesh.bounds()?;
    let area = mesh.area();
    let object_texel = (max - min).length() / TEXELS_ACROSS;
    let surfel_texel = (area / surfels.max(1) as f64).sqrt() / TEXELS_PER_SURFEL_SPACING;
    let texel = object_texel.max(surfel_texel);
    (texel > 0.0 && texel.is_finite()).then_some(texel)
}

/// The atlas of `mesh` on the smallest power-of-two texture in [`TEXTURE_SIZES`] whose packed
/// charts reach the density of [`target_texel`] (the largest size when none does): from the size
/// the surface would need with nothing lost to packing, doubled while the charts come out coarser.
/// Gutters of 4 texels, 8 at 2048.
pub fn sized_atlas(mesh: &TriangleMesh, surfels: usize) -> UvAtlas {
    let (lo, hi) = TEXTURE_SIZES;
    let texel = target_texel(mesh, surfels);
    let mut size = lo;
    if let Some(texel) = texel {
        while f64::from(size) < mesh.area().sqrt() / texel && size < hi {
            size *= 2;
        }
    }
    loop {
        let atlas = UvAtlas::build(
            mesh,
            AtlasParams {
                size,
                gutter: (size / 256).max(4),
                ..AtlasParams::default()
            },
        );
        let dense_enough = texel.is_none_or(|t| atlas.texels_per_unit * t >= 1.0);
        if dense_enough || size >= hi {
            return atlas;
        }
        size *= 2;
    }
}

/// Writes `mesh` (extracted from `model`) with the model's materials as a glTF binary at `path`,
/// in the form `form` chooses ([`gltf`]).
pub fn write_model_glb(
    model: &Model,
    mesh: &TriangleMesh,
    path: &Path,
    form: MeshMaterials,
) -> Result<GlbSummary, ExportError> {
    let _span = tracing::info_span!("write_model_glb", form = ?form).entered();
    let surfels = materials::surfel_list(&model.surfels);
    let sampler = materials::SurfelSampler::new(&surfels)?;
    let up = model.world_up()?;
    let summary = match form {
        MeshMaterials::Vertex => {
            let points: Vec<DVec3> = mesh
                .vertices
                .iter()
                .map(|v| DVec3::from_array(*v))
                .collect();
            let vertex_materials: Vec<VertexMaterial> = sampler
                .sample(&points, None)
                .into_iter()
                .map(|(m, _)| m)
                .collect();
            gltf::write_glb(path, mesh, &vertex_materials, up)?
        }
        MeshMaterials::Textures => {
            let atlas = sized_atlas(mesh, sampler.len());
            let size = atlas.size;
            let gutter = (size / 256).max(4);
            let tangents = atlas.tangents();
            let maps = bake::bake(
                &atlas,
                &tangents,
                bake::BakeParams { dilate: gutter },
                |points| {
                    let positions: Vec<DVec3> = points.iter().map(|p| p.position).collect();
                    let normals: Vec<DVec3> = points.iter().map(|p| p.normal).collect();
                    sampler
                        .sample(&positions, Some(&normals))
                        .into_iter()
                        .map(|(material, normal)| bake::SurfaceSample { material, normal })
                        .collect()
                },
            );
            let points: Vec<DVec3> = mesh
                .vertices
                .iter()
                .map(|v| DVec3::from_array(*v))
                .collect();
            let at_vertices = sampler.sample(&points, None);
            let vertex_materials: Vec<VertexMaterial> = atlas
                .source_vertex
                .iter()
                .map(|&v| at_vertices[v as usize].0)
                .collect();
            tracing::info!(
                charts = atlas.charts,
                texture = size,
                covered = maps.covered,
                "materials baked"
            );
            gltf::write_textured_glb(
                path,
                &TexturedMesh {
                    atlas: &atlas,
                    tangents: &tangents,
                    vertex_materials: &vertex_materials,
                    maps: &maps,
                },
                up,
            )?
        }
    };
    tracing::info!(
        vertices = summary.vertices,
        triangles = summary.triangles,
        ior = summary.ior,
        bytes = summary.bytes,
        texture = summary.texture_size,
        "glTF written"
    );
    Ok(summary)
}

/// Writes the deliverables of `model_dir` into `out_dir` (created if needed), the glTF's mesh
/// simplified to the model's `mesh_triangles`, its materials in the model's `mesh_materials`
/// form; returns the files.
pub fn export(model_dir: &Path, out_dir: &Path) -> Result<Vec<PathBuf>, ExportError> {
    export_with(model_dir, out_dir, ExportOptions::default())
}

/// What an export may choose instead of the model's config.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ExportOptions {
    /// The glTF's triangle budget (`Some(0)`: the dense mesh) instead of `mesh_triangles`.
    pub mesh_triangles: Option<u32>,
    /// The glTF's form of the materials instead of `mesh_materials`.
    pub mesh_materials: Option<MeshMaterials>,
}

/// [`export`] with [`ExportOptions`].
pub fn export_with(
    model_dir: &Path,
    out_dir: &Path,
    options: ExportOptions,
) -> Result<Vec<PathBuf>, ExportError> {
    let _span = tracing::info_span!("export", model = %model_dir.display()).entered();
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| ExportError::Io { path, source }
    };
    let model = Model::load(model_dir)?;
    std::fs::create_dir_all(out_dir).map_err(io(out_dir))?;
    let mut written = Vec::new();
    for name in COPIED {
        let from = model_dir.join(name);
        if from.exists() {
            let to = out_dir.join(name);
            std::fs::copy(&from, &to).map_err(io(&from))?;
            written.push(to);
        }
    }
    let deliverable = match mesh_extraction::extract_deliverable(&model, DEFAULT_MESH_RESOLUTION) {
        Ok(deliverable) => Some(deliverable),
        // A run too short to form a surface still has its light, materials and renders.
        Err(MeshingError::Mesh(MeshError::NoSurface)) if !model.config.require_mesh => {
            let warning = format!("no {MESH_FILE} or {GLB_FILE}: {}", MeshError::NoSurface);
            tracing::warn!(%warning, "exporting without a mesh");
            let metrics = out_dir.join(METRICS_FILE);
            add_warning(&metrics, &warning)?;
            if !written.contains(&metrics) {
                written.push(metrics);
            }
            None
        }
        Err(e) => return Err(e.into()),
    };
    if let Some(deliverable) = deliverable {
        let mesh_path = out_dir.join(MESH_FILE);
        mesh_extraction::write_mesh(&deliverable.mesh, &mesh_path)?;
        written.push(mesh_path);
        let glb_path = out_dir.join(GLB_FILE);
        let budget = options
            .mesh_triangles
            .unwrap_or(model.config.mesh_triangles);
        let form = options
            .mesh_materials
            .unwrap_or(model.config.mesh_materials);
        let light = (budget > 0)
            .then(|| mesh_extraction::simplify_deliverable(&deliverable, budget as usize).0)
            // A surface of a few voxels (a run of a few steps) can collapse entirely; the
            // glTF then carries the dense mesh, which is as small.
            .filter(|light| {
                light
                    .triangles
                    .iter()
                    .any(|&[a, b, c]| a != b && b != c && a != c)
            });
        write_model_glb(
            &model,
            light.as_ref().unwrap_or(&deliverable.mesh),
            &glb_path,
            form,
        )?;
        written.push(glb_path);
    }
    let up = model.world_up()?;
    let latlong = model.envmap.to_latlong(LATLONG_HEIGHT, up);
    let exr_path = out_dir.join(ENVMAP_EXR_FILE);
    if !model_dir.join(ENVMAP_EXR_FILE).exists() {
        image_io::write_exr(&exr_path, &latlong)?;
        written.push(exr_path);
    }
    written.extend(envmap_files::write_envmap_files(out_dir, &latlong)?);
    let cameras_file = model_dir.join(TEST_CAMERAS_FILE);
    if cameras_file.exists() {
        let cameras = capture::load_cameras(&cameras_file)?;
        let reconstruction = Reconstruction::new(model)?;
        written.extend(reconstruction.render_to_dir(
            &cameras,
            &out_dir.join("renders"),
            &RENDERED,
        )?);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_texture_reaches_the_density_of_the_surfels_or_of_the_object() {
        let sphere = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 4);
        let area = sphere.area();
        // Few surfels: two texels along their spacing.
        let texel = target_texel(&sphere, 5_000).unwrap();
        assert!((texel - (area / 5_000.0).sqrt() / 2.0).abs() < 1e-12);
        // Many: 1024 texels along the box's diagonal (2√3 for the unit sphere).
        let texel = target_texel(&sphere, 10_000_000).unwrap();
        assert!((texel - 12f64.sqrt() / 1024.0).abs() < 1e-9, "{texel}");
        assert_eq!(target_texel(&TriangleMesh::default(), 100), None);
        let mut sizes = Vec::new();
        for surfels in [2_000, 20_000, 200_000, 10_000_000] {
            let atlas = sized_atlas(&sphere, surfels);
            let texel = target_texel(&sphere, surfels).unwrap();
            // Dense enough, and the next smaller texture would not be (or it is the smallest).
            assert!(atlas.texels_per_unit * texel >= 1.0 || atlas.size == 2048);
            if atlas.size > 256 {
                let smaller = UvAtlas::build(
                    &sphere,
                    AtlasParams {
                        size: atlas.size / 2,
                        gutter: (atlas.size / 512).max(4),
                        ..AtlasParams::default()
                    },
                );
                assert!(smaller.texels_per_unit * texel < 1.0, "{surfels} surfels");
            }
            sizes.push(atlas.size);
        }
        assert!(sizes.windows(2).all(|w| w[0] <= w[1]), "{sizes:?}");
        assert_eq!((sizes[0], sizes[3]), (256, 2048), "{sizes:?}");
    }
}

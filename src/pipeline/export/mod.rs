//! Exporting a trained model's deliverables into a folder: surfels, the environment map (lat-long
//! EXR, Radiance HDR and a tone-mapped PNG preview, [`envmap_files`]), the extracted mesh, closed
//! and smoothed (`mesh.ply`, dense), the mesh simplified to the model's triangle budget with its
//! learned materials as glTF 2.0 binary (`model.glb`, [`gltf`], materials sampled from the surfels
//! by [`materials`]), configuration, metrics, and
//! S0/normal/albedo/DoLP/AoLP renders of the capture's test views. This is what the service
//! publishes as a job's artifacts and what `phygap export` writes.

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use crate::core::envmap::EnvMapError;
use crate::core::mesh::{MeshError, TriangleMesh};
use crate::formats::image_io::{self, ImageError};
use crate::io::capture::{self, CaptureError};
use crate::io::model::{Model, ModelError, LATLONG_HEIGHT, TEST_CAMERAS_FILE};
use crate::pipeline::mesh_extraction::{self, MeshingError, DEFAULT_MESH_RESOLUTION};
use crate::pipeline::reconstruction::{Reconstruction, ReconstructionError};

pub mod envmap_files;
pub mod gltf;
pub mod material_mesh;
pub mod materials;

pub use envmap_files::{ENVMAP_HDR_FILE, ENVMAP_PNG_FILE};
pub use gltf::{write_glb, GlbSummary, GltfError};
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

/// Writes `mesh` (extracted from `model`) with the model's materials on its vertices as a glTF
/// binary at `path`.
pub fn write_model_glb(
    model: &Model,
    mesh: &TriangleMesh,
    path: &Path,
) -> Result<GlbSummary, ExportError> {
    let points: Vec<DVec3> = mesh
        .vertices
        .iter()
        .map(|v| DVec3::from_array(*v))
        .collect();
    let vertex_materials =
        materials::transfer_materials(&points, &materials::surfel_list(&model.surfels))?;
    let summary = gltf::write_glb(path, mesh, &vertex_materials, model.world_up()?)?;
    tracing::info!(
        vertices = summary.vertices,
        triangles = summary.triangles,
        ior = summary.ior,
        bytes = summary.bytes,
        "glTF written"
    );
    Ok(summary)
}

/// Writes the deliverables of `model_dir` into `out_dir` (created if needed), the glTF's mesh
/// simplified to the model's `mesh_triangles`; returns the files.
pub fn export(model_dir: &Path, out_dir: &Path) -> Result<Vec<PathBuf>, ExportError> {
    export_with(model_dir, out_dir, None)
}

/// [`export`] with the glTF's triangle budget given (`Some(0)`: the dense mesh), instead of the
/// model's config's `mesh_triangles`.
pub fn export_with(
    model_dir: &Path,
    out_dir: &Path,
    mesh_triangles: Option<u32>,
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
        let budget = mesh_triangles.unwrap_or(model.config.mesh_triangles);
        if budget == 0 {
            write_model_glb(&model, &deliverable.mesh, &glb_path)?;
        } else {
            let (light, _) = mesh_extraction::simplify_deliverable(&deliverable, budget as usize);
            write_model_glb(&model, &light, &glb_path)?;
        }
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

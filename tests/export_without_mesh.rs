//! A model whose depth fuses to no surface (the TSDF has no zero crossing, as after a run too
//! short to form one) still exports its light, materials and renders: without `mesh.ply` and
//! `model.glb`, saying why in `metrics.json`'s `warnings`; unless its config has `require_mesh`,
//! when the export fails as before.

use std::collections::BTreeMap;

use glam::DVec3;
use phygap::core::config::{BackendChoice, TrainConfig};
use phygap::core::envmap::{CubeMap, NUM_FACES};
use phygap::core::mesh::cameras_around;
use phygap::core::surfels::logit;
use phygap::io::model::{Model, ModelInfo};
use phygap::pipeline::export::{self, ExportError, GLB_FILE, MESH_FILE, METRICS_FILE};
use phygap::pipeline::mesh_extraction::MeshingError;
use phygap::testing::sphere_surfels;

const SIZE: usize = 8;

/// A sphere of surfels too faint to leave any depth: no surface to extract.
fn faint_model(require_mesh: bool) -> Model {
    let mut surfels = sphere_surfels(DVec3::ZERO, 1.0, 500, DVec3::new(0.6, 0.4, 0.2));
    for opacity in surfels.opacity.iter_mut() {
        *opacity = logit(1e-4);
    }
    let train_cameras = cameras_around(6, 4.0, 24, 40f64.to_radians())
        .into_iter()
        .enumerate()
        .map(|(i, c)| (format!("{i:03}"), c))
        .collect();
    Model {
        info: ModelInfo {
            mode: phygap::core::config::Mode::Full,
            world_up: [0.0, 0.0, 1.0],
            polarizer_angles_deg: BTreeMap::new(),
            iterations: 20,
            train_seconds: 0.0,
            num_surfels: surfels.len(),
            backend: "cpu".into(),
            working_resolution: None,
            refined_poses: None,
            silhouette_offset_px: None,
            frame_registration: None,
        },
        config: TrainConfig {
            iterations: 20.into(),
            envmap_resolution: SIZE as u32,
            backend: BackendChoice::Cpu,
            gridmap: false,
            require_mesh,
            ..TrainConfig::default()
        },
        surfels,
        envmap: CubeMap::from_radiance(SIZE, &[0.5; NUM_FACES * SIZE * SIZE * 3]).unwrap(),
        train_cameras,
    }
}

#[test]
fn an_export_without_a_surface_goes_on_without_the_mesh_and_says_why() {
    let dir = tempfile::tempdir().unwrap();
    let model_dir = dir.path().join("model");
    faint_model(false).save(&model_dir).unwrap();
    std::fs::write(model_dir.join(METRICS_FILE), r#"{"psnr": 12.5}"#).unwrap();
    let out = dir.path().join("export");
    let files = export::export(&model_dir, &out).unwrap();
    assert!(!out.join(MESH_FILE).exists() && !out.join(GLB_FILE).exists());
    assert!(out.join("envmap.exr").exists() && out.join("envmap.hdr").exists());
    assert!(files.contains(&out.join(METRICS_FILE)));
    let warnings = export::warnings(&out);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains("no zero crossing"), "{warnings:?}");
    assert!(warnings[0].contains(MESH_FILE), "{warnings:?}");
    // The metrics the run wrote are kept beside the warning.
    let metrics: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join(METRICS_FILE)).unwrap()).unwrap();
    assert_eq!(metrics["psnr"], 12.5);
}

#[test]
fn an_export_that_requires_the_mesh_fails_without_one() {
    let dir = tempfile::tempdir().unwrap();
    let model_dir = dir.path().join("model");
    faint_model(true).save(&model_dir).unwrap();
    let error = export::export(&model_dir, &dir.path().join("export")).unwrap_err();
    assert!(
        matches!(error, ExportError::Meshing(MeshingError::Mesh(_))),
        "{error}"
    );
    assert!(error.to_string().contains("no zero crossing"), "{error}");
}

/// After 10 steps a capture's surfels fuse to a surface of a few voxels, which the simplification
/// can collapse to nothing: `model.glb` then carries the dense mesh instead of failing the export.
#[test]
fn a_surface_the_simplification_collapses_exports_the_dense_mesh() {
    use phygap::pipeline::mesh_extraction::{
        extract_deliverable, simplify_deliverable, DEFAULT_MESH_RESOLUTION,
    };
    let dir = tempfile::tempdir().unwrap();
    let capture_dir = dir.path().join("capture");
    phygap::pipeline::synth::synth(
        &capture_dir,
        &phygap::pipeline::synth::SynthOptions {
            views: 10,
            ..Default::default()
        },
    )
    .unwrap();
    let capture = phygap::io::capture::load(&capture_dir).unwrap();
    let model_dir = dir.path().join("model");
    let config = TrainConfig {
        iterations: 10.into(),
        gridmap: false,
        ..TrainConfig::default()
    };
    let cancel = std::sync::atomic::AtomicBool::new(false);
    phygap::pipeline::train::train(&capture, &model_dir, &config, false, &cancel, &mut |_| {})
        .unwrap();
    let model = Model::load(&model_dir).unwrap();
    let deliverable = extract_deliverable(&model, DEFAULT_MESH_RESOLUTION).unwrap();
    let (light, _) = simplify_deliverable(&deliverable, config.mesh_triangles as usize);
    let proper = |m: &phygap::core::mesh::TriangleMesh| {
        m.triangles
            .iter()
            .filter(|&&[a, b, c]| a != b && b != c && a != c)
            .count()
    };
    // The case this test is about: nothing left after the simplification, a few dense triangles.
    assert_eq!(
        proper(&light),
        0,
        "the simplified mesh kept {} of {} triangles",
        proper(&light),
        proper(&deliverable.mesh)
    );
    assert!(proper(&deliverable.mesh) > 0);
    let out = dir.path().join("export");
    export::export(&model_dir, &out).unwrap();
    assert!(out.join(MESH_FILE).exists() && out.join(GLB_FILE).exists());
    assert!(export::warnings(&out).is_empty());
}

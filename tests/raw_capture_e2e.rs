//! End to end on raw polarization frames: a capture the project renders itself (`phygap::pipeline::synth`),
//! re-recorded by a simulated IMX250MZR as a folder of 12-bit mosaic PNG frames with a
//! `transforms.json`, loads and trains through the PolarDR stage; so do the same frames named
//! after the images of a COLMAP model, with its sparse points seeding the surfels.

use std::path::Path;
use std::sync::atomic::AtomicBool;

use phygap::core::config::{BackendChoice, Mode, TrainConfig};
use phygap::core::events::{Stage, TrainEvent};
use phygap::io::capture::colmap::model::{
    write_model, ColmapCamera, ColmapImage, ColmapModel, ColmapPoint, ModelFormat,
};
use phygap::io::capture::colmap::pose_from_camera_to_world;
use phygap::io::capture::simulate::{write_raw_capture, SimulateOptions};
use phygap::io::capture::{self, Capture, Measurement};
use phygap::pipeline::synth::{synth, SynthOptions};
use phygap::pipeline::train::{train, TrainOutcome};

fn config() -> TrainConfig {
    TrainConfig {
        iterations: 40.into(),
        initial_surfels: 1000,
        envmap_resolution: 16,
        geometry_stage_end: 0.25,
        material_stage_end: 0.5,
        checkpoint_interval: 0,
        eval_interval: 0,
        mesh_interval: 20,
        gridmap_interval: 10,
        backend: BackendChoice::Cpu,
        ..TrainConfig::default()
    }
}

/// Trains `capture` and returns the events; checks it finished in full (Stokes) mode with finite
/// losses in the PolarDR stage.
fn train_briefly(capture: &Capture, model: &Path) -> Vec<TrainEvent> {
    let mut events = Vec::new();
    let never = AtomicBool::new(false);
    let outcome = train(capture, model, &config(), false, &never, &mut |e| {
        events.push(e.clone())
    })
    .unwrap();
    assert_eq!(outcome, TrainOutcome::Finished);
    let polar: Vec<f64> = events
        .iter()
        .filter_map(|e| match e {
            TrainEvent::Step {
                stage: Stage::Polar,
                losses,
                ..
            } => losses.get("stokes").copied(),
            _ => None,
        })
        .collect();
    assert!(polar.len() >= 15, "{} PolarDR steps", polar.len());
    assert!(polar.iter().all(|l| l.is_finite() && *l > 0.0), "{polar:?}");
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(model.join("model.json")).unwrap()).unwrap();
    assert_eq!(info["mode"], serde_json::json!(Mode::Full), "{info}");
    assert!(model.join("surfels.ply").is_file());
    events
}

/// A small synthetic capture re-recorded as 12-bit IMX250MZR PNG frames in `raw_dir`.
fn raw_frames(dir: &Path) -> (Capture, f32) {
    let reference_dir = dir.join("reference");
    synth(
        &reference_dir,
        &SynthOptions {
            views: 9,
            size: 32,
            ..SynthOptions::default()
        },
    )
    .unwrap();
    let reference = capture::load(&reference_dir).unwrap();
    let full_scale = reference
        .views
        .iter()
        .filter_map(|v| match &v.measurement {
            Measurement::Stokes { s0, .. } => s0.data.iter().copied().reduce(f32::max),
            _ => None,
        })
        .fold(0.0, f32::max);
    let options = SimulateOptions {
        bit_depth: 12,
        full_scale,
        ..SimulateOptions::default()
    };
    write_raw_capture(&reference, &dir.join("raw_capture"), &options).unwrap();
    (reference, full_scale)
}

#[test]
fn a_folder_of_12_bit_mosaic_png_frames_loads_and_trains() {
    let dir = tempfile::tempdir().unwrap();
    let (reference, _) = raw_frames(dir.path());
    let folder = dir.path().join("raw_capture");
    let frame = std::fs::read_dir(folder.join("raw"))
        .unwrap()
        .next()
        .unwrap()
        .unwrap()
        .path();
    let decoded = image::open(&frame).unwrap();
    assert!(
        matches!(decoded, image::DynamicImage::ImageLuma16(_)),
        "16-bit grey PNG of 12-bit counts"
    );
    let capture = capture::load(&folder).unwrap();
    let summary = capture.summary();
    assert_eq!(summary.kinds, ["raw"]);
    assert_eq!(summary.views, reference.views.len());
    assert!(summary.dolp.unwrap().mean > 0.01);
    train_briefly(&capture, &dir.path().join("model"));
}

#[test]
fn a_colmap_model_with_mosaic_frames_and_sparse_points_loads_and_trains() {
    let dir = tempfile::tempdir().unwrap();
    let (reference, _) = raw_frames(dir.path());
    let folder = dir.path().join("colmap_capture");
    let mut model = ColmapModel::default();
    for (k, view) in reference.views.iter().enumerate() {
        let name = format!("view_{k:02}.png");
        let from = dir.path().join(format!("raw_capture/raw/{k:03}.png"));
        std::fs::create_dir_all(folder.join("raw")).unwrap();
        std::fs::create_dir_all(folder.join("masks")).unwrap();
        std::fs::copy(&from, folder.join("raw").join(&name)).unwrap();
        std::fs::copy(
            dir.path().join(format!("raw_capture/mask/{k:03}.png")),
            folder.join("masks").join(format!("{name}.png")),
        )
        .unwrap();
        let c = &view.camera;
        let r = c.rotation_opencv();
        let c2w = glam::DMat4::from_cols(
            r.x_axis.extend(0.0),
            r.y_axis.extend(0.0),
            r.z_axis.extend(0.0),
            c.origin().extend(1.0),
        );
        let (qvec, tvec) = pose_from_camera_to_world(&c2w);
        model.images.insert(
            k as i32 + 1,
            ColmapImage {
                id: k as i32 + 1,
                qvec,
                tvec,
                camera_id: 1,
                name,
                points2d: Vec::new(),
            },
        );
        model.cameras.insert(
            1,
            ColmapCamera {
                id: 1,
                model: "SIMPLE_PINHOLE".into(),
                width: c.width as u64,
                height: c.height as u64,
                params: vec![c.fx, c.cx, c.cy],
            },
        );
    }
    // Points on the unit sphere the capture shows, and a few far-away outliers.
    model.points = (0..300u64)
        .map(|k| {
            let z = 1.0 - 2.0 * (k as f64 + 0.5) / 300.0;
            let phi = k as f64 * 2.399_963_229_728_653;
            let s = (1.0 - z * z).sqrt();
            let xyz = if k % 50 == 0 {
                [5.0, 5.0, k as f64]
            } else {
                [s * phi.cos(), s * phi.sin(), z]
            };
            ColmapPoint {
                id: k,
                xyz,
                rgb: [200, 80, 40],
                error: 0.5,
                track: vec![(1, 0), (2, 0)],
            }
        })
        .collect();
    write_model(&model, &folder.join("sparse/0"), ModelFormat::Binary).unwrap();
    std::fs::write(
        folder.join("capture.json"),
        r#"{"world_up": [0, 0, 1], "white_balance": [1, 1, 1],
            "raw": {"sensor": "IMX250MZR", "bit_depth": 12}}"#,
    )
    .unwrap();
    let capture = capture::load(&folder).unwrap();
    assert_eq!(capture.summary().kinds, ["raw"]);
    assert_eq!(capture.points.len(), 300);
    // The surfels start on the sphere's points (all but the 6 outliers), then inside the hull.
    let surfels = phygap::pipeline::train::sparse::init_for_capture(&capture, 1000, 0);
    let on_sphere = surfels.position[..294]
        .iter()
        .filter(|p| (glam::DVec3::from_array(**p).length() - 1.0).abs() < 1e-9)
        .count();
    assert_eq!(on_sphere, 294);
    train_briefly(&capture, &dir.path().join("model"));
}

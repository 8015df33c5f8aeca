//! COLMAP captures: models written in both formats read back identically, captures converted to
//! COLMAP (the project's own and the shared ones) load the original cameras to 1e-9, `OPENCV`
//! views are undistorted, raw mosaic frames and sparse points come through, and malformed models
//! give errors that say what is wrong where.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::DMat4;

use super::model::{read_model, write_model};
use super::*;
use crate::core::camera::Camera;
use crate::formats::image_io::{read_image, write_exr, write_png, Image};
use crate::io::capture::mosaic::Sensor;
use crate::io::capture::simulate::{write_raw_capture, SimulateOptions};
use crate::io::capture::{load, load_cameras, Measurement, View};
use crate::pipeline::synth::{synth, SynthOptions};

/// The OpenCV camera-to-world matrix of a camera (kept in OpenGL axes by [`Camera`]).
fn c2w_opencv(camera: &Camera) -> DMat4 {
    let r = camera.rotation_opencv();
    DMat4::from_cols(
        r.x_axis.extend(0.0),
        r.y_axis.extend(0.0),
        r.z_axis.extend(0.0),
        camera.origin().extend(1.0),
    )
}

/// A COLMAP model of named cameras: one PINHOLE camera per image, no 2D points.
fn model_of(cameras: &[(String, Camera)]) -> ColmapModel {
    let mut model = ColmapModel::default();
    for (k, (name, camera)) in cameras.iter().enumerate() {
        let id = k as i32 + 1;
        model.cameras.insert(
            id,
            ColmapCamera {
                id,
                model: "PINHOLE".into(),
                width: camera.width as u64,
                height: camera.height as u64,
                params: vec![camera.fx, camera.fy, camera.cx, camera.cy],
            },
        );
        let (qvec, tvec) = pose_from_camera_to_world(&c2w_opencv(camera));
        model.images.insert(
            id,
            ColmapImage {
                id,
                qvec,
                tvec,
                camera_id: id,
                name: name.clone(),
                points2d: Vec::new(),
            },
        );
    }
    model
}

/// Largest difference between two cameras' intrinsics and camera-to-world entries.
fn camera_difference(a: &Camera, b: &Camera) -> f64 {
    assert_eq!((a.width, a.height), (b.width, b.height));
    let intrinsics = [a.fx - b.fx, a.fy - b.fy, a.cx - b.cx, a.cy - b.cy];
    (a.c2w - b.c2w)
        .to_cols_array()
        .iter()
        .chain(&intrinsics)
        .fold(0.0f64, |m, v| m.max(v.abs()))
}

fn copy(from: &Path, to: &Path) {
    std::fs::create_dir_all(to.parent().unwrap()).unwrap();
    std::fs::copy(from, to).unwrap();
}

fn a_model() -> ColmapModel {
    let mut model = ColmapModel::default();
    model.cameras.insert(
        1,
        ColmapCamera {
            id: 1,
            model: "PINHOLE".into(),
            width: 640,
            height: 480,
            params: vec![500.25, 501.5, 320.1, 239.9],
        },
    );
    model.cameras.insert(
        7,
        ColmapCamera {
            id: 7,
            model: "OPENCV".into(),
            width: 2448,
            height: 2048,
            params: vec![2000.0, 2001.0, 1224.5, 1023.5, -0.1, 0.01, 1e-4, -2e-4],
        },
    );
    for id in [3, 5] {
        model.images.insert(
            id,
            ColmapImage {
                id,
                qvec: [0.9, 0.1 * id as f64, -0.2, 0.3].map(|v| v / 1.0),
                tvec: [0.5, -1.25, 3.0 + id as f64 / 3.0],
                camera_id: if id == 3 { 1 } else { 7 },
                name: format!("img_{id}.png"),
                points2d: if id == 3 {
                    vec![(10.5, 20.25, 0), (11.0, 1.0 / 3.0, -1)]
                } else {
                    Vec::new()
                },
            },
        );
    }
    model.points = vec![
        ColmapPoint {
            id: 0,
            xyz: [0.1, -0.2, 0.3],
            rgb: [255, 128, 0],
            error: 0.5,
            track: vec![(3, 0)],
        },
        ColmapPoint {
            id: 9,
            xyz: [1e-7, 2.0 / 3.0, -5.0],
            rgb: [1, 2, 3],
            error: 1.25,
            track: vec![(3, 1), (5, 0)],
        },
    ];
    model
}

#[test]
fn text_and_binary_models_read_back_what_was_written() {
    let model = a_model();
    for format in [ModelFormat::Binary, ModelFormat::Text] {
        let dir = tempfile::tempdir().unwrap();
        write_model(&model, dir.path(), format).unwrap();
        assert_eq!(read_model(dir.path(), format).unwrap(), model, "{format:?}");
    }
}

/// COLMAP image names of a synthetic capture's views and its cameras.
fn named_cameras(capture: &Capture) -> Vec<(String, Camera)> {
    capture
        .views
        .iter()
        .map(|v| (format!("{:03}.png", v.frame_index), v.camera))
        .collect()
}

/// A COLMAP capture folder of a synthetic capture: its Stokes EXRs and masks, a model in `format`.
fn colmap_folder(synth_dir: &Path, capture: &Capture, format: ModelFormat) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for view in &capture.views {
        let stem = format!("{:03}", view.frame_index);
        for s in ["s0", "s1", "s2"] {
            copy(
                &synth_dir.join(format!("{s}/{stem}.exr")),
                &dir.path().join(format!("{s}/{stem}.exr")),
            );
        }
        copy(
            &synth_dir.join(format!("mask/{stem}.png")),
            &dir.path().join(format!("masks/{stem}.png.png")),
        );
    }
    write_model(
        &model_of(&named_cameras(capture)),
        &dir.path().join("sparse/0"),
        format,
    )
    .unwrap();
    dir
}

fn synth_capture(views: usize, size: u32) -> (tempfile::TempDir, Capture) {
    let dir = tempfile::tempdir().unwrap();
    let options = SynthOptions {
        views,
        size,
        ..SynthOptions::default()
    };
    synth(dir.path(), &options).unwrap();
    let capture = load(dir.path()).unwrap();
    (dir, capture)
}

#[test]
fn a_capture_converted_to_colmap_loads_the_same_cameras_and_views_in_both_formats() {
    let (synth_dir, reference) = synth_capture(10, 32);
    let mut loaded = Vec::new();
    for format in [ModelFormat::Binary, ModelFormat::Text] {
        let dir = colmap_folder(synth_dir.path(), &reference, format);
        let capture = load(dir.path()).unwrap();
        let report = capture.colmap.clone().unwrap();
        assert_eq!(
            (report.format, report.cameras, report.undistorted_views),
            (format, 10, 0)
        );
        assert!(capture.warnings.is_empty(), "{:?}", capture.warnings);
        let mut worst = 0.0f64;
        for (ours, theirs) in capture.views.iter().zip(&reference.views) {
            worst = worst.max(camera_difference(&ours.camera, &theirs.camera));
            assert_eq!(ours.measurement, theirs.measurement);
            assert_eq!(ours.mask, theirs.mask);
            assert_eq!(
                ours.split, theirs.split,
                "index % 8 == 0 is held out in both"
            );
        }
        eprintln!("synth → COLMAP {format:?}: largest camera difference {worst:.1e}");
        assert!(worst < 1e-9, "{worst}");
        // `load_cameras` reads a COLMAP folder too.
        let cameras = load_cameras(dir.path()).unwrap();
        assert_eq!(cameras.len(), 10);
        assert!(camera_difference(&cameras[3].1, &reference.views[3].camera) < 1e-9);
        loaded.push(capture);
    }
    for (a, b) in loaded[0].views.iter().zip(&loaded[1].views) {
        assert_eq!(
            a.camera, b.camera,
            "binary and text models give identical cameras"
        );
    }
}

#[test]
fn a_shared_capture_converted_to_colmap_loads_its_cameras() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    let scene = data.join("sphere");
    let reference = load_cameras(&scene).unwrap();
    // COLMAP names "train/000.png", …: the frame label holds `s0_path` = "train/s0/000.exr".
    let named: Vec<(String, Camera)> = reference
        .iter()
        .map(|(label, camera)| {
            let path = label
                .split_once('(')
                .and_then(|(_, p)| p.strip_suffix(')'))
                .unwrap();
            let (split, file) = path.split_once("/s0/").unwrap();
            (format!("{split}/{}", file.replace(".exr", ".png")), *camera)
        })
        .collect();
    let dir = tempfile::tempdir().unwrap();
    for (kind, folder) in [("s0", "s0"), ("s1", "s1"), ("s2", "s2"), ("masks", "mask")] {
        for split in ["train", "test"] {
            let link = dir.path().join(kind).join(split);
            std::fs::create_dir_all(link.parent().unwrap()).unwrap();
            #[cfg(unix)]
            std::os::unix::fs::symlink(scene.join(split).join(folder), &link).unwrap();
            #[cfg(not(unix))]
            {
                let _ = link;
                eprintln!("skipping: no symlinks here");
                return;
            }
        }
    }
    let expected: HashMap<String, Camera> = named.iter().cloned().collect();
    for format in [ModelFormat::Binary, ModelFormat::Text] {
        let sparse = dir.path().join("sparse");
        let _ = std::fs::remove_dir_all(&sparse);
        write_model(&model_of(&named), &sparse.join("0"), format).unwrap();
        let capture = load(dir.path()).unwrap();
        assert_eq!(capture.views.len(), 56);
        let mut worst = 0.0f64;
        for view in &capture.views {
            // "frame 3 (s0/train/003.exr)" → "train/003.png".
            let path = view
                .name
                .split_once("(s0/")
                .unwrap()
                .1
                .trim_end_matches(')');
            let name = path.replace(".exr", ".png");
            worst = worst.max(camera_difference(&view.camera, &expected[&name]));
        }
        eprintln!("sphere → COLMAP {format:?}: largest camera difference {worst:.1e}");
        assert!(worst < 1e-9, "{worst}");
    }
}

/// Bilinear sample at continuous pixel coordinates (clamped), as a test-side reference.
fn bilinear(image: &Image, u: f64, v: f64, c: usize) -> f32 {
    let x = (u - 0.5).clamp(0.0, image.width as f64 - 1.0);
    let y = (v - 0.5).clamp(0.0, image.height as f64 - 1.0);
    let (x0, y0) = (x.floor() as usize, y.floor() as usize);
    let (x1, y1) = (
        (x0 + 1).min(image.width - 1),
        (y0 + 1).min(image.height - 1),
    );
    let (tx, ty) = ((x - x0 as f64) as f32, (y - y0 as f64) as f32);
    let at = |a: usize, b: usize| image.pixel(a, b)[c];
    let top = at(x0, y0) * (1.0 - tx) + at(x1, y0) * tx;
    let bottom = at(x0, y1) * (1.0 - tx) + at(x1, y1) * tx;
    top * (1.0 - ty) + bottom * ty
}

const LENS: Distortion = Distortion {
    k1: -0.5,
    k2: 0.1,
    p1: 5e-4,
    p2: -3e-4,
};

/// Writes what a lens with `LENS` records of `view` (at each pixel, the pinhole image where its
/// undistorted ray lands): its Stokes images at `stokes` (S0, S1, S2) and its mask at `mask`.
fn write_through_lens(view: &View, stokes: [PathBuf; 3], mask: PathBuf) {
    let camera = view.camera;
    let distorted = |image: &Image| {
        Image::from_fn(image.width, image.height, image.channels, |i, j, o| {
            let (xd, yd) = (
                (i as f64 + 0.5 - camera.cx) / camera.fx,
                (j as f64 + 0.5 - camera.cy) / camera.fy,
            );
            let (x, y) = LENS.undistort(xd, yd).unwrap();
            let (u, v) = (camera.fx * x + camera.cx, camera.fy * y + camera.cy);
            for (c, out) in o.iter_mut().enumerate() {
                *out = bilinear(image, u, v, c);
            }
        })
    };
    let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
        panic!("synth views are full Stokes");
    };
    for (path, image) in stokes.iter().zip([s0, s1, s2]) {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        write_exr(path, &distorted(image)).unwrap();
    }
    let binary = distorted(&view.mask)
        .data
        .iter()
        .map(|v| if *v > 0.5 { 1.0 } else { 0.0 })
        .collect();
    std::fs::create_dir_all(mask.parent().unwrap()).unwrap();
    let image = Image {
        data: binary,
        ..view.mask.clone()
    };
    write_png(&mask, &image, false).unwrap();
}

/// Checks that `capture`'s views, loaded from images written through `LENS`, are `reference`'s
/// pinhole views again: same cameras, S0 within interpolation error away from the silhouette
/// (and much closer than the distorted S0 at `distorted_s0(frame)`), masks nearly equal.
fn assert_undistorted(
    capture: &Capture,
    reference: &Capture,
    distorted_s0: impl Fn(usize) -> PathBuf,
) {
    let (mut error, mut before, mut total, mut mask_disagree, mut mask_pixels) =
        (0.0, 0.0, 0.0, 0, 0);
    for (ours, theirs) in capture.views.iter().zip(&reference.views) {
        assert!(camera_difference(&ours.camera, &theirs.camera) < 1e-9);
        let (Measurement::Stokes { s0: a, .. }, Measurement::Stokes { s0: b, .. }) =
            (&ours.measurement, &theirs.measurement)
        else {
            panic!("Stokes views");
        };
        let (raw, _) = read_image(&distorted_s0(ours.frame_index)).unwrap();
        for p in 0..a.num_pixels() {
            let (x, y) = (p % a.width, p / a.width);
            // Away from the silhouette, where both images are smooth.
            let interior = (x.saturating_sub(2)..(x + 3).min(a.width)).all(|xx| {
                (y.saturating_sub(2)..(y + 3).min(a.height))
                    .all(|yy| theirs.mask.pixel(xx, yy)[0] > 0.5)
            });
            if interior {
                for c in 0..3 {
                    let i = p * 3 + c;
                    error += (a.data[i] - b.data[i]).abs() as f64;
                    before += (raw.data[i] - b.data[i]).abs() as f64;
                    total += b.data[i].abs() as f64;
                }
            }
            mask_pixels += (theirs.mask.data[p] > 0.5) as usize;
            mask_disagree += ((ours.mask.data[p] > 0.5) != (theirs.mask.data[p] > 0.5)) as usize;
        }
    }
    let (error, before) = (error / total, before / total);
    let disagree = mask_disagree as f64 / mask_pixels as f64;
    eprintln!(
        "undistortion: S0 error {error:.4} of mean S0 (distorted: {before:.4}); masks disagree on {disagree:.4} of the object"
    );
    // The reference was interpolated once to make the lens's image and once more to undo it.
    assert!(error < 0.008 && before > 2.0 * error, "{error} {before}");
    assert!(disagree < 0.05, "{disagree}");
}

#[test]
fn opencv_views_are_undistorted_to_their_pinhole_images() {
    let (_synth_dir, reference) = synth_capture(6, 64);
    let dir = tempfile::tempdir().unwrap();
    let mut model = model_of(&named_cameras(&reference));
    for camera in model.cameras.values_mut() {
        camera.model = "OPENCV".into();
        camera.params.extend([LENS.k1, LENS.k2, LENS.p1, LENS.p2]);
    }
    for view in &reference.views {
        let stem = format!("{:03}", view.frame_index);
        let stokes = ["s0", "s1", "s2"].map(|s| dir.path().join(format!("{s}/{stem}.exr")));
        write_through_lens(view, stokes, dir.path().join(format!("masks/{stem}.png")));
    }
    write_model(&model, &dir.path().join("sparse/0"), ModelFormat::Text).unwrap();
    let capture = load(dir.path()).unwrap();
    assert_eq!(capture.colmap.as_ref().unwrap().undistorted_views, 6);
    assert_undistorted(&capture, &reference, |frame| {
        dir.path().join(format!("s0/{frame:03}.exr"))
    });
}

/// The same lens given as nerfstudio's top-level `k1`, `k2`, `p1`, `p2` in `transforms.json`.
#[test]
fn transforms_json_lens_terms_are_undistorted_like_opencv_cameras() {
    let (synth_dir, reference) = synth_capture(6, 64);
    let json_path = synth_dir.path().join("transforms.json");
    let mut document: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json_path).unwrap()).unwrap();
    let frame_path = |frame: usize, key: &str| {
        synth_dir
            .path()
            .join(document["frames"][frame][key].as_str().unwrap())
    };
    for view in &reference.views {
        let k = view.frame_index;
        let stokes = ["s0_path", "s1_path", "s2_path"].map(|key| frame_path(k, key));
        write_through_lens(view, stokes, frame_path(k, "mask_path"));
    }
    let distorted_s0: Vec<PathBuf> = (0..reference.views.len())
        .map(|k| frame_path(k, "s0_path"))
        .collect();
    for (key, value) in [
        ("k1", LENS.k1),
        ("k2", LENS.k2),
        ("p1", LENS.p1),
        ("p2", LENS.p2),
    ] {
        document[key] = serde_json::json!(value);
    }
    std::fs::write(&json_path, document.to_string()).unwrap();
    let capture = load(synth_dir.path()).unwrap();
    assert_undistorted(&capture, &reference, |frame| distorted_s0[frame].clone());
}

#[test]
fn raw_mosaic_frames_and_sparse_points_come_through_a_colmap_capture() {
    let (_synth_dir, reference) = synth_capture(6, 32);
    // Raw frames named after the COLMAP images, settings in capture.json.
    let raw_dir = tempfile::tempdir().unwrap();
    write_raw_capture(
        &reference,
        raw_dir.path(),
        &SimulateOptions {
            sensor: Sensor::Imx250Myr,
            ..SimulateOptions::default()
        },
    )
    .unwrap();
    let dir = tempfile::tempdir().unwrap();
    for view in &reference.views {
        let stem = format!("{:03}", view.frame_index);
        copy(
            &raw_dir.path().join(format!("raw/{stem}.png")),
            &dir.path().join(format!("raw/{stem}.png")),
        );
        copy(
            &raw_dir.path().join(format!("mask/{stem}.png")),
            &dir.path().join(format!("masks/{stem}.png")),
        );
    }
    std::fs::write(
        dir.path().join("capture.json"),
        r#"{"demosaic": "half", "white_balance": [1, 1, 1],
            "raw": {"sensor": "IMX250MYR", "bit_depth": 12}}"#,
    )
    .unwrap();
    let mut model = model_of(&named_cameras(&reference));
    model.points = (0..50)
        .map(|k| ColmapPoint {
            id: k,
            xyz: [0.01 * k as f64, 0.0, 0.5],
            rgb: [200, 100, 50],
            error: 0.3,
            track: vec![(1, 0), (2, 0)],
        })
        .collect();
    write_model(&model, &dir.path().join("sparse/0"), ModelFormat::Binary).unwrap();
    let capture = load(dir.path()).unwrap();
    let summary = capture.summary();
    assert_eq!(summary.kinds, ["raw"]);
    assert_eq!((summary.width, summary.height), (16, 16));
    assert_eq!(summary.sparse_points, 50);
    assert_eq!(capture.points[7].position, glam::DVec3::new(0.07, 0.0, 0.5));
    assert_eq!(capture.points[7].colour, [200, 100, 50]);
    let (ours, theirs) = (&capture.views[2].camera, &reference.views[2].camera);
    assert!((ours.fx - theirs.fx / 2.0).abs() < 1e-12 && ours.width == 16);
    assert!((ours.c2w - theirs.c2w)
        .abs()
        .to_cols_array()
        .iter()
        .all(|v| *v < 1e-9));
}

/// A folder with a written model and one image per COLMAP image, for error tests.
fn broken_folder(model: &ColmapModel, format: ModelFormat) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    write_model(model, &dir.path().join("sparse/0"), format).unwrap();
    std::fs::create_dir_all(dir.path().join("images")).unwrap();
    for image in model.images.values() {
        let path = dir.path().join("images").join(&image.name);
        write_png(&path, &Image::filled(4, 4, 3, 0.5), false).unwrap();
    }
    dir
}

fn load_error(dir: &Path) -> String {
    match load(dir) {
        Ok(_) => panic!("the capture should be rejected"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn malformed_models_are_clear_errors() {
    let model = a_model();
    let dir = broken_folder(&model, ModelFormat::Binary);
    let cameras = dir.path().join("sparse/0/cameras.bin");
    let bytes = std::fs::read(&cameras).unwrap();

    // Truncated: the last parameter of the second camera is cut short.
    std::fs::write(&cameras, &bytes[..bytes.len() - 5]).unwrap();
    let e = load_error(dir.path());
    assert!(
        e.contains("cameras.bin is truncated: camera 7's parameter 7 of 8 (OPENCV)"),
        "{e}"
    );
    // A count larger than the file can hold.
    let mut huge = bytes.clone();
    huge[..8].copy_from_slice(&u64::MAX.to_le_bytes());
    std::fs::write(&cameras, &huge).unwrap();
    let e = load_error(dir.path());
    assert!(e.contains("is truncated") && e.contains("cameras"), "{e}");
    // Unknown model id (the first camera's model id is at bytes 12..16).
    let mut unknown = bytes.clone();
    unknown[12..16].copy_from_slice(&42i32.to_le_bytes());
    std::fs::write(&cameras, &unknown).unwrap();
    let e = load_error(dir.path());
    assert!(
        e.contains("camera 1 has the unknown camera model id 42"),
        "{e}"
    );
    // Trailing bytes.
    let mut long = bytes.clone();
    long.extend([0u8; 3]);
    std::fs::write(&cameras, &long).unwrap();
    let e = load_error(dir.path());
    assert!(
        e.contains("3 unexpected bytes after the last record"),
        "{e}"
    );
    // Truncated images.bin: inside the second image's NUL-terminated name (the first image takes
    // 64 bytes of pose and ids, "img_3.png" and its NUL, a count and two 24-byte points).
    std::fs::write(&cameras, &bytes).unwrap();
    let images = dir.path().join("sparse/0/images.bin");
    let image_bytes = std::fs::read(&images).unwrap();
    let second_name = 8 + (64 + 10 + 8 + 48) + 64;
    std::fs::write(&images, &image_bytes[..second_name + 3]).unwrap();
    let e = load_error(dir.path());
    assert!(
        e.contains("images.bin is truncated: image 5's name (no terminating NUL byte)"),
        "{e}"
    );

    // Text: an unknown model name, a bad number, a wrong parameter count.
    let dir = broken_folder(&model, ModelFormat::Text);
    let cameras = dir.path().join("sparse/0/cameras.txt");
    let text = std::fs::read_to_string(&cameras).unwrap();
    std::fs::write(&cameras, text.replace("PINHOLE", "FISHEYE_X")).unwrap();
    assert!(load_error(dir.path()).contains("camera 1 has the unknown camera model FISHEYE_X"));
    std::fs::write(&cameras, text.replace("500.25", "5OO.25")).unwrap();
    let e = load_error(dir.path());
    assert!(
        e.contains("cameras.txt, line 4: parameter \"5OO.25\" is not a valid number"),
        "{e}"
    );
    std::fs::write(&cameras, text.replace(" 239.9", "")).unwrap();
    let e = load_error(dir.path());
    assert!(
        e.contains("line 4: PINHOLE has 4 parameters, found 3"),
        "{e}"
    );

    // Models phygap does not read, a camera id that does not exist, a missing measurement: all
    // listed together.
    let mut unsupported = model.clone();
    let camera = unsupported.cameras.get_mut(&7).unwrap();
    camera.model = "SIMPLE_RADIAL".into();
    camera.params.truncate(4);
    unsupported.images.get_mut(&3).unwrap().camera_id = 99;
    unsupported.images.insert(
        4,
        ColmapImage {
            name: "nowhere.png".into(),
            id: 4,
            camera_id: 1,
            ..unsupported.images[&3].clone()
        },
    );
    let dir = broken_folder(&unsupported, ModelFormat::Binary);
    std::fs::remove_file(dir.path().join("images/nowhere.png")).unwrap();
    std::fs::write(
        dir.path().join("capture.json"),
        r#"{"w": 12, "demosaic": "half"}"#,
    )
    .unwrap();
    let err = load(dir.path()).unwrap_err();
    let problems: Vec<(String, String)> = err
        .problems()
        .iter()
        .map(|p| (p.frame.clone(), p.key.clone()))
        .collect();
    eprintln!("{err}");
    assert!(err.to_string().contains(
        "camera 7, key `model`: camera model SIMPLE_RADIAL is not supported (PINHOLE, SIMPLE_PINHOLE and OPENCV are)"
    ));
    assert!(err
        .to_string()
        .contains("camera 99 is not in the model's cameras"));
    assert!(err
        .to_string()
        .contains("no measurement for this image: looked for s0/nowhere.exr"));
    for expected in [
        ("capture.json", "w"),
        ("camera 7", "model"),
        ("image 3 (img_3.png)", "camera_id"),
        ("image 4 (nowhere.png)", "name"),
    ] {
        assert!(
            problems.contains(&(expected.0.to_owned(), expected.1.to_owned())),
            "{expected:?} not in {problems:?}"
        );
    }
}

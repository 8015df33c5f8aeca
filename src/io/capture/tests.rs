//! Loading and validation tests on small captures written to temporary folders.

use glam::{DMat4, DVec3};
use serde_json::{json, Value};

use super::*;
use crate::formats::image_io::{write_exr, write_png, Image};

const W: usize = 8;
const H: usize = 6;

/// A camera on a ring around the origin, as JSON rows of its OpenGL camera-to-world matrix.
fn ring_camera(i: usize) -> (Camera, Value) {
    let angle = i as f64 * 0.7;
    let eye = DVec3::new(3.0 * angle.cos(), 3.0 * angle.sin(), 0.5);
    let cam = Camera::look_at(W as u32, H as u32, 0.8, eye, DVec3::ZERO, DVec3::Z);
    (cam, matrix_rows(&cam.c2w))
}

fn matrix_rows(m: &DMat4) -> Value {
    let rows: Vec<Vec<f64>> = (0..4).map(|r| m.row(r).to_array().to_vec()).collect();
    json!(rows)
}

/// Distinct, recognizable pixel values: 1000·frame + 100·image + pixel + channel / 10.
fn pattern(frame: usize, image: usize, channels: usize) -> Image {
    Image::from_fn(W, H, channels, |x, y, o| {
        for (c, v) in o.iter_mut().enumerate() {
            *v = (1000 * frame + 100 * image + y * W + x) as f32 + c as f32 / 10.0;
        }
    })
}

/// Object in the left half of the image.
fn mask_image() -> Image {
    Image::from_fn(W, H, 1, |x, _, o| o[0] = if x < W / 2 { 1.0 } else { 0.0 })
}

struct Fixture {
    dir: tempfile::TempDir,
}

impl Fixture {
    /// `frames` full-Stokes frames with masks; returns the fixture and its JSON.
    fn stokes(frames: usize) -> (Fixture, Value) {
        let fixture = Fixture {
            dir: tempfile::tempdir().unwrap(),
        };
        let mut list = Vec::new();
        for i in 0..frames {
            let mut frame = json!({ "transform_matrix": ring_camera(i).1 });
            for (k, name) in ["s0", "s1", "s2"].iter().enumerate() {
                let rel = format!("{name}/{i:03}.exr");
                fixture.exr(&rel, &pattern(i, k, 3));
                frame[format!("{name}_path")] = json!(rel);
            }
            let mask = format!("mask/{i:03}.png");
            fixture.png(&mask, &mask_image());
            frame["mask_path"] = json!(mask);
            frame["depth_path"] = json!(format!("depth/{i:03}.exr"));
            list.push(frame);
        }
        let doc = json!({ "w": W, "h": H, "fl_x": 10.0, "fl_y": 11.0, "frames": list });
        (fixture, doc)
    }

    fn path(&self, rel: &str) -> std::path::PathBuf {
        let p = self.dir.path().join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        p
    }

    fn exr(&self, rel: &str, image: &Image) {
        write_exr(&self.path(rel), image).unwrap();
    }

    fn png(&self, rel: &str, image: &Image) {
        write_png(&self.path(rel), image, false).unwrap();
    }

    fn load(&self, doc: &Value) -> Result<Capture, CaptureError> {
        self.load_text(&serde_json::to_string_pretty(doc).unwrap())
    }

    fn load_text(&self, text: &str) -> Result<Capture, CaptureError> {
        std::fs::write(self.dir.path().join("transforms.json"), text).unwrap();
        load(self.dir.path())
    }

    /// Loads, expects failure, and returns the message.
    fn error(&self, doc: &Value) -> String {
        match self.load(doc) {
            Ok(_) => panic!("the capture should be rejected"),
            Err(e) => e.to_string(),
        }
    }
}

/// Asserts that `message` names all of `parts`.
fn assert_names(message: &str, parts: &[&str]) {
    for part in parts {
        assert!(
            message.contains(part),
            "error should mention {part:?}: {message}"
        );
    }
}

#[test]
fn stokes_capture_loads_with_default_split_masks_and_cameras() {
    let (fx, doc) = Fixture::stokes(10);
    let capture = fx.load(&doc).unwrap();
    assert_eq!(capture.views.len(), 10);
    let test: Vec<usize> = capture.test_views().map(|v| v.frame_index).collect();
    assert_eq!(test, vec![0, 8], "index % 8 == 0 is held out");
    assert_eq!(capture.train_views().count(), 8);
    assert_eq!(capture.world_up, DVec3::Z);
    assert!(capture.warnings.is_empty(), "{:?}", capture.warnings);
    let view = &capture.views[3];
    assert_eq!(view.name, "frame 3 (s0/003.exr)");
    let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
        panic!("expected Stokes");
    };
    assert_eq!(s0, &pattern(3, 0, 3));
    assert_eq!(s1, &pattern(3, 1, 3));
    assert_eq!(s2, &pattern(3, 2, 3));
    assert_eq!(view.mask, mask_image());
    let (cam, _) = ring_camera(3);
    assert!(view.camera.c2w.abs_diff_eq(cam.c2w, 1e-12));
    assert_eq!((view.camera.fx, view.camera.fy), (10.0, 11.0));
    assert_eq!(
        (view.camera.cx, view.camera.cy),
        (W as f64 / 2.0, H as f64 / 2.0)
    );
    let depth = view.ground_truth.depth.as_ref().unwrap();
    assert!(depth.is_absolute() && depth.ends_with("depth/003.exr"));
    assert!(view
        .ground_truth
        .s1
        .as_ref()
        .unwrap()
        .ends_with("s1/003.exr"));
    assert!(view.ground_truth.normal.is_none());
    let summary = capture.summary();
    assert_eq!(summary.kinds, vec!["stokes"]);
    assert_eq!((summary.width, summary.height), (W as u32, H as u32));
    assert_eq!((summary.train_views, summary.test_views), (8, 2));
}

#[test]
fn explicit_split_keys_win_over_the_default() {
    let (fx, mut doc) = Fixture::stokes(3);
    doc["frames"][0]["split"] = json!("train");
    doc["frames"][2]["split"] = json!("test");
    let capture = fx.load(&doc).unwrap();
    let splits: Vec<Split> = capture.views.iter().map(|v| v.split).collect();
    // Frame 1 has no key: with explicit splits elsewhere it trains.
    assert_eq!(splits, vec![Split::Train, Split::Train, Split::Test]);
    doc["frames"][1]["split"] = json!("validation");
    assert_names(
        &fx.error(&doc),
        &["frame 1 (s0/001.exr)", "`split`", "unknown split"],
    );
}

#[test]
fn intrinsics_from_field_of_view_overrides_and_opencv_axes() {
    let (fx, mut doc) = Fixture::stokes(3);
    let doc_obj = doc.as_object_mut().unwrap();
    doc_obj.remove("fl_x");
    doc_obj.remove("fl_y");
    doc_obj.insert("camera_angle_x".into(), json!(0.8));
    doc_obj.insert("cx".into(), json!(3.5));
    doc_obj.insert("camera_convention".into(), json!("OpenCV"));
    // OpenCV matrices of the same cameras.
    for i in 0..3 {
        let (cam, _) = ring_camera(i);
        let flip = DMat4::from_diagonal(glam::DVec4::new(1.0, -1.0, -1.0, 1.0));
        doc["frames"][i]["transform_matrix"] = matrix_rows(&(cam.c2w * flip));
    }
    doc["frames"][1]["fl_y"] = json!(20.0);
    let capture = fx.load(&doc).unwrap();
    let expected_f = 0.5 * W as f64 / (0.4f64).tan();
    let c0 = &capture.views[0].camera;
    assert!((c0.fx - expected_f).abs() < 1e-12 && (c0.fy - expected_f).abs() < 1e-12);
    assert_eq!((c0.cx, c0.cy), (3.5, H as f64 / 2.0));
    assert_eq!(capture.views[1].camera.fy, 20.0);
    for i in 0..3 {
        assert!(capture.views[i]
            .camera
            .c2w
            .abs_diff_eq(ring_camera(i).0.c2w, 1e-12));
    }
}

#[test]
fn polarizer_images_give_stokes_and_stokes_files_take_precedence() {
    let (fx, mut doc) = Fixture::stokes(3);
    let intensities: Vec<Image> = (0..4).map(|k| pattern(7, k, 3)).collect();
    for (k, key) in frame::POLARIZER_KEYS.iter().enumerate() {
        let rel = format!("pol/{k}.exr");
        fx.exr(&rel, &intensities[k]);
        for i in 0..3 {
            doc["frames"][i][*key] = json!(rel);
        }
    }
    // Frame 2 keeps its Stokes files as well: those are used.
    for i in 0..2 {
        let frame = doc["frames"][i].as_object_mut().unwrap();
        for key in frame::STOKES_KEYS {
            frame.remove(key);
        }
    }
    let check = |capture: &Capture, swapped: bool| {
        let Measurement::Stokes { s0, s1, s2 } = &capture.views[0].measurement else {
            panic!("expected Stokes");
        };
        let [i0, i45, i90, i135] = [0, 1, 2, 3].map(|k| &intensities[k].data);
        for p in 0..W * H * 3 {
            assert_eq!(s0.data[p], i0[p] + i90[p]);
            assert_eq!(s1.data[p], i0[p] - i90[p]);
            let s2_up = if swapped {
                i135[p] - i45[p]
            } else {
                i45[p] - i135[p]
            };
            assert_eq!(s2.data[p], s2_up);
        }
        let Measurement::Stokes { s0, .. } = &capture.views[2].measurement else {
            panic!("expected Stokes");
        };
        assert_eq!(s0, &pattern(2, 0, 3));
        assert_eq!(capture.summary().kinds, vec!["stokes", "polarizer4"]);
    };
    check(&fx.load(&doc).unwrap(), false);
    doc["stokes_convention"] = json!("image_y_down");
    check(&fx.load(&doc).unwrap(), true);
}

#[test]
fn image_y_down_negates_s2_and_mirrors_polarizer_angles() {
    let (fx, mut doc) = Fixture::stokes(3);
    doc["stokes_convention"] = json!("image_y_down");
    fx.exr("lp.exr", &pattern(9, 0, 3));
    let frame = json!({
        "transform_matrix": ring_camera(5).1, "file_path": "lp.exr", "polarizer_deg": 30.0,
        "mask_path": "mask/000.png"
    });
    doc["frames"].as_array_mut().unwrap().push(frame);
    let capture = fx.load(&doc).unwrap();
    let Measurement::Stokes { s2, .. } = &capture.views[1].measurement else {
        panic!("expected Stokes");
    };
    let expected: Vec<f32> = pattern(1, 2, 3).data.iter().map(|v| -v).collect();
    assert_eq!(s2.data, expected);
    let Measurement::Polarizer { angle, image } = &capture.views[3].measurement else {
        panic!("expected a polarizer view");
    };
    assert_eq!(angle, &PolarizerAngle::Known { degrees: 150.0 });
    assert_eq!(image, &pattern(9, 0, 3));
}

#[test]
fn partial_and_rgb_views_with_srgb_alpha_masks_and_missing_masks() {
    let fx = Fixture {
        dir: tempfile::tempdir().unwrap(),
    };
    // RGBA PNG: colour is sRGB-encoded, alpha is coverage.
    let rgba = Image::from_fn(W, H, 4, |x, y, o| {
        o[..3].fill(0.5);
        o[3] = if (x + y) % 2 == 0 { 1.0 } else { 0.0 };
    });
    fx.png("a.png", &rgba);
    fx.png(
        "b.png",
        &pattern(0, 0, 3).channel(0).to_rgb().map_for_test(),
    );
    let frames: Vec<Value> = (0..5)
        .map(|i| {
            let mut f = json!({ "transform_matrix": ring_camera(i).1, "split": "train" });
            match i {
                0 => f["file_path"] = json!("a.png"),
                4 => {
                    f["file_path"] = json!("a.png");
                    f["split"] = json!("test");
                }
                1 => {
                    f["file_path"] = json!("a.png");
                    f["polarizer_group"] = json!("cam1");
                }
                2 => {
                    f["file_path"] = json!("a.png");
                    f["polarizer_group"] = json!("cam0");
                }
                _ => {
                    f["file_path"] = json!("b.png");
                    f["polarizer_deg"] = json!(200.0);
                }
            }
            f
        })
        .collect();
    let mut doc = json!({ "w": W, "h": H, "fl_x": 9.0, "frames": frames, "world_up": [0, 1, 0] });
    let capture = fx.load(&doc).unwrap();
    assert_eq!(capture.world_up, DVec3::Y);
    let Measurement::Rgb { image } = &capture.views[0].measurement else {
        panic!("expected RGB");
    };
    assert_eq!(image.channels, 3);
    let linear = crate::formats::image_io::srgb_to_linear(128.0 / 255.0);
    assert!(
        image.data.iter().all(|v| (v - linear).abs() < 1e-6),
        "sRGB → linear"
    );
    assert_eq!(capture.views[0].mask, rgba.channel(3));
    assert_eq!(
        capture.views[3].measurement,
        Measurement::Polarizer {
            image: capture_image(&capture, 3),
            angle: PolarizerAngle::Known { degrees: 20.0 }
        }
    );
    assert_eq!(capture.views[3].mask, Image::filled(W, H, 1, 1.0));
    assert_eq!(capture.warnings.len(), 1);
    assert_names(
        &capture.warnings[0],
        &["1 view(s)", "no mask_path", "frames 3"],
    );
    let summary = capture.summary();
    assert_eq!(summary.kinds, vec!["partial", "rgb"]);
    assert_eq!(summary.polarizer_groups, vec!["cam0", "cam1"]);
    // "linear" colour space leaves PNG values as stored.
    doc["color_space"] = json!("linear");
    let capture = fx.load(&doc).unwrap();
    let Measurement::Rgb { image } = &capture.views[0].measurement else {
        panic!("expected RGB");
    };
    assert!(image.data.iter().all(|v| (v - 128.0 / 255.0).abs() < 1e-6));
}

fn capture_image(capture: &Capture, view: usize) -> Image {
    match &capture.views[view].measurement {
        Measurement::Polarizer { image, .. } | Measurement::Rgb { image } => image.clone(),
        Measurement::Stokes { s0, .. } => s0.clone(),
    }
}

trait MapForTest {
    fn map_for_test(self) -> Image;
}

impl MapForTest for Image {
    /// Scales pattern values into [0, 1] for an 8-bit file.
    fn map_for_test(mut self) -> Image {
        self.data.iter_mut().for_each(|v| *v /= 64.0);
        self
    }
}

// ---- validation: every rule of CAPTURE_FORMAT.md §3 -------------------------------------------

#[test]
fn missing_file_is_named() {
    let (fx, doc) = Fixture::stokes(3);
    std::fs::remove_file(fx.dir.path().join("s1/002.exr")).unwrap();
    assert_names(
        &fx.error(&doc),
        &[
            "frame 2 (s0/002.exr)",
            "`s1_path`",
            "missing file s1/002.exr",
        ],
    );
}

#[test]
fn size_mismatch_with_w_h_is_named() {
    let (fx, doc) = Fixture::stokes(3);
    fx.exr("s2/001.exr", &Image::filled(W + 1, H, 3, 0.0));
    assert_names(
        &fx.error(&doc),
        &[
            "frame 1 (s0/001.exr)",
            "`s2_path`",
            "9×6 pixels but w×h is 8×6",
        ],
    );
}

#[test]
fn mask_size_mismatch_is_named() {
    let (fx, doc) = Fixture::stokes(3);
    fx.png("mask/000.png", &Image::filled(W, H + 2, 1, 1.0));
    assert_names(
        &fx.error(&doc),
        &["frame 0 (s0/000.exr)", "`mask_path`", "8×8 pixels"],
    );
}

#[test]
fn non_finite_transform_is_named() {
    let (fx, doc) = Fixture::stokes(3);
    let text = serde_json::to_string_pretty(&doc).unwrap();
    // Python's json.dump writes NaN bare; replace frame 1's first matrix entry.
    let first = text.find("\"transform_matrix\"").unwrap();
    let second = first + 1 + text[first + 1..].find("\"transform_matrix\"").unwrap();
    let entry = second
        + text[second..]
            .find(|c: char| c == '-' || c.is_ascii_digit())
            .unwrap();
    let end = entry + text[entry..].find(',').unwrap();
    let text = format!("{}NaN{}", &text[..entry], &text[end..]);
    let message = fx.load_text(&text).unwrap_err().to_string();
    assert_names(
        &message,
        &[
            "frame 1 (s0/001.exr)",
            "`transform_matrix`",
            "row 0, column 0",
            "non-finite value NaN",
        ],
    );
}

#[test]
fn non_rigid_transform_is_named() {
    let (fx, mut doc) = Fixture::stokes(3);
    let scaled = ring_camera(2).0.c2w * DMat4::from_scale(DVec3::splat(1.5));
    doc["frames"][2]["transform_matrix"] = matrix_rows(&scaled);
    assert_names(
        &fx.error(&doc),
        &["frame 2 (s0/002.exr)", "`transform_matrix`", "not a rigid"],
    );
    doc["frames"][2]["transform_matrix"] = json!([[1, 0, 0], [0, 1, 0]]);
    assert_names(
        &fx.error(&doc),
        &["frame 2", "`transform_matrix`", "4 rows of 4 numbers"],
    );
}

#[test]
fn wrong_channel_counts_are_named() {
    let (fx, doc) = Fixture::stokes(3);
    fx.exr("s0/001.exr", &Image::filled(W, H, 1, 0.5));
    assert_names(
        &fx.error(&doc),
        &[
            "frame 1 (s0/001.exr)",
            "`s0_path`",
            "1 channel(s); expected an RGB image",
        ],
    );
    // A 3-channel mask is read when its channels are equal (white = object), refused otherwise.
    let (fx, doc) = Fixture::stokes(3);
    fx.png("mask/002.png", &Image::filled(W, H, 3, 1.0));
    let capture = fx.load(&doc).unwrap();
    assert!(capture.views[2].mask.data.iter().all(|&v| v == 1.0));
    let coloured = Image::from_fn(W, H, 3, |x, _, o| {
        o.copy_from_slice(&[1.0, 0.0, (x % 2) as f32])
    });
    fx.png("mask/002.png", &coloured);
    assert_names(
        &fx.error(&doc),
        &[
            "frame 2 (s0/002.exr)",
            "`mask_path`",
            "3 colour channels that are not equal",
        ],
    );
}

#[test]
fn paths_escaping_the_folder_are_named() {
    let (fx, mut doc) = Fixture::stokes(3);
    doc["frames"][1]["s1_path"] = json!("../outside.exr");
    doc["frames"][2]["mask_path"] = json!("/etc/passwd");
    let message = fx.error(&doc);
    assert_names(
        &message,
        &[
            "frame 1 (s0/001.exr), key `s1_path`",
            "escapes the capture folder (contains `..`)",
        ],
    );
    assert_names(
        &message,
        &["frame 2 (s0/002.exr), key `mask_path`", "(absolute path)"],
    );
    assert_names(&message, &["2 problems"]);
}

#[test]
fn mixed_sizes_are_named() {
    let (fx, mut doc) = Fixture::stokes(3);
    let small = Image::filled(4, 3, 3, 0.25);
    for name in ["s0", "s1", "s2"] {
        fx.exr(&format!("{name}/002.exr"), &small);
    }
    fx.png("mask/002.png", &Image::filled(4, 3, 1, 1.0));
    doc["frames"][2]["w"] = json!(4);
    doc["frames"][2]["h"] = json!(3);
    assert_names(
        &fx.error(&doc),
        &[
            "frame 2 (s0/002.exr)",
            "`w`",
            "mixed sizes",
            "4×3",
            "frame 0 (s0/000.exr) is 8×6",
        ],
    );
}

#[test]
fn non_finite_pixels_are_named_but_negative_s0_is_accepted() {
    let (fx, doc) = Fixture::stokes(3);
    let mut s0 = pattern(1, 0, 3);
    s0.data.iter_mut().for_each(|v| *v = -1e-4);
    fx.exr("s0/001.exr", &s0);
    assert!(fx.load(&doc).is_ok(), "slightly negative S0 is normal");
    let mut s2 = pattern(1, 2, 3);
    s2.data[(2 * W + 5) * 3 + 1] = f32::INFINITY;
    fx.exr("s2/001.exr", &s2);
    assert_names(
        &fx.error(&doc),
        &[
            "frame 1 (s0/001.exr)",
            "`s2_path`",
            "non-finite pixel value (inf) at x = 5, y = 2, channel 1",
        ],
    );
    s2.data[0] = f32::NAN;
    fx.exr("s2/001.exr", &s2);
    assert_names(&fx.error(&doc), &["`s2_path`", "(NaN) at x = 0, y = 0"]);
}

#[test]
fn incomplete_stokes_and_polarizer_sets_are_named() {
    let (fx, mut doc) = Fixture::stokes(3);
    doc["frames"][1].as_object_mut().unwrap().remove("s2_path");
    assert_names(
        &fx.error(&doc),
        &[
            "frame 1 (s0/001.exr)",
            "`s2_path`",
            "incomplete set: the frame has s0_path, s1_path but not s2_path",
        ],
    );
    let (fx, mut doc) = Fixture::stokes(3);
    fx.exr("p.exr", &pattern(0, 0, 3));
    let frame = doc["frames"][0].as_object_mut().unwrap();
    for key in frame::STOKES_KEYS {
        frame.remove(key);
    }
    frame.insert("pol000_path".into(), json!("p.exr"));
    frame.insert("pol090_path".into(), json!("p.exr"));
    assert_names(
        &fx.error(&doc),
        &[
            "frame 0 (p.exr)",
            "`pol045_path`",
            "not pol045_path, pol135_path",
        ],
    );
}

#[test]
fn unknown_convention_names_are_named() {
    let (fx, mut doc) = Fixture::stokes(3);
    doc["camera_convention"] = json!("Vulkan");
    doc["stokes_convention"] = json!("clockwise");
    doc["color_space"] = json!("adobe");
    doc["world_up"] = json!([1, 0, 0]);
    let message = fx.error(&doc);
    assert_names(
        &message,
        &[
            "top level, key `camera_convention`",
            "unknown convention \"Vulkan\"",
        ],
    );
    assert_names(
        &message,
        &["top level, key `stokes_convention`", "\"clockwise\""],
    );
    assert_names(&message, &["top level, key `color_space`", "\"adobe\""]);
    assert_names(
        &message,
        &["top level, key `world_up`", "[0, 0, 1] or [0, 1, 0]"],
    );
}

#[test]
fn fewer_than_two_training_views_is_rejected() {
    let (fx, mut doc) = Fixture::stokes(2);
    doc["frames"][0]["split"] = json!("train");
    doc["frames"][1]["split"] = json!("test");
    assert_names(
        &fx.error(&doc),
        &[
            "top level",
            "`split`",
            "only 1 training view(s) among 2 frames; at least 2",
        ],
    );
}

#[test]
fn missing_required_keys_are_named() {
    let (fx, mut doc) = Fixture::stokes(3);
    doc.as_object_mut().unwrap().remove("w");
    doc["frames"][1]
        .as_object_mut()
        .unwrap()
        .remove("transform_matrix");
    let message = fx.error(&doc);
    assert_names(
        &message,
        &["frame 0 (s0/000.exr), key `w`", "missing required key"],
    );
    assert_names(
        &message,
        &[
            "frame 1 (s0/001.exr), key `transform_matrix`",
            "missing required key",
        ],
    );

    let (fx, mut doc) = Fixture::stokes(3);
    doc.as_object_mut().unwrap().remove("fl_x");
    doc.as_object_mut().unwrap().remove("fl_y");
    assert_names(&fx.error(&doc), &["frame 0", "`fl_x`", "camera_angle_x"]);

    let (fx, mut doc) = Fixture::stokes(3);
    doc.as_object_mut().unwrap().remove("frames");
    assert_names(
        &fx.error(&doc),
        &["top level, key `frames`", "missing required key"],
    );

    let (fx, mut doc) = Fixture::stokes(3);
    let frame = doc["frames"][2].as_object_mut().unwrap();
    for key in frame::STOKES_KEYS {
        frame.remove(key);
    }
    assert_names(&fx.error(&doc), &["frame 2, key `file_path`", "no image"]);
}

#[test]
fn malformed_json_reports_the_line() {
    let (fx, _) = Fixture::stokes(3);
    let err = fx
        .load_text("{\n  \"w\": 8,\n  \"h\": 6\n  \"frames\": []\n}")
        .unwrap_err();
    assert!(matches!(err, CaptureError::Json { line: 4, .. }), "{err:?}");
    assert_names(
        &err.to_string(),
        &["malformed JSON", "transforms.json", "line 4"],
    );
    let missing = load(&fx.dir.path().join("nothing.json")).unwrap_err();
    assert!(matches!(missing, CaptureError::Read { .. }));
}

#[test]
fn every_problem_is_collected_into_one_error() {
    let (fx, mut doc) = Fixture::stokes(4);
    std::fs::remove_file(fx.dir.path().join("s0/000.exr")).unwrap();
    doc["frames"][1]["polarizer_deg"] = json!("ten");
    doc["frames"][3]["transform_matrix"] = json!("identity");
    // frame 1 has Stokes files, so polarizer_deg is not read; frame 2 gets an escaping mask.
    doc["frames"][2]["mask_path"] = json!("../m.png");
    let err = fx.load(&doc).unwrap_err();
    let keys: Vec<(String, String)> = err
        .problems()
        .iter()
        .map(|p| (p.frame.clone(), p.key.clone()))
        .collect();
    assert_eq!(keys.len(), 3, "{err}");
    assert!(keys.contains(&("frame 0 (s0/000.exr)".into(), "s0_path".into())));
    assert!(keys.contains(&("frame 2 (s0/002.exr)".into(), "mask_path".into())));
    assert!(keys.contains(&("frame 3 (s0/003.exr)".into(), "transform_matrix".into())));
}

#[test]
fn a_json_file_inside_a_folder_is_loaded_relative_to_that_folder() {
    let (fx, doc) = Fixture::stokes(3);
    let sub = fx.dir.path().join("alt.json");
    std::fs::write(&sub, serde_json::to_string(&doc).unwrap()).unwrap();
    let capture = load(&sub).unwrap();
    assert_eq!(capture.views.len(), 3);
    assert_eq!(capture.root, fx.dir.path().canonicalize().unwrap());
}

#[test]
fn a_capture_without_test_views_loads_but_is_not_trainable() {
    let (fx, mut doc) = Fixture::stokes(3);
    assert!(fx.load(&doc).unwrap().check_trainable().is_ok());
    for i in 0..3 {
        doc["frames"][i]["split"] = json!("train");
    }
    let capture = fx.load(&doc).unwrap();
    assert_names(
        &capture.check_trainable().unwrap_err().to_string(),
        &[
            "top level",
            "`split`",
            "none of the 3 frames is a test view",
        ],
    );
}

#[test]
fn captures_over_their_limits_are_refused_before_any_image_is_read() {
    let too_large = |result: Result<Capture, CaptureError>| match result {
        Err(CaptureError::TooLarge { exceeded, .. }) => exceeded,
        Err(other) => panic!("expected TooLarge, got {other}"),
        Ok(_) => panic!("expected TooLarge, the capture loaded"),
    };
    // 8,000 frames naming the files of three.
    let (fx, mut doc) = Fixture::stokes(3);
    let frames = doc["frames"].as_array().unwrap().clone();
    doc["frames"] = json!((0..8000).map(|i| frames[i % 3].clone()).collect::<Vec<_>>());
    let exceeded = too_large(fx.load(&doc));
    assert_eq!(
        (exceeded.limit, exceeded.needed, exceeded.allowed),
        ("max_views", 8000, 2000)
    );
    // One size declared far beyond the 8×6 files: refused on the declaration, not on the files.
    let (fx, mut doc) = Fixture::stokes(3);
    doc["w"] = json!(60_000);
    doc["h"] = json!(60_000);
    doc["fl_x"] = json!(60_000.0);
    doc["fl_y"] = json!(60_000.0);
    let exceeded = too_large(fx.load(&doc));
    assert_eq!(exceeded.limit, "max_pixels_per_view");
    assert!(
        exceeded.message.contains("60000×60000"),
        "{}",
        exceeded.message
    );
    // The decoded bytes of all views together, under an operator's lower budget.
    let (fx, doc) = Fixture::stokes(3);
    std::fs::write(fx.dir.path().join("transforms.json"), doc.to_string()).unwrap();
    let view_bytes = CaptureLimits::decoded_bytes(1, W as u64, H as u64);
    let limits = CaptureLimits {
        max_decoded_bytes: 3 * view_bytes - 1,
        ..CaptureLimits::DEFAULT
    };
    let exceeded = too_large(load_within(fx.dir.path(), &limits));
    assert_eq!(
        (exceeded.limit, exceeded.needed),
        ("max_decoded_bytes", 3 * view_bytes)
    );
    assert!(load_within(
        fx.dir.path(),
        &CaptureLimits {
            max_decoded_bytes: 3 * view_bytes,
            ..limits
        }
    )
    .is_ok());
}

#[test]
fn an_image_file_larger_than_its_frame_is_refused_from_its_header() {
    use crate::testing::hostile::exr_declaring;
    let (fx, doc) = Fixture::stokes(3);
    std::fs::write(fx.path("s1/001.exr"), exr_declaring(100_000, 100_000)).unwrap();
    assert_names(
        &fx.error(&doc),
        &[
            "frame 1",
            "`s1_path`",
            "s1/001.exr is 100000×100000 pixels but w×h is 8×6",
        ],
    );
}

#[test]
fn implausible_intrinsics_and_poses_are_named() {
    let (fx, doc) = Fixture::stokes(3);
    let with = |key: &str, value: Value| {
        let mut doc = doc.clone();
        doc[key] = value;
        doc
    };
    assert_names(
        &fx.error(&with("fl_x", json!(1e308))),
        &["`fl_x`", "focal length 1e308", "field of view"],
    );
    assert_names(&fx.error(&with("fl_y", json!(0.01))), &["`fl_y`"]);
    assert_names(
        &fx.error(&with("cx", json!(-100.0))),
        &["`cx`", "outside the image"],
    );
    assert_names(
        &fx.error(&with("w", json!(100_000))),
        &["`w`", "at most 65536 pixels"],
    );
    let mut far = doc.clone();
    far["frames"][1]["transform_matrix"][0][3] = json!(1e300);
    assert_names(
        &fx.error(&far),
        &["frame 1", "`transform_matrix`", "farther than"],
    );
}

#[test]
fn captures_load_at_a_working_resolution() {
    use crate::core::resolution::Resolution;
    let (fx, doc) = Fixture::stokes(3);
    std::fs::write(fx.dir.path().join("transforms.json"), doc.to_string()).unwrap();
    let full = load(fx.dir.path()).unwrap();
    let at = |resolution, pixel_budget| {
        let options = LoadOptions {
            resolution,
            pixel_budget,
            ..LoadOptions::default()
        };
        load_with(fx.dir.path(), &options).unwrap()
    };
    let half = at(Resolution::Downscale(2), 0);
    assert_eq!((half.downscale, half.full_size), (2, (8, 6)));
    assert_eq!(half.working_resolution(), "4×3 (8×6 ÷ 2)");
    assert_eq!(full.working_resolution(), "8×6");
    for (small, big) in half.views.iter().zip(&full.views) {
        assert_eq!(small.camera, resample::downscale_camera(&big.camera, 2));
        let (Measurement::Stokes { s0, .. }, Measurement::Stokes { s0: big_s0, .. }) =
            (&small.measurement, &big.measurement)
        else {
            panic!("Stokes views");
        };
        assert_eq!((s0.width, s0.height), (4, 3));
        for c in 0..3 {
            let block: f32 = [(2, 2), (3, 2), (2, 3), (3, 3)]
                .iter()
                .map(|&(x, y)| big_s0.pixel(x, y)[c])
                .sum();
            assert!((s0.pixel(1, 1)[c] - block / 4.0).abs() < 1e-3);
        }
        // The object is the left half: the second of four columns is its edge.
        assert_eq!(small.mask.pixel(1, 0), &[1.0]);
        assert_eq!(small.mask.pixel(2, 0), &[0.0]);
    }
    // `auto` shrinks by the smallest factor within the pixel budget: 48 pixels a view, 12 → ÷2.
    assert_eq!(at(Resolution::Auto, 12).downscale, 2);
    assert_eq!(at(Resolution::Auto, 48).downscale, 1);
    assert_eq!(at(Resolution::LongestSide(3), 0).downscale, 3);
}

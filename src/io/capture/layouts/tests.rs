//! Tests of the dataset-layout readers: the IDR projection decomposition, LLFF's column order,
//! folder and file names, masks of every common layout, `.npy` limits and corrupt files, small
//! IDR/LLFF folders written here, and the real LLFF sample in ../shared.

use std::path::Path;

use glam::{DMat3, DMat4, DQuat, DVec3};
use serde_json::Value;

use super::folders::{angle_of_folder, number_of_file, stokes_component_of_folder, FileIndex};
use super::llff::LlffPose;
use super::*;
use crate::formats::image_io::{write_exr, write_png, Image};
use crate::io::capture::images::mask_from_file;
use crate::io::capture::npy::{npy_bytes, read_array_from, NpyArray, NpyError};
use crate::io::capture::Measurement;

fn assert_mat_close(a: &DMat4, b: &DMat4, tolerance: f64) {
    let (a, b) = (a.to_cols_array(), b.to_cols_array());
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < tolerance, "{a:?}\n{b:?}");
    }
}

fn assert_camera_close(a: &Camera, b: &Camera, tolerance: f64) {
    assert_eq!((a.width, a.height), (b.width, b.height));
    for (x, y) in [(a.fx, b.fx), (a.fy, b.fy), (a.cx, b.cx), (a.cy, b.cy)] {
        assert!((x - y).abs() < tolerance, "{a:?}\n{b:?}");
    }
    assert_mat_close(&a.c2w, &b.c2w, tolerance);
}

#[test]
fn a_known_projection_decomposes_into_its_k_r_and_centre_whatever_its_scale() {
    let k = DMat3::from_cols(
        DVec3::new(812.5, 0.0, 0.0),
        DVec3::new(0.0, 790.25, 0.0),
        DVec3::new(301.75, 255.5, 1.0),
    );
    let rotation = DMat3::from_quat(DQuat::from_axis_angle(
        DVec3::new(0.3, -0.8, 0.5).normalize(),
        2.1,
    ));
    let centre = DVec3::new(1.5, -2.25, 3.0);
    let t = -(rotation * centre);
    let (kr, kt) = (k * rotation, k * t);
    for scale in [1.0, 3.7, -0.02] {
        let p = DMat4::from_cols(
            (kr.x_axis * scale).extend(0.0),
            (kr.y_axis * scale).extend(0.0),
            (kr.z_axis * scale).extend(0.0),
            (kt * scale).extend(1.0),
        );
        let d = idr::decompose_projection(&p).unwrap();
        assert!(d.k.abs_diff_eq(k, 1e-9), "scale {scale}: {:?}", d.k);
        assert!(d.rotation.abs_diff_eq(rotation, 1e-12), "scale {scale}");
        assert!(d.centre.abs_diff_eq(centre, 1e-9), "scale {scale}");
        assert!((d.rotation.determinant() - 1.0).abs() < 1e-12);
    }
    // A singular block is no camera.
    assert!(idr::decompose_projection(&DMat4::ZERO).is_none());
}

#[test]
fn world_and_scale_matrices_give_back_the_camera_in_the_normalised_frame() {
    let camera = Camera::look_at(
        64,
        48,
        0.9,
        DVec3::new(2.0, -3.0, 1.2),
        DVec3::new(0.1, 0.0, -0.1),
        DVec3::Z,
    );
    let offset = DVec3::new(0.3, -0.2, 0.1);
    let world_mat = idr::world_mat_of(&camera, 2.5, offset);
    let back = idr::camera_from_matrices(&world_mat, &idr::scale_mat(2.5, offset), 64, 48).unwrap();
    assert_camera_close(&back, &camera, 1e-9);
    // In the world frame (no scale_mat) the camera centre is where scale_mat puts it.
    let world = idr::camera_from_matrices(&world_mat, &DMat4::IDENTITY, 64, 48).unwrap();
    assert!(world
        .origin()
        .abs_diff_eq(2.5 * camera.origin() + offset, 1e-9));
    // A skewed camera is refused with its skew.
    let mut skewed = world_mat;
    skewed.y_axis.x += 5.0;
    let error = idr::camera_from_matrices(&skewed, &DMat4::IDENTITY, 64, 48).unwrap_err();
    assert!(error.contains("skew"), "{error}");
}

#[test]
fn llff_columns_are_down_right_back() {
    // A camera at (0, −4, 0) looking at the origin with +Z up: image right = +X, image down = −Z,
    // backward = −Y.
    let row = [
        0.0, 1.0, 0.0, 0.0, 480.0, //
        0.0, 0.0, -1.0, -4.0, 640.0, //
        -1.0, 0.0, 0.0, 0.0, 500.0, //
        0.5, 7.5,
    ];
    let pose = LlffPose::from_row(&row);
    assert_eq!(pose.down, DVec3::new(0.0, 0.0, -1.0));
    assert_eq!(pose.right, DVec3::X);
    assert_eq!((pose.near, pose.far), (0.5, 7.5));
    let camera = pose.camera(640, 480).unwrap();
    assert!(camera.up().abs_diff_eq(DVec3::Z, 1e-15));
    assert!(camera.forward().abs_diff_eq(DVec3::Y, 1e-15));
    assert!(camera
        .origin()
        .abs_diff_eq(DVec3::new(0.0, -4.0, 0.0), 1e-15));
    assert_eq!((camera.fx, camera.cx, camera.cy), (500.0, 320.0, 240.0));
    // Half-size images halve the focal length; another aspect ratio is refused.
    assert_eq!(pose.camera(320, 240).unwrap().fx, 250.0);
    assert!(pose.camera(320, 320).unwrap_err().contains("aspect"));
    // The row of a camera reads back as the camera.
    assert_eq!(LlffPose::of_camera(&camera, 0.5, 7.5).to_row(), row);
}

#[test]
fn angle_folders_are_found_by_the_angle_in_their_names() {
    for (name, angle) in [
        ("I-00", 0),
        ("I-45", 45),
        ("I-90", 90),
        ("I-135", 135),
        ("i_135", 135),
        ("pol000", 0),
        ("pol045", 45),
        ("POL090", 90),
        ("45deg", 45),
        ("135_deg", 135),
        ("0", 0),
        ("90", 90),
        ("Angle_45", 45),
        ("images_90", 90),
    ] {
        assert_eq!(angle_of_folder(name), Some(angle), "{name}");
    }
    for name in [
        "s0", "images_4", "I-30", "mask", "images", "cam45a0", "rgb", "pol45x90",
    ] {
        assert_eq!(angle_of_folder(name), None, "{name}");
    }
    for (name, component) in [("s0", 0), ("S1", 1), ("images_s2", 2), ("stokes_s0", 0)] {
        assert_eq!(stokes_component_of_folder(name), Some(component), "{name}");
    }
    for name in ["pos0", "s3", "images", "I-00"] {
        assert_eq!(stokes_component_of_folder(name), None, "{name}");
    }
    assert!(folders::is_mask_folder("masks") && folders::is_mask_folder("Mask"));
    assert!(!folders::is_mask_folder("c_masks"));
}

#[test]
fn files_are_matched_to_views_by_the_number_in_their_names() {
    assert_eq!(number_of_file("000_pseudo.png"), Some(0));
    assert_eq!(number_of_file("img_012.exr"), Some(12));
    assert_eq!(number_of_file("IMG_2024_0003.jpg"), Some(3));
    assert_eq!(number_of_file("view.png"), None);
    let file = |name: &str| folders::NumberedFile {
        name: name.into(),
        number: number_of_file(name),
    };
    let masks = FileIndex::new(&[
        file("000_pseudo.png"),
        file("001_pseudo.png"),
        file("front.png"),
    ]);
    assert_eq!(masks.matching(&file("000.jpg")), Some("000_pseudo.png"));
    assert_eq!(masks.matching(&file("img_1.png")), Some("001_pseudo.png"));
    assert_eq!(masks.matching(&file("front.exr")), Some("front.png"));
    assert_eq!(masks.matching(&file("002.jpg")), None);
    let doubled = FileIndex::new(&[file("003.png"), file("003_b.png")]);
    assert_eq!(doubled.duplicates, vec!["003_b.png".to_owned()]);
    assert_eq!(doubled.matching(&file("3.jpg")), Some("003.png"));
}

fn image_of(width: usize, channels: usize, values: &[f32]) -> Image {
    Image {
        width,
        height: values.len() / width / channels,
        channels,
        data: values.to_vec(),
    }
}

#[test]
fn masks_of_three_equal_channels_or_with_alpha_are_read_and_coloured_ones_refused() {
    // Grey, RGB with equal channels: > 127 is object.
    let grey = mask_from_file(&image_of(3, 1, &[0.0, 1.0, 0.6]), "m.png").unwrap();
    assert_eq!(grey.data, vec![0.0, 1.0, 1.0]);
    let rgb = image_of(3, 3, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.3, 0.3, 0.3]);
    assert_eq!(
        mask_from_file(&rgb, "m.png").unwrap().data,
        vec![0.0, 1.0, 0.0]
    );
    // A cutout: one colour everywhere, the object in alpha (RGBA and grey + alpha).
    let cutout = image_of(2, 4, &[1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
    assert_eq!(
        mask_from_file(&cutout, "m.png").unwrap().data,
        vec![0.0, 1.0]
    );
    let grey_alpha = image_of(2, 2, &[0.0, 0.0, 0.0, 1.0]);
    assert_eq!(
        mask_from_file(&grey_alpha, "m.png").unwrap().data,
        vec![0.0, 1.0]
    );
    // A black/white mask with alpha: white where opaque.
    let opaque = image_of(
        3,
        4,
        &[1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0],
    );
    assert_eq!(
        mask_from_file(&opaque, "m.png").unwrap().data,
        vec![1.0, 0.0, 0.0]
    );
    // Colour channels that differ are not a mask.
    let red = image_of(2, 3, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    let error = mask_from_file(&red, "masks/001.png").unwrap_err();
    assert!(
        error.contains("masks/001.png has 3 colour channels that are not equal")
            && error.contains("x = 1, y = 0"),
        "{error}"
    );
    let error = mask_from_file(&image_of(1, 5, &[0.0; 5]), "m.png").unwrap_err();
    assert!(error.contains("5 channel(s)"), "{error}");
}

fn read_bytes(bytes: &[u8], limits: &NpyLimits) -> Result<NpyArray<f64>, NpyError> {
    read_array_from(bytes, bytes.len() as u64, "a.npy", limits)
}

#[test]
fn npy_files_are_read_in_c_order_and_their_declared_sizes_checked_before_allocation() {
    let limits = NpyLimits::CAMERAS;
    let values: Vec<f64> = (0..6).map(f64::from).collect();
    let array = read_bytes(&npy_bytes(&[2, 3], &values), &limits).unwrap();
    assert_eq!((array.shape, array.data), (vec![2, 3], values.clone()));
    // float16 and float32.
    let halves: Vec<npyz::half::f16> = [0.5f32, -2.0, 1024.0]
        .iter()
        .map(|&v| npyz::half::f16::from_f32(v))
        .collect();
    let array = read_bytes(&npy_bytes(&[3], &halves), &limits).unwrap();
    assert_eq!(array.data, vec![0.5, -2.0, 1024.0]);
    let singles = [0.25f32, 8.0];
    assert_eq!(
        read_bytes(&npy_bytes(&[2], &singles), &limits)
            .unwrap()
            .data,
        vec![0.25, 8.0]
    );
    // Fortran order comes back in C order.
    let mut fortran = npy_bytes(&[2, 3], &[0.0, 3.0, 1.0, 4.0, 2.0, 5.0]);
    let text = String::from_utf8_lossy(&fortran[10..60]).replace("False", "True ");
    fortran[10..60].copy_from_slice(text.as_bytes());
    assert_eq!(read_bytes(&fortran, &limits).unwrap().data, values);

    let message =
        |bytes: &[u8], limits: &NpyLimits| read_bytes(bytes, limits).unwrap_err().to_string();
    // A header declaring 4 GiB is refused before anything is allocated.
    let mut huge_header = b"\x93NUMPY\x02\x00".to_vec();
    huge_header.extend_from_slice(&u32::MAX.to_le_bytes());
    let error = message(&huge_header, &limits);
    assert!(
        error.contains("4294967295 bytes, over the limit"),
        "{error}"
    );
    // A shape of 10^12 elements is refused by the limit; one the file cannot hold is truncated.
    let mut declared = npy_bytes(&[2, 3], &values);
    let text = String::from_utf8_lossy(&declared[10..70]).replace("(2, 3)", "(1000000, 1000000)");
    let mut reshaped = declared[..10].to_vec();
    reshaped.extend_from_slice(text.as_bytes());
    reshaped.extend_from_slice(&declared[70..]);
    let error = message(&reshaped, &limits);
    assert!(
        error.contains("1000000000000 elements, over the limit"),
        "{error}"
    );
    declared.truncate(declared.len() - 8);
    let error = message(&declared, &limits);
    assert!(
        error.contains("truncated") && error.contains("needs 48 bytes"),
        "{error}"
    );
    // Not an .npy file; an unsupported dtype.
    assert!(message(b"PK\x03\x04 not numpy", &limits).contains("magic string"));
    assert!(message(b"\x93NU", &limits).contains("preamble"));
    let mut complex = npy_bytes(&[1], &[0.0f64]);
    let text = String::from_utf8_lossy(&complex[10..30]).replace("<f8", "<c8");
    complex[10..30].copy_from_slice(text.as_bytes());
    assert!(
        message(&complex, &limits).contains("dtype"),
        "{}",
        message(&complex, &limits)
    );
}

#[test]
fn npz_archives_are_read_by_member_and_their_member_count_limited() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cameras.npz");
    let arrays: Vec<(String, Vec<usize>, Vec<f64>)> = (0..3)
        .map(|k| (format!("world_mat_{k}"), vec![2, 2], vec![f64::from(k); 4]))
        .collect();
    npy::write_npz(&path, &arrays).unwrap();
    let read = npy::read_npz::<f64>(&path, &NpyLimits::CAMERAS, |n| n != "world_mat_1").unwrap();
    assert_eq!(
        read.keys().collect::<Vec<_>>(),
        ["world_mat_0", "world_mat_2"]
    );
    assert_eq!(read["world_mat_2"].data, vec![2.0; 4]);
    let few = NpyLimits {
        max_members: 2,
        ..NpyLimits::CAMERAS
    };
    let error = npy::read_npz::<f64>(&path, &few, |_| true).unwrap_err();
    assert!(
        error.to_string().contains("3 members, over the limit of 2"),
        "{error}"
    );
    std::fs::write(&path, b"not a zip").unwrap();
    let error = npy::read_npz::<f64>(&path, &NpyLimits::CAMERAS, |_| true).unwrap_err();
    assert!(error.to_string().contains("not a zip archive"), "{error}");
}

const W: usize = 12;
const H: usize = 10;

/// Cameras on a ring around the origin looking at it.
fn ring_cameras(n: usize) -> Vec<Camera> {
    (0..n)
        .map(|i| {
            let angle = i as f64 * 0.9;
            let eye = DVec3::new(3.0 * angle.cos(), 3.0 * angle.sin(), 0.8);
            Camera::look_at(W as u32, H as u32, 0.8, eye, DVec3::ZERO, DVec3::Z)
        })
        .collect()
}

/// Stokes of view `k`: S0 a ramp, S1 and S2 a fraction of it with signs (grey).
fn stokes_values(k: usize, x: usize, y: usize) -> [f32; 3] {
    let s0 = 0.2 + 0.01 * (x + W * y) as f32 + 0.1 * k as f32;
    [s0, 0.3 * s0, -0.2 * s0]
}

/// Writes an IDR-layout folder: cameras, Stokes as one stacked float16 `.npy` a view, RGB masks
/// with a suffix.
fn write_idr_stokes_folder(root: &Path, cameras: &[Camera]) {
    let offset = DVec3::new(-1.0, 0.5, 2.0);
    let mut arrays = Vec::new();
    for (k, camera) in cameras.iter().enumerate() {
        let world = idr::world_mat_of(camera, 3.0, offset);
        arrays.push((
            format!("world_mat_{k}"),
            vec![4, 4],
            idr::rows_of_mat4(&world),
        ));
        let scale = idr::scale_mat(3.0, offset);
        arrays.push((
            format!("scale_mat_{k}"),
            vec![4, 4],
            idr::rows_of_mat4(&scale),
        ));
    }
    npy::write_npz(&root.join("cameras_new.npz"), &arrays).unwrap();
    std::fs::create_dir_all(root.join("stokes")).unwrap();
    std::fs::create_dir_all(root.join("masks")).unwrap();
    for k in 0..cameras.len() {
        let values: Vec<npyz::half::f16> = (0..W * H)
            .flat_map(|p| stokes_values(k, p % W, p / W))
            .map(npyz::half::f16::from_f32)
            .collect();
        npy::write_npy(
            &root.join(format!("stokes/{k:03}.npy")),
            &[H, W, 3],
            &values,
        )
        .unwrap();
        let mask = Image::from_fn(W, H, 3, |x, _, o| o.fill(if x < W / 2 { 1.0 } else { 0.0 }));
        write_png(&root.join(format!("masks/{k:03}_pseudo.png")), &mask, false).unwrap();
    }
}

#[test]
fn an_idr_folder_with_stacked_stokes_npy_and_rgb_masks_loads_with_its_cameras() {
    let dir = tempfile::tempdir().unwrap();
    let cameras = ring_cameras(9);
    write_idr_stokes_folder(dir.path(), &cameras);
    let location = find_layout(dir.path()).unwrap();
    assert_eq!(location.kind, LayoutKind::Idr);
    let capture = crate::io::capture::load(dir.path()).unwrap();
    assert_eq!(capture.views.len(), 9);
    assert_eq!(
        capture.test_views().count(),
        2,
        "every 8th view is held out"
    );
    for (k, (view, camera)) in capture.views.iter().zip(&cameras).enumerate() {
        assert_camera_close(&view.camera, camera, 1e-9);
        let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
            panic!("{}: not Stokes", view.name);
        };
        for (x, y) in [(0, 0), (7, 3), (11, 9)] {
            let expected = stokes_values(k, x, y);
            for (image, value) in [s0, s1, s2].iter().zip(expected) {
                let read = image.pixel(x, y);
                let tolerance = value.abs() * 1e-3;
                assert!(
                    read.iter().all(|v| (v - value).abs() <= tolerance),
                    "{read:?} {value}"
                );
            }
        }
        assert_eq!(view.mask.pixel(2, 2)[0], 1.0);
        assert_eq!(view.mask.pixel(9, 2)[0], 0.0);
    }
    let imported = import(dir.path(), &location).unwrap();
    assert_eq!(imported.report.measurement, "stokes_stacked");
    assert_eq!(imported.report.masked_views, 9);
    assert!(
        imported.report.frame.contains("normalised"),
        "{}",
        imported.report.frame
    );
    assert_eq!(imported.report.world_up, [0.0, 0.0, 1.0]);
    // The cameras alone, as rendering reads them.
    let read = crate::io::capture::load_cameras(dir.path()).unwrap();
    assert_camera_close(&read[4].1, &cameras[4], 1e-9);
}

#[test]
fn an_llff_folder_of_per_angle_pngs_loads_and_missing_files_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let cameras = ring_cameras(4);
    let rows: Vec<f64> = cameras
        .iter()
        .flat_map(|c| LlffPose::of_camera(c, 1.0, 5.0).to_row())
        .collect();
    npy::write_npy(&root.join("poses_bounds.npy"), &[4, 17], &rows).unwrap();
    // 16-bit PNGs at the files' linear values, stated in capture.json.
    std::fs::write(root.join("capture.json"), r#"{"color_space": "linear"}"#).unwrap();
    let intensity = |angle: usize, x: usize| 0.1 + 0.05 * angle as f32 + 0.01 * x as f32;
    for (a, folder) in ["I-00", "I-45", "I-90", "I-135"].iter().enumerate() {
        std::fs::create_dir_all(root.join(folder)).unwrap();
        for k in 0..4 {
            let values: Vec<u16> = (0..W * H)
                .flat_map(|p| [(intensity(a, p % W) * 65535.0).round() as u16; 3])
                .collect();
            let image =
                image::ImageBuffer::<image::Rgb<u16>, _>::from_raw(W as u32, H as u32, values)
                    .unwrap();
            image
                .save(root.join(format!("{folder}/img_{:03}.png", k + 1)))
                .unwrap();
        }
    }
    let capture = crate::io::capture::load(root).unwrap();
    assert_eq!(capture.views.len(), 4);
    for (view, camera) in capture.views.iter().zip(&cameras) {
        assert_camera_close(&view.camera, camera, 1e-12);
        let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
            panic!("not Stokes")
        };
        // I0 + I90 = S0, I0 − I90 = S1, I45 − I135 = S2.
        let x = 5;
        let near = |a: f32, b: f32| (a - b).abs() < 1e-4;
        assert!(near(s0.pixel(x, 1)[0], intensity(0, x) + intensity(2, x)));
        assert!(near(s1.pixel(x, 1)[1], intensity(0, x) - intensity(2, x)));
        assert!(near(s2.pixel(x, 1)[2], intensity(1, x) - intensity(3, x)));
    }
    assert!(
        capture.warnings.iter().any(|w| w.contains("no mask_path")),
        "{:?}",
        capture.warnings
    );
    let location = find_layout(root).unwrap();
    let report = import(root, &location).unwrap().report;
    assert_eq!(report.measurement, "polarizer4");
    let roles: Vec<(&str, &str)> = report
        .folders
        .iter()
        .map(|f| (f.folder.as_str(), f.role.as_str()))
        .collect();
    assert!(roles.contains(&("I-135", "polarizer 135°")), "{roles:?}");
    assert!(report.color_space.starts_with("linear (from capture.json)"));
    // A view missing from one angle folder is named.
    std::fs::remove_file(root.join("I-90/img_003.png")).unwrap();
    let error = crate::io::capture::load(root).unwrap_err().to_string();
    assert!(error.contains("no file numbered 3 in I-90/"), "{error}");
    // Only three angle folders: which were found is said.
    std::fs::remove_dir_all(root.join("I-90")).unwrap();
    let error = crate::io::capture::load(root).unwrap_err().to_string();
    assert!(
        error.contains("only 3 of the four polarizer folders"),
        "{error}"
    );
}

#[test]
fn a_manifest_names_the_polarizer_folders_where_their_names_say_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let cameras = ring_cameras(3);
    let rows: Vec<f64> = cameras
        .iter()
        .flat_map(|c| LlffPose::of_camera(c, 1.0, 5.0).to_row())
        .collect();
    npy::write_npy(&root.join("poses_bounds.npy"), &[3, 17], &rows).unwrap();
    let folders = ["cam_a", "cam_b", "cam_c", "cam_d"];
    for (a, folder) in folders.iter().enumerate() {
        std::fs::create_dir_all(root.join(folder)).unwrap();
        for k in 0..3 {
            let image = Image::filled(W, H, 3, 0.1 * (a + 1) as f32);
            write_exr(&root.join(format!("{folder}/{k}.exr")), &image).unwrap();
        }
    }
    let error = crate::io::capture::load(root).unwrap_err().to_string();
    assert!(error.contains("no image folders found"), "{error}");
    std::fs::write(
        root.join("capture.json"),
        r#"{"polarizer_folders": {"0": "cam_a", "45": "cam_b", "90": "cam_c", "135": "cam_d"}}"#,
    )
    .unwrap();
    let capture = crate::io::capture::load(root).unwrap();
    let Measurement::Stokes { s0, s2, .. } = &capture.views[1].measurement else {
        panic!("not Stokes")
    };
    assert!((s0.data[0] - 0.4).abs() < 1e-6 && (s2.data[0] - (0.2 - 0.4)).abs() < 1e-6);
}

#[test]
fn the_real_llff_sample_reads_with_its_stokes_masks_and_cameras() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    let root = data.join("real/neisfpp-sample");
    let location = find_layout(&root).expect("poses_bounds.npy");
    assert_eq!(location.kind, LayoutKind::Llff);
    let imported = import(&root, &location).unwrap();
    let report = &imported.report;
    eprintln!("{report}");
    assert_eq!((report.views, report.width, report.height), (2, 612, 512));
    assert_eq!(report.measurement, "stokes");
    assert_eq!(
        (report.masks.as_deref(), report.masked_views),
        (Some("masks"), 2)
    );
    // Two views are too few to train on (one would be held out): read both as training views.
    let mut document = imported.document.clone();
    for frame in document["frames"].as_array_mut().unwrap() {
        frame["split"] = Value::from("train");
    }
    let capture = crate::io::capture::load_document(
        &location.cameras,
        imported.root.clone(),
        &document,
        Vec::new(),
        &LoadOptions::default(),
    )
    .unwrap();
    assert_eq!(capture.views.len(), 2);
    let camera = &capture.views[0].camera;
    assert!((camera.fx - 904.07391).abs() < 1e-3, "{}", camera.fx);
    assert_eq!((camera.cx, camera.cy), (306.0, 256.0));
    // Row 0 of poses_bounds.npy: down (0.16903, 0.80171, 0.57332), right (0.68429, −0.51410,
    // 0.51715), back (0.70935, 0.30490, −0.63550), centre (2.32094, 2.34010, −0.53581).
    let expected_c2w = DMat4::from_cols(
        DVec3::new(0.68429, -0.51410, 0.51715).extend(0.0),
        DVec3::new(-0.16903, -0.80171, -0.57332).extend(0.0),
        DVec3::new(0.70935, 0.30490, -0.63550).extend(0.0),
        DVec3::new(2.32094, 2.34010, -0.53581).extend(1.0),
    );
    assert_mat_close(&camera.c2w, &expected_c2w, 1e-5);
    // Both cameras look at one place: their optical axes pass within 0.16 of each other, 3.5 and
    // 4.1 in front of them (a camera looking backward, as a misread column order gives, fails).
    let (p0, d0) = (capture.views[0].camera.origin(), camera.forward());
    let (p1, d1) = (
        capture.views[1].camera.origin(),
        capture.views[1].camera.forward(),
    );
    let w = p0 - p1;
    let (b, d, e) = (d0.dot(d1), d0.dot(w), d1.dot(w));
    let denominator = 1.0 - b * b;
    let (s, t) = ((b * e - d) / denominator, (e - b * d) / denominator);
    let gap = ((p0 + s * d0) - (p1 + t * d1)).length();
    assert!(s > 3.0 && t > 3.0 && gap < 0.2, "s {s}, t {t}, gap {gap}");
    for view in &capture.views {
        let covered = view.mask.data.iter().sum::<f32>() / view.mask.data.len() as f32;
        assert!(
            covered > 0.02 && covered < 0.9,
            "{}: mask covers {covered}",
            view.name
        );
        let Measurement::Stokes { s0, .. } = &view.measurement else {
            panic!("not Stokes")
        };
        let mean = s0.data.iter().sum::<f32>() / s0.data.len() as f32;
        assert!(mean > 0.0 && mean.is_finite(), "{mean}");
    }
}

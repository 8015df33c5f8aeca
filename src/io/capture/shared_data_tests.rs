//! Tests on the shared ground-truth datasets (../shared/data): both scenes load, GT depth lands on
//! the GT surface through our cameras, the GT normals predict the measured AoLP in our per-pixel
//! Stokes frame, and Stokes from the four polarizer images match the Stokes files.

use std::path::Path;

use glam::DVec3;
use rayon::prelude::*;

use super::*;
use crate::core::mesh::TriangleMesh;
use crate::formats::image_io::read_image;

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(|a, b| a.total_cmp(b));
    values[values.len() / 2]
}

/// World points of the object pixels of a view, back-projected from its GT z-depth.
fn backprojected_depth(view: &View) -> Vec<DVec3> {
    let (depth, _) = read_image(view.ground_truth.depth.as_ref().expect("depth_path")).unwrap();
    assert_eq!(depth.channels, 1);
    let mut points = Vec::new();
    for y in 0..depth.height {
        for x in 0..depth.width {
            let z = depth.pixel(x, y)[0] as f64;
            if z > 0.0 && view.mask.pixel(x, y)[0] > 0.5 {
                points.push(view.camera.backproject(x as f64 + 0.5, y as f64 + 0.5, z));
            }
        }
    }
    points
}

#[test]
fn both_scenes_load_with_their_counts_and_bounds() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    for scene in ["sphere", "knot"] {
        let capture = load(&data.join(scene)).unwrap();
        let summary = capture.summary();
        assert_eq!(
            (summary.views, summary.train_views, summary.test_views),
            (56, 48, 8)
        );
        assert_eq!((summary.width, summary.height), (256, 256));
        assert_eq!(
            summary.kinds,
            vec!["stokes"],
            "{scene}: Stokes files win over pol*"
        );
        assert!(summary.warnings.is_empty(), "{:?}", summary.warnings);
        assert_eq!(capture.world_up, DVec3::Z);
        let b = summary.bounds;
        eprintln!("{scene}: bounds centre {} radius {:.4}", b.center, b.radius);
        assert!(b.center.length() < 0.1, "{scene}: {b:?}");
        assert!(b.radius > 0.98 && b.radius < 1.2, "{scene}: {b:?}");
        assert_eq!(capture.views[0].name, "frame 0 (train/s0/000.exr)");
        // Masks are binary and cover a plausible part of the image.
        let covered: f32 = capture.views[0].mask.data.iter().sum();
        assert!(covered > 1000.0 && covered < 30000.0);
    }
    let test_only = load(&data.join("sphere/transforms_test.json")).unwrap_err();
    assert!(
        test_only.to_string().contains("only 0 training view(s)"),
        "{test_only}"
    );
}

#[test]
fn gt_depth_backprojects_onto_the_unit_sphere() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    let capture = load(&data.join("sphere")).unwrap();
    for view in capture.views.iter().step_by(9) {
        let points = backprojected_depth(view);
        assert!(points.len() > 1000);
        let distances: Vec<f64> = points.iter().map(|p| (p.length() - 1.0).abs()).collect();
        let med = median(distances);
        eprintln!("sphere {}: median |‖X‖ − 1| = {med:.2e}", view.name);
        assert!(med < 1e-3, "{}: median distance {med}", view.name);
    }
}

/// Distance from `p` to the triangle (a, b, c) (Ericson, Real-Time Collision Detection §5.1.5).
fn point_triangle_distance(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return ap.length();
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return bp.length();
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return (p - (a + ab * (d1 / (d1 - d3)))).length();
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return cp.length();
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return (p - (a + ac * (d2 / (d2 - d6)))).length();
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return (p - (b + (c - b) * w)).length();
    }
    let denom = 1.0 / (va + vb + vc);
    (p - (a + ab * (vb * denom) + ac * (vc * denom))).length()
}

#[test]
fn point_triangle_distance_cases() {
    let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
    assert!((point_triangle_distance(DVec3::new(0.2, 0.2, 0.5), a, b, c) - 0.5).abs() < 1e-12);
    assert!(
        (point_triangle_distance(DVec3::new(-1.0, -1.0, 0.0), a, b, c) - 2f64.sqrt()).abs() < 1e-12
    );
    assert!((point_triangle_distance(DVec3::new(0.5, -2.0, 0.0), a, b, c) - 2.0).abs() < 1e-12);
    let on_hypotenuse = DVec3::new(1.0, 1.0, 0.0);
    assert!((point_triangle_distance(on_hypotenuse, a, b, c) - 0.5f64.sqrt()).abs() < 1e-12);
}

#[test]
fn gt_depth_backprojects_onto_the_knot_mesh() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    let capture = load(&data.join("knot")).unwrap();
    let mesh = TriangleMesh::read_ply(&data.join("knot/mesh.ply")).unwrap();
    let triangles: Vec<([DVec3; 3], DVec3, f64)> = (0..mesh.triangles.len())
        .map(|t| {
            let corners = mesh.triangle_corners(t);
            let centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
            let radius = corners
                .iter()
                .map(|c| (*c - centroid).length())
                .fold(0.0, f64::max);
            (corners, centroid, radius)
        })
        .collect();
    let distance_to_mesh = |p: DVec3| {
        // Nearest vertex bounds the distance; only triangles whose sphere is nearer are tested.
        let mut best = mesh
            .vertices
            .iter()
            .map(|v| (DVec3::from_array(*v) - p).length())
            .fold(f64::INFINITY, f64::min);
        for ([a, b, c], centroid, radius) in &triangles {
            if (*centroid - p).length() - radius < best {
                best = best.min(point_triangle_distance(p, *a, *b, *c));
            }
        }
        best
    };
    let first_test = capture.test_views().next().expect("a test view");
    for view in [&capture.views[1], first_test] {
        let points = backprojected_depth(view);
        let stride = (points.len() / 600).max(1);
        let distances: Vec<f64> = points
            .par_iter()
            .step_by(stride)
            .map(|p| distance_to_mesh(*p))
            .collect();
        let med = median(distances);
        eprintln!(
            "knot {} ({:?}): median point-to-mesh distance {med:.2e} over {} pixels",
            view.name,
            view.split,
            points.len() / stride
        );
        assert!(med < 1e-3, "{}: median distance {med}", view.name);
    }
}

/// Fractions of specular-dominant pixels whose AoLP ψ agrees with φ_n + 90° (mod 180°), in our
/// Stokes frame and in the frame with ŷ flipped.
fn specular_aolp_agreement(
    capture: &Capture,
    dolp_min: f64,
    tolerance_deg: f64,
) -> (f64, f64, usize) {
    let (mut agree, mut agree_flipped, mut total) = (0usize, 0usize, 0usize);
    let wrap = |angle_deg: f64| (angle_deg + 90.0).rem_euclid(180.0) - 90.0;
    for view in capture.train_views().step_by(4) {
        let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
            panic!("expected Stokes");
        };
        let (normals, _) = read_image(view.ground_truth.normal.as_ref().unwrap()).unwrap();
        for y in 0..s0.height {
            for x in 0..s0.width {
                let sum = |img: &Image| img.pixel(x, y).iter().map(|v| *v as f64).sum::<f64>();
                let (i, q, u) = (sum(s0), sum(s1), sum(s2));
                if view.mask.pixel(x, y)[0] < 0.5
                    || i <= 1e-3
                    || (q * q + u * u).sqrt() / i < dolp_min
                {
                    continue;
                }
                let n = normals.pixel(x, y);
                let n = DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
                let d = view.camera.pixel_dir(x as u32, y as u32);
                let (xh, yh) = view.camera.stokes_frame(d);
                let psi = 0.5 * u.atan2(q).to_degrees();
                let phi = n.dot(yh).atan2(n.dot(xh)).to_degrees();
                let phi_flipped = (-n.dot(yh)).atan2(n.dot(xh)).to_degrees();
                total += 1;
                agree += (wrap(psi - phi - 90.0).abs() < tolerance_deg) as usize;
                agree_flipped += (wrap(psi - phi_flipped - 90.0).abs() < tolerance_deg) as usize;
            }
        }
    }
    (
        agree as f64 / total as f64,
        agree_flipped as f64 / total as f64,
        total,
    )
}

#[test]
fn sphere_specular_aolp_is_perpendicular_to_the_gt_normal_azimuth() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    let capture = load(&data.join("sphere")).unwrap();
    let (fraction, flipped, total) = specular_aolp_agreement(&capture, 0.2, 10.0);
    eprintln!(
        "sphere: ψ ≈ φ_n + 90° within 10° for {:.1}% of {total} pixels with DoLP > 0.2; flipped frame {:.1}%",
        100.0 * fraction,
        100.0 * flipped
    );
    assert!(total > 2000, "{total} pixels");
    assert!(fraction > 0.9, "agreement {fraction}");
    assert!(
        flipped < 0.5 * fraction,
        "flipped-frame agreement {flipped}"
    );
}

#[test]
fn sphere_polarizer_images_give_the_stokes_files() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    let scene = data.join("sphere");
    let dir = tempfile::tempdir().unwrap();
    // The JSON lives in its own folder; the image folders are linked into it.
    for split in ["train", "test"] {
        if symlink(&scene.join(split), &dir.path().join(split)).is_err() {
            eprintln!("skipping: cannot create symlinks here");
            return;
        }
    }
    let text = std::fs::read_to_string(scene.join("transforms.json")).unwrap();
    let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let frames = doc["frames"].as_array_mut().unwrap();
    frames.truncate(4);
    for frame in frames.iter_mut() {
        let object = frame.as_object_mut().unwrap();
        object.retain(|k, _| !["s0_path", "s1_path", "s2_path"].contains(&k.as_str()));
    }
    std::fs::write(dir.path().join("transforms.json"), doc.to_string()).unwrap();
    let from_pol = load(dir.path()).unwrap();
    let reference = load(&scene).unwrap();
    assert_eq!(from_pol.summary().kinds, vec!["polarizer4"]);
    let mut worst: f64 = 0.0;
    for (a, b) in from_pol.views.iter().zip(&reference.views) {
        let (
            Measurement::Stokes { s0, s1, s2 },
            Measurement::Stokes {
                s0: r0,
                s1: r1,
                s2: r2,
            },
        ) = (&a.measurement, &b.measurement)
        else {
            panic!("expected Stokes");
        };
        for (ours, theirs) in [(s0, r0), (s1, r1), (s2, r2)] {
            for (p, (x, y)) in ours.data.iter().zip(&theirs.data).enumerate() {
                // Half-float rounding of the two polarizer images and of the Stokes value.
                let scale = r0.data[p].abs() as f64 + 1e-4;
                let error = (*x as f64 - *y as f64).abs() / scale;
                worst = worst.max(error);
            }
        }
    }
    eprintln!("sphere: worst |S(pol) − S(file)| / S0 = {worst:.2e}");
    assert!(
        worst < 3.0 * 2f64.powi(-11),
        "worst relative difference {worst}"
    );
}

#[cfg(unix)]
fn symlink(target: &Path, link: &Path) -> std::io::Result<()> {
    std::os::unix::fs::symlink(target, link)
}

#[cfg(not(unix))]
fn symlink(_target: &Path, _link: &Path) -> std::io::Result<()> {
    Err(std::io::Error::other("no symlinks"))
}

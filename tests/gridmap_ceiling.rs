//! GridMap against the Mitsuba ground truth of the shared captures: ground-truth geometry (the GT
//! mesh, GT depth for surface points), materials and environment fed straight into PolarDR, lit by
//! the global map alone and by GridMap over it (METHOD.md §4 "measured ceiling", §5). Mitsuba
//! renders visibility and inter-reflections, so on the self-occluding knot GridMap must bring S0
//! closer to the ground truth; the convex sphere shows its cost where nothing is occluded.

use std::path::{Path, PathBuf};

use glam::DVec3;
use phygap::brdf_lut::BrdfLut;
use phygap::capture::{self, Measurement, View};
use phygap::envmap::{CubeMap, LightProbe, MipChainSpec, PrefilterPlan, PreparedEnv, WorldUp};
use phygap::gridmap::GridMap;
use phygap::image_io::{read_image, Image};
use phygap::mesh::TriangleMesh;
use phygap::shading::{shade, PixelInput};
use phygap::surfels::{Surfel, Surfels};

fn data_root() -> Option<PathBuf> {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data"));
    if root.exists() {
        Some(root.to_owned())
    } else {
        println!("skipping: ../shared/data not found");
        None
    }
}

fn image(path: &Option<PathBuf>) -> Image {
    read_image(path.as_ref().expect("ground truth present"))
        .unwrap()
        .0
}

fn rgb(img: &Image, p: usize) -> DVec3 {
    let c = img.channels;
    if c >= 3 {
        DVec3::new(
            f64::from(img.data[p * c]),
            f64::from(img.data[p * c + 1]),
            f64::from(img.data[p * c + 2]),
        )
    } else {
        DVec3::splat(f64::from(img.data[p * c]))
    }
}

/// Surfels carrying the GT albedo at back-projected GT depth pixels of some training views (every
/// `stride`-th masked pixel): what GridMap's probes read the bounce colour from.
fn albedo_surfels(views: &[&View], stride: usize) -> Surfels {
    let mut surfels = Surfels::default();
    for view in views {
        let (depth, albedo) = (
            image(&view.ground_truth.depth),
            image(&view.ground_truth.albedo),
        );
        let width = view.camera.width as usize;
        for p in (0..view.camera.num_pixels()).step_by(stride) {
            let z = f64::from(depth.data[p * depth.channels]);
            if z <= 0.0 || view.mask.data[p] < 0.5 {
                continue;
            }
            let (u, v) = ((p % width) as f64 + 0.5, (p / width) as f64 + 0.5);
            surfels.push_activated(&Surfel {
                position: view.camera.backproject(u, v, z),
                scale: glam::DVec2::splat(0.01),
                rotation: glam::DMat3::IDENTITY,
                opacity: 0.9,
                albedo: rgb(&albedo, p).clamp(DVec3::splat(1e-4), DVec3::splat(0.9999)),
                roughness: 0.5,
                ior: 1.5,
            });
        }
    }
    surfels
}

/// S0 PSNR (linear, peak 1) inside the mask of a test view shaded with `light`.
fn s0_psnr(view: &View, light: &dyn LightProbe) -> f64 {
    let gt = |path: &Option<PathBuf>| image(path);
    let g = &view.ground_truth;
    let (normal, albedo, alpha, ior, depth) = (
        gt(&g.normal),
        gt(&g.albedo),
        gt(&g.roughness),
        gt(&g.ior),
        gt(&g.depth),
    );
    let s0 = match &view.measurement {
        Measurement::Stokes { s0, .. } => s0.clone(),
        _ => panic!("full-Stokes capture expected"),
    };
    let camera = &view.camera;
    let width = camera.width as usize;
    let (mut sq, mut count) = (0.0, 0usize);
    for p in 0..camera.num_pixels() {
        let z = f64::from(depth.data[p * depth.channels]);
        if view.mask.data[p] < 0.5 || z <= 0.0 {
            continue;
        }
        let (x, y) = ((p % width) as u32, (p / width) as u32);
        let d = camera.pixel_dir(x, y);
        let (stokes_x, stokes_y) = camera.stokes_frame(d);
        let input = PixelInput {
            position: camera.backproject(f64::from(x) + 0.5, f64::from(y) + 0.5, z),
            normal: rgb(&normal, p),
            view: -d,
            stokes_x,
            stokes_y,
            albedo: rgb(&albedo, p),
            roughness: rgb(&alpha, p).x.max(0.0).sqrt(),
            ior: rgb(&ior, p).x,
        };
        let shaded = shade(&input, light, BrdfLut::shared());
        sq += (shaded.s0 - rgb(&s0, p)).length_squared();
        count += 3;
    }
    -10.0 * (sq / count as f64).log10()
}

/// (global, GridMap) S0 PSNR over test views 0–2 of a shared capture.
fn compare(scene: &str) -> Option<(f64, f64)> {
    let root = data_root()?.join(scene);
    let capture = capture::load(&root).unwrap();
    let spec = MipChainSpec::default();
    let scene_json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("scene.json")).unwrap()).unwrap();
    let env_file = root.join(scene_json["env_map"]["train_test"].as_str().unwrap());
    let cube = CubeMap::load_latlong(&env_file, WorldUp::Z, spec.base_size).unwrap();
    let env = PreparedEnv::new(&cube, PrefilterPlan::new(spec).unwrap()).unwrap();
    let mesh = TriangleMesh::read_ply(&root.join("mesh.ply")).unwrap();
    let train: Vec<&View> = capture.train_views().step_by(4).collect();
    let surfels = albedo_surfels(&train, 7);
    let grid = GridMap::build(&mesh, &surfels, &cube, env.clone()).unwrap();
    let tests: Vec<&View> = capture.test_views().take(3).collect();
    let mean = |light: &dyn LightProbe| {
        tests.iter().map(|v| s0_psnr(v, light)).sum::<f64>() / tests.len() as f64
    };
    let (global, with_grid) = (mean(&env), mean(&grid));
    println!(
        "{scene}: S0 PSNR (linear, GT inputs, test views 0-2): global {global:.2} dB, GridMap {with_grid:.2} dB ({} anchors)",
        grid.anchors().len()
    );
    Some((global, with_grid))
}

#[test]
fn gridmap_brings_the_knot_closer_to_the_ground_truth() {
    let Some((global, with_grid)) = compare("knot") else {
        return;
    };
    assert!(
        with_grid > global + 0.5,
        "GridMap {with_grid:.2} dB vs global {global:.2} dB"
    );
}

#[test]
fn gridmap_costs_little_on_the_convex_sphere() {
    let Some((global, with_grid)) = compare("sphere") else {
        return;
    };
    assert!(
        with_grid > global - 1.5,
        "GridMap {with_grid:.2} dB vs global {global:.2} dB"
    );
}

//! `phygap export` end to end on a small model (a sphere of surfels under a coloured sky): the
//! folder gains `model.glb`, `envmap.hdr` and `envmap.png`; the GLB holds the mesh with the
//! surfels' materials (baked into textures by default, per vertex on request), the HDR the model's
//! lat-long map; and both forms of the GLB pass the Khronos glTF validator (npm package
//! `gltf-validator`, pinned in `tests/gltf-validator/`) with no error and no warning.
//!
//! The validator needs Node.js and `npm ci --prefix tests/gltf-validator` (`.ci/run` does it). Without
//! them the validator step prints a notice and the test ends after the Rust-side checks, except
//! under `CI=true`, where that fails.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use glam::DVec3;
use phygap::core::config::{BackendChoice, MeshMaterials, TrainConfig};
use phygap::core::envmap::{texel_dir, CubeMap, NUM_FACES};
use phygap::core::mesh::cameras_around;
use phygap::formats::image_io::read_image;
use phygap::io::model::{Model, ModelInfo};
use phygap::pipeline::export::ExportOptions;
use phygap::testing::{running_in_ci, sphere_surfels};
use serde_json::Value;

const SIZE: usize = 16;

/// A unit sphere of surfels (albedo (0.6, 0.4, 0.2), roughness 0.3, IoR 1.5) under a sky that is
/// brighter above, with 12 training cameras around it.
fn sphere_model() -> Model {
    let radiance: Vec<f64> = (0..NUM_FACES * SIZE * SIZE)
        .flat_map(|t| {
            let (face, rest) = (t / (SIZE * SIZE), t % (SIZE * SIZE));
            let d = texel_dir(SIZE, face, rest % SIZE, rest / SIZE);
            let v = 0.3 + 1.2 * d.z.max(0.0) + 0.6 * (d.x + 1.0);
            [v, 0.8 * v, 0.5 * v + 0.2]
        })
        .collect();
    let surfels = sphere_surfels(DVec3::ZERO, 1.0, 3000, DVec3::new(0.6, 0.4, 0.2));
    let train_cameras = cameras_around(12, 4.0, 48, 40f64.to_radians())
        .into_iter()
        .enumerate()
        .map(|(i, c)| (format!("{i:03}"), c))
        .collect();
    Model {
        info: ModelInfo {
            mode: phygap::core::config::Mode::Full,
            world_up: [0.0, 0.0, 1.0],
            polarizer_angles_deg: BTreeMap::new(),
            iterations: 100,
            train_seconds: 0.0,
            num_surfels: surfels.len(),
            backend: "cpu".into(),
            working_resolution: None,
            refined_poses: None,
            silhouette_offset_px: None,
            frame_registration: None,
        },
        config: TrainConfig {
            iterations: 100.into(),
            envmap_resolution: SIZE as u32,
            backend: BackendChoice::Cpu,
            gridmap: false,
            ..TrainConfig::default()
        },
        surfels,
        envmap: CubeMap::from_radiance(SIZE, &radiance).unwrap(),
        train_cameras,
    }
}

/// The validator script, or `None` (after a notice) where Node.js or the package is missing.
fn validator_script() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/gltf-validator");
    let node = Command::new("node")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    let package = dir
        .join("node_modules/gltf-validator/package.json")
        .is_file();
    if node && package {
        return Some(dir.join("validate.mjs"));
    }
    let message = if node {
        "the gltf-validator package is not installed (npm ci --prefix tests/gltf-validator)"
    } else {
        "Node.js is not installed"
    };
    assert!(!running_in_ci(), "CI=true but {message}");
    println!("skipping the glTF validator: {message}");
    None
}

/// The validator's report on `file`.
fn validate(script: &Path, file: &Path) -> Value {
    let output = Command::new("node")
        .arg(script)
        .arg(file)
        .output()
        .expect("node runs");
    assert!(
        output.status.success(),
        "the validator did not run: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("the validator prints its report as JSON")
}

#[test]
fn export_writes_a_glb_that_the_khronos_validator_accepts() {
    let dir = tempfile::tempdir().unwrap();
    let model_dir = dir.path().join("model");
    let model = sphere_model();
    model.save(&model_dir).unwrap();
    let out = dir.path().join("export");
    let started = std::time::Instant::now();
    let files = phygap::pipeline::export::export(&model_dir, &out).unwrap();
    println!("export: {:.1} s", started.elapsed().as_secs_f64());
    for name in [
        "model.glb",
        "mesh.ply",
        "envmap.exr",
        "envmap.hdr",
        "envmap.png",
    ] {
        assert!(files.contains(&out.join(name)), "{name} in {files:?}");
    }

    // The HDR and the PNG are the model's lat-long map (512 × 256).
    let (exr, _) = read_image(&out.join("envmap.exr")).unwrap();
    let (hdr, _) = read_image(&out.join("envmap.hdr")).unwrap();
    assert_eq!((hdr.width, hdr.height, hdr.channels), (512, 256, 3));
    let worst = exr
        .data
        .chunks_exact(3)
        .zip(hdr.data.chunks_exact(3))
        .map(|(a, b)| {
            let largest = a.iter().copied().fold(0.0, f32::max);
            (0..3)
                .map(|c| (a[c] - b[c]).abs() / largest)
                .fold(0.0, f32::max)
        })
        .fold(0.0, f32::max);
    assert!(worst < 0.01, "HDR vs EXR: {worst}");
    let (png, _) = read_image(&out.join("envmap.png")).unwrap();
    assert_eq!((png.width, png.height), (512, 256));

    // The GLB (textured, the default): its materials are the surfels' (uniform here), baked on
    // the extracted mesh's atlas.
    let mesh = phygap::core::mesh::TriangleMesh::read_ply(&out.join("mesh.ply")).unwrap();
    let (json, glb_bytes) = read_glb(&out.join("model.glb"));
    let attributes = &json["meshes"][0]["primitives"][0]["attributes"];
    for name in ["POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "_IOR"] {
        assert!(attributes.get(name).is_some(), "{name} in {attributes}");
    }
    let material = &json["materials"][0];
    for texture in [
        &material["pbrMetallicRoughness"]["baseColorTexture"],
        &material["pbrMetallicRoughness"]["metallicRoughnessTexture"],
        &material["normalTexture"],
    ] {
        assert!(texture["index"].is_u64(), "{material}");
    }
    // The base colour texture is the albedo (0.6, 0.4, 0.2) in sRGB wherever a chart lies.
    let base = image_of(&json, &glb_bytes, 0);
    let srgb = [0.6f32, 0.4, 0.2]
        .map(|c| (phygap::formats::image_io::linear_to_srgb(c) * 255.0).round() as i32);
    let matching = base
        .pixels()
        .filter(|p| (0..3).all(|c| (i32::from(p[c]) - srgb[c]).abs() <= 2))
        .count();
    assert!(
        matching > base.pixels().len() / 3,
        "{matching} of {} texels hold the albedo {srgb:?}",
        base.pixels().len()
    );
    check_geometry(&json, &mesh, true);
    println!(
        "model.glb (textures): {} bytes, {}² textures",
        glb_bytes.len(),
        base.width()
    );

    // The vertex form, on request.
    let vertex_out = dir.path().join("export-vertex");
    let options = ExportOptions {
        mesh_materials: Some(MeshMaterials::Vertex),
        ..ExportOptions::default()
    };
    let started = std::time::Instant::now();
    phygap::pipeline::export::export_with(&model_dir, &vertex_out, options).unwrap();
    println!("export (vertex): {:.1} s", started.elapsed().as_secs_f64());
    let (vertex_json, vertex_bytes) = read_glb(&vertex_out.join("model.glb"));
    let attributes = &vertex_json["meshes"][0]["primitives"][0]["attributes"];
    assert!(attributes.get("COLOR_0").is_some() && attributes.get("TANGENT").is_none());
    check_geometry(&vertex_json, &mesh, false);
    println!("model.glb (vertex): {} bytes", vertex_bytes.len());

    let Some(script) = validator_script() else {
        return;
    };
    for (form, path) in [
        ("textures", out.join("model.glb")),
        ("vertex", vertex_out.join("model.glb")),
    ] {
        let report = validate(&script, &path);
        let issues = &report["issues"];
        println!(
            "glTF validator {} ({form}): {} errors, {} warnings, {} infos, {} hints; {}",
            report["validatorVersion"],
            issues["numErrors"],
            issues["numWarnings"],
            issues["numInfos"],
            issues["numHints"],
            report["info"]
        );
        for message in issues["messages"].as_array().into_iter().flatten() {
            println!("  {message}");
        }
        assert_eq!(issues["numErrors"], 0, "{form}: {issues}");
        assert_eq!(issues["numWarnings"], 0, "{form}: {issues}");
        let used = &report["info"]["extensionsUsed"];
        assert!(
            used.as_array()
                .is_some_and(|e| e.iter().any(|e| e == "KHR_materials_ior")),
            "{used}"
        );
    }
}

/// A GLB's JSON document and its bytes.
fn read_glb(path: &Path) -> (Value, Vec<u8>) {
    let glb = std::fs::read(path).unwrap();
    assert_eq!(&glb[..4], b"glTF");
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let json: Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    (json, glb)
}

/// Image `index` of a GLB, decoded.
fn image_of(json: &Value, glb: &[u8], index: usize) -> image::RgbImage {
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let bin = &glb[20 + json_len + 8..];
    let view = &json["bufferViews"][json["images"][index]["bufferView"].as_u64().unwrap() as usize];
    let offset = view["byteOffset"].as_u64().unwrap() as usize;
    let length = view["byteLength"].as_u64().unwrap() as usize;
    image::load_from_memory(&bin[offset..offset + length])
        .unwrap()
        .to_rgb8()
}

/// The glTF's mesh is the dense one simplified: a smooth sphere to a few thousand triangles, far
/// below the default budget, closed like the dense one (`seams`: the textured form's atlas copies
/// vertices along its seams, so the count is checked on distinct positions).
fn check_geometry(json: &Value, mesh: &phygap::core::mesh::TriangleMesh, seams: bool) {
    let ior = json["materials"][0]["extensions"]["KHR_materials_ior"]["ior"]
        .as_f64()
        .unwrap();
    assert!((ior - 1.5).abs() < 1e-6, "{ior}");
    let position = json["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
        .as_u64()
        .unwrap() as usize;
    let glb_vertices = json["accessors"][position]["count"].as_u64().unwrap() as usize;
    let glb_indices = json["accessors"][0]["count"].as_u64().unwrap() as usize;
    assert!(
        glb_vertices > 100 && glb_vertices < mesh.vertices.len() / 10,
        "{glb_vertices} of {} vertices",
        mesh.vertices.len()
    );
    assert!(glb_indices <= 3 * phygap::core::config::DEFAULT_MESH_TRIANGLES as usize);
    let radius = json["accessors"][position]["max"][0].as_f64().unwrap();
    assert!(
        (radius - 1.0).abs() < 0.05,
        "the unit sphere's extent: {radius}"
    );
    if seams {
        assert!(glb_indices / 3 < 2 * glb_vertices - 4, "seams add vertices");
    } else {
        // Closed (Euler: V − E + F = 2 with E = 3F/2 for a sphere): F = 2V − 4.
        assert_eq!(glb_indices / 3, 2 * glb_vertices - 4);
    }
}

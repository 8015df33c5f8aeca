//! Fuzzing of the core's readers of untrusted bytes (`phygap::testing::fuzz`): image headers and
//! decoders behind the size checks, capture documents (transforms.json, raw frames), COLMAP
//! models (binary and text), PLY files (surfels and meshes), checkpoints, and job configs. Each
//! target replays its committed corpus (`tests/fuzz-corpus/TARGET/`, the inputs of issue 27
//! among them), then mutants for `PHYGAP_FUZZ_SECONDS` (default 15). A reader must answer every
//! input with a value or an error: a panic fails the test (the input is saved in the corpus),
//! an allocation from an unchecked size aborts it.
//!
//! `cargo test --release --test fuzz -- --ignored regenerate` rewrites the seed files.

use std::path::{Path, PathBuf};

use phygap::core::config::{TrainConfig, MAX_SURFELS};
use phygap::formats::image_io::{decoder_limits, read_header, read_image_within, ImageLimits};
use phygap::io::capture::{self, CaptureLimits};
use phygap::testing::fuzz::{self, Input, Mutation};

fn corpus_dir(target: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fuzz-corpus")
        .join(target)
}

/// Seconds each target runs (`PHYGAP_FUZZ_SECONDS`).
fn budget() -> std::time::Duration {
    fuzz::budget(15)
}

/// Small limits, so that what passes a check stays cheap to decode.
const IMAGE_LIMITS: ImageLimits = ImageLimits {
    max_pixels: 1 << 16,
};

const CAPTURE_LIMITS: CaptureLimits = CaptureLimits {
    max_views: 64,
    max_pixels_per_view: 1 << 16,
    max_decoded_bytes: 64 << 20,
};

/// The extension of a corpus file's name (`seed.exr` → `exr`).
fn extension(input: &Input<'_>) -> &'static str {
    match Path::new(input.name).extension().and_then(|e| e.to_str()) {
        Some("exr") => "exr",
        Some("png") => "png",
        Some("hdr") => "hdr",
        Some("tif") => "tif",
        Some("raw") => "raw",
        Some("json") => "json",
        Some("ply") => "ply",
        Some("bin") => "bin",
        Some("txt") => "txt",
        _ => "dat",
    }
}

#[test]
fn fuzz_image_headers_and_decoders() {
    let dir = tempfile::tempdir().unwrap();
    fuzz::run(
        "images",
        &corpus_dir("images"),
        Mutation::Bytes,
        budget(),
        |input| {
            let path = dir.path().join(format!("input.{}", extension(input)));
            std::fs::write(&path, input.bytes).unwrap();
            if extension(input) == "tif" {
                // Raw mosaic frames: the image crate's TIFF decoder under the same limits.
                if let Ok(reader) =
                    image::ImageReader::open(&path).and_then(|r| r.with_guessed_format())
                {
                    let mut reader = reader;
                    reader.limits(decoder_limits(&IMAGE_LIMITS));
                    let _ = reader.decode();
                }
                return;
            }
            let header = read_header(&path);
            if let Ok((image, _)) = read_image_within(&path, &IMAGE_LIMITS) {
                let header = header.expect("a decoded file has a header");
                assert!(
                    (image.num_pixels() as u64) <= IMAGE_LIMITS.max_pixels,
                    "decoded {}×{} past the limit",
                    image.width,
                    image.height
                );
                assert_eq!((image.width, image.height), (header.width, header.height));
                assert_eq!(image.data.len(), image.num_pixels() * image.channels);
            }
        },
    );
}

/// A folder holding a small full-Stokes capture (its files at the top) and a raw-mosaic one
/// (under `raw-capture/`), whose documents the capture target mutates.
fn capture_folder() -> tempfile::TempDir {
    use phygap::io::capture::simulate::{write_raw_capture, SimulateOptions};
    use phygap::pipeline::synth::{synth, SynthOptions};
    let dir = tempfile::tempdir().unwrap();
    let options = SynthOptions {
        views: 6,
        size: 16,
        ..SynthOptions::default()
    };
    synth(dir.path(), &options).unwrap();
    let loaded = capture::load(dir.path()).unwrap();
    write_raw_capture(
        &loaded,
        &dir.path().join("raw-capture"),
        &SimulateOptions::default(),
    )
    .unwrap();
    dir
}

#[test]
fn fuzz_capture_documents() {
    let folder = capture_folder();
    fuzz::run(
        "captures",
        &corpus_dir("captures"),
        Mutation::Json,
        budget(),
        |input| {
            let root = match input.name.starts_with("raw") {
                true => folder.path().join("raw-capture"),
                false => folder.path().to_owned(),
            };
            std::fs::write(root.join("transforms.json"), input.bytes).unwrap();
            if let Ok(loaded) = capture::load_within(&root, &CAPTURE_LIMITS) {
                assert!(loaded.views.len() <= CAPTURE_LIMITS.max_views);
                for view in &loaded.views {
                    let pixels = view.camera.width as u64 * view.camera.height as u64;
                    assert!(pixels <= CAPTURE_LIMITS.max_pixels_per_view);
                }
                let _ = loaded.summary();
                let _ = loaded.check_trainable();
            }
            let _ = capture::load_cameras_within(&root, &CAPTURE_LIMITS);
        },
    );
}

/// A folder with a COLMAP model in both formats (`sparse/0` binary, `text/sparse/0` text).
fn colmap_folders() -> tempfile::TempDir {
    use phygap::io::capture::colmap::model::write_model;
    use phygap::io::capture::colmap::ModelFormat;
    let dir = tempfile::tempdir().unwrap();
    let model = seed_colmap_model();
    write_model(&model, &dir.path().join("sparse/0"), ModelFormat::Binary).unwrap();
    write_model(&model, &dir.path().join("text/sparse/0"), ModelFormat::Text).unwrap();
    dir
}

fn seed_colmap_model() -> phygap::io::capture::colmap::ColmapModel {
    use phygap::io::capture::colmap::{ColmapCamera, ColmapImage, ColmapModel, ColmapPoint};
    let camera = ColmapCamera {
        id: 1,
        model: "OPENCV".into(),
        width: 32,
        height: 24,
        params: vec![30.0, 30.0, 16.0, 12.0, 0.01, -0.002, 0.0005, 0.0],
    };
    let images = (1..=3)
        .map(|id| ColmapImage {
            id,
            qvec: [1.0, 0.0, 0.0, 0.0],
            tvec: [0.1 * id as f64, 0.0, 3.0],
            camera_id: 1,
            name: format!("view_{id}.png"),
            points2d: vec![(5.0, 6.0, 1), (7.0, 8.0, -1)],
        })
        .map(|image| (image.id, image))
        .collect();
    ColmapModel {
        cameras: [(1, camera)].into_iter().collect(),
        images,
        points: vec![ColmapPoint {
            id: 1,
            xyz: [0.1, 0.2, 0.3],
            rgb: [200, 100, 50],
            error: 0.5,
            track: vec![(1, 0), (2, 0)],
        }],
    }
}

#[test]
fn fuzz_colmap_models() {
    use phygap::io::capture::colmap::model::read_model;
    use phygap::io::capture::colmap::ModelFormat;
    let folders = colmap_folders();
    fuzz::run(
        "colmap",
        &corpus_dir("colmap"),
        Mutation::Bytes,
        budget(),
        |input| {
            let (root, format) = match extension(input) {
                "txt" => (folders.path().join("text"), ModelFormat::Text),
                _ => (folders.path().to_owned(), ModelFormat::Binary),
            };
            let model_dir = root.join("sparse/0");
            let original = model_dir.join(input.name);
            let kept = std::fs::read(&original).unwrap();
            std::fs::write(&original, input.bytes).unwrap();
            let _ = read_model(&model_dir, format);
            let _ = capture::load_cameras_within(&root, &CAPTURE_LIMITS);
            std::fs::write(&original, kept).unwrap();
        },
    );
}

#[test]
fn fuzz_ply_and_checkpoint_readers() {
    let dir = tempfile::tempdir().unwrap();
    fuzz::run(
        "models",
        &corpus_dir("models"),
        Mutation::Bytes,
        budget(),
        |input| {
            let path = dir.path().join(input.name);
            std::fs::write(&path, input.bytes).unwrap();
            match extension(input) {
                "ply" => {
                    let _ = phygap::formats::ply::read_ply(&path);
                    let _ = phygap::core::surfels::ply::load_ply(&path);
                    let _ = phygap::core::mesh::TriangleMesh::read_ply(&path);
                }
                _ => {
                    let _ = phygap::formats::checkpoint::Archive::read(&path);
                    let _ = phygap::pipeline::train::state::TrainState::load(&path);
                }
            }
        },
    );
}

#[test]
fn fuzz_train_configs() {
    fuzz::run(
        "configs",
        &corpus_dir("configs"),
        Mutation::Json,
        budget(),
        |input| {
            let Ok(text) = std::str::from_utf8(input.bytes) else {
                return;
            };
            if let Ok(config) = TrainConfig::from_json(text) {
                // What the one check accepts is what training can hold.
                assert!(config.max_surfels <= MAX_SURFELS);
                assert!(
                    config.initial_surfels >= 1 && config.initial_surfels <= config.max_surfels
                );
                assert!((4..=1024).contains(&config.envmap_resolution));
                assert!((1..=1_000_000).contains(&config.steps()));
                assert!(config.validate().is_ok());
            }
        },
    );
}

/// Rewrites the seed corpus: files made by the project's own writers, and the hostile inputs of
/// issue 27. Run by hand after a format changes; the files are committed.
#[test]
#[ignore = "rewrites tests/fuzz-corpus; run by hand"]
fn regenerate_the_seed_corpus() {
    use phygap::formats::image_io::{write_exr, write_png, Image};
    use phygap::testing::hostile::{exr_declaring, hdr_declaring, png_declaring};
    let write = |target: &str, name: &str, bytes: &[u8]| {
        let dir = corpus_dir(target);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join(name), bytes).unwrap();
    };
    let scratch = tempfile::tempdir().unwrap();
    let file_bytes = |name: &str, save: &dyn Fn(&Path)| {
        let path = scratch.path().join(name);
        save(&path);
        std::fs::read(&path).unwrap()
    };
    let ramp = |channels| {
        Image::from_fn(6, 4, channels, |x, y, o| {
            for (c, v) in o.iter_mut().enumerate() {
                *v = (x + 2 * y + c) as f32 / 12.0;
            }
        })
    };
    for (name, channels) in [("y.exr", 1), ("rgb.exr", 3), ("rgba.exr", 4)] {
        write(
            "images",
            name,
            &file_bytes(name, &|p| write_exr(p, &ramp(channels)).unwrap()),
        );
    }
    for (name, channels) in [("grey.png", 1), ("rgb.png", 3), ("rgba.png", 4)] {
        let bytes = file_bytes(name, &|p| write_png(p, &ramp(channels), false).unwrap());
        write("images", name, &bytes);
    }
    let sixteen: Vec<u16> = (0..24).map(|i| i * 2000).collect();
    let tif = file_bytes("mosaic.tif", &|p| {
        image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::from_raw(6, 4, sixteen.clone())
            .unwrap()
            .save(p)
            .unwrap()
    });
    write("images", "mosaic.tif", &tif);
    let png16 = file_bytes("mosaic16.png", &|p| {
        image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::from_raw(6, 4, sixteen.clone())
            .unwrap()
            .save(p)
            .unwrap()
    });
    write("images", "mosaic16.png", &png16);
    let hdr = file_bytes("sky.hdr", &|p| {
        let rgb: Vec<f32> = ramp(3).data;
        image::DynamicImage::ImageRgb32F(image::ImageBuffer::from_raw(6, 4, rgb).unwrap())
            .save(p)
            .unwrap()
    });
    write("images", "sky.hdr", &hdr);
    write("images", "huge.exr", &exr_declaring(100_000, 100_000));
    write("images", "huge.png", &png_declaring(100_000, 100_000));
    write("images", "huge.hdr", &hdr_declaring(100_000, 100_000));

    let folder = capture_folder();
    let stokes = std::fs::read(folder.path().join("transforms.json")).unwrap();
    write("captures", "stokes.json", &stokes);
    let raw = std::fs::read(folder.path().join("raw-capture/transforms.json")).unwrap();
    write("captures", "raw.json", &raw);
    let doc: serde_json::Value = serde_json::from_slice(&stokes).unwrap();
    let edited = |edit: &dyn Fn(&mut serde_json::Value)| {
        let mut doc = doc.clone();
        edit(&mut doc);
        serde_json::to_vec_pretty(&doc).unwrap()
    };
    write(
        "captures",
        "many-frames.json",
        &edited(&|d| {
            let frames = d["frames"].as_array().unwrap().clone();
            d["frames"] =
                serde_json::json!((0..100).map(|i| frames[i % 6].clone()).collect::<Vec<_>>());
        }),
    );
    write(
        "captures",
        "far-focal.json",
        &edited(&|d| d["fl_x"] = 1e308.into()),
    );
    write(
        "captures",
        "huge-view.json",
        &edited(&|d| {
            d["w"] = 60_000.into();
            d["h"] = 60_000.into();
        }),
    );
    write(
        "captures",
        "no-test-view.json",
        &edited(&|d| {
            for frame in d["frames"].as_array_mut().unwrap() {
                frame["split"] = "train".into();
            }
        }),
    );

    let colmap = colmap_folders();
    for name in ["cameras", "images", "points3D"] {
        for (root, ext) in [
            (colmap.path().to_owned(), "bin"),
            (colmap.path().join("text"), "txt"),
        ] {
            let file = format!("{name}.{ext}");
            write(
                "colmap",
                &file,
                &std::fs::read(root.join("sparse/0").join(&file)).unwrap(),
            );
        }
    }

    let surfels =
        phygap::testing::sphere_surfels(glam::DVec3::ZERO, 1.0, 12, glam::DVec3::splat(0.5));
    let ply = file_bytes("surfels.ply", &|p| {
        phygap::core::surfels::ply::save_ply(p, &surfels).unwrap()
    });
    write("models", "surfels.ply", &ply);
    let mesh = phygap::core::mesh::TriangleMesh {
        vertices: vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ],
        normals: Vec::new(),
        triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        material_ids: Vec::new(),
    };
    let mesh_bytes = file_bytes("mesh.ply", &|p| mesh.write_ply(p).unwrap());
    write("models", "mesh.ply", &mesh_bytes);
    write(
        "models",
        "ascii.ply",
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
          property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
          0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    );
    let mut archive =
        phygap::formats::checkpoint::Archive::new(serde_json::json!({"iteration": 3}));
    archive.put("positions", &[0.0, 1.0, 2.0]);
    archive.put("empty", &[]);
    let ckpt = file_bytes("archive.ckpt", &|p| archive.write(p).unwrap());
    write("models", "archive.ckpt", &ckpt);
    let trained = scratch.path().join("model");
    let config = TrainConfig {
        iterations: 3.into(),
        initial_surfels: 40,
        max_surfels: 100,
        envmap_resolution: 4,
        gridmap: false,
        backend: phygap::core::config::BackendChoice::Cpu,
        ..TrainConfig::default()
    };
    let loaded = capture::load(folder.path()).unwrap();
    let cancel = std::sync::atomic::AtomicBool::new(false);
    phygap::pipeline::train::train(&loaded, &trained, &config, false, &cancel, &mut |_| {})
        .unwrap();
    write(
        "models",
        "checkpoint.ckpt",
        &std::fs::read(trained.join("checkpoint.bin")).unwrap(),
    );

    write(
        "configs",
        "default.json",
        &serde_json::to_vec_pretty(&TrainConfig::default()).unwrap(),
    );
    write(
        "configs",
        "huge-surfels.json",
        br#"{"iterations": 40, "max_surfels": 4294967295, "initial_surfels": 4000000000}"#,
    );
    write(
        "configs",
        "partial.json",
        br#"{"iterations": 300, "mode": "partial", "seed": 7, "gridmap": false}"#,
    );
}

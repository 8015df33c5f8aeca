//! Fuzzing of what the API process itself reads from uploads (`phygap::testing::fuzz`): capture
//! archives (zip and tar, extracted under the extraction limits) and relight forms (the map's
//! header and the cameras, checked before a job is queued). The decoding of images happens in
//! job processes and is fuzzed by the core's `tests/fuzz.rs`. Each target replays its committed
//! corpus (`api/tests/fuzz-corpus/TARGET/`), then mutants for `PHYGAP_FUZZ_SECONDS` (default
//! 15); a panic or an abort fails it.
//!
//! `cargo test --release -p phygap-api --test fuzz -- --ignored regenerate` rewrites the seeds.

mod common;

use std::path::{Path, PathBuf};

use common::*;
use phygap::testing::fuzz::{self, Mutation};
use phygap_api::storage::archive::{extract, ExtractLimits};
use phygap_api::ServiceLimits;

fn corpus_dir(target: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fuzz-corpus")
        .join(target)
}

/// The bytes of every file under `dir` (none where it does not exist).
fn bytes_under(dir: &Path) -> u64 {
    if !dir.exists() {
        return 0;
    }
    files_of(dir).iter().map(|(_, b)| b.len() as u64).sum()
}

#[test]
fn fuzz_capture_archives() {
    let scratch = tempfile::tempdir().unwrap();
    let limits = ExtractLimits {
        max_entries: 64,
        max_total_bytes: 8 << 20,
        max_ratio: 200,
    };
    fuzz::run(
        "archives",
        &corpus_dir("archives"),
        Mutation::Bytes,
        fuzz::budget(15),
        |input| {
            let upload = scratch.path().join("upload");
            let dest = scratch.path().join("out/capture");
            std::fs::write(&upload, input.bytes).unwrap();
            let _ = std::fs::remove_dir_all(scratch.path().join("out"));
            if let Ok(root) = extract(&upload, &dest, &limits) {
                assert!(
                    root.starts_with(&dest),
                    "{} outside the extraction",
                    root.display()
                );
            }
            // Nothing lands beside the extraction folder, whatever the entries said.
            let beside: Vec<PathBuf> = std::fs::read_dir(scratch.path().join("out"))
                .map(|entries| {
                    entries
                        .filter_map(Result::ok)
                        .map(|e| e.path())
                        .filter(|p| p != &dest)
                        .collect()
                })
                .unwrap_or_default();
            assert!(beside.is_empty(), "written outside: {beside:?}");
            assert!(bytes_under(&dest) <= limits.max_total_bytes);
        },
    );
}

#[test]
fn fuzz_relight_inputs() {
    let scratch = tempfile::tempdir().unwrap();
    let map = corpus_dir("relight").join("sky.exr");
    let limits = ServiceLimits {
        max_envmap_pixels: 1 << 16,
        ..ServiceLimits::default()
    };
    fuzz::run(
        "relight",
        &corpus_dir("relight"),
        Mutation::Json,
        fuzz::budget(15),
        |input| {
            let path = scratch.path().join(input.name);
            std::fs::write(&path, input.bytes).unwrap();
            let _ = match Path::new(input.name).extension().and_then(|e| e.to_str()) {
                Some("json") => {
                    phygap_api::http::intake::check_relight_inputs(&map, Some(&path), &limits)
                }
                _ => phygap_api::http::intake::check_relight_inputs(&path, None, &limits),
            };
        },
    );
}

/// Rewrites the seed corpus: the test capture archived both ways, archives that break the
/// extraction rules, and relight maps and cameras, the hostile ones of issue 27 among them.
#[test]
#[ignore = "rewrites api/tests/fuzz-corpus; run by hand"]
fn regenerate_the_seed_corpus() {
    use phygap::testing::hostile::{exr_declaring, hdr_declaring};
    use serde_json::json;
    let write = |target: &str, name: &str, bytes: &[u8]| {
        let dir = corpus_dir(target);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join(name), bytes).unwrap();
    };
    let capture = tempfile::tempdir().unwrap();
    phygap::pipeline::synth::synth(
        capture.path(),
        &phygap::pipeline::synth::SynthOptions {
            views: 3,
            size: 8,
            ..Default::default()
        },
    )
    .unwrap();
    let files = files_of(capture.path());
    write("archives", "capture.tar", &tar_of(&files));
    let nested: Vec<_> = files
        .iter()
        .map(|(n, b)| (format!("capture/{n}"), b.clone()))
        .collect();
    write("archives", "capture.zip", &zip_of(&nested));
    write(
        "archives",
        "traversal.zip",
        &zip_of(&[("../escape.txt".into(), b"x".to_vec())]),
    );
    write(
        "archives",
        "long-name.tar",
        &tar_of(&[(format!("{}.exr", "n".repeat(300)), vec![1, 2, 3])]),
    );
    let bomb = vec![0u8; 4 << 20];
    write(
        "archives",
        "bomb.zip",
        &zip_of(&[("zeros.bin".into(), bomb)]),
    );

    let sky = capture.path().join("sky.exr");
    let image = phygap::formats::image_io::Image::filled(8, 4, 3, 0.5);
    phygap::formats::image_io::write_exr(&sky, &image).unwrap();
    write("relight", "sky.exr", &std::fs::read(&sky).unwrap());
    write("relight", "huge.exr", &exr_declaring(100_000, 100_000));
    write("relight", "huge.hdr", &hdr_declaring(100_000, 100_000));
    let camera = |side: u32| {
        json!({"camera_convention": "OpenGL", "frames": [{
            "w": side, "h": side, "fl_x": side, "fl_y": side,
            "transform_matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 3], [0, 0, 0, 1]]}]})
    };
    for (name, side) in [("cameras.json", 16), ("huge-cameras.json", 100_000)] {
        write(
            "relight",
            name,
            &serde_json::to_vec_pretty(&camera(side)).unwrap(),
        );
    }
}

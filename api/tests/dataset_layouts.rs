//! Captures in the dataset layouts polarization datasets ship (IDR/NeuS, LLFF) uploaded as they
//! are, with no transforms.json: the service finds the capture in the archive and admits it with
//! its views read from per-angle images, 3-channel masks and the layout's camera file.

mod common;

use common::*;
use phygap::io::capture::layouts::LayoutKind;
use phygap::pipeline::synth::{synth_layout, SynthOptions};
use serde_json::json;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn idr_and_llff_archives_are_admitted_with_their_views() {
    let (_data, t) = TestServer::start_fresh().await;
    for kind in [LayoutKind::Idr, LayoutKind::Llff] {
        let dir = tempfile::tempdir().unwrap();
        let options = SynthOptions {
            views: 10,
            size: 24,
            ..SynthOptions::default()
        };
        synth_layout(dir.path(), &options, kind).unwrap();
        // The layout alone, under a top-level folder: the transforms form stays behind.
        std::fs::remove_dir_all(dir.path().join("reference")).unwrap();
        let entries: Vec<(String, Vec<u8>)> = files_of(dir.path())
            .into_iter()
            .map(|(name, data)| (format!("scan/{name}"), data))
            .collect();
        let (status, capture) = t.upload(zip_of(&entries)).await;
        assert_eq!(status, 201, "{kind:?}: {capture}");
        assert_eq!(capture["views"], 10, "{kind:?}");
        assert_eq!(capture["kinds"], json!(["polarizer4"]), "{kind:?}");
        let warnings = capture["warnings"].as_array().cloned().unwrap_or_default();
        assert!(
            !warnings
                .iter()
                .any(|w| w.as_str().is_some_and(|w| w.contains("mask"))),
            "{kind:?}: every view's mask was found: {warnings:?}"
        );
    }
}

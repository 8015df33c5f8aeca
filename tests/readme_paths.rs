//! README's file references point at files that exist: every backticked path in README.md that
//! names a source file or folder (`src/core/raster/cpu.rs`, `core/gridmap.rs`, `api/migrations/`) is
//! found relative to the repository root or to `src/`, so the code map cannot drift from the tree.

use std::path::Path;

/// Backticked tokens of `text` that look like paths of the repository's sources.
fn source_paths(text: &str) -> Vec<&str> {
    const SUFFIXES: [&str; 6] = [".rs", ".wgsl", ".sql", ".js", ".sh", "/"];
    text.split('`')
        .skip(1)
        .step_by(2)
        // Two components at least (`store/` alone is relative to the sentence's folder).
        .filter(|t| t.trim_end_matches('/').contains('/'))
        .filter(|t| !t.contains([' ', '*', '{', '#']) && !t.contains("://"))
        .filter(|t| !t.starts_with("..") && !t.starts_with('/'))
        .filter(|t| SUFFIXES.iter().any(|s| t.ends_with(s)))
        .collect()
}

#[test]
fn every_source_path_in_the_readme_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let paths = source_paths(&readme);
    assert!(paths.len() > 30, "found only {} paths", paths.len());
    let missing: Vec<&str> = paths
        .into_iter()
        .filter(|p| !root.join(p).exists() && !root.join("src").join(p).exists())
        .collect();
    assert!(
        missing.is_empty(),
        "README names missing files: {missing:#?}"
    );
}

#[test]
fn the_scan_finds_paths_and_ignores_commands_and_urls() {
    let text = "see `src/core/camera.rs`, `shaders/`, `cargo test --release`, \
                `http://127.0.0.1:8080/`, `../shared/data/`, `store/`, `shaders/*.wgsl` and `a/b.rs`";
    assert_eq!(source_paths(text), ["src/core/camera.rs", "a/b.rs"]);
}

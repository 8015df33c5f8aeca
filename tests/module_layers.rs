//! The core crate's layers point one way: every module uses only its own layer and the layers
//! listed before it in [`LAYERS`], and the files of one folder (`gpu/raster.rs`, `gpu/shade.rs`,
//! …) never use each other in a circle. The checker, shared with the service's
//! `api/tests/module_layers.rs`, is `tests/layers/checker.rs`.

#[path = "layers/checker.rs"]
mod checker;

use std::collections::BTreeSet;
use std::path::Path;

use checker::*;

/// The layers, lowest first (as `src/lib.rs` documents them).
const LAYERS: [&str; 6] = ["formats", "core", "testing", "gpu", "io", "pipeline"];

/// Every module of the core crate.
fn core_modules() -> Vec<Module> {
    crate_modules(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs"))
}

#[test]
fn every_module_uses_only_its_own_and_lower_layers() {
    let graph = dependency_graph(&core_modules());
    // The walk found the layers' modules (a broken walker would pass vacuously).
    for expected in [
        "core::raster",
        "gpu::train",
        "io::capture",
        "pipeline::train",
    ] {
        assert!(graph.contains_key(expected), "{expected} not found");
    }
    let upward = upward_uses(&graph, &LAYERS);
    assert!(upward.is_empty(), "uses of a higher layer: {upward:#?}");
}

#[test]
fn no_files_of_a_folder_use_each_other_in_a_circle() {
    let modules = core_modules();
    let folders = folder_graphs(&modules);
    // The walk found nested folders (a broken walker would pass vacuously).
    for expected in ["", "core", "gpu", "io::capture", "core::raster"] {
        assert!(
            folders.contains_key(expected),
            "folder `{expected}` not found"
        );
    }
    let circles = folder_circles(&modules);
    assert!(circles.is_empty(), "circles between files: {circles:#?}");
}

#[test]
fn the_checks_see_upward_uses_grouped_imports_and_cycles() {
    let modules = [
        module(
            "core::raster",
            "use crate::core::{camera::Camera, shading};\n// crate::pipeline::train in a comment\n\
             #[cfg(test)]\nmod tests { use crate::testing::x; }",
            &[],
        ),
        module(
            "core::camera",
            "fn f() { crate::gpu::GpuBackend::new() }",
            &[],
        ),
        module("core::shading", "use crate::core::raster::Backend;", &[]),
        module("core", "", &["raster", "camera", "shading"]),
        module("gpu", "", &[]),
        module("testing", "", &[]),
    ];
    let graph = dependency_graph(&modules);
    assert_eq!(
        graph["core::raster"],
        BTreeSet::from(["core::camera".to_owned(), "core::shading".to_owned()])
    );
    assert_eq!(graph["core::camera"], BTreeSet::from(["gpu".to_owned()]));
    assert!(layer_of(&LAYERS, "gpu") > layer_of(&LAYERS, "core::camera"));
    let cycle = find_cycle(&graph).expect("core::raster ↔ core::shading");
    assert!(cycle.contains(&"core::shading".to_owned()));
    assert_eq!(folder_circles(&modules).len(), 1);
}

/// The circle the first version of this test could not see: files of one folder that use each
/// other through `super::` and through the folder's re-exports (`gpu/raster.rs` defining the
/// backend, `gpu/shade.rs` adding an `impl` block to it, and raster calling shade).
#[test]
fn the_checks_see_super_paths_and_reexports() {
    let modules = [
        module(
            "gpu",
            "mod raster;\nmod shade;\nmod band;\npub use raster::{GpuBackend, GpuOptions as Options};",
            &["raster", "shade", "band", "deep"],
        ),
        module("gpu::raster", "pub struct GpuBackend;\nfn f() { super::shade::lights(); }", &[]),
        module("gpu::shade", "impl super::GpuBackend { }\npub fn lights() {}", &[]),
        module("gpu::band", "use self::inner::X;\nuse super::super::core::y;", &["inner"]),
        module("gpu::band::inner", "use super::super::Options;", &[]),
        module("gpu::deep", "", &[]),
        module("core", "", &[]),
    ];
    let uses = module_uses(&modules);
    let path = |p: &str| p.split("::").map(str::to_owned).collect::<Vec<_>>();
    for (from, to) in [
        ("gpu::shade", "gpu::raster"),
        ("gpu::raster", "gpu::shade"),
        ("gpu::band", "gpu::band::inner"),
        ("gpu::band", "core"),
        ("gpu::band::inner", "gpu::raster"),
    ] {
        assert!(
            uses.contains(&(path(from), path(to))),
            "{from} → {to}: {uses:?}"
        );
    }
    let circles = folder_circles(&modules);
    assert_eq!(circles.len(), 1, "{circles:?}");
    assert!(circles[0].starts_with("gpu: "), "{circles:?}");
    let graphs = folder_graphs(&modules);
    // band (through its subfolder) uses raster; deep uses nothing.
    assert!(graphs["gpu"]["band"].contains("raster"));
    assert!(graphs["gpu"]["deep"].is_empty());
}

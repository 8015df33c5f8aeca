//! The service crate's layers point one way: every module uses only its own layer and the layers
//! listed before it in [`LAYERS`] (as `api/src/lib.rs` documents them), only the binary's edge
//! (the crate root and `cli`) uses what the root defines, and the files of one folder
//! (`http/intake.rs`, `http/bodies.rs`, …; a subfolder counts as one file) never use each other
//! in a circle. The checker is the core crate's, `tests/layers/checker.rs`.

#[path = "../../tests/layers/checker.rs"]
mod checker;

use std::collections::BTreeSet;
use std::path::Path;

use checker::*;

/// The layers, lowest first; `cli` and the crate root are the binary's edge, at the top.
const LAYERS: [&str; 6] = ["domain", "storage", "accounts", "jobs", "http", "cli"];

/// What may use the items the crate root defines (`Server`, `StartError`).
const EDGE: [&str; 1] = ["cli"];

/// Every module of the service crate.
fn api_modules() -> Vec<Module> {
    crate_modules(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs"))
}

#[test]
fn every_module_uses_only_its_own_and_lower_layers() {
    let modules = api_modules();
    let graph = dependency_graph(&modules);
    // The walk found the layers' modules (a broken walker would pass vacuously).
    for expected in [
        "domain::refusal",
        "storage::store",
        "accounts::quotas",
        "jobs::worker",
        "jobs::child_process_runner",
        "http::routes",
        "cli",
    ] {
        assert!(graph.contains_key(expected), "{expected} not found");
    }
    let upward = upward_uses(&graph, &LAYERS);
    assert!(upward.is_empty(), "uses of a higher layer: {upward:#?}");
    let root = root_uses(&modules, &EDGE);
    assert!(root.is_empty(), "uses of the crate root: {root:#?}");
}

#[test]
fn no_files_of_a_folder_use_each_other_in_a_circle() {
    let modules = api_modules();
    let folders = folder_graphs(&modules);
    // The walk found nested folders (a broken walker would pass vacuously).
    for expected in ["", "http", "http::routes", "jobs", "storage::store"] {
        assert!(
            folders.contains_key(expected),
            "folder `{expected}` not found"
        );
    }
    let circles = folder_circles(&modules);
    assert!(circles.is_empty(), "circles between files: {circles:#?}");
}

/// The checks fail on what the layers forbid: a lower layer using a higher one (the store using
/// the accounts' types, a job answering with the HTTP error), a use of the root's state from
/// below, and two files of a folder using each other (`http/intake.rs` ↔ `http/routes`).
#[test]
fn the_checks_see_upward_uses_root_uses_and_circles() {
    let modules = [
        module(
            "",
            "pub struct AppState;\npub mod http;\npub mod jobs;",
            &["http", "jobs", "storage", "accounts"],
        ),
        module("storage", "", &["store"]),
        module(
            "storage::store",
            "use crate::accounts::quotas::{AccountUsage, RunningLimits};",
            &[],
        ),
        module("accounts", "", &["quotas"]),
        module("accounts::quotas", "use crate::AppState;", &[]),
        module("jobs", "", &["purge"]),
        module(
            "jobs::purge",
            "fn f() -> crate::http::error::ApiError { todo!() }",
            &[],
        ),
        module(
            "http",
            "pub mod intake;\npub mod routes;\npub mod error;",
            &["intake", "routes", "error"],
        ),
        module(
            "http::intake",
            "use crate::http::routes::captures::body_error;",
            &[],
        ),
        module("http::routes", "mod captures;", &["captures"]),
        module(
            "http::routes::captures",
            "use super::super::intake::Filed;",
            &[],
        ),
        module("http::error", "", &[]),
    ];
    let graph = dependency_graph(&modules);
    let upward = upward_uses(&graph, &LAYERS);
    assert_eq!(
        BTreeSet::from_iter(upward.iter().map(String::as_str)),
        BTreeSet::from([
            "storage::store uses accounts::quotas",
            "jobs::purge uses http::error"
        ]),
        "{upward:?}"
    );
    assert_eq!(
        root_uses(&modules, &EDGE),
        ["accounts::quotas uses the crate root"]
    );
    let circles = folder_circles(&modules);
    assert_eq!(circles.len(), 1, "{circles:?}");
    assert!(circles[0].starts_with("http: "), "{circles:?}");
}

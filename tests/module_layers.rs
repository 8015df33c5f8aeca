//! The core crate's layers point one way: reads every module reachable from `src/lib.rs` (test
//! modules excluded), collects the `crate::…` paths each one names, and checks that
//!
//! - a module uses only its own layer and the layers listed before it in [`LAYERS`], and
//! - the second-level modules (`core::raster`, `pipeline::train`, `gpu::shade`, …) never use
//!   each other in a circle.
//!
//! Paths are read from the source text with comments removed, so doc links do not count and a
//! `use` of any form (grouped, nested, inline `crate::a::b::f()`) does.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The layers, lowest first (as `src/lib.rs` documents them).
const LAYERS: [&str; 6] = ["formats", "core", "testing", "gpu", "io", "pipeline"];

/// A module of the crate: its path below the crate root and its source without test modules.
struct Module {
    path: Vec<String>,
    code: String,
}

/// `text` without `//` comments (string literals holding `//` are not an issue in this crate's
/// module paths: a path is only read where it is preceded by `crate::`).
fn without_comments(text: &str) -> String {
    text.lines()
        .map(|line| match line.find("//") {
            Some(at) => &line[..at],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `code` without the bodies of inline `#[cfg(test)] mod name { … }` blocks.
fn without_inline_tests(code: &str) -> String {
    let mut out = String::new();
    let mut rest = code;
    while let Some(at) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..at]);
        let after = &rest[at..];
        let header_end = after.find(['{', ';']).unwrap_or(after.len());
        if !after[..header_end].contains("mod ") || after[header_end..].starts_with(';') {
            // A test-only item other than an inline module (or `mod x;`, skipped by the walker).
            out.push_str("#[cfg(test)]");
            rest = &after["#[cfg(test)]".len()..];
            continue;
        }
        let mut depth = 0usize;
        let mut end = after.len();
        for (i, c) in after.char_indices().skip(header_end) {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = i + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// The `mod name;` declarations of `code` that are not test-only.
fn declared_modules(code: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut test_only = false;
    for line in code.lines().map(str::trim) {
        if line.starts_with("#[cfg(test)]") {
            test_only = true;
            continue;
        }
        let declaration = line
            .trim_start_matches("pub(crate) ")
            .trim_start_matches("pub ");
        if let Some(name) = declaration
            .strip_prefix("mod ")
            .and_then(|d| d.strip_suffix(';'))
        {
            if !test_only {
                names.push(name.trim().to_owned());
            }
        }
        if !line.starts_with("#[") {
            test_only = false;
        }
    }
    names
}

fn collect(file: &Path, path: Vec<String>, modules: &mut Vec<Module>) {
    let text = std::fs::read_to_string(file).unwrap();
    let code = without_inline_tests(&without_comments(&text));
    let is_dir_root = matches!(
        file.file_name().and_then(|n| n.to_str()),
        Some("lib.rs" | "mod.rs")
    );
    let dir: PathBuf = if is_dir_root {
        file.parent().unwrap().to_owned()
    } else {
        file.with_extension("")
    };
    for name in declared_modules(&code) {
        let child = [
            dir.join(format!("{name}.rs")),
            dir.join(&name).join("mod.rs"),
        ]
        .into_iter()
        .find(|p| p.is_file())
        .unwrap_or_else(|| panic!("{}: no file for `mod {name};`", file.display()));
        let mut child_path = path.clone();
        child_path.push(name);
        collect(&child, child_path, modules);
    }
    modules.push(Module { path, code });
}

/// The module paths (`a::b::…`, identifiers only) that `code` names after `crate::`, with grouped
/// imports expanded one level (`crate::core::{camera, raster::Backend}`).
fn crate_paths(code: &str) -> Vec<Vec<String>> {
    let ident = |s: &str| -> Vec<String> {
        s.split("::")
            .map(|p| {
                p.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect::<String>()
            })
            .take_while(|p| !p.is_empty())
            .collect()
    };
    let mut paths = Vec::new();
    for (at, _) in code.match_indices("crate::") {
        let rest = &code[at + "crate::".len()..];
        let prefix = ident(rest);
        let after_prefix: usize = prefix.iter().map(|p| p.len() + 2).sum();
        if rest[after_prefix.min(rest.len())..].starts_with('{') {
            let group = &rest[after_prefix + 1..rest.find('}').unwrap_or(rest.len())];
            for item in group.split(',') {
                let mut path = prefix.clone();
                path.extend(ident(item.trim()));
                paths.push(path);
            }
        } else {
            paths.push(prefix);
        }
    }
    paths
}

/// The node a module path belongs to: its first two components (`core::raster`).
fn node(path: &[String]) -> String {
    path.iter().take(2).cloned().collect::<Vec<_>>().join("::")
}

fn layer_of(node: &str) -> usize {
    let top = node.split("::").next().unwrap();
    LAYERS
        .iter()
        .position(|l| *l == top)
        .unwrap_or_else(|| panic!("module `{top}` is in no layer: add it to LAYERS and lib.rs"))
}

/// Edges between nodes (`from` uses `to`), from every module's paths.
fn dependency_graph(modules: &[Module]) -> BTreeMap<String, BTreeSet<String>> {
    let nodes: BTreeSet<String> = modules
        .iter()
        .filter(|m| !m.path.is_empty())
        .map(|m| node(&m.path))
        .collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> =
        nodes.iter().map(|n| (n.clone(), BTreeSet::new())).collect();
    for module in modules.iter().filter(|m| !m.path.is_empty()) {
        let from = node(&module.path);
        for path in crate_paths(&module.code) {
            // The longest prefix of the path that is a node (`core::raster` of
            // `core::raster::cpu::CpuBackend`, `gpu` of `gpu::GpuBackend`).
            let target = (1..=path.len().min(2))
                .rev()
                .map(|k| path[..k].join("::"))
                .find(|candidate| nodes.contains(candidate));
            if let Some(to) = target.filter(|to| *to != from) {
                graph.get_mut(&from).unwrap().insert(to);
            }
        }
    }
    graph
}

/// One cycle of `graph`, if it has any (depth-first search keeping the current path).
fn find_cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        done: &mut BTreeSet<String>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(start) = stack.iter().position(|n| n == node) {
            let mut cycle = stack[start..].to_vec();
            cycle.push(node.to_owned());
            return Some(cycle);
        }
        if done.contains(node) {
            return None;
        }
        stack.push(node.to_owned());
        for next in &graph[node] {
            if let Some(cycle) = visit(next, graph, done, stack) {
                return Some(cycle);
            }
        }
        stack.pop();
        done.insert(node.to_owned());
        None
    }
    let mut done = BTreeSet::new();
    graph
        .keys()
        .find_map(|n| visit(n, graph, &mut done, &mut Vec::new()))
}

fn crate_graph() -> BTreeMap<String, BTreeSet<String>> {
    let mut modules = Vec::new();
    let lib = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs");
    collect(&lib, Vec::new(), &mut modules);
    dependency_graph(&modules)
}

#[test]
fn every_module_uses_only_its_own_and_lower_layers() {
    let graph = crate_graph();
    // The walk found the layers' modules (a broken walker would pass vacuously).
    for expected in [
        "core::raster",
        "gpu::train",
        "io::capture",
        "pipeline::train",
    ] {
        assert!(graph.contains_key(expected), "{expected} not found");
    }
    let upward: Vec<String> = graph
        .iter()
        .flat_map(|(from, tos)| tos.iter().map(move |to| (from, to)))
        .filter(|(from, to)| layer_of(to) > layer_of(from))
        .map(|(from, to)| format!("{from} uses {to}"))
        .collect();
    assert!(upward.is_empty(), "uses of a higher layer: {upward:#?}");
}

#[test]
fn no_modules_use_each_other_in_a_circle() {
    let graph = crate_graph();
    assert_eq!(find_cycle(&graph), None, "a module cycle");
}

#[test]
fn the_checks_see_upward_uses_grouped_imports_and_cycles() {
    let module = |path: &str, code: &str| Module {
        path: path.split("::").map(str::to_owned).collect(),
        code: without_inline_tests(&without_comments(code)),
    };
    let modules = [
        module(
            "core::raster",
            "use crate::core::{camera::Camera, shading};\n// crate::pipeline::train in a comment\n\
             #[cfg(test)]\nmod tests { use crate::testing::x; }",
        ),
        module("core::camera", "fn f() { crate::gpu::GpuBackend::new() }"),
        module("core::shading", "use crate::core::raster::Backend;"),
        module("gpu", ""),
        module("testing", ""),
    ];
    let graph = dependency_graph(&modules);
    assert_eq!(
        graph["core::raster"],
        BTreeSet::from(["core::camera".to_owned(), "core::shading".to_owned()])
    );
    assert_eq!(graph["core::camera"], BTreeSet::from(["gpu".to_owned()]));
    assert!(layer_of("gpu") > layer_of("core::camera"));
    let cycle = find_cycle(&graph).expect("core::raster ↔ core::shading");
    assert!(cycle.contains(&"core::shading".to_owned()));
}

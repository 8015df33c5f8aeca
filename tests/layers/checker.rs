//! The checker behind the layer tests of both crates, `tests/module_layers.rs` (the core) and
//! `api/tests/module_layers.rs` (the service), which include it with `#[path]`. It reads every
//! module reachable from a crate's `src/lib.rs` (test modules excluded), collects the module
//! paths each one names (`crate::…`, and `super::…` and `self::…` resolved against the module's
//! own path, through the `pub use` re-exports of a folder's `mod.rs`), and builds
//!
//! - the graph between second-level modules (`core::raster`, `http::routes`), whose edges the
//!   tests check against the crate's list of layers ([`upward_uses`]), and
//! - for each folder, the graph between its files (a subfolder counts as one file with
//!   everything in it; the folder's `mod.rs` is its interface, not one of them), which must have
//!   no circle ([`folder_circles`]).
//!
//! Paths are read from the source text with comments removed, so doc links do not count and a
//! `use` of any form (grouped, nested, inline `crate::a::b::f()`) does.

// Each crate's test uses its own part of the checker.
#![allow(dead_code)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module of the crate: its path below the crate root, its source without test modules, and
/// the modules it declares.
pub struct Module {
    pub path: Vec<String>,
    pub code: String,
    pub children: Vec<String>,
}

/// `text` without `//` comments (string literals holding `//` are not an issue for the crates'
/// module paths: a path is only read where it is preceded by `crate::`).
pub fn without_comments(text: &str) -> String {
    text.lines()
        .map(|line| match line.find("//") {
            Some(at) => &line[..at],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `code` without the bodies of inline `#[cfg(test)] mod name { … }` blocks.
pub fn without_inline_tests(code: &str) -> String {
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
pub fn declared_modules(code: &str) -> Vec<String> {
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

pub fn collect(file: &Path, path: Vec<String>, modules: &mut Vec<Module>) {
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
    let children = declared_modules(&code);
    for name in &children {
        let child = [
            dir.join(format!("{name}.rs")),
            dir.join(name).join("mod.rs"),
        ]
        .into_iter()
        .find(|p| p.is_file())
        .unwrap_or_else(|| panic!("{}: no file for `mod {name};`", file.display()));
        let mut child_path = path.clone();
        child_path.push(name.clone());
        collect(&child, child_path, modules);
    }
    modules.push(Module {
        path,
        code,
        children,
    });
}

/// Identifiers of a path as written (`a::b::C` → `[a, b, C]`), up to the first non-identifier.
pub fn idents(s: &str) -> Vec<String> {
    s.split("::")
        .map(|p| {
            p.trim()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect::<String>()
        })
        .take_while(|p| !p.is_empty())
        .collect()
}

/// The paths `code` names after `prefix` (`crate::`, `super::`, `self::`), as written after it,
/// with grouped imports expanded one level (`crate::core::{camera, raster::Backend}`). A `super::`
/// path keeps its further `super`s.
pub fn paths_after(code: &str, prefix: &str) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    for (at, _) in code.match_indices(prefix) {
        // `super::` inside `super::super::` is counted once, from the first.
        let before = &code[..at];
        if before.ends_with("super::") || before.ends_with("crate::") || before.ends_with("self::")
        {
            continue;
        }
        let identifier_before = before
            .chars()
            .next_back()
            .is_some_and(|c| c.is_alphanumeric() || c == '_');
        if identifier_before {
            continue;
        }
        let rest = &code[at + prefix.len()..];
        let head = idents(rest);
        let after_head: usize = head.iter().map(|p| p.len() + 2).sum();
        if rest[after_head.min(rest.len())..].starts_with('{') {
            let group = &rest[after_head + 1..rest.find('}').unwrap_or(rest.len())];
            for item in group.split(',') {
                let mut path = head.clone();
                path.extend(idents(item));
                paths.push(path);
            }
        } else {
            paths.push(head);
        }
    }
    paths
}

/// The absolute path (below the crate root) of `written`, named by `prefix` in the module at
/// `at` (`is_root`: a `mod.rs` or `lib.rs`, whose `self` is its folder).
pub fn absolute(prefix: &str, written: &[String], at: &[String]) -> Vec<String> {
    match prefix {
        "crate::" => written.to_vec(),
        "self::" => at.iter().chain(written).cloned().collect(),
        _ => {
            // `super::` and any further `super`s climb one module each.
            let climbs = 1 + written.iter().take_while(|p| *p == "super").count();
            let base = &at[..at.len().saturating_sub(climbs)];
            base.iter()
                .chain(written.iter().skip(climbs - 1))
                .cloned()
                .collect()
        }
    }
}

/// Every module path `code` (the module at `at`) names, absolute, re-exports not yet followed.
pub fn named_paths(code: &str, at: &[String]) -> Vec<Vec<String>> {
    ["crate::", "super::", "self::"]
        .into_iter()
        .flat_map(|prefix| {
            paths_after(code, prefix)
                .into_iter()
                .map(move |written| absolute(prefix, &written, at))
        })
        .collect()
}

/// The `pub use child::{A, B as C}` re-exports of a module: the name it gives each (in the
/// module) and the absolute path it stands for.
pub fn reexports(code: &str, at: &[String], children: &[String]) -> BTreeMap<String, Vec<String>> {
    let mut names = BTreeMap::new();
    for statement in code.split(';') {
        let statement = statement.trim();
        let Some(rest) = ["pub use ", "pub(crate) use "]
            .iter()
            .find_map(|p| statement.strip_prefix(p))
        else {
            continue;
        };
        let rest = rest.trim();
        let (head, items): (&str, Vec<&str>) = match rest.find('{') {
            Some(open) => (
                rest[..open].trim_end_matches("::"),
                rest[open + 1..rest.rfind('}').unwrap_or(rest.len())]
                    .split(',')
                    .collect(),
            ),
            None => match rest.rsplit_once("::") {
                Some((head, item)) => (head, vec![item]),
                None => continue,
            },
        };
        let head_path = idents(head);
        let Some(first) = head_path.first() else {
            continue;
        };
        let base: Vec<String> = match first.as_str() {
            "crate" => head_path[1..].to_vec(),
            "self" => absolute("self::", &head_path[1..], at),
            "super" => absolute("super::", &head_path[1..], at),
            child if children.iter().any(|c| c == child) => {
                at.iter().chain(&head_path).cloned().collect()
            }
            _ => continue,
        };
        for item in items {
            let item = item.trim();
            let (original, alias) = match item.split_once(" as ") {
                Some((original, alias)) => (original.trim(), alias.trim()),
                None => (item, item.rsplit("::").next().unwrap_or(item)),
            };
            let mut target = base.clone();
            target.extend(idents(original));
            if !alias.is_empty() && alias != "*" {
                names.insert(alias.to_owned(), target);
            }
        }
    }
    names
}

/// The node a module path belongs to: its first two components (`core::raster`).
pub fn node(path: &[String]) -> String {
    path.iter().take(2).cloned().collect::<Vec<_>>().join("::")
}

/// The position of `node`'s layer in `layers` (lowest first).
pub fn layer_of(layers: &[&str], node: &str) -> usize {
    let top = node.split("::").next().unwrap();
    layers
        .iter()
        .position(|l| *l == top)
        .unwrap_or_else(|| panic!("module `{top}` is in no layer: add it to LAYERS and lib.rs"))
}

/// Every use of a higher layer in `graph`, as `from uses to`.
pub fn upward_uses(graph: &BTreeMap<String, BTreeSet<String>>, layers: &[&str]) -> Vec<String> {
    graph
        .iter()
        .flat_map(|(from, tos)| tos.iter().map(move |to| (from, to)))
        .filter(|(from, to)| layer_of(layers, to) > layer_of(layers, from))
        .map(|(from, to)| format!("{from} uses {to}"))
        .collect()
}

/// The modules that name an item defined in the crate root itself (not one it re-exports), other
/// than the root and the modules of `edge`: where the root is the top of the crate, a use of it
/// from below points up.
pub fn root_uses(modules: &[Module], edge: &[&str]) -> Vec<String> {
    module_uses(modules)
        .into_iter()
        .filter(|(from, to)| to.is_empty() && !from.is_empty() && !edge.contains(&from[0].as_str()))
        .map(|(from, _)| format!("{} uses the crate root", from.join("::")))
        .collect()
}

/// Every module reachable from the crate root `lib` (`src/lib.rs`), test modules excluded.
pub fn crate_modules(lib: &Path) -> Vec<Module> {
    let mut modules = Vec::new();
    collect(lib, Vec::new(), &mut modules);
    modules
}

/// Every use between modules: (the module that names a path, the module the path leads to),
/// re-exports followed to the module that defines the item.
pub fn module_uses(modules: &[Module]) -> Vec<(Vec<String>, Vec<String>)> {
    let known: BTreeSet<&[String]> = modules.iter().map(|m| m.path.as_slice()).collect();
    let exports: BTreeMap<&[String], BTreeMap<String, Vec<String>>> = modules
        .iter()
        .map(|m| (m.path.as_slice(), reexports(&m.code, &m.path, &m.children)))
        .collect();
    // The longest prefix of `path` that is a module.
    let module_of = |path: &[String]| -> usize {
        (0..=path.len())
            .rev()
            .find(|&k| known.contains(&path[..k]))
            .unwrap_or(0)
    };
    let mut uses = Vec::new();
    for module in modules {
        for mut path in named_paths(&module.code, &module.path) {
            for _ in 0..8 {
                let k = module_of(&path);
                let Some(target) = path
                    .get(k)
                    .and_then(|name| exports.get(&path[..k])?.get(name))
                else {
                    break;
                };
                path = target.iter().chain(&path[k + 1..]).cloned().collect();
            }
            let k = module_of(&path);
            uses.push((module.path.clone(), path[..k].to_vec()));
        }
    }
    uses
}

/// Edges between second-level nodes (`from` uses `to`), from every module's paths.
pub fn dependency_graph(modules: &[Module]) -> BTreeMap<String, BTreeSet<String>> {
    let nodes: BTreeSet<String> = modules
        .iter()
        .filter(|m| !m.path.is_empty())
        .map(|m| node(&m.path))
        .collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> =
        nodes.iter().map(|n| (n.clone(), BTreeSet::new())).collect();
    for (from, to) in module_uses(modules) {
        if from.is_empty() || to.is_empty() {
            continue;
        }
        let (from, to) = (node(&from), node(&to));
        if from != to {
            graph.get_mut(&from).unwrap().insert(to);
        }
    }
    graph
}

/// For each folder (a module with modules of its own), the uses between its files: `a` uses
/// `b` when anything in `a` (a subfolder counts with everything in it) names something in `b`.
/// Uses of the folder's own `mod.rs`, its interface, are not counted.
pub fn folder_graphs(modules: &[Module]) -> BTreeMap<String, BTreeMap<String, BTreeSet<String>>> {
    let mut folders: BTreeMap<String, BTreeMap<String, BTreeSet<String>>> = modules
        .iter()
        .filter(|m| !m.children.is_empty())
        .map(|m| {
            let files = m.children.iter().map(|c| (c.clone(), BTreeSet::new()));
            (m.path.join("::"), files.collect())
        })
        .collect();
    for (from, to) in module_uses(modules) {
        let shared = from.iter().zip(&to).take_while(|(a, b)| a == b).count();
        if shared >= from.len() || shared >= to.len() {
            continue; // within one file, or a use of an enclosing folder's interface
        }
        if let Some(files) = folders.get_mut(&from[..shared].join("::")) {
            files
                .get_mut(&from[shared])
                .map(|uses| uses.insert(to[shared].clone()));
        }
    }
    folders
}

/// One cycle of `graph`, if it has any (depth-first search keeping the current path).
pub fn find_cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
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

/// The circles between the files of each folder, as `folder: a → b → a`.
pub fn folder_circles(modules: &[Module]) -> Vec<String> {
    folder_graphs(modules)
        .iter()
        .filter_map(|(folder, files)| {
            let cycle = find_cycle(files)?;
            Some(format!("{folder}: {}", cycle.join(" → ")))
        })
        .collect()
}

/// A synthetic module at `path` (`a::b`), for the checker's own tests.
pub fn module(path: &str, code: &str, children: &[&str]) -> Module {
    Module {
        path: path
            .split("::")
            .filter(|p| !p.is_empty())
            .map(str::to_owned)
            .collect(),
        code: without_inline_tests(&without_comments(code)),
        children: children.iter().map(|c| (*c).to_owned()).collect(),
    }
}

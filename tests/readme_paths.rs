//! README.md and the manual under docs/ cannot drift from the tree and the binaries:
//!
//! - every relative Markdown link (`[text](path)`, images, reference definitions) resolves to a
//!   file or folder inside the repository (anchors are not checked);
//! - every backticked path that names a source file or folder (`src/core/raster/cpu.rs`,
//!   `api/migrations/`) exists, relative to the repository root or to `src/`;
//! - every `--flag` a document attributes to `phygap` exists in that subcommand's `--help`, and
//!   every one attributed to `phygap-api` in `phygap-api`'s.
//!
//! The flag check runs from the documents to the binaries, so flags the binaries gain need no
//! change here; a flag a document names must exist. A flag belongs to the command written before
//! it in the same code span or code line (`phygap bench quality … --json`); a span or line that
//! starts with the flag itself (`--max-views`) belongs to the section's command: the nearest
//! heading that names one (`## phygap train`), else the document's (`phygap-api` for
//! docs/service.md, `phygap` elsewhere, where a flag of any subcommand is accepted). Spans and lines
//! that start with another program (`cargo test --release`, `curl --data-binary …`) are not checked.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Component, Path, PathBuf};
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every Markdown file under docs/, as (path relative to the root, text).
fn documents() -> Vec<(PathBuf, String)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let mut paths = vec![root().join("README.md")];
    walk(&root().join("docs"), &mut paths);
    paths
        .into_iter()
        .map(|path| {
            let text = std::fs::read_to_string(&path).unwrap();
            (path.strip_prefix(root()).unwrap().to_owned(), text)
        })
        .collect()
}

/// A piece of a document: prose (code spans removed), one inline code span, or one line of a
/// fenced code block; with the heading path it sits under.
#[derive(Clone, Debug, PartialEq)]
enum Piece<'a> {
    Heading(usize, &'a str),
    Prose(String),
    Span(&'a str),
    CodeLine(&'a str),
}

fn pieces(text: &str) -> Vec<Piece<'_>> {
    let mut out = Vec::new();
    let mut fence: Option<&str> = None;
    // Where the paragraph being read starts: code spans may run over its line breaks.
    let mut paragraph: Option<usize> = None;
    let mut offset = 0;
    for raw in text.split_inclusive('\n') {
        let start = offset;
        offset += raw.len();
        let line = raw.trim_end_matches(['\n', '\r']);
        let trimmed = line.trim_start();
        if let Some(marker) = fence {
            if trimmed.starts_with(marker) {
                fence = None;
            } else {
                out.push(Piece::CodeLine(line));
            }
            continue;
        }
        let opens_fence = trimmed.starts_with("```") || trimmed.starts_with("~~~");
        let heading = trimmed.strip_prefix('#');
        if opens_fence || heading.is_some() || trimmed.is_empty() {
            if let Some(first) = paragraph.take() {
                paragraph_pieces(&text[first..start], &mut out);
            }
        }
        if opens_fence {
            fence = Some(&trimmed[..3]);
        } else if let Some(rest) = heading {
            let level = 1 + rest.chars().take_while(|c| *c == '#').count();
            out.push(Piece::Heading(level, rest.trim_start_matches('#').trim()));
        } else if !trimmed.is_empty() {
            paragraph.get_or_insert(start);
        }
    }
    if let Some(first) = paragraph {
        paragraph_pieces(&text[first..], &mut out);
    }
    out
}

/// A paragraph's code spans, then its prose with each span replaced by a space.
fn paragraph_pieces<'a>(paragraph: &'a str, out: &mut Vec<Piece<'a>>) {
    let mut prose = String::new();
    for (i, part) in paragraph.split('`').enumerate() {
        if i % 2 == 1 {
            out.push(Piece::Span(part));
            prose.push(' ');
        } else {
            prose.push_str(part);
        }
    }
    out.push(Piece::Prose(prose));
}

// ---------------------------------------------------------------------------------------------
// Source paths

/// Backticked tokens of `text` that look like paths of the repository's sources.
fn source_paths(text: &str) -> Vec<&str> {
    const SUFFIXES: [&str; 6] = [".rs", ".wgsl", ".sql", ".js", ".sh", "/"];
    pieces(text)
        .into_iter()
        .filter_map(|p| match p {
            Piece::Span(t) => Some(t),
            _ => None,
        })
        // Two components at least (`store/` alone is relative to the sentence's folder).
        .filter(|t| t.trim_end_matches('/').contains('/'))
        .filter(|t| !t.contains([' ', '\n', '*', '{', '#']) && !t.contains("://"))
        .filter(|t| !t.starts_with("..") && !t.starts_with('/'))
        .filter(|t| SUFFIXES.iter().any(|s| t.ends_with(s)))
        .collect()
}

#[test]
fn every_source_path_in_the_readme_and_the_docs_exists() {
    let mut found = 0;
    let mut missing = Vec::new();
    for (doc, text) in documents() {
        for path in source_paths(&text) {
            found += 1;
            if !root().join(path).exists() && !root().join("src").join(path).exists() {
                missing.push(format!("{}: {path}", doc.display()));
            }
        }
    }
    assert!(found > 30, "found only {found} paths");
    assert!(
        missing.is_empty(),
        "documents name missing files: {missing:#?}"
    );
}

#[test]
fn the_scan_finds_paths_and_ignores_commands_and_urls() {
    let text = "see `src/core/camera.rs`, `shaders/`, `cargo test --release`, \
                `http://127.0.0.1:8080/`, `../shared/data/`, `store/`, `shaders/*.wgsl` and `a/b.rs`\n\
                ```\nsrc/in/a/fence.rs\n```\n";
    assert_eq!(source_paths(text), ["src/core/camera.rs", "a/b.rs"]);
}

// ---------------------------------------------------------------------------------------------
// Links

/// The targets of the Markdown links and images of `text` (outside code), and of its reference
/// definitions (`[label]: target`).
fn link_targets(text: &str) -> Vec<String> {
    let mut targets = Vec::new();
    for piece in pieces(text) {
        let Piece::Prose(prose) = piece else { continue };
        for line in prose.lines() {
            let trimmed = line.trim_start();
            if trimmed.starts_with('[') {
                if let Some((label, target)) = trimmed.split_once("]:") {
                    if !label.contains(']') {
                        targets.push(target.split_whitespace().next().unwrap_or("").to_owned());
                        continue;
                    }
                }
            }
            let mut rest = line;
            while let Some(at) = rest.find("](") {
                let after = &rest[at + 2..];
                let end = after.find(')').unwrap_or(after.len());
                let inside = after[..end].trim();
                let target = match inside.strip_prefix('<') {
                    Some(angled) => angled.split('>').next().unwrap_or(""),
                    // `[text](path "title")`
                    None => inside.split_whitespace().next().unwrap_or(""),
                };
                targets.push(target.to_owned());
                rest = &after[end..];
            }
        }
    }
    targets
}

/// Whether a link target is relative to the document (not a URL, a mail address or an anchor).
fn is_relative(target: &str) -> bool {
    !(target.is_empty()
        || target.starts_with('#')
        || target.contains("://")
        || target.starts_with("mailto:"))
}

/// Where a relative link of the document at `doc` (relative to the root) points, relative to the
/// root, without its anchor or query; `None` when it leaves the repository.
fn resolve(doc: &Path, target: &str) -> Option<PathBuf> {
    let path = target.split(['#', '?']).next().unwrap_or("");
    let path = path.replace("%20", " ");
    let joined = match path.strip_prefix('/') {
        Some(from_root) => PathBuf::from(from_root),
        None => doc.parent().unwrap_or(Path::new("")).join(path),
    };
    let mut normal = PathBuf::new();
    for component in joined.components() {
        match component {
            Component::Normal(c) => normal.push(c),
            Component::CurDir => {}
            Component::ParentDir => {
                if !normal.pop() {
                    return None;
                }
            }
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(normal)
}

#[test]
fn every_relative_link_in_the_readme_and_the_docs_resolves_inside_the_repository() {
    let mut checked = 0;
    let mut broken = Vec::new();
    for (doc, text) in documents() {
        for target in link_targets(&text).into_iter().filter(|t| is_relative(t)) {
            checked += 1;
            match resolve(&doc, &target) {
                None => broken.push(format!("{}: {target} leaves the repository", doc.display())),
                Some(path) if !root().join(&path).exists() => broken.push(format!(
                    "{}: {target} ({} does not exist)",
                    doc.display(),
                    path.display()
                )),
                Some(_) => {}
            }
        }
    }
    assert!(checked > 20, "found only {checked} relative links");
    assert!(broken.is_empty(), "broken links: {broken:#?}");
}

#[test]
fn the_link_scan_reads_links_images_and_definitions_but_not_code() {
    let text = "A [link](docs/cli.md#flags \"title\"), an ![image](web.png), <https://x.org>, \
                [web](https://example.org/a) and [anchor](#here); `[not](code.md)`\n\
                [ref]: ../shared/docs/CAPTURE_FORMAT.md\n```\n[nor](fenced.md)\n```\n";
    assert_eq!(
        link_targets(text),
        [
            "docs/cli.md#flags",
            "web.png",
            "https://example.org/a",
            "#here",
            "../shared/docs/CAPTURE_FORMAT.md"
        ]
    );
    let doc = Path::new("docs/cli.md");
    assert_eq!(
        resolve(doc, "service.md#limits"),
        Some("docs/service.md".into())
    );
    assert_eq!(
        resolve(doc, "../api/openapi.yaml"),
        Some("api/openapi.yaml".into())
    );
    assert_eq!(resolve(Path::new("README.md"), "../shared/docs/x.md"), None);
    assert!(!is_relative("https://example.org") && !is_relative("#anchor"));
}

// ---------------------------------------------------------------------------------------------
// Flags

/// The project's two binaries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Bin {
    Phygap,
    Api,
}

/// Whom the flags of a piece of text belong to: a binary's (sub)command, or another program.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Owner {
    Command(Bin, Vec<String>),
    Foreign,
}

/// The binary a word of a command line runs (`phygap`, `target/release/phygap-api`, `"$bin/phygap"`).
fn command_word(word: &str) -> Option<Bin> {
    let name = word.rsplit('/').next().unwrap_or(word);
    match name {
        "phygap" => Some(Bin::Phygap),
        "phygap-api" => Some(Bin::Api),
        _ => None,
    }
}

/// The `--flag` a word starts with (`--gridmap`, from `--gridmap=on` or `--resolution`).
fn flag_of(word: &str) -> Option<&str> {
    let name = word.strip_prefix("--")?;
    let end = name
        .find(|c: char| !(c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'))
        .unwrap_or(name.len());
    let name = name[..end].trim_end_matches('-');
    name.starts_with(|c: char| c.is_ascii_lowercase())
        .then_some(&word[..2 + name.len()])
}

fn words(unit: &str) -> Vec<&str> {
    unit.split(|c: char| c.is_whitespace() || "[](){}|,;\"'<>`".contains(c))
        .filter(|w| !w.is_empty())
        .collect()
}

/// The command that `words[0]` starts, consuming the subcommand words after it; returns it and
/// the number of words taken.
fn command_at(
    words: &[&str],
    subcommands: &mut dyn FnMut(Bin, &[String]) -> Vec<String>,
) -> Option<(Owner, usize)> {
    let bin = command_word(words.first()?)?;
    let mut path = Vec::new();
    for word in &words[1..] {
        if !subcommands(bin, &path).iter().any(|s| s == word) {
            break;
        }
        path.push((*word).to_owned());
    }
    let taken = 1 + path.len();
    Some((Owner::Command(bin, path), taken))
}

/// Every `--flag` of `text` with its owner (module docs), `default` being the document's command.
fn attributed_flags(
    text: &str,
    default: &Owner,
    subcommands: &mut dyn FnMut(Bin, &[String]) -> Vec<String>,
) -> Vec<(Owner, String)> {
    let mut out = Vec::new();
    let mut sections: Vec<(usize, Owner)> = Vec::new();
    // The owner at the end of the previous code line, for the lines that continue it: those that
    // start with a flag, and those after a line ending in `\\`.
    let mut previous_line: Option<Owner> = None;
    let mut previous_backslash = false;
    for piece in pieces(text) {
        let section = sections.last().map_or(default, |(_, owner)| owner).clone();
        let (unit, continued) = match piece {
            Piece::Heading(level, heading) => {
                sections.retain(|(l, _)| *l < level);
                let w = words(heading);
                if let Some((owner, _)) =
                    (0..w.len()).find_map(|i| command_at(&w[i..], subcommands))
                {
                    sections.push((level, owner));
                }
                previous_line = None;
                continue;
            }
            Piece::Prose(_) => {
                previous_line = None;
                continue;
            }
            Piece::Span(span) => (span, None),
            Piece::CodeLine(line) => (line, previous_line.take()),
        };
        let continued_by_backslash = matches!(piece, Piece::CodeLine(_)) && previous_backslash;
        previous_backslash = false;
        let mut w = words(unit);
        // A prompt and environment assignments (`$ RUST_LOG=phygap=debug phygap …`).
        while w
            .first()
            .is_some_and(|f| *f == "$" || (f.contains('=') && !f.starts_with('-')))
        {
            w.remove(0);
        }
        let ends_with_backslash = unit.trim_end().ends_with('\\');
        let Some(first) = w.first() else {
            previous_line = continued;
            continue;
        };
        let (mut owner, mut i) = if first.starts_with('-') || continued_by_backslash {
            (continued.unwrap_or(section), 0)
        } else if let Some((owner, taken)) = command_at(&w, subcommands) {
            (owner, taken)
        } else {
            (Owner::Foreign, 1)
        };
        // Another program's line names no flag of ours, even with our name in it
        // (`cargo run -p phygap-api -- openapi --out …`).
        if owner != Owner::Foreign {
            while i < w.len() {
                if let Some((next, taken)) = command_at(&w[i..], subcommands) {
                    owner = next;
                    i += taken;
                    continue;
                }
                if let Some(flag) = flag_of(w[i]) {
                    out.push((owner.clone(), flag.to_owned()));
                }
                i += 1;
            }
        }
        if matches!(piece, Piece::CodeLine(_)) {
            previous_line = Some(owner);
            previous_backslash = ends_with_backslash;
        }
    }
    out
}

/// A binary's help texts by subcommand path, each read once.
struct Help {
    exe: PathBuf,
    texts: BTreeMap<Vec<String>, Option<String>>,
}

impl Help {
    fn new(exe: PathBuf) -> Self {
        Help {
            exe,
            texts: BTreeMap::new(),
        }
    }

    /// `exe PATH… --help`, or `None` where that is not a command.
    fn text(&mut self, path: &[String]) -> Option<&str> {
        let exe = &self.exe;
        self.texts
            .entry(path.to_vec())
            .or_insert_with(|| {
                let output = Command::new(exe)
                    .args(path)
                    .arg("--help")
                    .env("NO_COLOR", "1")
                    .output()
                    .unwrap_or_else(|e| panic!("{}: {e}", exe.display()));
                output
                    .status
                    .success()
                    .then(|| String::from_utf8_lossy(&output.stdout).into_owned())
            })
            .as_deref()
    }

    /// The subcommands listed under `Commands:` in the help of `path`.
    fn subcommands(&mut self, path: &[String]) -> Vec<String> {
        let Some(text) = self.text(path) else {
            return Vec::new();
        };
        text.lines()
            .skip_while(|l| l.trim() != "Commands:")
            .skip(1)
            .take_while(|l| !l.trim().is_empty())
            .filter_map(|l| l.split_whitespace().next())
            .filter(|name| *name != "help")
            .map(String::from)
            .collect()
    }

    /// The flags the help of `path` names; with an empty path, those of every subcommand too.
    fn flags(&mut self, path: &[String]) -> Option<BTreeSet<String>> {
        let text = self.text(path)?.to_owned();
        let mut flags: BTreeSet<String> = words(&text)
            .into_iter()
            .filter_map(flag_of)
            .map(String::from)
            .collect();
        if path.is_empty() {
            let mut pending: Vec<Vec<String>> = vec![Vec::new()];
            while let Some(parent) = pending.pop() {
                for sub in self.subcommands(&parent) {
                    let mut child = parent.clone();
                    child.push(sub);
                    let text = self.text(&child).unwrap_or_default().to_owned();
                    flags.extend(
                        words(&text)
                            .into_iter()
                            .filter_map(flag_of)
                            .map(String::from),
                    );
                    pending.push(child);
                }
            }
        }
        Some(flags)
    }
}

/// `phygap-api`, built beside `phygap` by the workspace (`cargo test --release --workspace`).
fn api_exe() -> Option<PathBuf> {
    let exe = Path::new(env!("CARGO_BIN_EXE_phygap"))
        .with_file_name(format!("phygap-api{}", std::env::consts::EXE_SUFFIX));
    exe.is_file().then_some(exe)
}

#[test]
fn every_flag_the_docs_name_exists_in_the_binaries_help() {
    let mut helps = BTreeMap::from([(Bin::Phygap, Help::new(env!("CARGO_BIN_EXE_phygap").into()))]);
    match api_exe() {
        Some(exe) => {
            helps.insert(Bin::Api, Help::new(exe));
        }
        None if std::env::var("CI").is_ok_and(|v| v == "true") => {
            panic!("phygap-api is not built beside phygap (cargo test --release --workspace)")
        }
        None => eprintln!(
            "skipping phygap-api's flags: it is not built beside phygap \
             (cargo build --release -p phygap-api)"
        ),
    }
    let mut checked = BTreeMap::<Bin, usize>::new();
    let mut unknown = Vec::new();
    for (doc, text) in documents() {
        // Another engineer's page, with other programs' flags.
        if doc == Path::new("docs/python-client.md") {
            continue;
        }
        let default = match doc.to_str() {
            Some("docs/service.md") => Owner::Command(Bin::Api, Vec::new()),
            _ => Owner::Command(Bin::Phygap, Vec::new()),
        };
        let mut subcommands = |bin: Bin, path: &[String]| {
            helps
                .get_mut(&bin)
                .map_or_else(Vec::new, |h| h.subcommands(path))
        };
        let flags = attributed_flags(&text, &default, &mut subcommands);
        for (owner, flag) in flags {
            let Owner::Command(bin, path) = owner else {
                continue;
            };
            let Some(help) = helps.get_mut(&bin) else {
                continue;
            };
            *checked.entry(bin).or_default() += 1;
            let command = std::iter::once(match bin {
                Bin::Phygap => "phygap",
                Bin::Api => "phygap-api",
            })
            .chain(path.iter().map(String::as_str))
            .collect::<Vec<_>>()
            .join(" ");
            match help.flags(&path) {
                None => unknown.push(format!("{}: `{command}` is not a command", doc.display())),
                Some(known) if !known.contains(&flag) => unknown.push(format!(
                    "{}: `{command} --help` does not list {flag}",
                    doc.display()
                )),
                Some(_) => {}
            }
        }
    }
    eprintln!("flags checked: {checked:?}");
    assert!(
        checked.get(&Bin::Phygap).copied().unwrap_or(0) > 50,
        "found only {checked:?} flags"
    );
    if helps.contains_key(&Bin::Api) {
        assert!(
            checked.get(&Bin::Api).copied().unwrap_or(0) > 20,
            "found only {checked:?} flags"
        );
    }
    unknown.sort();
    unknown.dedup();
    assert!(
        unknown.is_empty(),
        "documented flags the binaries lack: {unknown:#?}"
    );
}

#[test]
fn flags_belong_to_the_command_before_them_or_to_the_section() {
    let text = "\
Intro `--backend gpu`, `cargo test --release` and `curl --data-binary @x`.\n\
## `phygap train`\n\
Takes `--iterations N`; `phygap eval --resolution full` and `phygap-api serve\n\
--token T`.\n\
### Working resolution\n\
`--resolution auto`\n\
```\n\
$ phygap bench quality CAPTURE --json\n\
             [--out MODEL]\n\
cargo run --release -p phygap-api -- openapi --out x\n\
```\n\
## Other\n\
`--config FILE`\n";
    let mut subcommands = |bin: Bin, path: &[String]| -> Vec<String> {
        match (bin, path) {
            (Bin::Phygap, []) => vec!["train".into(), "eval".into(), "bench".into()],
            (Bin::Phygap, [b]) if b == "bench" => vec!["quality".into()],
            (Bin::Api, []) => vec!["serve".into()],
            _ => Vec::new(),
        }
    };
    let phygap =
        |path: &[&str]| Owner::Command(Bin::Phygap, path.iter().map(|s| s.to_string()).collect());
    let found = attributed_flags(text, &phygap(&[]), &mut subcommands);
    let expected: Vec<(Owner, String)> = [
        (phygap(&[]), "--backend"),
        (phygap(&["train"]), "--iterations"),
        (phygap(&["eval"]), "--resolution"),
        (Owner::Command(Bin::Api, vec!["serve".into()]), "--token"),
        (phygap(&["train"]), "--resolution"),
        (phygap(&["bench", "quality"]), "--json"),
        (phygap(&["bench", "quality"]), "--out"),
        (phygap(&[]), "--config"),
    ]
    .into_iter()
    .map(|(o, f)| (o, f.to_owned()))
    .collect();
    assert_eq!(found, expected);
    assert_eq!(flag_of("--gridmap=on"), Some("--gridmap"));
    assert_eq!(flag_of("--"), None);
    assert_eq!(flag_of("--iterations…"), Some("--iterations"));
}

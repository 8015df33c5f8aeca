//! The data dir's folders walked as the files in them, named by their `/`-separated paths: what
//! artifact storage publishes and lists, and what the object store uploads of a folder.

use std::path::{Path, PathBuf};

/// Appends every file under `dir` (recursively) to `out`, named by its `/`-separated path below
/// `dir` with `prefix` before it.
pub fn walk_files(
    dir: &Path,
    prefix: &str,
    out: &mut Vec<(String, PathBuf)>,
) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let file_name = entry.file_name().to_string_lossy().into_owned();
        let name = if prefix.is_empty() {
            file_name
        } else {
            format!("{prefix}/{file_name}")
        };
        let kind = entry.file_type()?;
        if kind.is_dir() {
            walk_files(&entry.path(), &name, out)?;
        } else if kind.is_file() {
            out.push((name, entry.path()));
        }
    }
    Ok(())
}

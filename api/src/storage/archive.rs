//! Safe extraction of uploaded capture archives (`.zip`, `.tar`). Untrusted input: every entry
//! path must be relative and stay inside the target (no `..`, no absolute or drive paths, no
//! backslashes); links, devices and sparse files are refused; the entry count, the total
//! uncompressed size and the compression ratio are bounded while bytes are written (declared sizes
//! are not trusted), so a decompression bomb stops early. The caller owns the target folder and
//! removes it on error.

use std::fs::{File, OpenOptions};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use phygap::io::capture;
use thiserror::Error;

/// Bounds on what an archive may expand to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExtractLimits {
    /// Most entries (files and folders).
    pub max_entries: usize,
    /// Most bytes written in total.
    pub max_total_bytes: u64,
    /// Most uncompressed bytes per compressed byte, for the archive and for each zip entry
    /// (applied past the first MiB, so small, very compressible files pass).
    pub max_ratio: u64,
}

impl Default for ExtractLimits {
    fn default() -> Self {
        ExtractLimits {
            max_entries: 20_000,
            max_total_bytes: 16 << 30,
            max_ratio: 200,
        }
    }
}

/// Why an archive was refused.
#[derive(Debug, Error)]
pub enum ArchiveError {
    #[error("unsupported archive format: {0}")]
    UnknownFormat(String),
    #[error("corrupt archive: {0}")]
    Corrupt(String),
    #[error("unsafe archive entry `{entry}`: {reason}")]
    Unsafe { entry: String, reason: String },
    #[error("archive too large: {0}")]
    TooLarge(String),
    #[error("I/O error on `{path}`: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// The container formats accepted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArchiveFormat {
    Zip,
    Tar,
}

const RATIO_GRACE_BYTES: u64 = 1 << 20;

/// Longest file or folder name in an entry's path (what Linux file systems store).
const MAX_NAME_BYTES: usize = 255;

/// Recognizes the format from the first 512 bytes.
pub fn sniff(head: &[u8]) -> Result<ArchiveFormat, ArchiveError> {
    if head.starts_with(b"PK\x03\x04") || head.starts_with(b"PK\x05\x06") {
        Ok(ArchiveFormat::Zip)
    } else if head.len() >= 262 && &head[257..262] == b"ustar" {
        Ok(ArchiveFormat::Tar)
    } else if head.starts_with(&[0x1f, 0x8b]) {
        Err(ArchiveError::UnknownFormat(
            "gzip-compressed data; upload a plain .tar or a .zip".into(),
        ))
    } else {
        Err(ArchiveError::UnknownFormat(
            "expected a .zip or a POSIX .tar archive".into(),
        ))
    }
}

/// Checks an entry name and turns it into a relative path (`None`: an entry to skip, such as the
/// `__MACOSX/` metadata folder or `./`).
fn safe_relative_path(name: &str) -> Result<Option<PathBuf>, ArchiveError> {
    let unsafe_entry = |reason: &str| ArchiveError::Unsafe {
        entry: name.chars().take(200).collect(),
        reason: reason.to_owned(),
    };
    if name.starts_with('/') {
        return Err(unsafe_entry("absolute path"));
    }
    if name.contains('\\') {
        return Err(unsafe_entry("backslash in path"));
    }
    if name.contains('\0') || name.len() > 1024 {
        return Err(unsafe_entry("malformed path"));
    }
    let mut path = PathBuf::new();
    let mut depth = 0;
    for (i, segment) in name.split('/').enumerate() {
        match segment {
            "" | "." => continue,
            ".." => return Err(unsafe_entry("path traversal (`..`)")),
            s if i == 0 && s.len() == 2 && s.ends_with(':') => {
                return Err(unsafe_entry("absolute path (drive letter)"))
            }
            "__MACOSX" if i == 0 => return Ok(None),
            s if s.len() > MAX_NAME_BYTES => {
                return Err(unsafe_entry(&format!(
                    "a file or folder name of {} bytes (at most {MAX_NAME_BYTES})",
                    s.len()
                )))
            }
            s => {
                depth += 1;
                path.push(s);
            }
        }
    }
    if depth > 32 {
        return Err(unsafe_entry("path nested too deeply"));
    }
    Ok((depth > 0).then_some(path))
}

/// Running totals of one extraction.
struct Budget {
    limits: ExtractLimits,
    archive_len: u64,
    entries: usize,
    written: u64,
}

impl Budget {
    fn count_entry(&mut self) -> Result<(), ArchiveError> {
        self.entries += 1;
        if self.entries > self.limits.max_entries {
            return Err(ArchiveError::TooLarge(format!(
                "more than {} entries",
                self.limits.max_entries
            )));
        }
        Ok(())
    }

    /// Copies `reader` into a new file at `target`; `compressed` is the entry's compressed size
    /// when the format has one (zip).
    fn write_file(
        &mut self,
        reader: &mut dyn Read,
        target: &Path,
        entry: &str,
        compressed: Option<u64>,
    ) -> Result<(), ArchiveError> {
        let io = |source| ArchiveError::Io {
            path: target.to_owned(),
            source,
        };
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent).map_err(io)?;
        }
        let mut file = OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(target)
            .map_err(|e| {
                if e.kind() == std::io::ErrorKind::AlreadyExists {
                    ArchiveError::Unsafe {
                        entry: entry.to_owned(),
                        reason: "duplicate entry".into(),
                    }
                } else {
                    ArchiveError::Io {
                        path: target.to_owned(),
                        source: e,
                    }
                }
            })?;
        let ratio = self.limits.max_ratio;
        let entry_cap = compressed.map(|c| c.saturating_mul(ratio).max(RATIO_GRACE_BYTES));
        let archive_cap = self
            .archive_len
            .saturating_mul(ratio)
            .max(RATIO_GRACE_BYTES);
        let mut entry_written = 0u64;
        let mut buffer = vec![0u8; 64 * 1024];
        loop {
            let n = reader
                .read(&mut buffer)
                .map_err(|e| ArchiveError::Corrupt(format!("reading entry `{entry}`: {e}")))?;
            if n == 0 {
                break;
            }
            entry_written += n as u64;
            self.written += n as u64;
            if self.written > self.limits.max_total_bytes {
                return Err(ArchiveError::TooLarge(format!(
                    "expands to more than {} bytes",
                    self.limits.max_total_bytes
                )));
            }
            if entry_cap.is_some_and(|cap| entry_written > cap) || self.written > archive_cap {
                return Err(ArchiveError::TooLarge(format!(
                    "entry `{entry}` expands more than {ratio}x (decompression bomb)"
                )));
            }
            file.write_all(&buffer[..n]).map_err(io)?;
        }
        file.flush().map_err(io)?;
        Ok(())
    }
}

fn open_archive(path: &Path) -> Result<(File, u64, ArchiveFormat), ArchiveError> {
    let io = |source| ArchiveError::Io {
        path: path.to_owned(),
        source,
    };
    let mut file = File::open(path).map_err(io)?;
    let len = file.metadata().map_err(io)?.len();
    let mut head = Vec::with_capacity(512);
    (&mut file).take(512).read_to_end(&mut head).map_err(io)?;
    let format = sniff(&head)?;
    let file = File::open(path).map_err(io)?;
    Ok((file, len, format))
}

/// Extracts the archive at `archive` into the (empty or new) folder `target` and returns the
/// capture root: `target`, or its single top-level folder when that holds the capture
/// (`transforms.json` or a COLMAP model in `sparse/0/` or `sparse/`).
pub fn extract(
    archive: &Path,
    target: &Path,
    limits: &ExtractLimits,
) -> Result<PathBuf, ArchiveError> {
    let (file, archive_len, format) = open_archive(archive)?;
    std::fs::create_dir_all(target).map_err(|source| ArchiveError::Io {
        path: target.to_owned(),
        source,
    })?;
    let mut budget = Budget {
        limits: *limits,
        archive_len,
        entries: 0,
        written: 0,
    };
    match format {
        ArchiveFormat::Zip => extract_zip(file, target, &mut budget)?,
        ArchiveFormat::Tar => extract_tar(file, target, &mut budget)?,
    }
    Ok(capture_root(target))
}

fn extract_zip(file: File, target: &Path, budget: &mut Budget) -> Result<(), ArchiveError> {
    let mut zip =
        zip::ZipArchive::new(file).map_err(|e| ArchiveError::Corrupt(format!("zip: {e}")))?;
    if zip.len() > budget.limits.max_entries {
        return Err(ArchiveError::TooLarge(format!(
            "{} entries (at most {})",
            zip.len(),
            budget.limits.max_entries
        )));
    }
    for index in 0..zip.len() {
        let mut entry = zip
            .by_index(index)
            .map_err(|e| ArchiveError::Corrupt(format!("zip entry {index}: {e}")))?;
        let name = entry.name().to_owned();
        budget.count_entry()?;
        let Some(relative) = safe_relative_path(&name)? else {
            continue;
        };
        if entry.is_symlink() {
            return Err(ArchiveError::Unsafe {
                entry: name,
                reason: "links are not allowed".into(),
            });
        }
        let path = target.join(&relative);
        if entry.is_dir() {
            std::fs::create_dir_all(&path).map_err(|source| ArchiveError::Io { path, source })?;
        } else if entry.is_file() {
            let compressed = entry.compressed_size();
            budget.write_file(&mut entry, &path, &name, Some(compressed))?;
        } else {
            return Err(ArchiveError::Unsafe {
                entry: name,
                reason: "only regular files and folders are allowed".into(),
            });
        }
    }
    Ok(())
}

fn extract_tar(file: File, target: &Path, budget: &mut Budget) -> Result<(), ArchiveError> {
    let mut tar = tar::Archive::new(file);
    let entries = tar
        .entries()
        .map_err(|e| ArchiveError::Corrupt(format!("tar: {e}")))?;
    for entry in entries {
        let mut entry = entry.map_err(|e| ArchiveError::Corrupt(format!("tar: {e}")))?;
        budget.count_entry()?;
        let raw_path = entry
            .path()
            .map_err(|e| ArchiveError::Corrupt(format!("tar entry path: {e}")))?;
        let name = raw_path
            .to_str()
            .ok_or_else(|| ArchiveError::Unsafe {
                entry: raw_path.to_string_lossy().into_owned(),
                reason: "path is not UTF-8".into(),
            })?
            .to_owned();
        let Some(relative) = safe_relative_path(&name)? else {
            continue;
        };
        let path = target.join(&relative);
        let kind = entry.header().entry_type();
        if kind.is_dir() {
            std::fs::create_dir_all(&path).map_err(|source| ArchiveError::Io { path, source })?;
        } else if kind.is_file() || kind == tar::EntryType::Continuous {
            budget.write_file(&mut entry, &path, &name, None)?;
        } else if kind.is_symlink() || kind.is_hard_link() {
            return Err(ArchiveError::Unsafe {
                entry: name,
                reason: "links are not allowed".into(),
            });
        } else if kind.is_pax_global_extensions() || kind.is_pax_local_extensions() {
            continue;
        } else {
            return Err(ArchiveError::Unsafe {
                entry: name,
                reason: format!("entry type {kind:?} is not allowed"),
            });
        }
    }
    Ok(())
}

/// Whether `dir` is the root of a capture: it holds `transforms.json`, a COLMAP model, or the
/// camera file of a dataset layout (IDR/NeuS `cameras*.npz`, LLFF `poses_bounds.npy`).
fn is_capture_root(dir: &Path) -> bool {
    capture::is_capture_folder(dir)
}

fn capture_root(target: &Path) -> PathBuf {
    if is_capture_root(target) {
        return target.to_owned();
    }
    let children: Vec<PathBuf> = std::fs::read_dir(target)
        .map(|dir| dir.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    match children.as_slice() {
        [only] if only.is_dir() && is_capture_root(only) => only.clone(),
        _ => target.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;

    fn zip_bytes(entries: &[(&str, &[u8])]) -> Vec<u8> {
        let mut writer = zip::ZipWriter::new(Cursor::new(Vec::new()));
        let options = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated);
        for (name, data) in entries {
            writer.start_file(*name, options).unwrap();
            writer.write_all(data).unwrap();
        }
        writer.finish().unwrap().into_inner()
    }

    fn extract_bytes(
        bytes: &[u8],
        limits: ExtractLimits,
    ) -> (tempfile::TempDir, Result<PathBuf, ArchiveError>) {
        let dir = tempfile::tempdir().unwrap();
        let archive = dir.path().join("upload");
        std::fs::write(&archive, bytes).unwrap();
        let result = extract(&archive, &dir.path().join("out"), &limits);
        (dir, result)
    }

    #[test]
    fn entry_paths_are_checked() {
        assert_eq!(
            safe_relative_path("a/./b.json").unwrap(),
            Some(PathBuf::from("a/b.json"))
        );
        assert_eq!(safe_relative_path("__MACOSX/._a").unwrap(), None);
        assert_eq!(safe_relative_path("./").unwrap(), None);
        let long_name = format!("capture/{}.exr", "n".repeat(300));
        assert!(safe_relative_path(&format!("a/{}", "n".repeat(255))).is_ok());
        for bad in [
            "../x",
            "a/../../x",
            "/etc/passwd",
            "C:/x",
            "a\\..\\x",
            &long_name,
        ] {
            assert!(
                matches!(safe_relative_path(bad), Err(ArchiveError::Unsafe { .. })),
                "{bad}"
            );
        }
    }

    #[test]
    fn a_colmap_folder_is_a_capture_root() {
        let bytes = zip_bytes(&[
            ("scan/sparse/0/cameras.txt", b"# none"),
            ("scan/raw/a.png", b"xyz"),
        ]);
        let (dir, root) = extract_bytes(&bytes, ExtractLimits::default());
        assert_eq!(root.unwrap(), dir.path().join("out/scan"));
        // Without a model, the folder is not recognised and the archive's top is the root.
        let bytes = zip_bytes(&[("scan/sparse/0/notes.txt", b"-"), ("scan/raw/a.png", b"x")]);
        let (dir, root) = extract_bytes(&bytes, ExtractLimits::default());
        assert_eq!(root.unwrap(), dir.path().join("out"));
    }

    #[test]
    fn an_idr_or_llff_dataset_folder_is_a_capture_root() {
        for camera_file in ["cameras_sphere.npz", "cameras_new.npz", "poses_bounds.npy"] {
            let entry = format!("scan/{camera_file}");
            let bytes = zip_bytes(&[(entry.as_str(), b"-"), ("scan/I-00/000.jpg", b"x")]);
            let (dir, root) = extract_bytes(&bytes, ExtractLimits::default());
            assert_eq!(root.unwrap(), dir.path().join("out/scan"), "{camera_file}");
        }
    }

    #[test]
    fn zip_extracts_into_the_single_top_folder() {
        let bytes = zip_bytes(&[("cap/transforms.json", b"{}"), ("cap/img/a.png", b"xyz")]);
        let (dir, root) = extract_bytes(&bytes, ExtractLimits::default());
        let root = root.unwrap();
        assert_eq!(root, dir.path().join("out/cap"));
        assert_eq!(std::fs::read(root.join("img/a.png")).unwrap(), b"xyz");
    }

    #[test]
    fn zip_traversal_is_refused() {
        let bytes = zip_bytes(&[("ok.txt", b"1"), ("../evil.txt", b"2")]);
        let (dir, result) = extract_bytes(&bytes, ExtractLimits::default());
        assert!(
            matches!(result, Err(ArchiveError::Unsafe { ref reason, .. }) if reason.contains("traversal")),
            "{result:?}"
        );
        assert!(!dir.path().join("evil.txt").exists());
    }

    #[test]
    fn zip_bomb_stops_at_the_ratio_limit() {
        let zeros = vec![0u8; 8 << 20];
        let bytes = zip_bytes(&[("zeros.bin", &zeros)]);
        assert!(bytes.len() < 100_000, "deflate packs zeros tightly");
        let (_dir, result) = extract_bytes(&bytes, ExtractLimits::default());
        assert!(
            matches!(result, Err(ArchiveError::TooLarge(ref m)) if m.contains("bomb")),
            "{result:?}"
        );
        let limits = ExtractLimits {
            max_ratio: 100_000,
            max_total_bytes: 4 << 20,
            ..Default::default()
        };
        let (_dir, result) = extract_bytes(&bytes, limits);
        assert!(
            matches!(result, Err(ArchiveError::TooLarge(ref m)) if m.contains("more than")),
            "{result:?}"
        );
    }

    #[test]
    fn too_many_entries_are_refused() {
        let names: Vec<String> = (0..30).map(|i| format!("f{i}.txt")).collect();
        let entries: Vec<(&str, &[u8])> = names.iter().map(|n| (n.as_str(), &b"x"[..])).collect();
        let limits = ExtractLimits {
            max_entries: 20,
            ..Default::default()
        };
        let (_dir, result) = extract_bytes(&zip_bytes(&entries), limits);
        assert!(
            matches!(result, Err(ArchiveError::TooLarge(ref m)) if m.contains("entries")),
            "{result:?}"
        );
    }

    #[test]
    fn tar_links_and_garbage_are_refused() {
        let mut builder = tar::Builder::new(Vec::new());
        let mut header = tar::Header::new_ustar();
        header.set_entry_type(tar::EntryType::Symlink);
        header.set_size(0);
        builder
            .append_link(&mut header, "link", "/etc/passwd")
            .unwrap();
        let bytes = builder.into_inner().unwrap();
        let (_dir, result) = extract_bytes(&bytes, ExtractLimits::default());
        assert!(
            matches!(result, Err(ArchiveError::Unsafe { ref reason, .. }) if reason.contains("links")),
            "{result:?}"
        );
        let (_dir, result) = extract_bytes(b"definitely not an archive", ExtractLimits::default());
        assert!(
            matches!(result, Err(ArchiveError::UnknownFormat(_))),
            "{result:?}"
        );
        let mut truncated = zip_bytes(&[("a.txt", b"hello hello hello")]);
        truncated.truncate(20);
        let (_dir, result) = extract_bytes(&truncated, ExtractLimits::default());
        assert!(
            matches!(result, Err(ArchiveError::Corrupt(_))),
            "{result:?}"
        );
    }

    #[test]
    fn tar_files_extract() {
        let mut builder = tar::Builder::new(Vec::new());
        let mut header = tar::Header::new_ustar();
        header.set_size(5);
        header.set_mode(0o644);
        header.set_cksum();
        builder
            .append_data(&mut header, "transforms.json", &b"{\"a\"}"[..])
            .unwrap();
        let bytes = builder.into_inner().unwrap();
        let (dir, root) = extract_bytes(&bytes, ExtractLimits::default());
        assert_eq!(root.unwrap(), dir.path().join("out"));
    }
}

//! Checkpoint files: named f64 arrays plus a JSON metadata value, stored bit-exactly.
//!
//! Layout: the magic `PHYGAPCK`, a little-endian u64 header length, a JSON header
//! `{meta, arrays: [{name, len}]}`, then each array as little-endian f64 in header order.
//! Files are written to a temporary name and renamed into place, so a process killed mid-write
//! leaves the previous checkpoint intact.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use thiserror::Error;

const MAGIC: &[u8; 8] = b"PHYGAPCK";

#[derive(Debug, Error)]
pub enum CheckpointError {
    #[error("checkpoint {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("checkpoint {path}: not a phygap checkpoint or truncated ({problem})")]
    Corrupt { path: PathBuf, problem: String },
    #[error("checkpoint {path}: missing array `{name}`")]
    Missing { path: PathBuf, name: String },
}

#[derive(Serialize, Deserialize)]
struct Header {
    meta: serde_json::Value,
    arrays: Vec<ArrayHeader>,
}

#[derive(Serialize, Deserialize)]
struct ArrayHeader {
    name: String,
    len: usize,
}

/// Named arrays and metadata, read from or written to one file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Archive {
    pub meta: serde_json::Value,
    arrays: Vec<(String, Vec<f64>)>,
}

impl Archive {
    pub fn new(meta: serde_json::Value) -> Self {
        Archive {
            meta,
            arrays: Vec::new(),
        }
    }

    /// Adds an array (names should be unique; the first of a name wins on lookup).
    pub fn put(&mut self, name: &str, values: &[f64]) {
        self.arrays.push((name.to_owned(), values.to_vec()));
    }

    /// The array called `name`, if present.
    pub fn get(&self, name: &str) -> Option<&[f64]> {
        self.arrays
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_slice())
    }

    /// Like [`Archive::get`] but an error naming the file when absent.
    pub fn require(&self, path: &Path, name: &str) -> Result<&[f64], CheckpointError> {
        self.get(name).ok_or_else(|| CheckpointError::Missing {
            path: path.to_owned(),
            name: name.to_owned(),
        })
    }

    /// Writes the archive atomically (temporary file + rename).
    pub fn write(&self, path: &Path) -> Result<(), CheckpointError> {
        let io = |source| CheckpointError::Io {
            path: path.to_owned(),
            source,
        };
        let header = Header {
            meta: self.meta.clone(),
            arrays: self
                .arrays
                .iter()
                .map(|(name, v)| ArrayHeader {
                    name: name.clone(),
                    len: v.len(),
                })
                .collect(),
        };
        let header = serde_json::to_vec(&header).expect("a JSON value always serializes");
        let tmp = path.with_extension("tmp");
        {
            let file = std::fs::File::create(&tmp).map_err(io)?;
            let mut out = std::io::BufWriter::new(file);
            out.write_all(MAGIC).map_err(io)?;
            out.write_all(&(header.len() as u64).to_le_bytes())
                .map_err(io)?;
            out.write_all(&header).map_err(io)?;
            for (_, values) in &self.arrays {
                for v in values {
                    out.write_all(&v.to_le_bytes()).map_err(io)?;
                }
            }
            let file = out.into_inner().map_err(|e| io(e.into_error()))?;
            file.sync_all().map_err(io)?;
        }
        std::fs::rename(&tmp, path).map_err(io)
    }

    /// Reads an archive, checking the magic, the header and every array's length.
    pub fn read(path: &Path) -> Result<Self, CheckpointError> {
        let io = |source| CheckpointError::Io {
            path: path.to_owned(),
            source,
        };
        let corrupt = |problem: &str| CheckpointError::Corrupt {
            path: path.to_owned(),
            problem: problem.to_owned(),
        };
        let mut bytes = Vec::new();
        std::fs::File::open(path)
            .and_then(|mut f| f.read_to_end(&mut bytes))
            .map_err(io)?;
        if bytes.len() < 16 || &bytes[..8] != MAGIC {
            return Err(corrupt("bad magic"));
        }
        let header_len = u64::from_le_bytes(bytes[8..16].try_into().expect("8 bytes")) as usize;
        let body = bytes
            .get(16..16usize.saturating_add(header_len))
            .ok_or_else(|| corrupt("header past end of file"))?;
        let header: Header =
            serde_json::from_slice(body).map_err(|e| corrupt(&format!("header: {e}")))?;
        let mut offset = 16 + header_len;
        let mut arrays = Vec::with_capacity(header.arrays.len());
        for a in header.arrays {
            let end = a
                .len
                .checked_mul(8)
                .and_then(|n| n.checked_add(offset))
                .filter(|&end| end <= bytes.len())
                .ok_or_else(|| corrupt(&format!("array `{}` past end of file", a.name)))?;
            let values = bytes[offset..end]
                .chunks_exact(8)
                .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
                .collect();
            arrays.push((a.name, values));
            offset = end;
        }
        if offset != bytes.len() {
            return Err(corrupt("trailing bytes"));
        }
        Ok(Archive {
            meta: header.meta,
            arrays,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_bit_exact() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("state.ckpt");
        let mut a = Archive::new(serde_json::json!({"iteration": 42}));
        let tricky = [0.1 + 0.2, -0.0, f64::MIN_POSITIVE, 1e300, -7.5];
        a.put("x", &tricky);
        a.put("empty", &[]);
        a.write(&path).unwrap();
        let b = Archive::read(&path).unwrap();
        assert_eq!(b.meta["iteration"], 42);
        let x = b.get("x").unwrap();
        assert!(x
            .iter()
            .zip(&tricky)
            .all(|(p, q)| p.to_bits() == q.to_bits()));
        assert_eq!(b.get("empty").unwrap().len(), 0);
        assert!(matches!(
            b.require(&path, "nope"),
            Err(CheckpointError::Missing { .. })
        ));
    }

    #[test]
    fn truncated_and_foreign_files_are_rejected() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("state.ckpt");
        let mut a = Archive::new(serde_json::json!(null));
        a.put("x", &[1.0, 2.0, 3.0]);
        a.write(&path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        std::fs::write(&path, &bytes[..bytes.len() - 4]).unwrap();
        assert!(matches!(
            Archive::read(&path),
            Err(CheckpointError::Corrupt { .. })
        ));
        std::fs::write(&path, b"hello world, not a checkpoint").unwrap();
        assert!(matches!(
            Archive::read(&path),
            Err(CheckpointError::Corrupt { .. })
        ));
    }
}

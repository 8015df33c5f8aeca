//! Errors of capture loading. Validation collects every [`Problem`] it finds (frame, key, what is
//! wrong) into one [`CaptureError::Invalid`], so a user fixes a capture in one round.

use std::fmt;
use std::path::PathBuf;

use thiserror::Error;

/// One rule of CAPTURE_FORMAT.md §3 broken by one frame (or by the top level).
#[derive(Clone, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct Problem {
    /// The frame, e.g. `frame 3 (train/s0/003.exr)`, or `top level` for keys outside `frames`.
    pub frame: String,
    /// The JSON key at fault, e.g. `s1_path`.
    pub key: String,
    /// What is wrong.
    pub message: String,
}

impl Problem {
    pub fn new(
        frame: impl Into<String>,
        key: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        Problem {
            frame: frame.into(),
            key: key.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}, key `{}`: {}", self.frame, self.key, self.message)
    }
}

/// How many problems [`CaptureError::Invalid`] spells out before summarizing the rest.
const PROBLEMS_SHOWN: usize = 8;

fn describe_problems(path: &std::path::Path, problems: &[Problem]) -> String {
    let shown: Vec<String> = problems
        .iter()
        .take(PROBLEMS_SHOWN)
        .map(Problem::to_string)
        .collect();
    let mut text = if problems.len() == 1 {
        format!("invalid capture {}: {}", path.display(), shown[0])
    } else {
        format!(
            "invalid capture {} ({} problems): {}",
            path.display(),
            problems.len(),
            shown.join("; ")
        )
    };
    if problems.len() > PROBLEMS_SHOWN {
        text.push_str(&format!("; … and {} more", problems.len() - PROBLEMS_SHOWN));
    }
    text
}

/// Why a capture could not be loaded. Nothing is half-imported: any error rejects the whole capture.
#[derive(Debug, Error)]
pub enum CaptureError {
    /// The capture folder or its JSON file cannot be read.
    #[error("cannot read capture {path}: {message}")]
    Read { path: PathBuf, message: String },
    /// The JSON file is not valid JSON.
    #[error("malformed JSON in {path} at line {line}, column {column}: {message}")]
    Json {
        path: PathBuf,
        line: usize,
        column: usize,
        message: String,
    },
    /// The capture breaks one or more rules; every problem found is listed.
    #[error("{}", describe_problems(.path, .problems))]
    Invalid {
        /// The JSON file.
        path: PathBuf,
        problems: Vec<Problem>,
    },
    /// The COLMAP model of a capture folder cannot be read (`colmap/`).
    #[error(transparent)]
    Colmap(#[from] ColmapError),
    /// The capture declares more than its [`CaptureLimits`](super::CaptureLimits) allow; no
    /// image was read.
    #[error("{path} is over a limit: {}", .exceeded.message)]
    TooLarge {
        path: PathBuf,
        exceeded: LimitExceeded,
    },
}

impl CaptureError {
    /// The individual problems (empty for read and JSON syntax errors).
    pub fn problems(&self) -> &[Problem] {
        match self {
            CaptureError::Invalid { problems, .. } => problems,
            _ => &[],
        }
    }
}

/// Why a COLMAP model could not be read.
#[derive(Debug, Error)]
pub enum ColmapError {
    #[error("cannot read {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error(
        "{path} is truncated: {what} needs bytes from byte {offset}, but the file ends at {len}"
    )]
    Truncated {
        path: PathBuf,
        what: String,
        offset: usize,
        len: usize,
    },
    #[error("{path}, line {line}: {message}")]
    Text {
        path: PathBuf,
        line: usize,
        message: String,
    },
    #[error("{path}: camera {camera} has the unknown camera model {model}")]
    UnknownModel {
        path: PathBuf,
        camera: i32,
        model: String,
    },
    #[error("{path}: {message}")]
    Malformed { path: PathBuf, message: String },
}

/// A capture over its [`CaptureLimits`]: which limit, its value, and what the capture declares.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LimitExceeded {
    /// The limit's name: `max_views`, `max_pixels_per_view` or `max_decoded_bytes`.
    pub limit: &'static str,
    /// What the capture needs.
    pub needed: u64,
    /// What the limit allows.
    pub allowed: u64,
    /// For people: what is over, and by how much.
    pub message: String,
}

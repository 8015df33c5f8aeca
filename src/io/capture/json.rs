//! Reading `transforms.json` values with precise complaints: typed getters that record a
//! [`Problem`] (frame, key, what is wrong) instead of failing, so validation reports every problem.
//!
//! Python's `json.dump` writes non-finite floats as bare `NaN` / `Infinity`, which is not JSON;
//! [`parse_lenient`] turns them into strings so the getters can say "non-finite value" with the key.

use std::path::{Component, Path, PathBuf};

use glam::DMat4;
use serde_json::{Map, Value};

use super::error::{CaptureError, Problem};

/// The frame label of problems with top-level keys.
pub(crate) const TOP_LEVEL: &str = "top level";

/// A file named by a key, relative path as written and path joined to the capture folder.
#[derive(Clone, Debug)]
pub(crate) struct KeyedPath {
    pub key: &'static str,
    pub relative: PathBuf,
    pub path: PathBuf,
}

/// Bare non-finite tokens accepted by [`parse_lenient`] and reported by [`Fields::number`].
const NON_FINITE_TOKENS: [&str; 3] = ["-Infinity", "Infinity", "NaN"];

/// The top-level object of the optional JSON file `name` in `root` (a folder's `capture.json`):
/// `None` when there is no such file, or when it holds something else than an object (recorded in
/// `problems`); an error when it cannot be read or parsed.
pub(crate) fn read_optional_object(
    root: &Path,
    name: &str,
    problems: &mut Vec<Problem>,
) -> Result<Option<Map<String, Value>>, CaptureError> {
    let path = root.join(name);
    if !path.is_file() {
        return Ok(None);
    }
    let text = std::fs::read_to_string(&path).map_err(|e| CaptureError::Read {
        path: path.clone(),
        message: e.to_string(),
    })?;
    let value = parse_lenient(&text).map_err(|e| CaptureError::Json {
        path: path.clone(),
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
    })?;
    match value {
        Value::Object(object) => Ok(Some(object)),
        _ => {
            problems.push(Problem::new(name, "(document)", "expected a JSON object"));
            Ok(None)
        }
    }
}

/// Parses JSON, first quoting bare `NaN`, `Infinity` and `-Infinity` outside strings
/// (line numbers of errors are unchanged).
pub(crate) fn parse_lenient(text: &str) -> Result<Value, serde_json::Error> {
    let mut out = String::with_capacity(text.len() + 16);
    let mut in_string = false;
    let mut escaped = false;
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if in_string {
            if escaped {
                escaped = false;
            } else if c == '\\' {
                escaped = true;
            } else if c == '"' {
                in_string = false;
            }
        } else if c == '"' {
            in_string = true;
        } else if let Some(token) = NON_FINITE_TOKENS.iter().find(|t| rest.starts_with(**t)) {
            let preceded_by_word = out
                .chars()
                .next_back()
                .is_some_and(|p| p.is_alphanumeric() || p == '_');
            if !preceded_by_word {
                out.push('"');
                out.push_str(token);
                out.push('"');
                rest = &rest[token.len()..];
                continue;
            }
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    serde_json::from_str(&out)
}

/// The keys of one JSON object, read on behalf of one frame (or the top level).
pub(crate) struct Fields<'a> {
    pub object: &'a Map<String, Value>,
    pub frame: String,
}

impl<'a> Fields<'a> {
    pub fn new(object: &'a Map<String, Value>, frame: impl Into<String>) -> Self {
        Fields {
            object,
            frame: frame.into(),
        }
    }

    pub fn has(&self, key: &str) -> bool {
        self.object.contains_key(key)
    }

    pub fn problem(&self, key: &str, message: impl Into<String>) -> Problem {
        Problem::new(self.frame.clone(), key, message)
    }

    /// A finite number, or `None` when absent (nothing recorded) or invalid (problem recorded).
    pub fn number(&self, key: &str, problems: &mut Vec<Problem>) -> Option<f64> {
        let value = self.object.get(key)?;
        match number_value(value) {
            Ok(v) => Some(v),
            Err(message) => {
                problems.push(self.problem(key, message));
                None
            }
        }
    }

    /// A positive integer (image sizes).
    pub fn positive_int(&self, key: &str, problems: &mut Vec<Problem>) -> Option<u32> {
        let v = self.number(key, problems)?;
        if v >= 1.0 && v.fract() == 0.0 && v <= u32::MAX as f64 {
            Some(v as u32)
        } else {
            problems.push(self.problem(key, format!("expected a positive integer, found {v}")));
            None
        }
    }

    /// A string, or `None` when absent or not a string (problem recorded).
    pub fn string(&self, key: &str, problems: &mut Vec<Problem>) -> Option<&'a str> {
        match self.object.get(key)? {
            Value::String(s) => Some(s),
            other => {
                problems.push(self.problem(key, format!("expected a string, found {other}")));
                None
            }
        }
    }

    /// A relative file path that stays inside the capture folder.
    pub fn path(&self, key: &str, problems: &mut Vec<Problem>) -> Option<PathBuf> {
        let text = self.string(key, problems)?;
        match check_relative_path(text) {
            Ok(path) => Some(path),
            Err(message) => {
                problems.push(self.problem(key, message));
                None
            }
        }
    }

    /// A 4×4 matrix given as 4 rows of 4 finite numbers.
    pub fn matrix4(&self, key: &str, problems: &mut Vec<Problem>) -> Option<DMat4> {
        let value = self.object.get(key)?;
        match matrix_value(value) {
            Ok(m) => Some(m),
            Err(message) => {
                problems.push(self.problem(key, message));
                None
            }
        }
    }
}

fn number_value(value: &Value) -> Result<f64, String> {
    match value {
        Value::Number(n) => n
            .as_f64()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("non-finite value {n}")),
        Value::String(s) if NON_FINITE_TOKENS.contains(&s.as_str()) => {
            Err(format!("non-finite value {s}"))
        }
        other => Err(format!("expected a number, found {other}")),
    }
}

fn matrix_value(value: &Value) -> Result<DMat4, String> {
    let shape_error = || "expected 4 rows of 4 numbers (row-major 4×4 matrix)".to_string();
    let rows = value
        .as_array()
        .filter(|r| r.len() == 4)
        .ok_or_else(shape_error)?;
    let mut m = [[0.0f64; 4]; 4];
    for (r, row) in rows.iter().enumerate() {
        let row = row
            .as_array()
            .filter(|c| c.len() == 4)
            .ok_or_else(shape_error)?;
        for (c, entry) in row.iter().enumerate() {
            m[r][c] = number_value(entry).map_err(|e| format!("row {r}, column {c}: {e}"))?;
        }
    }
    // `from_cols_array_2d` takes columns; the JSON lists rows.
    Ok(DMat4::from_cols_array_2d(&m).transpose())
}

/// Accepts a relative path without `..`, root or drive components.
pub(crate) fn check_relative_path(text: &str) -> Result<PathBuf, String> {
    if text.is_empty() {
        return Err("empty path".into());
    }
    let path = Path::new(text);
    for component in path.components() {
        match component {
            Component::Normal(_) | Component::CurDir => {}
            Component::ParentDir => {
                return Err(format!(
                    "path {text:?} escapes the capture folder (contains `..`)"
                ))
            }
            Component::RootDir | Component::Prefix(_) => {
                return Err(format!(
                    "path {text:?} escapes the capture folder (absolute path)"
                ))
            }
        }
    }
    Ok(path.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bare_non_finite_tokens_become_strings_outside_strings_only() {
        let v =
            parse_lenient(r#"{"a": [NaN, -Infinity, Infinity], "b": "NaN x", "NaNa": 1}"#).unwrap();
        assert_eq!(v["a"][0], Value::String("NaN".into()));
        assert_eq!(v["a"][1], Value::String("-Infinity".into()));
        assert_eq!(v["a"][2], Value::String("Infinity".into()));
        assert_eq!(v["b"], Value::String("NaN x".into()));
        assert_eq!(v["NaNa"], serde_json::json!(1));
        let err = parse_lenient("{\n\"a\": 1,\n}").unwrap_err();
        assert_eq!(err.line(), 3);
    }

    #[test]
    fn paths_must_stay_inside_the_folder() {
        assert!(check_relative_path("train/s0/000.exr").is_ok());
        assert!(check_relative_path("./a.png").is_ok());
        assert!(check_relative_path("../a.png").unwrap_err().contains(".."));
        assert!(check_relative_path("a/../../b.png").is_err());
        assert!(check_relative_path("/etc/passwd")
            .unwrap_err()
            .contains("absolute"));
    }

    #[test]
    fn matrices_are_row_major() {
        let v = serde_json::json!([[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7], [0, 0, 0, 1]]);
        let m = matrix_value(&v).unwrap();
        assert_eq!(m.w_axis.truncate(), glam::DVec3::new(5.0, 6.0, 7.0));
        let bad = serde_json::json!([[1, 0, 0], [0, 1, 0]]);
        assert!(matrix_value(&bad).is_err());
    }
}

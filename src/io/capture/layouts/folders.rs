//! What the folders and files of a dataset layout hold, from their names: the polarizer angle of a
//! per-angle image folder (`I-00` … `I-135`, `pol045`, `45deg`, `0`/`45`/`90`/`135`, any case),
//! the Stokes component of a Stokes folder (`s0`, `images_s1`, `stokes_s2`), mask and plain image
//! folders, and the view number of a file (`000_pseudo.png` and `img_000.exr` are view 0), by
//! which files of different folders are matched.

use std::collections::BTreeMap;
use std::path::Path;

/// The polarizer angles of a full-Stokes polarization camera, in degrees.
pub const ANGLES: [u32; 4] = [0, 45, 90, 135];

/// Words that may stand beside the angle in a per-angle folder's name.
const ANGLE_WORDS: [&str; 14] = [
    "",
    "i",
    "p",
    "a",
    "pol",
    "polar",
    "polarizer",
    "polariser",
    "deg",
    "degree",
    "degrees",
    "angle",
    "img",
    "images",
];

/// Extensions of the files a layout's image folders may hold.
pub const IMAGE_EXTENSIONS: [&str; 7] = ["exr", "hdr", "png", "jpg", "jpeg", "npy", "tif"];

/// The name split into lower-case runs of letters and of digits, separators dropped:
/// `I-135` → `["i", "135"]`, `pol045` → `["pol", "045"]`.
fn tokens(name: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut last_kind = None;
    for c in name.chars() {
        let kind = if c.is_ascii_digit() {
            Some(true)
        } else if c.is_alphabetic() {
            Some(false)
        } else {
            None
        };
        match kind {
            None => last_kind = None,
            Some(k) if last_kind == Some(k) => {
                out.last_mut()
                    .expect("a run in progress")
                    .push(c.to_ascii_lowercase());
            }
            Some(k) => {
                out.push(c.to_ascii_lowercase().to_string());
                last_kind = Some(k);
            }
        }
    }
    out
}

/// The polarizer angle a folder's name gives: one number among 0, 45, 90, 135 and otherwise only
/// the words of a per-angle folder (`I-00`, `pol045`, `45deg`, `135`, `Angle_90`).
pub fn angle_of_folder(name: &str) -> Option<u32> {
    let tokens = tokens(name);
    let numbers: Vec<&String> = tokens
        .iter()
        .filter(|t| t.starts_with(|c: char| c.is_ascii_digit()))
        .collect();
    let [number] = numbers.as_slice() else {
        return None;
    };
    let words_fit = tokens
        .iter()
        .filter(|t| !t.starts_with(|c: char| c.is_ascii_digit()))
        .all(|w| ANGLE_WORDS.contains(&w.as_str()));
    let angle: u32 = number.parse().ok()?;
    (words_fit && ANGLES.contains(&angle)).then_some(angle)
}

/// The Stokes component (0, 1 or 2) a folder's name gives: `s0`, `S1`, `images_s2`, `stokes_s0`.
pub fn stokes_component_of_folder(name: &str) -> Option<usize> {
    let lower = name.to_ascii_lowercase();
    let component = lower
        .strip_suffix('0')
        .map(|r| (r, 0))
        .or_else(|| lower.strip_suffix('1').map(|r| (r, 1)))
        .or_else(|| lower.strip_suffix('2').map(|r| (r, 2)))?;
    let prefix = component.0.strip_suffix('s')?;
    let prefix = prefix.trim_end_matches(['_', '-']);
    ["", "image", "images", "stokes"]
        .contains(&prefix)
        .then_some(component.1)
}

/// Whether a folder holds masks: `mask`, `masks`, `Mask`, `masks_png`.
pub fn is_mask_folder(name: &str) -> bool {
    matches!(
        tokens(name).first().map(String::as_str),
        Some("mask" | "masks")
    )
}

/// Whether a folder holds plain (unpolarized or preview) images: `image`, `images`, `rgb`.
pub fn is_image_folder(name: &str) -> bool {
    matches!(
        name.to_ascii_lowercase().as_str(),
        "image" | "images" | "rgb"
    )
}

/// Whether a folder holds one `.npy` of stacked Stokes components a view: `stokes`.
pub fn is_stacked_stokes_folder(name: &str) -> bool {
    name.eq_ignore_ascii_case("stokes")
}

/// The view number in a file's name: its last run of digits (`000_pseudo.png` → 0,
/// `img_012.exr` → 12, `IMG_2024_0003.jpg` → 3); `None` without digits.
pub fn number_of_file(name: &str) -> Option<u64> {
    let stem = Path::new(name)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or(name);
    tokens(stem)
        .iter()
        .rev()
        .find(|t| t.starts_with(|c: char| c.is_ascii_digit()))
        .and_then(|t| t.parse().ok())
}

/// A file of an image folder with its view number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NumberedFile {
    /// The file name (no folder).
    pub name: String,
    pub number: Option<u64>,
}

/// The image files of `dir` (by extension, hidden files skipped), sorted by view number, then by
/// name (files without a number last).
pub fn image_files(dir: &Path) -> Vec<NumberedFile> {
    let mut files: Vec<NumberedFile> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(Result::ok)
                .filter(|e| e.path().is_file())
                .filter_map(|e| e.file_name().to_str().map(str::to_owned))
                .filter(|name| !name.starts_with('.'))
                .filter(|name| {
                    Path::new(name)
                        .extension()
                        .and_then(|e| e.to_str())
                        .is_some_and(|e| {
                            IMAGE_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str())
                        })
                })
                .map(|name| NumberedFile {
                    number: number_of_file(&name),
                    name,
                })
                .collect()
        })
        .unwrap_or_default();
    files.sort_by(|a, b| {
        (a.number.is_none(), a.number, &a.name).cmp(&(b.number.is_none(), b.number, &b.name))
    });
    files
}

/// The files of a folder by view number (or, for files without one, by stem), to match another
/// folder's file to: the first file of each number wins, later ones are returned as duplicates.
pub struct FileIndex {
    by_number: BTreeMap<u64, String>,
    by_stem: BTreeMap<String, String>,
    pub duplicates: Vec<String>,
}

fn stem(name: &str) -> String {
    Path::new(name)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or(name)
        .to_owned()
}

impl FileIndex {
    pub fn new(files: &[NumberedFile]) -> Self {
        let mut index = FileIndex {
            by_number: BTreeMap::new(),
            by_stem: BTreeMap::new(),
            duplicates: Vec::new(),
        };
        for file in files {
            let fresh = match file.number {
                Some(n) => index.by_number.insert(n, file.name.clone()).is_none(),
                None => index
                    .by_stem
                    .insert(stem(&file.name), file.name.clone())
                    .is_none(),
            };
            if !fresh {
                index.duplicates.push(file.name.clone());
            }
        }
        // The first file of each number is kept (files come sorted by number, then name).
        for file in files.iter().rev() {
            match file.number {
                Some(n) => index.by_number.insert(n, file.name.clone()),
                None => index.by_stem.insert(stem(&file.name), file.name.clone()),
            };
        }
        index
    }

    /// The file matching `file` of another folder: the same view number, or the same stem.
    pub fn matching(&self, file: &NumberedFile) -> Option<&str> {
        match file.number {
            Some(n) => self.by_number.get(&n),
            None => self.by_stem.get(&stem(&file.name)),
        }
        .map(String::as_str)
    }
}

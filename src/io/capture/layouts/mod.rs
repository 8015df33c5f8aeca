//! Captures in the layouts polarization datasets ship, read without a hand-written
//! `transforms.json`: the IDR/NeuS layout (`cameras.npz`, `cameras_sphere.npz` or
//! `cameras_new.npz`: [`idr`]) and the LLFF layout (`poses_bounds.npy`: [`llff`]), with their
//! views in image folders found by name ([`folders`]):
//!
//! - Stokes folders `s0/`, `s1/`, `s2/` (also `images_s0/` …, `stokes_s0/` …) of EXR or `.npy`
//!   images; or `stokes/` with one `.npy` a view of stacked components (H×W×3|4: S0, S1, S2
//!   (S3) of a grey image; H×W×3|4×3: of an RGB one);
//! - else four per-angle folders whose names give 0°, 45°, 90° and 135° (`I-00` … `I-135`,
//!   `pol045`, `45deg`, `45`), 8/16-bit PNG, JPEG, EXR or `.npy` images; a `capture.json` may name
//!   them (`"polarizer_folders": {"0": "a", "45": "b", "90": "c", "135": "d"}`) where the names
//!   say nothing;
//! - else plain RGB images in `image/` or `images/`;
//! - masks in `mask/` or `masks/`, matched to views by the number in their names whatever the
//!   suffix (`masks/000_pseudo.png` is view 0's mask, `masks/img_001.png` that of `img_001.exr`).
//!
//! View k is the k-th file of the first measurement folder in number order (NeuS and LLFF pair
//! cameras and images by sorted name); the other folders' files are matched to it by number.
//! [`import`] builds the equivalent transforms document (OpenGL camera-to-world matrices, each
//! frame with its intrinsics) and a [`LayoutReport`] of what was decided; loading hands the
//! document to the ordinary validation, so every rule and message is that of `transforms.json`.
//! A `capture.json` beside may also give `stokes_convention`, `color_space` and `world_up`.

pub mod folders;
pub mod idr;
pub mod llff;
#[cfg(test)]
mod tests;
pub mod write;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use glam::{DMat4, DVec3};
use serde::Serialize;
use serde_json::{json, Map, Value};

use super::error::Problem;
use super::npy::{self, NpyLimits};
use super::{Capture, CaptureError, LoadOptions};
use crate::core::camera::Camera;
use folders::FileIndex;

/// The settings file a layout folder may hold.
pub const SETTINGS_FILE: &str = "capture.json";

/// Keys of `capture.json` in a layout folder.
const SETTINGS_KEYS: [&str; 4] = [
    "stokes_convention",
    "color_space",
    "world_up",
    "polarizer_folders",
];

/// A camera's mean up direction within this angle of +Z or +Y picks that `world_up`.
const WORLD_UP_TOLERANCE_DEG: f64 = 25.0;

/// Which layout a folder is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LayoutKind {
    /// IDR/NeuS: `cameras*.npz` with `world_mat_i`, `scale_mat_i`.
    Idr,
    /// LLFF: `poses_bounds.npy`.
    Llff,
}

impl LayoutKind {
    pub fn name(self) -> &'static str {
        match self {
            LayoutKind::Idr => "IDR/NeuS",
            LayoutKind::Llff => "LLFF",
        }
    }
}

/// A layout folder and its camera file.
#[derive(Clone, Debug, PartialEq)]
pub struct LayoutLocation {
    pub kind: LayoutKind,
    /// The camera file (`cameras*.npz` or `poses_bounds.npy`).
    pub cameras: PathBuf,
}

/// The layout of a capture folder that has no `transforms.json`: IDR/NeuS when it holds one of
/// [`idr::CAMERA_FILES`], else LLFF when it holds [`llff::POSES_FILE`].
pub fn find_layout(path: &Path) -> Option<LayoutLocation> {
    if !path.is_dir() || path.join("transforms.json").exists() {
        return None;
    }
    if let Some(name) = idr::CAMERA_FILES
        .iter()
        .find(|name| path.join(name).is_file())
    {
        return Some(LayoutLocation {
            kind: LayoutKind::Idr,
            cameras: path.join(name),
        });
    }
    let poses = path.join(llff::POSES_FILE);
    poses.is_file().then_some(LayoutLocation {
        kind: LayoutKind::Llff,
        cameras: poses,
    })
}

/// What a folder of the layout was taken to hold.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FolderRole {
    pub folder: String,
    /// E.g. `polarizer 45°`, `S1`, `masks`, `not used`.
    pub role: String,
    pub files: usize,
}

/// What [`import`] decided about a layout folder, for people (`phygap import`, the training log).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LayoutReport {
    pub layout: LayoutKind,
    /// The camera file used, relative to the folder.
    pub cameras_file: String,
    pub views: usize,
    pub width: u32,
    pub height: u32,
    /// The frame the cameras are in (normalised by `scale_mat`, or as given).
    pub frame: String,
    /// `stokes`, `stokes_stacked`, `polarizer4` or `rgb`.
    pub measurement: String,
    pub folders: Vec<FolderRole>,
    /// The mask folder and how many views have a mask.
    pub masks: Option<String>,
    pub masked_views: usize,
    pub color_space: String,
    pub world_up: [f64; 3],
    /// Why that `world_up`.
    pub world_up_reason: String,
    pub notes: Vec<String>,
}

impl std::fmt::Display for LayoutReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(
            f,
            "layout: {} ({}), {} views of {}×{}",
            self.layout.name(),
            self.cameras_file,
            self.views,
            self.width,
            self.height
        )?;
        writeln!(f, "cameras: {}", self.frame)?;
        writeln!(f, "measurement: {}", self.measurement)?;
        for folder in &self.folders {
            writeln!(
                f,
                "  {}/: {} ({} files)",
                folder.folder, folder.role, folder.files
            )?;
        }
        match &self.masks {
            Some(masks) => writeln!(
                f,
                "masks: {masks}/, matched by number to {} of {} views",
                self.masked_views, self.views
            )?,
            None => writeln!(f, "masks: none found (the whole image is object)")?,
        }
        writeln!(f, "colour space: {}", self.color_space)?;
        writeln!(
            f,
            "world up: [{}, {}, {}] ({})",
            self.world_up[0], self.world_up[1], self.world_up[2], self.world_up_reason
        )?;
        for note in &self.notes {
            writeln!(f, "note: {note}")?;
        }
        Ok(())
    }
}

/// A layout folder read as a transforms document.
#[derive(Clone, Debug)]
pub struct Imported {
    /// The capture folder (canonical); the document's paths are relative to it.
    pub root: PathBuf,
    /// The equivalent `transforms.json`.
    pub document: Value,
    pub report: LayoutReport,
}

/// How the views' measurement is stored.
#[derive(Clone, Debug)]
enum MeasurementFolders {
    /// `s0`, `s1`, `s2` folders.
    Stokes([String; 3]),
    /// One `.npy` of stacked components a view.
    StokesStacked(String),
    /// Folders of the 0°, 45°, 90°, 135° images.
    Polarizer4([String; 4]),
    Rgb(String),
}

impl MeasurementFolders {
    fn folders(&self) -> Vec<&str> {
        match self {
            MeasurementFolders::Stokes(f) => f.iter().map(String::as_str).collect(),
            MeasurementFolders::Polarizer4(f) => f.iter().map(String::as_str).collect(),
            MeasurementFolders::StokesStacked(f) | MeasurementFolders::Rgb(f) => vec![f.as_str()],
        }
    }

    fn keys(&self) -> &'static [&'static str] {
        match self {
            MeasurementFolders::Stokes(_) => &super::frame::STOKES_KEYS,
            MeasurementFolders::StokesStacked(_) => &super::frame::STOKES_KEYS,
            MeasurementFolders::Polarizer4(_) => &super::frame::POLARIZER_KEYS,
            MeasurementFolders::Rgb(_) => &["file_path"],
        }
    }

    fn name(&self) -> &'static str {
        match self {
            MeasurementFolders::Stokes(_) => "stokes",
            MeasurementFolders::StokesStacked(_) => "stokes_stacked",
            MeasurementFolders::Polarizer4(_) => "polarizer4",
            MeasurementFolders::Rgb(_) => "rgb",
        }
    }
}

/// The sub-folders of `root` by name.
fn sub_folders(root: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root)
        .map(|entries| {
            entries
                .filter_map(Result::ok)
                .filter(|e| e.path().is_dir())
                .filter_map(|e| e.file_name().to_str().map(str::to_owned))
                .filter(|n| !n.starts_with('.') && n != "__MACOSX")
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

/// The settings `capture.json` gives: keys copied into the document, and the polarizer folders
/// it names by angle.
#[derive(Default)]
struct Settings {
    document_keys: Map<String, Value>,
    polarizer_folders: BTreeMap<u32, String>,
}

/// Reads `capture.json` (optional).
fn read_settings(root: &Path, problems: &mut Vec<Problem>) -> Result<Settings, CaptureError> {
    let Some(object) = super::json::read_optional_object(root, SETTINGS_FILE, problems)? else {
        return Ok(Default::default());
    };
    let mut settings = Map::new();
    let mut polarizer_folders = BTreeMap::new();
    for (key, value) in object {
        match key.as_str() {
            "polarizer_folders" => {
                let entries = value.as_object().cloned().unwrap_or_default();
                for (angle, folder) in &entries {
                    match (angle.parse::<u32>(), folder.as_str()) {
                        (Ok(a), Some(folder)) if folders::ANGLES.contains(&a) => {
                            polarizer_folders.insert(a, folder.to_owned());
                        }
                        _ => problems.push(Problem::new(
                            SETTINGS_FILE,
                            "polarizer_folders",
                            format!(
                                "{angle:?}: {folder}: expected an angle of 0, 45, 90 or 135 and a folder name"
                            ),
                        )),
                    }
                }
                if entries.is_empty() {
                    problems.push(Problem::new(
                        SETTINGS_FILE,
                        "polarizer_folders",
                        "expected an object {\"0\": folder, \"45\": folder, \"90\": folder, \"135\": folder}",
                    ));
                }
            }
            k if SETTINGS_KEYS.contains(&k) => {
                settings.insert(key, value);
            }
            _ => problems.push(Problem::new(
                SETTINGS_FILE,
                key,
                format!(
                    "not a setting of a dataset layout folder (the cameras come from its camera file); expected {}",
                    SETTINGS_KEYS.join(", ")
                ),
            )),
        }
    }
    Ok(Settings {
        document_keys: settings,
        polarizer_folders,
    })
}

/// The measurement folders of `root`, in priority order, and the roles given to every folder.
fn choose_measurement(
    root: &Path,
    manifest: &BTreeMap<u32, String>,
    roles: &mut Vec<FolderRole>,
    problems: &mut Vec<Problem>,
) -> Option<MeasurementFolders> {
    let names = sub_folders(root);
    let count = |name: &str| folders::image_files(&root.join(name)).len();
    let mut stokes: [Option<String>; 3] = Default::default();
    let mut angles: BTreeMap<u32, String> = BTreeMap::new();
    let mut stacked = None;
    let mut rgb = None;
    let mut masks = None;
    for name in &names {
        if let Some(c) = folders::stokes_component_of_folder(name) {
            stokes[c].get_or_insert_with(|| name.clone());
        } else if let Some(a) = folders::angle_of_folder(name) {
            angles.entry(a).or_insert_with(|| name.clone());
        } else if folders::is_stacked_stokes_folder(name) {
            stacked.get_or_insert_with(|| name.clone());
        } else if folders::is_image_folder(name) {
            rgb.get_or_insert_with(|| name.clone());
        } else if folders::is_mask_folder(name) {
            // `masks` before `mask_x`: the exact names first.
            let exact = matches!(name.to_ascii_lowercase().as_str(), "mask" | "masks");
            if masks.is_none() || exact {
                masks = Some(name.clone());
            }
        }
    }
    if !manifest.is_empty() {
        for (angle, folder) in manifest {
            if !root.join(folder).is_dir() {
                problems.push(Problem::new(
                    SETTINGS_FILE,
                    "polarizer_folders",
                    format!("{folder}/ (the {angle}° folder) does not exist"),
                ));
            }
        }
        angles = manifest.clone();
    }
    let measurement = if let [Some(a), Some(b), Some(c)] = &stokes {
        Some(MeasurementFolders::Stokes([
            a.clone(),
            b.clone(),
            c.clone(),
        ]))
    } else if let Some(s) = &stacked {
        Some(MeasurementFolders::StokesStacked(s.clone()))
    } else if angles.len() == 4 {
        Some(MeasurementFolders::Polarizer4(
            folders::ANGLES.map(|a| angles[&a].clone()),
        ))
    } else {
        rgb.as_ref().map(|r| MeasurementFolders::Rgb(r.clone()))
    };
    if measurement.is_none() || matches!(measurement, Some(MeasurementFolders::Rgb(_))) {
        let found: Vec<String> = angles.iter().map(|(a, f)| format!("{f}/ ({a}°)")).collect();
        if !found.is_empty() && angles.len() < 4 {
            problems.push(Problem::new(
                "top level",
                "polarizer folders",
                format!(
                    "only {} of the four polarizer folders found: {}; name them by angle (I-00, I-45, I-90, I-135) or list them in capture.json's polarizer_folders",
                    angles.len(),
                    found.join(", ")
                ),
            ));
        }
    }
    let used: Vec<&str> = measurement
        .as_ref()
        .map(|m| m.folders())
        .unwrap_or_default();
    for name in &names {
        let role = if let Some(i) = used.iter().position(|u| u == name) {
            match &measurement {
                Some(MeasurementFolders::Stokes(_)) => format!("S{i}"),
                Some(MeasurementFolders::StokesStacked(_)) => {
                    "Stokes components (stacked .npy)".into()
                }
                Some(MeasurementFolders::Polarizer4(_)) => {
                    format!("polarizer {}°", folders::ANGLES[i])
                }
                _ => "RGB images".into(),
            }
        } else if Some(name) == masks.as_ref() {
            "masks".into()
        } else {
            "not used".into()
        };
        roles.push(FolderRole {
            folder: name.clone(),
            role,
            files: count(name),
        });
    }
    measurement
}

/// The size of the image (or image array) at `path`.
fn image_size(path: &Path) -> Result<(u32, u32), String> {
    let is_npy = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"));
    if is_npy {
        let header = npy::read_npy_header(path, &NpyLimits::image(u64::MAX, 12))
            .map_err(|e| e.to_string())?;
        let (w, h) = super::images::npy_image_size(&header.shape).ok_or_else(|| {
            format!(
                "{} has the shape {:?}, not an image",
                path.display(),
                header.shape
            )
        })?;
        return Ok((w as u32, h as u32));
    }
    let header = crate::formats::image_io::read_header(path).map_err(|e| e.to_string())?;
    Ok((header.width as u32, header.height as u32))
}

/// The cameras of the layout's camera file for `views` views of `width × height`, and the frame
/// they are in; problems are named by view.
fn read_cameras(
    location: &LayoutLocation,
    views: usize,
    (width, height): (u32, u32),
    problems: &mut Vec<Problem>,
    notes: &mut Vec<String>,
) -> Result<(Vec<Option<Camera>>, String), CaptureError> {
    let file = location
        .cameras
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let npy_error = |e: npy::NpyError| CaptureError::Read {
        path: location.cameras.clone(),
        message: e.to_string(),
    };
    match location.kind {
        LayoutKind::Idr => {
            let arrays = npy::read_npz::<f64>(&location.cameras, &NpyLimits::CAMERAS, |name| {
                name.starts_with("world_mat_") || name.starts_with("scale_mat_")
            })
            .map_err(npy_error)?;
            let indexed = |prefix: &str| -> BTreeMap<usize, &npy::NpyArray<f64>> {
                arrays
                    .iter()
                    .filter_map(|(name, a)| {
                        let i = name.strip_prefix(prefix)?.parse().ok()?;
                        Some((i, a))
                    })
                    .collect()
            };
            let world = indexed("world_mat_");
            let scale = indexed("scale_mat_");
            if world.len() != views {
                problems.push(Problem::new(
                    file.clone(),
                    "world_mat",
                    format!(
                        "{} world_mat_i entries for {views} views (images); view k takes world_mat_k",
                        world.len()
                    ),
                ));
            }
            let matrix = |a: &npy::NpyArray<f64>| -> Option<DMat4> {
                match a.shape.as_slice() {
                    [4, 4] => Some(idr::mat4_from_rows(&a.data)),
                    [3, 4] => {
                        let mut values = a.data.clone();
                        values.extend_from_slice(&[0.0, 0.0, 0.0, 1.0]);
                        Some(idr::mat4_from_rows(&values))
                    }
                    _ => None,
                }
            };
            let mut cameras = Vec::with_capacity(views);
            let mut unscaled = 0;
            for k in 0..views {
                let label = format!("view {k}");
                let Some(world_mat) = world.get(&k) else {
                    problems.push(Problem::new(
                        label,
                        format!("world_mat_{k}"),
                        format!("missing from {file}"),
                    ));
                    cameras.push(None);
                    continue;
                };
                let Some(world_mat) = matrix(world_mat) else {
                    problems.push(Problem::new(
                        label,
                        format!("world_mat_{k}"),
                        format!("shape {:?}; expected 4×4 or 3×4", world_mat.shape),
                    ));
                    cameras.push(None);
                    continue;
                };
                let scale_mat = match scale.get(&k).map(|a| matrix(a)) {
                    Some(Some(m)) => m,
                    Some(None) => {
                        problems.push(Problem::new(
                            label,
                            format!("scale_mat_{k}"),
                            "expected a 4×4 matrix",
                        ));
                        cameras.push(None);
                        continue;
                    }
                    None => {
                        unscaled += 1;
                        DMat4::IDENTITY
                    }
                };
                match idr::camera_from_matrices(&world_mat, &scale_mat, width, height) {
                    Ok(camera) => cameras.push(Some(camera)),
                    Err(message) => {
                        problems.push(Problem::new(label, format!("world_mat_{k}"), message));
                        cameras.push(None);
                    }
                }
            }
            let frame = match unscaled {
                0 => format!(
                    "decomposed from world_mat_i · scale_mat_i ({file}): the normalised frame \
                     (scale_mat maps it to the world; the object is inside its unit sphere)"
                ),
                n if n == views => format!(
                    "decomposed from world_mat_i ({file}, no scale_mat): the dataset's world frame"
                ),
                n => {
                    notes.push(format!(
                        "{n} of {views} views have no scale_mat_i and stay in the world frame"
                    ));
                    format!("decomposed from world_mat_i · scale_mat_i ({file}), partly unscaled")
                }
            };
            Ok((
                cameras,
                frame + "; principal points shifted by +0.5 px (OpenCV pixel centres)",
            ))
        }
        LayoutKind::Llff => {
            let array =
                npy::read_npy::<f64>(&location.cameras, &NpyLimits::CAMERAS).map_err(npy_error)?;
            let rows = match array.shape.as_slice() {
                [n, llff::ROW_LENGTH] => *n,
                _ => {
                    problems.push(Problem::new(
                        file.clone(),
                        "(array)",
                        format!(
                            "shape {:?}; expected N × 17 (a 3×5 pose [R | t | hwf] and near/far bounds a view)",
                            array.shape
                        ),
                    ));
                    return Ok((vec![None; views], String::new()));
                }
            };
            if rows != views {
                problems.push(Problem::new(
                    file.clone(),
                    "(array)",
                    format!("{rows} poses for {views} views (images); row k is view k"),
                ));
            }
            let poses: Vec<llff::LlffPose> = array
                .data
                .chunks_exact(llff::ROW_LENGTH)
                .map(llff::LlffPose::from_row)
                .collect();
            let mut cameras = Vec::with_capacity(views);
            for k in 0..views {
                match poses.get(k).map(|p| p.camera(width, height)) {
                    Some(Ok(camera)) => cameras.push(Some(camera)),
                    Some(Err(message)) => {
                        problems.push(Problem::new(format!("view {k}"), file.clone(), message));
                        cameras.push(None);
                    }
                    None => cameras.push(None),
                }
            }
            let (near, far) = poses.iter().fold((f64::INFINITY, 0.0f64), |(n, f), p| {
                (n.min(p.near), f.max(p.far))
            });
            let scaled = poses
                .first()
                .is_some_and(|p| (p.width - f64::from(width)).abs() > 0.5);
            if scaled {
                notes.push(format!(
                    "the poses are for {}×{} images; the focal length is scaled to the {width}×{height} images",
                    poses[0].width, poses[0].height
                ));
            }
            Ok((
                cameras,
                format!(
                    "LLFF poses ({file}: columns down, right, back → OpenGL right, up, back) in the \
                     dataset's world frame; principal point at the image centre; near/far bounds \
                     {near:.3}…{far:.3}"
                ),
            ))
        }
    }
}

/// The `world_up` of the document: `capture.json`'s, else +Z or +Y when the cameras' mean up
/// direction is within [`WORLD_UP_TOLERANCE_DEG`] of it, else +Z.
fn choose_world_up(settings: &Map<String, Value>, cameras: &[Camera]) -> ([f64; 3], String) {
    if let Some(up) = settings.get("world_up").and_then(|v| {
        let a = v.as_array()?;
        Some([
            a.first()?.as_f64()?,
            a.get(1)?.as_f64()?,
            a.get(2)?.as_f64()?,
        ])
    }) {
        return (up, format!("from {SETTINGS_FILE}"));
    }
    let mean = cameras.iter().map(Camera::up).sum::<DVec3>() / cameras.len().max(1) as f64;
    let direction = mean.normalize_or_zero();
    let cos_tolerance = WORLD_UP_TOLERANCE_DEG.to_radians().cos();
    let shown = format!(
        "({:.2}, {:.2}, {:.2})",
        direction.x, direction.y, direction.z
    );
    for axis in [DVec3::Z, DVec3::Y] {
        if direction.dot(axis) > cos_tolerance {
            return (
                axis.to_array(),
                format!("the cameras' mean up direction {shown} is within {WORLD_UP_TOLERANCE_DEG}° of it"),
            );
        }
    }
    (
        [0.0, 0.0, 1.0],
        format!(
            "the default: the cameras' mean up direction {shown} is near neither +Z nor +Y; give \
             world_up in {SETTINGS_FILE} (it orients the environment map)"
        ),
    )
}

/// Reads the layout folder `root` (at `location`) as a transforms document; every problem found
/// is reported at once.
pub fn import(root: &Path, location: &LayoutLocation) -> Result<Imported, CaptureError> {
    let root = root.canonicalize().unwrap_or_else(|_| root.to_owned());
    let mut problems = Vec::new();
    let mut notes = Vec::new();
    let Settings {
        document_keys: settings,
        polarizer_folders: manifest,
    } = read_settings(&root, &mut problems)?;
    let mut roles = Vec::new();
    let measurement = choose_measurement(&root, &manifest, &mut roles, &mut problems);
    let invalid = |problems: Vec<Problem>| CaptureError::Invalid {
        path: location.cameras.clone(),
        problems,
    };
    let Some(measurement) = measurement else {
        problems.push(Problem::new(
            "top level",
            "images",
            "no image folders found: expected s0/ s1/ s2/ (Stokes), stokes/ (stacked .npy), four \
             per-angle folders (I-00, I-45, I-90, I-135 or pol000 … pol135), or image/",
        ));
        return Err(invalid(problems));
    };
    let masks_folder = roles
        .iter()
        .find(|r| r.role == "masks")
        .map(|r| r.folder.clone());
    let folder_names = measurement.folders();
    let primary_files = folders::image_files(&root.join(folder_names[0]));
    if primary_files.is_empty() {
        problems.push(Problem::new(
            format!("{}/", folder_names[0]),
            "images",
            "the folder holds no image files",
        ));
        return Err(invalid(problems));
    }
    let others: Vec<FileIndex> = folder_names[1..]
        .iter()
        .map(|f| FileIndex::new(&folders::image_files(&root.join(f))))
        .collect();
    let mask_index = masks_folder
        .as_ref()
        .map(|m| FileIndex::new(&folders::image_files(&root.join(m))));
    let primary_index = FileIndex::new(&primary_files);
    for duplicate in &primary_index.duplicates {
        problems.push(Problem::new(
            format!("{}/{duplicate}", folder_names[0]),
            "name",
            "another file of this folder has the same view number",
        ));
    }
    let first = root.join(folder_names[0]).join(&primary_files[0].name);
    let size = image_size(&first).map_err(|message| {
        invalid(vec![Problem::new(
            format!("{}/{}", folder_names[0], primary_files[0].name),
            "size",
            message,
        )])
    })?;
    let (cameras, frame) = read_cameras(
        location,
        primary_files.len(),
        size,
        &mut problems,
        &mut notes,
    )?;

    let mut frames = Vec::with_capacity(primary_files.len());
    let mut masked_views = 0;
    for (k, (file, camera)) in primary_files.iter().zip(&cameras).enumerate() {
        let Some(camera) = camera else { continue };
        let mut frame = Map::new();
        let mut paths = vec![format!("{}/{}", folder_names[0], file.name)];
        for (folder, index) in folder_names[1..].iter().zip(&others) {
            match index.matching(file) {
                Some(name) => paths.push(format!("{folder}/{name}")),
                None => problems.push(Problem::new(
                    format!("view {k} ({}/{})", folder_names[0], file.name),
                    format!("{folder}/"),
                    format!(
                        "no file numbered {} in {folder}/",
                        file.number.map_or(file.name.clone(), |n| n.to_string())
                    ),
                )),
            }
        }
        if let MeasurementFolders::StokesStacked(_) = measurement {
            paths = vec![paths[0].clone(); 3];
        }
        for (key, path) in measurement.keys().iter().zip(&paths) {
            frame.insert((*key).into(), json!(path));
        }
        if let (Some(folder), Some(index)) = (&masks_folder, &mask_index) {
            if let Some(mask) = index.matching(file) {
                frame.insert("mask_path".into(), json!(format!("{folder}/{mask}")));
                masked_views += 1;
            }
        }
        let rows: Vec<[f64; 4]> = (0..4).map(|r| camera.c2w.row(r).to_array()).collect();
        frame.insert("w".into(), json!(camera.width));
        frame.insert("h".into(), json!(camera.height));
        frame.insert("fl_x".into(), json!(camera.fx));
        frame.insert("fl_y".into(), json!(camera.fy));
        frame.insert("cx".into(), json!(camera.cx));
        frame.insert("cy".into(), json!(camera.cy));
        frame.insert("transform_matrix".into(), json!(rows));
        frames.push(Value::Object(frame));
    }
    if let Some(folder) = &masks_folder {
        if masked_views < primary_files.len() {
            notes.push(format!(
                "{} view(s) have no mask in {folder}/ with their number",
                primary_files.len() - masked_views
            ));
        }
    }
    let cameras: Vec<Camera> = cameras.into_iter().flatten().collect();
    let (world_up, world_up_reason) = choose_world_up(&settings, &cameras);
    let float_files = ["exr", "hdr", "npy"];
    let extension = Path::new(&primary_files[0].name)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let color_space = match settings.get("color_space").and_then(Value::as_str) {
        Some(space) => format!("{space} (from {SETTINGS_FILE})"),
        None if float_files.contains(&extension.as_str()) => {
            format!("linear (.{extension} files hold linear values)")
        }
        None => format!(
            "sRGB assumed for the 8/16-bit .{extension} images (the default; give \
             \"color_space\": \"linear\" in {SETTINGS_FILE} for a camera's linear output)"
        ),
    };
    if !problems.is_empty() {
        return Err(invalid(problems));
    }
    let mut document = settings;
    document.insert("camera_convention".into(), json!("OpenGL"));
    document.insert("world_up".into(), json!(world_up));
    document.insert(
        "generator".into(),
        json!(format!("phygap import ({} layout)", location.kind.name())),
    );
    document.insert("frames".into(), Value::Array(frames));
    let report = LayoutReport {
        layout: location.kind,
        cameras_file: location
            .cameras
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default(),
        views: primary_files.len(),
        width: size.0,
        height: size.1,
        frame,
        measurement: measurement.name().into(),
        folders: roles,
        masks: masks_folder,
        masked_views,
        color_space,
        world_up,
        world_up_reason,
        notes,
    };
    Ok(Imported {
        root,
        document: Value::Object(document),
        report,
    })
}

/// Loads the layout folder `root` within `options`, as [`super::load_with`] loads a
/// `transforms.json` capture.
pub fn load(
    root: &Path,
    location: &LayoutLocation,
    options: &LoadOptions,
) -> Result<Capture, CaptureError> {
    let _span = tracing::info_span!("load_layout", cameras = %location.cameras.display()).entered();
    let imported = import(root, location)?;
    tracing::info!(
        "read as the {} layout: {} views, {}",
        imported.report.layout.name(),
        imported.report.views,
        imported.report.measurement
    );
    super::load_document(
        &location.cameras,
        imported.root,
        &imported.document,
        Vec::new(),
        options,
    )
}

/// The cameras of a layout folder's views, as `(frame name, camera)`; images are not read
/// (beyond the first file's header, for the size).
pub fn load_cameras(
    root: &Path,
    location: &LayoutLocation,
) -> Result<Vec<(String, Camera)>, CaptureError> {
    let imported = import(root, location)?;
    let (cameras, problems) = super::frame::parse_cameras(&imported.document);
    if problems.is_empty() {
        Ok(cameras)
    } else {
        Err(CaptureError::Invalid {
            path: location.cameras.clone(),
            problems,
        })
    }
}

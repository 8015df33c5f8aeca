//! Captures given as a COLMAP model instead of `transforms.json`: a folder with
//! `sparse/0/{cameras,images,points3D}.{bin,txt}` (or those files in `sparse/`), the views'
//! measurement files named after each COLMAP image, masks beside them, and an optional
//! `capture.json` with the top-level keys of `transforms.json` that are not cameras.
//!
//! Per image `NAME` (stem `STEM`), the first of these that exists is its measurement:
//! `s0/STEM.exr` with `s1/`, `s2/` (full Stokes), `raw/NAME` or `raw/STEM.{png,tif,tiff,raw}` (a
//! raw mosaic frame; sensor and bit depth from `capture.json`'s `raw` object), `images/NAME`
//! (plain RGB). Its mask is the first of `masks/NAME.png` (COLMAP's own convention),
//! `masks/STEM.png`, `masks/NAME`.
//!
//! Loading builds the equivalent transforms document (OpenCV camera-to-world matrices, exact:
//! c2w = [Rᵀ | −Rᵀt] of COLMAP's world-to-camera qvec, tvec) and hands it to the ordinary
//! validation and loading, so every rule and error message is the same; views of `OPENCV` cameras
//! are then undistorted to pinhole (`undistort.rs`), and `points3D` becomes
//! [`Capture::points`](super::Capture::points).

pub mod model;
#[cfg(test)]
mod tests;

use std::path::{Path, PathBuf};

use glam::{DMat3, DMat4, DQuat, DVec3};
use serde::Serialize;
use serde_json::{json, Map, Value};

pub use super::error::ColmapError;
use super::error::Problem;
use super::json::check_relative_path;
pub use super::undistort::Distortion;
use super::{Capture, CaptureError};
use crate::core::camera::{Camera, CameraConvention, Intrinsics};
pub use model::{ColmapCamera, ColmapImage, ColmapModel, ColmapPoint, ModelFormat};

/// The capture settings file of a COLMAP capture folder.
pub const SETTINGS_FILE: &str = "capture.json";

/// Top-level keys of `transforms.json` that `capture.json` may hold (the cameras come from COLMAP).
const SETTINGS_KEYS: [&str; 6] = [
    "stokes_convention",
    "color_space",
    "world_up",
    "demosaic",
    "white_balance",
    "raw",
];

/// Extensions tried for a raw frame named after a COLMAP image.
const RAW_EXTENSIONS: [&str; 4] = ["png", "tif", "tiff", "raw"];

/// A point of the sparse reconstruction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SparsePoint {
    pub position: DVec3,
    /// 8-bit sRGB colour COLMAP gave the point.
    pub colour: [u8; 3],
}

/// Where a COLMAP model folder is and in which format.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelLocation {
    pub dir: PathBuf,
    pub format: ModelFormat,
}

/// What `phygap inspect` says about a COLMAP capture.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ColmapReport {
    /// The model folder.
    pub model: PathBuf,
    pub format: ModelFormat,
    pub cameras: usize,
    /// Views undistorted from an `OPENCV` camera.
    pub undistorted_views: usize,
}

/// The COLMAP model of a capture folder that has no `transforms.json`: `sparse/0/` or `sparse/`
/// holding `cameras.bin` (preferred) or `cameras.txt`.
pub fn find_model(path: &Path) -> Option<ModelLocation> {
    if !path.is_dir() || path.join("transforms.json").exists() {
        return None;
    }
    for dir in [path.join("sparse/0"), path.join("sparse")] {
        for format in [ModelFormat::Binary, ModelFormat::Text] {
            let ext = match format {
                ModelFormat::Binary => "bin",
                ModelFormat::Text => "txt",
            };
            if dir.join(format!("cameras.{ext}")).is_file() {
                return Some(ModelLocation { dir, format });
            }
        }
    }
    None
}

/// The pinhole intrinsics and distortion of a COLMAP camera, or why phygap cannot use it.
fn intrinsics(camera: &ColmapCamera) -> Result<([f64; 4], Option<Distortion>), String> {
    let p = &camera.params;
    let needed = model::CAMERA_MODELS
        .iter()
        .find(|m| m.1 == camera.model)
        .map_or(0, |m| m.2);
    if p.len() != needed {
        return Err(format!(
            "camera model {} needs {needed} parameters, found {}",
            camera.model,
            p.len()
        ));
    }
    let side_limit = u64::from(super::frame::MAX_IMAGE_SIDE);
    if camera.width == 0 || camera.height == 0 || camera.width.max(camera.height) > side_limit {
        return Err(format!(
            "a {}×{} camera: image sides must be 1 to {side_limit} pixels",
            camera.width, camera.height
        ));
    }
    let intrinsics = |k: [f64; 4]| match super::frame::intrinsics_problem(
        camera.width as u32,
        camera.height as u32,
        k,
    ) {
        Some((key, message)) => Err(format!("{key}: {message}")),
        None => Ok(k),
    };
    match camera.model.as_str() {
        "SIMPLE_PINHOLE" => Ok((intrinsics([p[0], p[0], p[1], p[2]])?, None)),
        "PINHOLE" => Ok((intrinsics([p[0], p[1], p[2], p[3]])?, None)),
        "OPENCV" => {
            let d = Distortion {
                k1: p[4],
                k2: p[5],
                p1: p[6],
                p2: p[7],
            };
            Ok((
                intrinsics([p[0], p[1], p[2], p[3]])?,
                (!d.is_identity()).then_some(d),
            ))
        }
        other => Err(format!(
            "camera model {other} is not supported (PINHOLE, SIMPLE_PINHOLE and OPENCV are); \
             undistort the images first, e.g. with `colmap image_undistorter`, which writes PINHOLE cameras"
        )),
    }
}

/// The OpenCV camera-to-world matrix of a COLMAP image (world-to-camera `qvec`, `tvec`).
pub fn camera_to_world(image: &ColmapImage) -> DMat4 {
    let [w, x, y, z] = image.qvec;
    let rotation = DMat3::from_quat(DQuat::from_xyzw(x, y, z, w).normalize());
    let rt = rotation.transpose();
    let centre = -(rt * DVec3::from_array(image.tvec));
    DMat4::from_cols(
        rt.x_axis.extend(0.0),
        rt.y_axis.extend(0.0),
        rt.z_axis.extend(0.0),
        centre.extend(1.0),
    )
}

/// The COLMAP pose (qvec w, x, y, z; tvec) of an OpenCV camera-to-world matrix.
pub fn pose_from_camera_to_world(c2w_opencv: &DMat4) -> ([f64; 4], [f64; 3]) {
    let rotation = DMat3::from_mat4(*c2w_opencv).transpose();
    let q = DQuat::from_mat3(&rotation).normalize();
    let t = -(rotation * c2w_opencv.w_axis.truncate());
    ([q.w, q.x, q.y, q.z], t.to_array())
}

/// The first of `candidates` (relative to `root`) that is a file.
fn first_existing(root: &Path, candidates: &[String]) -> Option<String> {
    candidates.iter().find(|c| root.join(c).is_file()).cloned()
}

/// The frame of one COLMAP image: its measurement and mask keys, or a problem.
fn frame_files(root: &Path, name: &str) -> Result<Map<String, Value>, String> {
    check_relative_path(name).map_err(|e| format!("image name: {e}"))?;
    let stem = match name.rfind('.') {
        Some(dot) if !name[dot..].contains('/') => &name[..dot],
        _ => name,
    };
    let mut frame = Map::new();
    let stokes: Vec<String> = ["s0", "s1", "s2"]
        .iter()
        .map(|s| format!("{s}/{stem}.exr"))
        .collect();
    let raw = {
        let mut c = vec![format!("raw/{name}")];
        c.extend(RAW_EXTENSIONS.iter().map(|e| format!("raw/{stem}.{e}")));
        c
    };
    if root.join(&stokes[0]).is_file() {
        for (key, path) in ["s0_path", "s1_path", "s2_path"].iter().zip(stokes) {
            frame.insert((*key).into(), json!(path));
        }
    } else if let Some(raw) = first_existing(root, &raw).filter(|r| {
        RAW_EXTENSIONS
            .iter()
            .any(|e| r.to_ascii_lowercase().ends_with(&format!(".{e}")))
    }) {
        frame.insert("raw".into(), json!(raw));
    } else if root.join("images").join(name).is_file() {
        frame.insert("file_path".into(), json!(format!("images/{name}")));
    } else {
        return Err(format!(
            "no measurement for this image: looked for s0/{stem}.exr, raw/{name}, raw/{stem}.{{png,tif,tiff,raw}} and images/{name}"
        ));
    }
    let masks = [
        format!("masks/{name}.png"),
        format!("masks/{stem}.png"),
        format!("masks/{name}"),
    ];
    if let Some(mask) = first_existing(root, &masks) {
        frame.insert("mask_path".into(), json!(mask));
    }
    Ok(frame)
}

/// Reads `capture.json` (optional) as the top level of the transforms document.
fn read_settings(
    root: &Path,
    problems: &mut Vec<Problem>,
) -> Result<Map<String, Value>, CaptureError> {
    let Some(object) = super::json::read_optional_object(root, SETTINGS_FILE, problems)? else {
        return Ok(Map::new());
    };
    let mut settings = Map::new();
    for (key, value) in object {
        if SETTINGS_KEYS.contains(&key.as_str()) {
            settings.insert(key, value);
        } else {
            problems.push(Problem::new(
                SETTINGS_FILE,
                key,
                format!(
                    "not a setting of a COLMAP capture (the cameras come from the model); expected {}",
                    SETTINGS_KEYS.join(", ")
                ),
            ));
        }
    }
    Ok(settings)
}

/// Loads a COLMAP capture folder (`root`) whose model is at `location`, within `limits`.
pub fn load(
    root: &Path,
    location: &ModelLocation,
    options: &super::LoadOptions,
) -> Result<Capture, CaptureError> {
    let _span = tracing::info_span!("load_colmap", model = %location.dir.display()).entered();
    let model = model::read_model(&location.dir, location.format)?;
    let root = root.canonicalize().unwrap_or_else(|_| root.to_owned());
    let mut problems = Vec::new();
    let mut document = read_settings(&root, &mut problems)?;

    let mut cameras = std::collections::BTreeMap::new();
    for (id, camera) in &model.cameras {
        match intrinsics(camera) {
            Ok(k) => {
                cameras.insert(*id, (camera, k));
            }
            Err(message) => problems.push(Problem::new(format!("camera {id}"), "model", message)),
        }
    }
    let mut images: Vec<&ColmapImage> = model.images.values().collect();
    images.sort_by(|a, b| a.name.cmp(&b.name));
    let mut frames = Vec::with_capacity(images.len());
    let mut distortions = Vec::with_capacity(images.len());
    for image in images {
        let label = format!("image {} ({})", image.id, image.name);
        let Some((camera, ([fx, fy, cx, cy], distortion))) = cameras.get(&image.camera_id) else {
            if !model.cameras.contains_key(&image.camera_id) {
                problems.push(Problem::new(
                    label,
                    "camera_id",
                    format!("camera {} is not in the model's cameras", image.camera_id),
                ));
            }
            continue;
        };
        let mut frame = match frame_files(&root, &image.name) {
            Ok(frame) => frame,
            Err(message) => {
                problems.push(Problem::new(label, "name", message));
                continue;
            }
        };
        let c2w = camera_to_world(image);
        let rows: Vec<[f64; 4]> = (0..4).map(|r| c2w.row(r).to_array()).collect();
        frame.insert("w".into(), json!(camera.width));
        frame.insert("h".into(), json!(camera.height));
        frame.insert("fl_x".into(), json!(fx));
        frame.insert("fl_y".into(), json!(fy));
        frame.insert("cx".into(), json!(cx));
        frame.insert("cy".into(), json!(cy));
        frame.insert("transform_matrix".into(), json!(rows));
        frames.push(Value::Object(frame));
        distortions.push(*distortion);
    }
    if frames.is_empty() && problems.is_empty() {
        problems.push(Problem::new(
            "top level",
            "images",
            "the COLMAP model has no registered images",
        ));
    }
    document.insert("camera_convention".into(), json!("OpenCV"));
    document.insert("frames".into(), Value::Array(frames));
    let mut capture = super::load_document(
        &location.dir,
        root,
        &Value::Object(document),
        problems,
        options,
    )?;

    super::lens::undistort_views(&mut capture, &distortions);
    capture.points = model
        .points
        .iter()
        .map(|p| SparsePoint {
            position: DVec3::from_array(p.xyz),
            colour: p.rgb,
        })
        .collect();
    capture.colmap = Some(ColmapReport {
        model: location.dir.clone(),
        format: location.format,
        cameras: model.cameras.len(),
        undistorted_views: distortions.iter().filter(|d| d.is_some()).count(),
    });
    Ok(capture)
}

/// The pinhole cameras of a COLMAP model's images (sorted by name; `OPENCV` cameras as the pinhole
/// cameras their views are undistorted to), as `(image name, camera)`; images are not read.
pub fn load_cameras(location: &ModelLocation) -> Result<Vec<(String, Camera)>, CaptureError> {
    let model = model::read_model(&location.dir, location.format)?;
    let mut problems = Vec::new();
    let mut images: Vec<&ColmapImage> = model.images.values().collect();
    images.sort_by(|a, b| a.name.cmp(&b.name));
    let mut cameras = Vec::new();
    for image in images {
        let Some(camera) = model.cameras.get(&image.camera_id) else {
            problems.push(Problem::new(
                format!("image {} ({})", image.id, image.name),
                "camera_id",
                format!("camera {} is not in the model's cameras", image.camera_id),
            ));
            continue;
        };
        match intrinsics(camera) {
            Ok(([fx, fy, cx, cy], _)) => {
                let intrinsics = Intrinsics {
                    width: camera.width as u32,
                    height: camera.height as u32,
                    fx,
                    fy,
                    cx,
                    cy,
                };
                cameras.push((
                    image.name.clone(),
                    Camera::new(intrinsics, camera_to_world(image), CameraConvention::OpenCV),
                ));
            }
            Err(message) => problems.push(Problem::new(
                format!("camera {}", camera.id),
                "model",
                message,
            )),
        }
    }
    if problems.is_empty() {
        Ok(cameras)
    } else {
        Err(CaptureError::Invalid {
            path: location.dir.clone(),
            problems,
        })
    }
}

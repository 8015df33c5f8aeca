//! The model folder written by training and read by `render`, `eval`, `export` and `relight`:
//!
//! ```text
//! MODEL/
//!   model.json        mode, world up, learned polarizer angles, training time, surfel count,
//!                     the working resolution
//!   config.json       the resolved training configuration
//!   surfels.ply       surfels (3DGS-viewer properties + albedo, roughness, IoR)
//!   envmap.exr        the learned environment, lat-long linear HDR (CAPTURE_FORMAT.md §5)
//!   envmap_cube.exr   the learned cube map's stored texels (6 faces stacked vertically), exact
//!   progress.jsonl    training events, one JSON object per line
//!   checkpoint.bin    resumable training state
//!   metrics.json      evaluation on the capture's test views
//!   test_cameras.json the capture's test cameras (for renders of the model alone)
//!   train_cameras.json the capture's training cameras (mesh extraction for GridMap and export)
//! ```

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use glam::DVec3;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::core::camera::Camera;
use crate::core::config::{Mode, TrainConfig};
use crate::core::envmap::{CubeMap, EnvMapError, WorldUp};
use crate::core::raster::RasterSettings;
use crate::core::resolution::Resolution;
use crate::core::surfels::{self, Surfels};
use crate::formats::image_io::{self, Image, ImageError};
use crate::formats::ply::PlyError;

/// Cameras of the capture's test views, in the transforms format.
pub const TEST_CAMERAS_FILE: &str = "test_cameras.json";

/// Cameras of the capture's training views, in the transforms format.
pub const TRAIN_CAMERAS_FILE: &str = "train_cameras.json";

/// Height of the exported lat-long environment map (width is twice this).
pub const LATLONG_HEIGHT: usize = 256;

#[derive(Debug, Error)]
pub enum ModelError {
    #[error("model {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("model {path}: {message}")]
    Invalid { path: PathBuf, message: String },
    #[error(transparent)]
    Ply(#[from] PlyError),
    #[error(transparent)]
    Image(#[from] ImageError),
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
}

/// What `model.json` records.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelInfo {
    pub mode: Mode,
    pub world_up: [f64; 3],
    /// Learned angle per `polarizer_group`, degrees in [0, 180).
    pub polarizer_angles_deg: BTreeMap<String, f64>,
    pub iterations: u32,
    pub train_seconds: f64,
    pub num_surfels: usize,
    pub backend: String,
    /// The resolution it was trained at (absent in models written before it was recorded: the
    /// capture's full resolution).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub working_resolution: Option<WorkingResolution>,
    /// Whether the training cameras' poses were refined (`pose_refinement`; absent in models
    /// written before it was recorded, and where the run never reached the point of deciding).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub refined_poses: Option<bool>,
    /// What `pose_refinement: auto` measured where it decided: how far the training views' masks
    /// lay beside the silhouettes the surfels rendered, each view's own part, RMS pixels
    /// (`pipeline::train::estimated_poses`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub silhouette_offset_px: Option<f64>,
    /// How a refined run was moved back into the capture's frame at its end
    /// (`PoseRefinement::register`); absent where the poses were not refined.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frame_registration: Option<FrameRegistration>,
}

/// The similarity a refined run was moved by to put it back in the capture's frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameRegistration {
    /// Its rotation's angle, degrees.
    pub angle_deg: f64,
    /// Its scale.
    pub scale: f64,
    /// How far it moved the object's centre, as a fraction of the object's radius.
    pub shift_radius: f64,
}

/// The size of the views a model was trained on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct WorkingResolution {
    /// The whole factor the capture's views were shrunk by (1: full resolution).
    pub downscale: u32,
    pub width: u32,
    pub height: u32,
    /// The capture's views before shrinking.
    pub full_width: u32,
    pub full_height: u32,
}

impl WorkingResolution {
    /// What `capture` was loaded at.
    pub fn of(capture: &crate::io::capture::Capture) -> Self {
        let (width, height) = capture
            .views
            .first()
            .map_or((0, 0), |v| (v.camera.width, v.camera.height));
        WorkingResolution {
            downscale: capture.downscale,
            width,
            height,
            full_width: capture.full_size.0,
            full_height: capture.full_size.1,
        }
    }

    /// The resolution that shows views of `width × height` at this working size: this factor for
    /// views of the size trained from, else the factor that brings their longest side to the
    /// working one (a raw capture's full-Stokes reference, rendered at the sensor's size, is
    /// compared at the size its mosaics were demosaiced and shrunk to for training).
    pub fn for_views(&self, width: u32, height: u32) -> Resolution {
        if (width, height) == (self.full_width, self.full_height) {
            Resolution::Downscale(self.downscale)
        } else {
            Resolution::LongestSide(self.width.max(self.height))
        }
    }
}

/// A trained reconstruction.
#[derive(Clone, Debug)]
pub struct Model {
    pub info: ModelInfo,
    pub config: TrainConfig,
    pub surfels: Surfels,
    pub envmap: CubeMap,
    /// The training cameras (`train_cameras.json`; empty for a folder without it): the views the
    /// mesh is extracted from.
    pub train_cameras: Vec<(String, Camera)>,
}

fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> ModelError + '_ {
    move |source| ModelError::Io {
        path: path.to_owned(),
        source,
    }
}

impl Model {
    /// The world up axis as the environment-map convention.
    pub fn world_up(&self) -> Result<WorldUp, EnvMapError> {
        WorldUp::from_vector(self.info.world_up)
    }

    /// Learned polarizer angles in radians.
    pub fn polarizer_angles(&self) -> BTreeMap<String, f64> {
        self.info
            .polarizer_angles_deg
            .iter()
            .map(|(k, v)| (k.clone(), v.to_radians()))
            .collect()
    }

    /// The rasterizer's settings the model was trained with (and renders with).
    pub fn raster_settings(&self) -> RasterSettings {
        self.config.raster_settings()
    }

    /// Writes every file of the model folder except the checkpoint, progress log and metrics.
    pub fn save(&self, dir: &Path) -> Result<(), ModelError> {
        std::fs::create_dir_all(dir).map_err(io_err(dir))?;
        write_json(&dir.join("model.json"), &self.info)?;
        write_json(&dir.join("config.json"), &self.config)?;
        surfels::ply::save_ply(&dir.join("surfels.ply"), &self.surfels)?;
        let latlong = self.envmap.to_latlong(LATLONG_HEIGHT, self.world_up()?);
        image_io::write_exr(&dir.join("envmap.exr"), &latlong)?;
        image_io::write_exr(&dir.join("envmap_cube.exr"), &cube_to_image(&self.envmap))?;
        if !self.train_cameras.is_empty() {
            write_json(
                &dir.join(TRAIN_CAMERAS_FILE),
                &crate::io::capture::cameras_to_json(&self.train_cameras),
            )?;
        }
        Ok(())
    }

    /// Reads a model folder.
    pub fn load(dir: &Path) -> Result<Model, ModelError> {
        let read_json = |name: &str| -> Result<String, ModelError> {
            let path = dir.join(name);
            std::fs::read_to_string(&path).map_err(io_err(&path))
        };
        let invalid = |name: &str, e: serde_json::Error| ModelError::Invalid {
            path: dir.join(name),
            message: e.to_string(),
        };
        let info: ModelInfo = serde_json::from_str(&read_json("model.json")?)
            .map_err(|e| invalid("model.json", e))?;
        let config: TrainConfig = serde_json::from_str(&read_json("config.json")?)
            .map_err(|e| invalid("config.json", e))?;
        let surfels = surfels::ply::load_ply(&dir.join("surfels.ply"))?;
        let (cube_image, _) = image_io::read_image(&dir.join("envmap_cube.exr"))?;
        let envmap = image_to_cube(&cube_image).ok_or_else(|| ModelError::Invalid {
            path: dir.join("envmap_cube.exr"),
            message: "not 6 square faces stacked vertically (RGB)".into(),
        })?;
        let cameras_path = dir.join(TRAIN_CAMERAS_FILE);
        let train_cameras = if cameras_path.exists() {
            crate::io::capture::load_cameras(&cameras_path).map_err(|e| ModelError::Invalid {
                path: cameras_path.clone(),
                message: e.to_string(),
            })?
        } else {
            Vec::new()
        };
        Ok(Model {
            info,
            config,
            surfels,
            envmap,
            train_cameras,
        })
    }
}

/// Stored cube texels as an image: faces stacked vertically (width D, height 6D), RGB.
pub fn cube_to_image(cube: &CubeMap) -> Image {
    Image {
        width: cube.size,
        height: 6 * cube.size,
        channels: 3,
        data: cube.raw.iter().map(|&v| v as f32).collect(),
    }
}

/// Inverse of [`cube_to_image`].
pub fn image_to_cube(img: &Image) -> Option<CubeMap> {
    if img.channels != 3 || img.height != 6 * img.width || img.width == 0 {
        return None;
    }
    CubeMap::from_raw(img.width, img.data.iter().map(|&v| f64::from(v)).collect()).ok()
}

/// A uniform grey environment of radiance 0.5, the starting point of the learned map.
pub fn initial_envmap(size: usize) -> Result<CubeMap, EnvMapError> {
    CubeMap::constant(size, DVec3::splat(0.5))
}

/// Writes a value as pretty JSON.
pub fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), ModelError> {
    let text = serde_json::to_string_pretty(value).expect("plain data serializes");
    std::fs::write(path, text).map_err(io_err(path))
}

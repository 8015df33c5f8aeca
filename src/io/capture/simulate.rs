//! A simulated polarization camera: rewrites a loaded full-Stokes capture as the raw mosaic frames
//! an IMX250MZR or IMX250MYR would record (`mosaic::mosaic_from_stokes`, scaled by an exposure and
//! quantized), with masks and a `transforms.json` using the `raw` keys, so the raw pipeline can be
//! tried and tested without a camera. Views are written in parallel (rayon, one per task).

use std::path::{Path, PathBuf};

use rayon::prelude::*;
use serde_json::json;
use thiserror::Error;

use super::mosaic::{self, Demosaic, MosaicError, Sensor};
use super::{Capture, Measurement, Split};
use crate::formats::image_io::{write_png, ImageError};

/// How raw frames are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameFile {
    /// Grey PNG, 8-bit for bit depths ≤ 8, else 16-bit.
    Png,
    /// Grey TIFF, 8- or 16-bit likewise.
    Tiff,
    /// Little-endian bytes (1 or 2 per sample) with `.raw` extension.
    Bytes,
}

/// The simulated camera.
#[derive(Clone, Debug)]
pub struct SimulateOptions {
    pub sensor: Sensor,
    pub bit_depth: u32,
    pub black_level: u32,
    /// Radiance that maps to the full count range (Stokes are multiplied by 1 / this).
    pub full_scale: f32,
    pub file: FrameFile,
    /// Written as the capture's `demosaic` key.
    pub demosaic: Demosaic,
    /// Label the polarizer angles towards image-down (`"stokes_convention": "image_y_down"`).
    pub image_y_down: bool,
    /// Written as the capture's `white_balance` (`None`: the gray-world default). The simulated
    /// colours are already balanced, so the default is `[1, 1, 1]`.
    pub white_balance: Option<[f64; 3]>,
}

impl Default for SimulateOptions {
    fn default() -> Self {
        SimulateOptions {
            sensor: Sensor::Imx250Mzr,
            bit_depth: 12,
            black_level: 0,
            full_scale: 1.0,
            file: FrameFile::Png,
            demosaic: Demosaic::Bilinear,
            image_y_down: false,
            white_balance: Some([1.0; 3]),
        }
    }
}

#[derive(Debug, Error)]
pub enum SimulateError {
    #[error("simulate: view {view} has no full-Stokes measurement")]
    NotStokes { view: String },
    #[error("simulate: cannot write {path}: {message}")]
    Write { path: PathBuf, message: String },
    #[error(transparent)]
    Mosaic(#[from] MosaicError),
    #[error(transparent)]
    Image(#[from] ImageError),
}

/// Writes grey samples as an 8/16-bit PNG or TIFF, or as little-endian bytes.
pub fn write_counts(
    path: &Path,
    width: usize,
    height: usize,
    counts: &[u16],
    bit_depth: u32,
    file: FrameFile,
) -> Result<(), SimulateError> {
    let err = |e: &dyn std::fmt::Display| SimulateError::Write {
        path: path.to_owned(),
        message: e.to_string(),
    };
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| err(&e))?;
    }
    let (w, h) = (width as u32, height as u32);
    match (file, bit_depth <= 8) {
        (FrameFile::Bytes, true) => {
            let bytes: Vec<u8> = counts.iter().map(|&c| c as u8).collect();
            std::fs::write(path, bytes).map_err(|e| err(&e))
        }
        (FrameFile::Bytes, false) => {
            let bytes: Vec<u8> = counts.iter().flat_map(|c| c.to_le_bytes()).collect();
            std::fs::write(path, bytes).map_err(|e| err(&e))
        }
        (_, true) => {
            let bytes: Vec<u8> = counts.iter().map(|&c| c as u8).collect();
            let buffer = image::GrayImage::from_raw(w, h, bytes).ok_or_else(|| err(&"size"))?;
            buffer.save(path).map_err(|e| err(&e))
        }
        (_, false) => {
            let buffer = image::ImageBuffer::<image::Luma<u16>, _>::from_raw(w, h, counts.to_vec())
                .ok_or_else(|| err(&"size"))?;
            buffer.save(path).map_err(|e| err(&e))
        }
    }
}

/// Writes `capture`'s views into `out_dir` as raw frames `raw/NNN.<ext>` and masks `mask/NNN.png`
/// (sensor resolution), with a `transforms.json` whose cameras are those of the views (the
/// sensor's resolution is the views'), splits kept.
pub fn write_raw_capture(
    capture: &Capture,
    out_dir: &Path,
    options: &SimulateOptions,
) -> Result<(), SimulateError> {
    let ext = match options.file {
        FrameFile::Png => "png",
        FrameFile::Tiff => "tif",
        FrameFile::Bytes => "raw",
    };
    let frames: Vec<Result<serde_json::Value, SimulateError>> = capture
        .views
        .par_iter()
        .enumerate()
        .map(|(k, view)| {
            let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
                return Err(SimulateError::NotStokes {
                    view: view.name.clone(),
                });
            };
            let mut m =
                mosaic::mosaic_from_stokes([s0, s1, s2], options.sensor, options.image_y_down)?;
            m.data.iter_mut().for_each(|v| *v /= options.full_scale);
            let counts = m.to_counts(options.bit_depth, options.black_level);
            let raw = format!("raw/{k:03}.{ext}");
            write_counts(
                &out_dir.join(&raw),
                m.width,
                m.height,
                &counts,
                options.bit_depth,
                options.file,
            )?;
            let mask = format!("mask/{k:03}.png");
            let mask_path = out_dir.join(&mask);
            std::fs::create_dir_all(mask_path.parent().expect("mask folder")).map_err(|e| {
                SimulateError::Write {
                    path: mask_path.clone(),
                    message: e.to_string(),
                }
            })?;
            write_png(&mask_path, &view.mask, false)?;
            let c = &view.camera;
            let mut frame = json!({
                "split": match view.split { Split::Train => "train", Split::Test => "test" },
                "transform_matrix": (0..4).map(|r| c.c2w.row(r).to_array()).collect::<Vec<_>>(),
                "w": c.width, "h": c.height,
                "fl_x": c.fx, "fl_y": c.fy, "cx": c.cx, "cy": c.cy,
                "raw": { "file": raw },
                "mask_path": mask,
            });
            if options.file == FrameFile::Bytes {
                frame["raw"]["width"] = json!(m.width);
                frame["raw"]["height"] = json!(m.height);
            }
            Ok(frame)
        })
        .collect();
    let frames = frames.into_iter().collect::<Result<Vec<_>, _>>()?;
    let mut doc = json!({
        "camera_convention": "OpenGL",
        "stokes_convention": if options.image_y_down { "image_y_down" } else { "image_y_up" },
        "world_up": capture.world_up.to_array(),
        "demosaic": match options.demosaic { Demosaic::Half => "half", Demosaic::Bilinear => "bilinear" },
        "raw": {
            "sensor": options.sensor.name(),
            "bit_depth": options.bit_depth,
            "black_level": options.black_level,
        },
        "frames": frames,
    });
    if let Some(gains) = options.white_balance {
        doc["white_balance"] = json!(gains);
    }
    let path = out_dir.join("transforms.json");
    let text = serde_json::to_string_pretty(&doc).map_err(|e| SimulateError::Write {
        path: path.clone(),
        message: e.to_string(),
    })?;
    std::fs::write(&path, text).map_err(|e| SimulateError::Write {
        path,
        message: e.to_string(),
    })
}

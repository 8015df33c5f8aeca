//! Writing a full-Stokes capture in a dataset layout, as a polarization camera's datasets ship it:
//! the four polarizer images I(θ) = ½ (S0 + S1 cos 2θ + S2 sin 2θ) of each view, scaled by an
//! exposure and sRGB-encoded, in per-angle folders; masks as 3-channel black/white PNGs; and the
//! cameras in the layout's own file.
//!
//! - IDR/NeuS: `I-00/`, `I-45/`, `I-90/`, `I-135/` of 8-bit JPEG `NNN.jpg`,
//!   `masks/NNN_pseudo.png`, `cameras_sphere.npz` with `world_mat_i` in a world frame that
//!   `scale_mat_i` maps the capture's frame into (scale 2.5, offset (0.3, −0.2, 0.1)), so reading
//!   must undo it.
//! - LLFF: `pol000/` … `pol135/` of 16-bit PNG `img_NNN.png` numbered from 1, `masks/img_NNN.png`,
//!   `poses_bounds.npy` (near/far: the camera's distance to the origin ∓ 1.5).
//!
//! Views keep the capture's order; the layouts have no split, so a capture whose test views are
//! every 8th (index % 8 == 0) reads back with the same split.

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use super::llff::{LlffPose, POSES_FILE, ROW_LENGTH};
use super::{idr, LayoutKind};
use crate::formats::image_io::{linear_to_srgb, Image};
use crate::io::capture::npy::{self, NpyError};
use crate::io::capture::{Capture, Measurement};

/// The frame `scale_mat` maps the written cameras from: world = scale · x + offset.
pub const IDR_SCALE: f64 = 2.5;
pub const IDR_OFFSET: [f64; 3] = [0.3, -0.2, 0.1];

/// Quality of the IDR layout's JPEG images.
const JPEG_QUALITY: u8 = 95;

#[derive(Debug, Error)]
pub enum LayoutWriteError {
    #[error("{0}")]
    Invalid(String),
    #[error("cannot write {path}: {message}")]
    Write { path: PathBuf, message: String },
    #[error(transparent)]
    Npy(#[from] NpyError),
}

/// What [`write_layout`] wrote.
#[derive(Clone, Debug, PartialEq)]
pub struct WrittenLayout {
    pub views: usize,
    /// The factor linear intensities were multiplied by before encoding (the brightest polarizer
    /// sample becomes 1).
    pub exposure: f32,
}

/// The per-angle folder names of a layout.
pub fn angle_folders(kind: LayoutKind) -> [&'static str; 4] {
    match kind {
        LayoutKind::Idr => ["I-00", "I-45", "I-90", "I-135"],
        LayoutKind::Llff => ["pol000", "pol045", "pol090", "pol135"],
    }
}

/// The file stem of view `k` in a layout.
fn stem(kind: LayoutKind, k: usize) -> String {
    match kind {
        LayoutKind::Idr => format!("{k:03}"),
        LayoutKind::Llff => format!("img_{:03}", k + 1),
    }
}

/// The four polarizer images (0°, 45°, 90°, 135°, image_y_up) of a view's Stokes images.
pub fn polarizer_images(s0: &Image, s1: &Image, s2: &Image) -> [Image; 4] {
    let signs = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)];
    signs.map(|(c, s)| Image {
        data: s0
            .data
            .iter()
            .zip(&s1.data)
            .zip(&s2.data)
            .map(|((a, b), d)| 0.5 * (a + c * b + s * d))
            .collect(),
        ..s0.clone()
    })
}

fn write_error(path: &Path, e: impl std::fmt::Display) -> LayoutWriteError {
    LayoutWriteError::Write {
        path: path.to_owned(),
        message: e.to_string(),
    }
}

/// sRGB-encoded samples of `linear · exposure`, quantized to `max` (255 or 65535).
fn encode(image: &Image, exposure: f32, max: f32) -> Vec<u16> {
    image
        .data
        .iter()
        .map(|&v| (linear_to_srgb(v * exposure).clamp(0.0, 1.0) * max + 0.5) as u16)
        .collect()
}

fn write_jpeg(path: &Path, image: &Image, exposure: f32) -> Result<(), LayoutWriteError> {
    let bytes: Vec<u8> = encode(image, exposure, 255.0)
        .into_iter()
        .map(|v| v as u8)
        .collect();
    let file = std::fs::File::create(path).map_err(|e| write_error(path, e))?;
    let mut encoder = image::codecs::jpeg::JpegEncoder::new_with_quality(
        std::io::BufWriter::new(file),
        JPEG_QUALITY,
    );
    encoder
        .encode(
            &bytes,
            image.width as u32,
            image.height as u32,
            image::ExtendedColorType::Rgb8,
        )
        .map_err(|e| write_error(path, e))
}

fn write_png16(path: &Path, image: &Image, exposure: f32) -> Result<(), LayoutWriteError> {
    let buffer = image::ImageBuffer::<image::Rgb<u16>, _>::from_raw(
        image.width as u32,
        image.height as u32,
        encode(image, exposure, 65535.0),
    )
    .ok_or_else(|| write_error(path, "image size"))?;
    buffer.save(path).map_err(|e| write_error(path, e))
}

/// A binary mask as a 3-channel 8-bit black/white PNG.
fn write_rgb_mask(path: &Path, mask: &Image) -> Result<(), LayoutWriteError> {
    let bytes: Vec<u8> = mask
        .data
        .iter()
        .flat_map(|&v| [if v > 0.5 { 255u8 } else { 0 }; 3])
        .collect();
    image::save_buffer(
        path,
        &bytes,
        mask.width as u32,
        mask.height as u32,
        image::ExtendedColorType::Rgb8,
    )
    .map_err(|e| write_error(path, e))
}

/// Writes `capture` (full-Stokes views, one size) into `out` in the `kind` layout.
pub fn write_layout(
    capture: &Capture,
    out: &Path,
    kind: LayoutKind,
) -> Result<WrittenLayout, LayoutWriteError> {
    let mut stokes = Vec::with_capacity(capture.views.len());
    for view in &capture.views {
        match &view.measurement {
            Measurement::Stokes { s0, s1, s2 } => stokes.push(polarizer_images(s0, s1, s2)),
            _ => {
                return Err(LayoutWriteError::Invalid(format!(
                    "{}: only full-Stokes views can be written in a dataset layout",
                    view.name
                )))
            }
        }
    }
    let peak = stokes
        .iter()
        .flatten()
        .flat_map(|i| i.data.iter().copied())
        .fold(0.0f32, f32::max);
    if peak.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(LayoutWriteError::Invalid(
            "the capture's views are black".into(),
        ));
    }
    let exposure = 1.0 / peak;
    let folders = angle_folders(kind);
    for folder in folders.iter().chain(&["masks"]) {
        let dir = out.join(folder);
        std::fs::create_dir_all(&dir).map_err(|e| write_error(&dir, e))?;
    }
    for (k, (view, images)) in capture.views.iter().zip(&stokes).enumerate() {
        let stem = stem(kind, k);
        for (folder, image) in folders.iter().zip(images) {
            match kind {
                LayoutKind::Idr => write_jpeg(
                    &out.join(folder).join(format!("{stem}.jpg")),
                    image,
                    exposure,
                )?,
                LayoutKind::Llff => write_png16(
                    &out.join(folder).join(format!("{stem}.png")),
                    image,
                    exposure,
                )?,
            }
        }
        let mask_name = match kind {
            LayoutKind::Idr => format!("{stem}_pseudo.png"),
            LayoutKind::Llff => format!("{stem}.png"),
        };
        write_rgb_mask(&out.join("masks").join(mask_name), &view.mask)?;
    }
    match kind {
        LayoutKind::Idr => {
            let offset = DVec3::from_array(IDR_OFFSET);
            let scale_mat = idr::scale_mat(IDR_SCALE, offset);
            let mut arrays = Vec::new();
            for (k, view) in capture.views.iter().enumerate() {
                let world_mat = idr::world_mat_of(&view.camera, IDR_SCALE, offset);
                arrays.push((
                    format!("world_mat_{k}"),
                    vec![4, 4],
                    idr::rows_of_mat4(&world_mat),
                ));
                arrays.push((
                    format!("scale_mat_{k}"),
                    vec![4, 4],
                    idr::rows_of_mat4(&scale_mat),
                ));
            }
            npy::write_npz(&out.join(idr::CAMERA_FILES[0]), &arrays)?;
        }
        LayoutKind::Llff => {
            let mut rows = Vec::with_capacity(capture.views.len() * ROW_LENGTH);
            for view in &capture.views {
                let c = &view.camera;
                let centred = (c.cx - f64::from(c.width) / 2.0).abs() < 1e-9
                    && (c.cy - f64::from(c.height) / 2.0).abs() < 1e-9;
                if (c.fx - c.fy).abs() > 1e-9 * c.fx || !centred {
                    return Err(LayoutWriteError::Invalid(format!(
                        "{}: LLFF poses hold one focal length and a centred principal point",
                        view.name
                    )));
                }
                let distance = c.origin().length();
                let pose = LlffPose::of_camera(c, (distance - 1.5).max(0.01), distance + 1.5);
                rows.extend_from_slice(&pose.to_row());
            }
            npy::write_npy(
                &out.join(POSES_FILE),
                &[capture.views.len(), ROW_LENGTH],
                &rows,
            )?;
        }
    }
    Ok(WrittenLayout {
        views: capture.views.len(),
        exposure,
    })
}

//! Raw polarization-mosaic frames in a capture, as [`super::raw_frame`] parsed them: reading the
//! frame files (8/16-bit grey PNG or TIFF, or little-endian `.raw` bytes), checking their sizes
//! against the camera, and turning them into full-Stokes views: demosaic (`mosaic.rs`),
//! least-squares Stokes in the capture's angle convention, white balance.
//!
//! Validation records a [`Problem`] (frame, key, what is wrong) for every broken rule, like the rest
//! of the loader. Called per frame from the loader's rayon iterator; white balance runs once after.

use serde::Serialize;

use super::error::Problem;
use super::frame::{FrameSpec, Header, Source, StokesConvention};
use super::images::{mask_from_file, LoadedView};
use super::json::{KeyedPath, TOP_LEVEL};
use super::mosaic::{self, Demosaic, Mosaic};
use super::raw_frame::{RawFrame, RawSettings, WhiteBalance};
use super::{Measurement, View};
use crate::formats::image_io::{decoder_limits, Image, ImageLimits};

/// What the capture did with raw frames (reported by `phygap inspect`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RawReport {
    /// Frames (indices in `frames`) read from raw mosaics.
    pub frames: Vec<usize>,
    pub demosaic: Demosaic,
    /// The R, G, B gains applied to colour frames (`null` without colour frames).
    pub white_balance_gains: Option<[f64; 3]>,
    /// `"given"` or `"gray_world"` (`null` without colour frames).
    pub white_balance: Option<String>,
}

/// Integer samples of a raw frame file and the bits its container holds.
fn read_counts(
    raw: &RawFrame,
    problem: &dyn Fn(String) -> Problem,
) -> Result<(usize, usize, Vec<u16>, u32), Problem> {
    let shown = raw.file.relative.display();
    if !raw.file.path.is_file() {
        return Err(problem(format!("missing file {shown}")));
    }
    let is_bytes = raw
        .file
        .path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("raw"));
    let (w, h) = (
        raw.given_size.0.map_or(raw.sensor_size.0, |v| v as usize),
        raw.given_size.1.map_or(raw.sensor_size.1, |v| v as usize),
    );
    if is_bytes {
        let per_sample = if raw.bit_depth <= 8 { 1 } else { 2 };
        let expected = (w as u64) * (h as u64) * per_sample as u64;
        let wrong_size = |found: u64| {
            problem(format!(
                "{shown} holds {found} bytes but {w}×{h} samples of {} bits ({per_sample} byte{}{}) need {expected}",
                raw.bit_depth,
                if per_sample == 1 { "" } else { "s" },
                if per_sample == 2 { ", little-endian" } else { "" },
            ))
        };
        // The file's length is checked before it is read: it is the size the frame declares.
        let length = std::fs::metadata(&raw.file.path)
            .map_err(|e| problem(format!("{shown}: cannot read file: {e}")))?
            .len();
        if length != expected {
            return Err(wrong_size(length));
        }
        let bytes = std::fs::read(&raw.file.path)
            .map_err(|e| problem(format!("{shown}: cannot read file: {e}")))?;
        if bytes.len() as u64 != expected {
            return Err(wrong_size(bytes.len() as u64));
        }
        let counts = if per_sample == 1 {
            bytes.iter().map(|&b| b as u16).collect()
        } else {
            bytes
                .chunks_exact(2)
                .map(|c| u16::from_le_bytes([c[0], c[1]]))
                .collect()
        };
        return Ok((w, h, counts, 8 * per_sample as u32));
    }
    let open = || {
        image::ImageReader::open(&raw.file.path)
            .and_then(|r| r.with_guessed_format())
            .map_err(|e| problem(format!("{shown}: cannot read file: {e}")))
    };
    // The header's size is checked against the sensor's before anything is decoded.
    let (file_w, file_h) = open()?
        .into_dimensions()
        .map_err(|e| problem(format!("{shown}: corrupt or unreadable image: {e}")))?;
    let (file_w, file_h) = (file_w as usize, file_h as usize);
    if (file_w, file_h) != raw.sensor_size {
        // No samples: the caller's first check names the size mismatch.
        return Ok((file_w, file_h, Vec::new(), 16));
    }
    let mut reader = open()?;
    reader.limits(decoder_limits(&ImageLimits::pixels(file_w, file_h)));
    let decoded = reader
        .decode()
        .map_err(|e| problem(format!("{shown}: corrupt or unreadable image: {e}")))?;
    let (w, h) = (decoded.width() as usize, decoded.height() as usize);
    match decoded {
        image::DynamicImage::ImageLuma8(img) => {
            Ok((w, h, img.into_raw().into_iter().map(u16::from).collect(), 8))
        }
        image::DynamicImage::ImageLuma16(img) => Ok((w, h, img.into_raw(), 16)),
        other => Err(problem(format!(
            "{shown} is a {:?} image; a mosaic frame is one grey channel of 8 or 16 bits",
            other.color()
        ))),
    }
}

/// Reads the raw frame and mask of `spec` into a full-Stokes view.
pub(crate) fn load_view(
    spec: &FrameSpec,
    header: &Header,
    raw: &RawFrame,
) -> Result<LoadedView, Vec<Problem>> {
    let problem = |message: String| Problem::new(spec.name.clone(), raw.file.key, message);
    let shown = raw.file.relative.display().to_string();
    let (out_w, out_h) = (spec.camera.width as usize, spec.camera.height as usize);
    let mut problems = Vec::new();

    let stokes = read_counts(raw, &problem).and_then(|(w, h, counts, container_bits)| {
        if (w, h) != raw.sensor_size {
            return Err(problem(format!(
                "{shown} is {w}×{h} pixels but the camera's w×h is {}×{}; raw frames and the intrinsics are at the sensor's full resolution (phygap halves the intrinsics in demosaic \"half\" mode)",
                raw.sensor_size.0, raw.sensor_size.1
            )));
        }
        if raw.bit_depth > container_bits {
            return Err(problem(format!(
                "{shown} holds {container_bits}-bit samples but raw.bit_depth is {}",
                raw.bit_depth
            )));
        }
        let max = mosaic::max_count(raw.bit_depth);
        if let Some(p) = counts.iter().position(|&c| c as f64 > max) {
            return Err(problem(format!(
                "{shown} has the sample {} at x = {}, y = {}, above the {}-bit maximum {max} (a file storing its samples in the high bits needs raw.bit_depth {container_bits})",
                counts[p],
                p % w,
                p / w,
                raw.bit_depth
            )));
        }
        let clipped = counts.iter().filter(|&&c| c as f64 >= max).count();
        let clipped_fraction = clipped as f64 / counts.len().max(1) as f64;
        let mosaic = Mosaic::from_counts(w, h, &counts, raw.bit_depth, raw.black_level)
            .map_err(|e| problem(format!("{shown}: {e}")))?;
        let polarizers = mosaic::demosaic(&mosaic, raw.sensor, raw.demosaic)
            .map_err(|e| problem(format!("{shown}: {e}")))?;
        let y_down = header.stokes_convention == StokesConvention::ImageYDown;
        let [s0, s1, s2] = mosaic::stokes_from_polarizers(
            &polarizers.images,
            mosaic::channel_angles_image_y_up(y_down),
        );
        Ok(([s0.to_rgb(), s1.to_rgb(), s2.to_rgb()], clipped_fraction))
    });
    let stokes = stokes.map_err(|p| problems.push(p)).ok();
    let mask = spec
        .mask
        .as_ref()
        .map(|file| read_mask(spec, raw, file, (out_w, out_h)))
        .transpose()
        .map_err(|p| problems.push(p))
        .ok();
    let (Some(([s0, s1, s2], clipped_fraction)), Some(mask)) = (stokes, mask) else {
        return Err(problems);
    };
    let whole_image_mask = mask.is_none();
    Ok(LoadedView {
        view: View {
            name: spec.name.clone(),
            frame_index: spec.index,
            split: spec.split,
            camera: spec.camera,
            measurement: Measurement::Stokes { s0, s1, s2 },
            mask: mask.unwrap_or_else(|| Image::filled(out_w, out_h, 1, 1.0)),
            ground_truth: spec.ground_truth.clone(),
        },
        whole_image_mask,
        clipped_fraction,
    })
}

/// A raw frame's mask: at the views' resolution, or (in `half` mode) at the sensor's, reduced to
/// the views' by calling a 2×2 block object when at least two of its pixels are.
fn read_mask(
    spec: &FrameSpec,
    raw: &RawFrame,
    file: &KeyedPath,
    (out_w, out_h): (usize, usize),
) -> Result<Image, Problem> {
    let problem = |message: String| Problem::new(spec.name.clone(), file.key, message);
    let shown = file.relative.display();
    let (image, _) = super::images::read_sized(file, &[(out_w, out_h), raw.sensor_size], |w, h| {
        format!(
            "{shown} is {w}×{h} pixels but the view is {out_w}×{out_h} (the sensor {}×{})",
            raw.sensor_size.0, raw.sensor_size.1
        )
    })
    .map_err(problem)?;
    let mask = mask_from_file(&image, &shown.to_string()).map_err(problem)?;
    if (mask.width, mask.height) == (out_w, out_h) {
        return Ok(mask);
    }
    if (mask.width, mask.height) == raw.sensor_size {
        return Ok(Image::from_fn(out_w, out_h, 1, |x, y, o| {
            let sum: f32 = [(0, 0), (1, 0), (0, 1), (1, 1)]
                .iter()
                .map(|(dx, dy)| mask.pixel(2 * x + dx, 2 * y + dy)[0])
                .sum();
            o[0] = if sum >= 2.0 { 1.0 } else { 0.0 };
        }));
    }
    Err(problem(format!(
        "{shown} is {}×{} pixels but the view is {out_w}×{out_h} (the sensor {}×{})",
        mask.width, mask.height, raw.sensor_size.0, raw.sensor_size.1
    )))
}

/// Applies the capture's white balance to its colour raw views (same order as `frames`) and says
/// what was done. Gray world: gains `mean(G) / mean(c)` of S0 over every pixel of every colour raw
/// view, one set for the whole capture so that views stay consistent.
pub(crate) fn balance_white(
    frames: &[FrameSpec],
    views: &mut [View],
    settings: &RawSettings,
) -> Result<Option<RawReport>, Problem> {
    let raw_frames: Vec<usize> = frames
        .iter()
        .filter(|f| matches!(f.source, Source::Raw(_)))
        .map(|f| f.index)
        .collect();
    if raw_frames.is_empty() {
        return Ok(None);
    }
    let colour: Vec<usize> = frames
        .iter()
        .enumerate()
        .filter(|(_, f)| matches!(&f.source, Source::Raw(r) if r.sensor.is_colour()))
        .map(|(i, _)| i)
        .collect();
    let mut report = RawReport {
        frames: raw_frames,
        demosaic: settings.demosaic,
        white_balance_gains: None,
        white_balance: None,
    };
    if colour.is_empty() {
        return Ok(Some(report));
    }
    let (gains, how) = match settings.white_balance {
        WhiteBalance::Gains(g) => (g, "given"),
        WhiteBalance::GrayWorld => {
            let mut sums = [0.0f64; 3];
            for &i in &colour {
                if let Measurement::Stokes { s0, .. } = &views[i].measurement {
                    for (p, v) in s0.data.iter().enumerate() {
                        sums[p % 3] += *v as f64;
                    }
                }
            }
            if sums.iter().any(|s| s.is_nan() || *s <= 0.0) {
                return Err(Problem::new(
                    TOP_LEVEL,
                    "white_balance",
                    format!(
                        "gray-world white balance needs a positive mean in R, G and B over the colour raw frames (sums {sums:?}); give \"white_balance\": [r, g, b]"
                    ),
                ));
            }
            ([sums[1] / sums[0], 1.0, sums[1] / sums[2]], "gray_world")
        }
    };
    for &i in &colour {
        if let Measurement::Stokes { s0, s1, s2 } = &mut views[i].measurement {
            for image in [s0, s1, s2] {
                for (p, v) in image.data.iter_mut().enumerate() {
                    *v *= gains[p % 3] as f32;
                }
            }
        }
    }
    report.white_balance_gains = Some(gains);
    report.white_balance = Some(how.to_owned());
    Ok(Some(report))
}

//! A realistic capture from a clean one (`phygap degrade`): what a polarization camera, its
//! calibration and its masking would have given instead of a renderer's exact images, poses and
//! masks.
//!
//! Per view, from the clean linear Stokes S0–S2, the four polarizer images are recomputed as a
//! sensor measures them, I(θ) = ½ (S0 + S1 cos 2(θ + δ) + S2 sin 2(θ + δ)) with δ the polarizer
//! angle offset, then each sample goes through the sensor model:
//!
//! ```text
//! x  = I · gain · exposure_v · wb_v[c] · vignette(u, v)     fraction of full scale
//! e  = Poisson(x · full_well) + Normal(0, (read_noise · full_well)²)      electrons
//! DN = clamp(round(e / full_well · (2^bits − 1)), 0, 2^bits − 1)
//! ```
//!
//! `gain` puts the 99.5th percentile of the object's S0 at [`FULL_SCALE_TARGET`] of full scale (one
//! value for the whole capture, so exposure differences between views remain); `exposure_v` and
//! the per-channel `wb_v` are uniform in 1 ± their ranges, drawn per view; the vignette is
//! 1 − v · r² with r the distance to the image centre over the half diagonal. The images are
//! written as float EXR in the clean capture's radiance units (DN / (2^bits − 1) / gain: the same
//! units, so the metrics of models trained on both compare), as 16-bit linear PNG, or as 8-bit
//! sRGB JPEG at a quality. Poses get a rotation about the camera centre (σ in degrees) and a
//! translation (σ as a fraction of the object's radius), each random in direction with a
//! magnitude of root mean square σ; masks are eroded or dilated by a whole number of pixels drawn
//! per view in ±their range. A distant cluttered backdrop ([`super::backdrop`]) can be put behind
//! the object before the sensor sees it. Everything random comes from ChaCha streams seeded by
//! `seed` (one for the backdrop, one for the rest, in view order), so a run is reproducible.
//!
//! `degrade.json` beside the new `transforms.json` records the settings, the gain, each view's
//! exposure, white balance, mask change, true and noisy `transform_matrix`, so a pose-refinement
//! evaluation can compare.

use std::path::{Path, PathBuf};

use glam::{DMat4, DQuat, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use thiserror::Error;

use crate::formats::image_io::{linear_to_srgb, write_exr, write_png, Image, ImageError};

use super::backdrop::Backdrop;
use super::{CaptureError, Measurement, Split, View};

/// The object's 99.5th percentile of S0 lands at this fraction of full scale (before exposure).
pub const FULL_SCALE_TARGET: f64 = 0.8;
/// Mixed into the seed of the backdrop's random stream.
const BACKDROP_STREAM: u64 = 0xBAC_D209;

/// How the degraded per-angle images are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum OutputFormat {
    /// Float EXR in the clean capture's radiance units (after quantization and noise).
    Exr,
    /// 16-bit PNG holding the digital values linearly (`color_space: linear`).
    Png,
    /// 8-bit sRGB JPEG at [`DegradeOptions::jpeg_quality`].
    Jpeg,
}

/// The settings of a degradation; [`DegradeOptions::default`] changes nothing but the storage
/// (a 16-bit sensor, no noise, float EXR).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DegradeOptions {
    /// Bits of the sensor's digital values (1–16).
    pub bit_depth: u32,
    /// Full-well capacity in electrons: shot noise; `None`: no shot noise.
    pub full_well: Option<f64>,
    /// Read noise, standard deviation as a fraction of full scale.
    pub read_noise: f64,
    pub format: OutputFormat,
    /// JPEG quality 1–100 (with [`OutputFormat::Jpeg`]).
    pub jpeg_quality: u8,
    /// Per-view exposure factor uniform in 1 ± this.
    pub exposure_range: f64,
    /// Per-view, per-channel white-balance factor uniform in 1 ± this.
    pub white_balance_range: f64,
    /// Vignetting: 1 − this at the image corners.
    pub vignetting: f64,
    /// Pose rotation noise: root mean square of the rotation angle, in degrees.
    pub rotation_sigma_deg: f64,
    /// Pose translation noise: root mean square of the shift, as a fraction of the object's radius.
    pub translation_sigma: f64,
    /// Masks eroded (negative) or dilated (positive) by a whole number of pixels uniform in
    /// −this…this, per view.
    pub mask_px: u32,
    /// The polarizers sit this many degrees off their nominal 0/45/90/135°.
    pub polarizer_offset_deg: f64,
    /// A distant cluttered backdrop behind the object ([`super::backdrop`]), its mean this
    /// fraction of the object's bright level (its 99.5th percentile of S0); 0: black, as rendered.
    pub background: f64,
    pub seed: u64,
}

impl Default for DegradeOptions {
    fn default() -> Self {
        DegradeOptions {
            bit_depth: 16,
            full_well: None,
            read_noise: 0.0,
            format: OutputFormat::Exr,
            jpeg_quality: 90,
            exposure_range: 0.0,
            white_balance_range: 0.0,
            vignetting: 0.0,
            rotation_sigma_deg: 0.0,
            translation_sigma: 0.0,
            mask_px: 0,
            polarizer_offset_deg: 0.0,
            background: 0.0,
            seed: 0,
        }
    }
}

impl DegradeOptions {
    /// A machine-vision polarization camera: 12-bit, 10,000 e⁻ full well, read noise 0.5 % of
    /// full scale, exposure ±20 % and white balance ±10 % per view, pose noise 0.5° and 1 % of the
    /// object's radius, masks ±2 px.
    pub fn machine_vision() -> Self {
        DegradeOptions {
            bit_depth: 12,
            full_well: Some(10_000.0),
            read_noise: 0.005,
            exposure_range: 0.2,
            white_balance_range: 0.1,
            rotation_sigma_deg: 0.5,
            translation_sigma: 0.01,
            mask_px: 2,
            ..DegradeOptions::default()
        }
    }

    fn validate(&self) -> Result<(), DegradeError> {
        let bad = |what: String| Err(DegradeError::Option(what));
        if !(1..=16).contains(&self.bit_depth) {
            return bad(format!("bit depth {} (expected 1–16)", self.bit_depth));
        }
        if self.format == OutputFormat::Jpeg && self.bit_depth > 8 {
            return bad(format!(
                "JPEG stores 8 bits, but the bit depth is {}",
                self.bit_depth
            ));
        }
        if !(1..=100).contains(&self.jpeg_quality) {
            return bad(format!(
                "JPEG quality {} (expected 1–100)",
                self.jpeg_quality
            ));
        }
        if self.full_well.is_some_and(|w| !(w.is_finite() && w >= 1.0)) {
            return bad("full well must be at least 1 electron".to_owned());
        }
        let fractions = [
            ("read noise", self.read_noise),
            ("exposure range", self.exposure_range),
            ("white-balance range", self.white_balance_range),
            ("vignetting", self.vignetting),
        ];
        if !(self.background.is_finite() && (0.0..=4.0).contains(&self.background)) {
            return bad(format!(
                "background level {} (expected 0–4 times the object's)",
                self.background
            ));
        }
        for (name, v) in fractions {
            if !(v.is_finite() && (0.0..1.0).contains(&v)) {
                return bad(format!("{name} {v} (expected a fraction in [0, 1))"));
            }
        }
        for (name, v) in [
            ("rotation σ", self.rotation_sigma_deg),
            ("translation σ", self.translation_sigma),
            ("polarizer offset", self.polarizer_offset_deg),
        ] {
            if !v.is_finite() || (name != "polarizer offset" && v < 0.0) {
                return bad(format!("{name} {v}"));
            }
        }
        Ok(())
    }
}

/// Errors of [`degrade`].
#[derive(Debug, Error)]
pub enum DegradeError {
    #[error(transparent)]
    Capture(#[from] CaptureError),
    #[error(transparent)]
    Image(#[from] ImageError),
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("invalid setting: {0}")]
    Option(String),
    #[error(
        "{0} has no full-Stokes measurement: degrade needs S0–S2 (Stokes or polarizer images)"
    )]
    NotFullStokes(String),
}

/// What was done to one view.
#[derive(Clone, Debug, Serialize)]
pub struct ViewRecord {
    pub frame: usize,
    pub split: Split,
    pub exposure: f64,
    pub white_balance: [f64; 3],
    /// Pixels the mask grew (positive) or shrank (negative).
    pub mask_px: i32,
    /// Rotation of the pose error in degrees, and its translation in scene units.
    pub rotation_error_deg: f64,
    pub translation_error: f64,
    /// Camera-to-world, row-major, OpenGL axes: as rendered and as written.
    pub true_transform_matrix: [[f64; 4]; 4],
    pub noisy_transform_matrix: [[f64; 4]; 4],
}

/// `degrade.json`: the settings and what they drew.
#[derive(Clone, Debug, Serialize)]
pub struct DegradeRecord {
    pub source: PathBuf,
    pub options: DegradeOptions,
    /// Fraction of full scale per unit of the clean capture's radiance.
    pub gain: f64,
    pub object_radius: f64,
    pub views: Vec<ViewRecord>,
}

/// A sample of Normal(0, 1) (Box–Muller).
fn normal(rng: &mut ChaCha8Rng) -> f64 {
    let u: f64 = 1.0 - rng.random::<f64>();
    let v: f64 = rng.random();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// A sample of Poisson(λ): exact (Knuth) below 30, normal with continuity above.
fn poisson(rng: &mut ChaCha8Rng, lambda: f64) -> f64 {
    if lambda <= 0.0 {
        return 0.0;
    }
    if lambda < 30.0 {
        let limit = (-lambda).exp();
        let mut product: f64 = rng.random();
        let mut k = 0.0;
        while product > limit {
            product *= rng.random::<f64>();
            k += 1.0;
        }
        return k;
    }
    (lambda + lambda.sqrt() * normal(rng)).round().max(0.0)
}

/// The sensor model of the module doc on one value `x` (fraction of full scale): the digital
/// value over its maximum, in [0, 1].
pub fn sense(x: f64, options: &DegradeOptions, rng: &mut ChaCha8Rng) -> f64 {
    let levels = f64::from((1u32 << options.bit_depth) - 1);
    let noisy = match options.full_well {
        Some(well) => poisson(rng, x.max(0.0) * well) / well,
        None => x,
    } + options.read_noise * normal(rng);
    (noisy.clamp(0.0, 1.0) * levels).round() / levels
}

/// `mask` (one channel, binary at 0.5) dilated (`px` > 0) or eroded (`px` < 0) by a disc of
/// radius |px| pixels.
pub fn morph_mask(mask: &Image, px: i32) -> Image {
    if px == 0 {
        return mask.clone();
    }
    let (w, h) = (mask.width as i64, mask.height as i64);
    let r = i64::from(px.unsigned_abs());
    let on = |x: i64, y: i64| {
        (0..w).contains(&x)
            && (0..h).contains(&y)
            && mask.data[(y * w + x) as usize * mask.channels] >= 0.5
    };
    let dilate = px > 0;
    Image::from_fn(mask.width, mask.height, 1, |x, y, out| {
        let (x, y) = (x as i64, y as i64);
        let mut hit = !dilate;
        'search: for dy in -r..=r {
            for dx in -r..=r {
                if dx * dx + dy * dy > r * r {
                    continue;
                }
                // Dilation: any object pixel in the disc; erosion: every pixel of it object.
                if dilate == on(x + dx, y + dy) {
                    hit = dilate;
                    break 'search;
                }
            }
        }
        out[0] = f32::from(hit);
    })
}

/// `c2w` moved by a rotation about the camera centre whose angle has the root mean square
/// `rotation_sigma_deg` (a rotation vector of per-axis σ `rotation_sigma_deg / √3`) and a
/// translation whose length has the root mean square `translation_sigma`.
fn perturbed_pose(
    c2w: DMat4,
    rotation_sigma_deg: f64,
    translation_sigma: f64,
    rng: &mut ChaCha8Rng,
) -> DMat4 {
    let per_axis = 1.0 / 3f64.sqrt();
    let sigma = rotation_sigma_deg.to_radians() * per_axis;
    let omega = DVec3::new(normal(rng), normal(rng), normal(rng)) * sigma;
    let shift = DVec3::new(normal(rng), normal(rng), normal(rng)) * translation_sigma * per_axis;
    let rotation = if omega.length() > 0.0 {
        DQuat::from_scaled_axis(omega)
    } else {
        DQuat::IDENTITY
    };
    let (scale, q, t) = c2w.to_scale_rotation_translation();
    DMat4::from_scale_rotation_translation(scale, rotation * q, t + shift)
}

fn row_major(m: &DMat4) -> [[f64; 4]; 4] {
    m.transpose().to_cols_array_2d()
}

/// The angle in degrees of the rotation between two camera-to-world matrices.
pub fn rotation_between_deg(a: &DMat4, b: &DMat4) -> f64 {
    let (_, qa, _) = a.to_scale_rotation_translation();
    let (_, qb, _) = b.to_scale_rotation_translation();
    qa.angle_between(qb).to_degrees()
}

/// The gain that puts the 99.5th percentile of the object's S0 (brightest channel) of `views` at
/// [`FULL_SCALE_TARGET`].
fn capture_gain(views: &[View]) -> f64 {
    let mut values: Vec<f32> = Vec::new();
    for view in views {
        if let Measurement::Stokes { s0, .. } = &view.measurement {
            for (p, m) in s0.data.chunks(s0.channels).zip(&view.mask.data) {
                if *m >= 0.5 {
                    values.push(p.iter().copied().fold(0.0, f32::max));
                }
            }
        }
    }
    if values.is_empty() {
        return 1.0;
    }
    let at = (values.len() * 995 / 1000).min(values.len() - 1);
    let (_, p, _) = values.select_nth_unstable_by(at, f32::total_cmp);
    FULL_SCALE_TARGET / f64::from(p.max(1e-6))
}

/// The four degraded polarizer images of one view, as fractions of full scale.
fn sensed_images(
    s: [&Image; 3],
    gain: f64,
    exposure: f64,
    white_balance: [f64; 3],
    options: &DegradeOptions,
    rng: &mut ChaCha8Rng,
) -> [Image; 4] {
    let [s0, s1, s2] = s;
    let (w, h) = (s0.width, s0.height);
    let half_diagonal = 0.5 * (w as f64).hypot(h as f64);
    let offset = options.polarizer_offset_deg.to_radians();
    [0.0f64, 45.0, 90.0, 135.0].map(|deg| {
        let t = 2.0 * (deg.to_radians() + offset);
        let (c, s) = (t.cos(), t.sin());
        Image::from_fn(w, h, 3, |x, y, out| {
            let r = (x as f64 + 0.5 - 0.5 * w as f64).hypot(y as f64 + 0.5 - 0.5 * h as f64)
                / half_diagonal;
            let vignette = 1.0 - options.vignetting * r * r;
            for (k, o) in out.iter_mut().enumerate() {
                let i = (y * w + x) * s0.channels + k.min(s0.channels - 1);
                let radiance = 0.5
                    * (f64::from(s0.data[i])
                        + f64::from(s1.data[i]) * c
                        + f64::from(s2.data[i]) * s);
                let signal = radiance * gain * exposure * white_balance[k] * vignette;
                *o = sense(signal, options, rng) as f32;
            }
        })
    })
}

/// Writes `image` (fractions of full scale) as a 16-bit PNG holding them linearly.
fn write_png16(path: &Path, image: &Image) -> Result<(), DegradeError> {
    let data: Vec<u16> = image
        .data
        .iter()
        .map(|&v| (v.clamp(0.0, 1.0) * 65535.0).round() as u16)
        .collect();
    let buffer = image::ImageBuffer::<image::Rgb<u16>, Vec<u16>>::from_raw(
        image.width as u32,
        image.height as u32,
        data,
    )
    .ok_or_else(|| DegradeError::Option("image buffer size".to_owned()))?;
    buffer.save(path).map_err(|e| {
        DegradeError::Image(ImageError::Encode {
            path: path.to_owned(),
            message: e.to_string(),
        })
    })
}

/// Writes `image` (fractions of full scale, linear) as an sRGB JPEG of `quality`.
fn write_jpeg(path: &Path, image: &Image, quality: u8) -> Result<(), DegradeError> {
    let bytes: Vec<u8> = image
        .data
        .iter()
        .map(|&v| (linear_to_srgb(v).clamp(0.0, 1.0) * 255.0).round() as u8)
        .collect();
    let encode_error = |message: String| {
        DegradeError::Image(ImageError::Encode {
            path: path.to_owned(),
            message,
        })
    };
    let file = std::fs::File::create(path).map_err(|source| DegradeError::Io {
        path: path.to_owned(),
        source,
    })?;
    let mut encoder =
        image::codecs::jpeg::JpegEncoder::new_with_quality(std::io::BufWriter::new(file), quality);
    encoder
        .encode(
            &bytes,
            image.width as u32,
            image.height as u32,
            image::ExtendedColorType::Rgb8,
        )
        .map_err(|e| encode_error(e.to_string()))
}

/// Degrades the capture at `source` into `out` (created if needed): per-angle images, masks,
/// `transforms.json` and `degrade.json`. Returns what was recorded.
pub fn degrade(
    source: &Path,
    out: &Path,
    options: &DegradeOptions,
) -> Result<DegradeRecord, DegradeError> {
    options.validate()?;
    let capture = super::load(source)?;
    if let Some(view) = capture
        .views
        .iter()
        .find(|v| !matches!(v.measurement, Measurement::Stokes { .. }))
    {
        return Err(DegradeError::NotFullStokes(view.name.clone()));
    }
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| DegradeError::Io { path, source }
    };
    for folder in ["pol000", "pol045", "pol090", "pol135", "mask"] {
        std::fs::create_dir_all(out.join(folder)).map_err(io(&out.join(folder)))?;
    }
    let gain = capture_gain(&capture.views);
    let radius = capture.object_bounds().radius;
    let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
    // Its own stream: drawing the backdrop takes nothing from the stream of the poses,
    // exposures, masks and noise.
    let backdrop = (options.background > 0.0).then(|| {
        Backdrop::new(
            options.background * FULL_SCALE_TARGET / gain,
            options.seed ^ BACKDROP_STREAM,
        )
    });
    let extension = match options.format {
        OutputFormat::Exr => "exr",
        OutputFormat::Png => "png",
        OutputFormat::Jpeg => "jpg",
    };
    let mut records = Vec::new();
    let mut frames = Vec::new();
    for (n, view) in capture.views.iter().enumerate() {
        let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
            unreachable!("checked above");
        };
        let mut uniform = |range: f64| 1.0 + range * (2.0 * rng.random::<f64>() - 1.0);
        let exposure = uniform(options.exposure_range);
        let white_balance = [0; 3].map(|_| uniform(options.white_balance_range));
        let mask_px = if options.mask_px == 0 {
            0
        } else {
            let r = options.mask_px as i32;
            rng.random_range(-r..=r)
        };
        let noisy = perturbed_pose(
            view.camera.c2w,
            options.rotation_sigma_deg,
            options.translation_sigma * radius,
            &mut rng,
        );
        let photographed;
        let s0 = match &backdrop {
            Some(backdrop) => {
                photographed = backdrop.behind(s0, &view.mask, &view.camera);
                &photographed
            }
            None => s0,
        };
        let images = sensed_images(
            [s0, s1, s2],
            gain,
            exposure,
            white_balance,
            options,
            &mut rng,
        );
        let mut frame = serde_json::json!({
            "transform_matrix": row_major(&noisy),
            "split": view.split,
            "mask_path": format!("mask/{n:03}.png"),
            "w": view.camera.width, "h": view.camera.height,
            "fl_x": view.camera.fx, "fl_y": view.camera.fy,
            "cx": view.camera.cx, "cy": view.camera.cy,
        });
        for (image, deg) in images.iter().zip(["000", "045", "090", "135"]) {
            let relative = format!("pol{deg}/{n:03}.{extension}");
            let path = out.join(&relative);
            match options.format {
                OutputFormat::Exr => {
                    let radiance = Image {
                        data: image
                            .data
                            .iter()
                            .map(|&v| (f64::from(v) / gain) as f32)
                            .collect(),
                        ..image.clone()
                    };
                    write_exr(&path, &radiance)?;
                }
                OutputFormat::Png => write_png16(&path, image)?,
                OutputFormat::Jpeg => write_jpeg(&path, image, options.jpeg_quality)?,
            }
            frame[format!("pol{deg}_path")] = relative.into();
        }
        write_png(
            &out.join(format!("mask/{n:03}.png")),
            &morph_mask(&view.mask, mask_px),
            false,
        )?;
        frames.push(frame);
        records.push(ViewRecord {
            frame: view.frame_index,
            split: view.split,
            exposure,
            white_balance,
            mask_px,
            rotation_error_deg: rotation_between_deg(&view.camera.c2w, &noisy),
            translation_error: (noisy.w_axis.truncate() - view.camera.c2w.w_axis.truncate())
                .length(),
            true_transform_matrix: row_major(&view.camera.c2w),
            noisy_transform_matrix: row_major(&noisy),
        });
    }
    let camera = &capture.views[0].camera;
    let mut document = serde_json::json!({
        "camera_convention": "OpenGL",
        "stokes_convention": "image_y_up",
        "world_up": [capture.world_up.x, capture.world_up.y, capture.world_up.z],
        "w": camera.width, "h": camera.height,
        "fl_x": camera.fx, "fl_y": camera.fy, "cx": camera.cx, "cy": camera.cy,
        "frames": frames,
    });
    match options.format {
        OutputFormat::Png => document["color_space"] = "linear".into(),
        OutputFormat::Jpeg => document["color_space"] = "srgb".into(),
        OutputFormat::Exr => {}
    }
    let record = DegradeRecord {
        source: capture.root.clone(),
        options: options.clone(),
        gain,
        object_radius: radius,
        views: records,
    };
    let write_json = |name: &str, value: &serde_json::Value| {
        let path = out.join(name);
        let text = serde_json::to_string_pretty(value).expect("JSON values serialize");
        std::fs::write(&path, text).map_err(io(&path))
    };
    write_json("transforms.json", &document)?;
    write_json(
        "degrade.json",
        &serde_json::to_value(&record).expect("the record serializes"),
    )?;
    Ok(record)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::camera::Camera;

    /// Mean and variance of `values`.
    fn moments(values: &[f64]) -> (f64, f64) {
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        (
            mean,
            values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0),
        )
    }

    #[test]
    fn a_flat_patch_has_the_mean_and_variance_of_the_sensor_model() {
        let options = DegradeOptions::machine_vision();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        // S0 = 0.6, unpolarized: every polarizer image is 0.3 of full scale at gain 1.
        let flat = |v: f32| Image::filled(100, 100, 3, v);
        let (s0, zero) = (flat(0.6), flat(0.0));
        let images = sensed_images([&s0, &zero, &zero], 1.0, 1.0, [1.0; 3], &options, &mut rng);
        let levels = 4095.0f64;
        let expected_variance = 0.3 / 10_000.0 + 0.005f64.powi(2) + 1.0 / (12.0 * levels * levels);
        for image in &images {
            let values: Vec<f64> = image.data.iter().map(|&v| f64::from(v)).collect();
            let (mean, variance) = moments(&values);
            assert!((mean - 0.3).abs() < 3e-4, "mean {mean}");
            assert!(
                (variance / expected_variance - 1.0).abs() < 0.05,
                "variance {variance} vs {expected_variance}"
            );
            // 12-bit values.
            assert!(values
                .iter()
                .all(|v| ((v * levels) - (v * levels).round()).abs() < 1e-3));
        }
        // Shot noise alone at a few electrons is Poisson: variance = mean.
        let shot = DegradeOptions {
            full_well: Some(20.0),
            ..DegradeOptions::default()
        };
        let values: Vec<f64> = (0..40_000)
            .map(|_| sense(0.1, &shot, &mut rng) * 20.0)
            .collect();
        let (mean, variance) = moments(&values);
        assert!(
            (mean - 2.0).abs() < 0.03 && (variance - 2.0).abs() < 0.08,
            "{mean} {variance}"
        );
    }

    #[test]
    fn pose_noise_has_the_requested_magnitude() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let camera = Camera::look_at(
            64,
            64,
            0.7,
            DVec3::new(0.0, -4.0, 1.0),
            DVec3::ZERO,
            DVec3::Z,
        );
        let (mut angles, mut shifts) = (Vec::new(), Vec::new());
        for _ in 0..4000 {
            let noisy = perturbed_pose(camera.c2w, 0.5, 0.01, &mut rng);
            angles.push(rotation_between_deg(&camera.c2w, &noisy).powi(2));
            shifts.push(
                (noisy.w_axis - camera.c2w.w_axis)
                    .truncate()
                    .length_squared(),
            );
            // Still a rigid camera-to-world.
            assert!(crate::core::camera::is_rigid(&noisy, 1e-9));
        }
        // σ is the root mean square of the angle and of the shift.
        let rms = |v: &[f64]| (v.iter().sum::<f64>() / v.len() as f64).sqrt();
        let (angle, shift) = (rms(&angles), rms(&shifts));
        assert!((angle / 0.5 - 1.0).abs() < 0.04, "{angle}");
        assert!((shift / 0.01 - 1.0).abs() < 0.04, "{shift}");
    }

    #[test]
    fn masks_grow_and_shrink_by_the_pixels_asked() {
        let disc = Image::from_fn(80, 80, 1, |x, y, out| {
            out[0] = f32::from((x as f64 - 39.5).hypot(y as f64 - 39.5) < 20.0);
        });
        let area = |m: &Image| m.data.iter().sum::<f32>() as f64;
        let radius = |m: &Image| (area(m) / std::f64::consts::PI).sqrt();
        assert!((radius(&disc) - 20.0).abs() < 0.2);
        assert!(
            (radius(&morph_mask(&disc, -2)) - 18.0).abs() < 0.25,
            "{}",
            radius(&morph_mask(&disc, -2))
        );
        assert!(
            (radius(&morph_mask(&disc, 2)) - 22.0).abs() < 0.25,
            "{}",
            radius(&morph_mask(&disc, 2))
        );
        assert_eq!(morph_mask(&disc, 0), disc);
    }

    /// A clean capture of a unit sphere (S0 0.5, DoLP 0.2) seen by four cameras, 32×32.
    fn clean_capture(dir: &Path) {
        let mut frames = Vec::new();
        for k in 0..4 {
            let a = k as f64 * 1.3;
            let eye = DVec3::new(4.0 * a.cos(), 4.0 * a.sin(), 0.5);
            let camera = Camera::look_at(32, 32, 40f64.to_radians(), eye, DVec3::ZERO, DVec3::Z);
            let inside = |x: usize, y: usize| {
                let ray = camera.pixel_dir(x as u32, y as u32);
                let b = eye.dot(ray);
                b * b - (eye.length_squared() - 1.0) > 0.0
            };
            let mask = Image::from_fn(32, 32, 1, |x, y, o| o[0] = f32::from(inside(x, y)));
            let stokes = |v: f32| {
                Image::from_fn(32, 32, 3, |x, y, o| {
                    o.fill(if inside(x, y) { v } else { 0.0 })
                })
            };
            for (name, image) in [
                ("s0", stokes(0.5)),
                ("s1", stokes(0.06)),
                ("s2", stokes(-0.08)),
            ] {
                write_exr(&dir.join(format!("{name}_{k}.exr")), &image).unwrap();
            }
            write_png(&dir.join(format!("mask_{k}.png")), &mask, false).unwrap();
            frames.push(serde_json::json!({
                "transform_matrix": row_major(&camera.c2w),
                "s0_path": format!("s0_{k}.exr"), "s1_path": format!("s1_{k}.exr"),
                "s2_path": format!("s2_{k}.exr"), "mask_path": format!("mask_{k}.png"),
                "split": if k == 3 { "test" } else { "train" },
            }));
        }
        let document = serde_json::json!({
            "w": 32, "h": 32, "camera_angle_x": 40f64.to_radians(), "frames": frames,
        });
        std::fs::write(dir.join("transforms.json"), document.to_string()).unwrap();
    }

    #[test]
    fn a_degraded_capture_reads_back_and_repeats_with_its_seed() {
        let clean = tempfile::tempdir().unwrap();
        clean_capture(clean.path());
        let out = tempfile::tempdir().unwrap();
        for format in [OutputFormat::Exr, OutputFormat::Png, OutputFormat::Jpeg] {
            let options = DegradeOptions {
                format,
                bit_depth: if format == OutputFormat::Jpeg { 8 } else { 12 },
                polarizer_offset_deg: 3.0,
                vignetting: 0.2,
                seed: 11,
                ..DegradeOptions::machine_vision()
            };
            let dir = out.path().join(format!("{format:?}"));
            let record = degrade(clean.path(), &dir, &options).unwrap();
            assert_eq!(record.views.len(), 4);
            assert!(
                (record.gain - FULL_SCALE_TARGET / 0.5).abs() < 1e-6,
                "{}",
                record.gain
            );
            let capture = super::super::load(&dir).unwrap();
            assert_eq!(capture.views.len(), 4);
            assert_eq!(capture.test_views().count(), 1);
            for (view, r) in capture.views.iter().zip(&record.views) {
                let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
                    panic!("Stokes from the four polarizer images");
                };
                assert!((0.8..1.2).contains(&r.exposure));
                assert!(r.white_balance.iter().all(|w| (0.9..1.1).contains(w)));
                assert!((-2..=2).contains(&r.mask_px));
                assert!(r.rotation_error_deg < 3.0 && r.rotation_error_deg > 0.0);
                // The written pose is the noisy one.
                assert_eq!(row_major(&view.camera.c2w), r.noisy_transform_matrix);
                // Mean S0 of the object's centre, back in radiance units.
                let centre = (16 * 32 + 16) * 3 + 1;
                let scale = match format {
                    OutputFormat::Exr => 1.0,
                    _ => record.gain,
                };
                let s0 = f64::from(s0.data[centre]) / scale / r.exposure / r.white_balance[1];
                assert!((s0 - 0.5).abs() < 0.06, "{format:?}: S0 {s0}");
                // The polarizer offset turns the AoLP by −3° (AoLP of the clean data: −26.6°).
                let aolp = 0.5 * f64::from(s2.data[centre]).atan2(f64::from(s1.data[centre]));
                assert!(
                    (aolp.to_degrees() - (-26.57 - 3.0)).abs() < 6.0,
                    "{format:?}: {aolp}"
                );
            }
        }
        // Same settings and seed, same files; another seed, other noise.
        let options = DegradeOptions {
            format: OutputFormat::Png,
            bit_depth: 12,
            polarizer_offset_deg: 3.0,
            vignetting: 0.2,
            seed: 11,
            ..DegradeOptions::machine_vision()
        };
        let again = out.path().join("again");
        degrade(clean.path(), &again, &options).unwrap();
        let read = |dir: &Path, file: &str| std::fs::read(dir.join(file)).unwrap();
        for file in [
            "degrade.json",
            "transforms.json",
            "pol045/002.png",
            "mask/001.png",
        ] {
            // The source folder is the same; only the output folder differs.
            assert!(
                read(&out.path().join("Png"), file) == read(&again, file),
                "{file}"
            );
        }
        let other = out.path().join("other");
        degrade(
            clean.path(),
            &other,
            &DegradeOptions {
                seed: 12,
                ..options
            },
        )
        .unwrap();
        assert!(read(&again, "pol045/002.png") != read(&other, "pol045/002.png"));
    }

    #[test]
    fn a_backdrop_shows_beyond_the_mask_and_changes_nothing_else() {
        let clean = tempfile::tempdir().unwrap();
        clean_capture(clean.path());
        let out = tempfile::tempdir().unwrap();
        let load = |background: f64| {
            // Without sensor noise, whose Poisson draws take a varying count of random numbers.
            let options = DegradeOptions {
                background,
                seed: 5,
                full_well: None,
                read_noise: 0.0,
                ..DegradeOptions::machine_vision()
            };
            let dir = out.path().join(format!("{background}"));
            let record = degrade(clean.path(), &dir, &options).unwrap();
            (super::super::load(&dir).unwrap(), record)
        };
        let (black, black_record) = load(0.0);
        let (photographed, record) = load(0.5);
        for (a, b) in black_record.views.iter().zip(&record.views) {
            assert_eq!(a.noisy_transform_matrix, b.noisy_transform_matrix);
            assert_eq!((a.exposure, a.mask_px), (b.exposure, b.mask_px));
        }
        let summary = photographed.summary();
        assert!(black.summary().background_level.unwrap() < 0.05);
        assert!(summary.background_level.unwrap() > 0.3, "{summary:?}");
        // The sphere's centre pixel sees no backdrop; a corner does.
        for (view, clean_view) in photographed.views.iter().zip(&black.views) {
            let (Measurement::Stokes { s0, .. }, Measurement::Stokes { s0: s0_black, .. }) =
                (&view.measurement, &clean_view.measurement)
            else {
                panic!("Stokes views");
            };
            let centre = (16 * 32 + 16) * 3 + 1;
            let ratio = s0.data[centre] / s0_black.data[centre];
            assert!((ratio - 1.0).abs() < 0.1, "{}: {ratio}", view.name);
            assert!(s0.data[1] > s0_black.data[1] + 0.05, "{}", view.name);
        }
    }

    #[test]
    fn settings_out_of_range_are_refused() {
        for options in [
            DegradeOptions {
                bit_depth: 0,
                ..DegradeOptions::default()
            },
            DegradeOptions {
                format: OutputFormat::Jpeg,
                ..DegradeOptions::machine_vision()
            },
            DegradeOptions {
                read_noise: -0.1,
                ..DegradeOptions::default()
            },
            DegradeOptions {
                full_well: Some(0.0),
                ..DegradeOptions::default()
            },
            DegradeOptions {
                background: f64::NAN,
                ..DegradeOptions::default()
            },
            DegradeOptions {
                background: -1.0,
                ..DegradeOptions::default()
            },
        ] {
            assert!(
                matches!(options.validate(), Err(DegradeError::Option(_))),
                "{options:?}"
            );
        }
    }
}

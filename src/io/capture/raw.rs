//! Raw polarization-mosaic frames in a capture: the `raw` keys of `transforms.json` (per frame, with
//! defaults in a top-level `raw` object), the capture-wide `demosaic` and `white_balance` keys,
//! reading the frame files (8/16-bit grey PNG or TIFF, or little-endian `.raw` bytes), checking
//! their sizes against the camera, and turning them into full-Stokes views: demosaic
//! (`mosaic.rs`), least-squares Stokes in the capture's angle convention, white balance.
//!
//! Validation records a [`Problem`] (frame, key, what is wrong) for every broken rule, like the rest
//! of the loader. Called per frame from the loader's rayon iterator; white balance runs once after.

use std::path::Path;

use serde::Serialize;
use serde_json::{Map, Value};

use super::error::Problem;
use super::frame::{FrameSpec, Header, KeyedPath, Source, StokesConvention, TOP_LEVEL};
use super::images::{binarize, LoadedView};
use super::json::Fields;
use super::mosaic::{self, Demosaic, Mosaic, Sensor};
use super::{Measurement, View};
use crate::core::camera::Camera;
use crate::formats::image_io::{decoder_limits, Image, ImageLimits};

/// Keys of a `raw` object (`file` only per frame).
const RAW_KEYS: [&str; 6] = [
    "file",
    "sensor",
    "bit_depth",
    "black_level",
    "width",
    "height",
];

/// Extensions of raw frame files.
const RAW_EXTENSIONS: [&str; 4] = ["png", "tif", "tiff", "raw"];

/// How colour frames are white-balanced (`white_balance` key).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) enum WhiteBalance {
    /// Gains that make the mean S0 of every colour raw view together equal in R, G and B.
    #[default]
    GrayWorld,
    /// Given gains for R, G, B.
    Gains([f64; 3]),
}

/// Per-frame raw keys given once in the top-level `raw` object.
#[derive(Clone, Debug, Default)]
struct RawDefaults {
    sensor: Option<Sensor>,
    bit_depth: Option<u32>,
    black_level: Option<u32>,
    width: Option<u32>,
    height: Option<u32>,
    /// Keys given at the top level with an invalid value (already reported there).
    invalid: Vec<&'static str>,
}

/// The capture-wide raw settings: the top-level `demosaic`, `white_balance` and `raw` keys.
#[derive(Clone, Debug, Default)]
pub(crate) struct RawSettings {
    pub demosaic: Demosaic,
    pub white_balance: WhiteBalance,
    defaults: RawDefaults,
}

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

/// One frame's raw mosaic, parsed but not read.
#[derive(Clone, Debug)]
pub(crate) struct RawFrame {
    pub file: KeyedPath,
    pub sensor: Sensor,
    pub bit_depth: u32,
    pub black_level: u32,
    /// `width`/`height` as given (they must agree with the camera's `w`/`h`).
    given_size: (Option<u32>, Option<u32>),
    /// The sensor's resolution (the camera's `w`, `h` as written); set by [`attach_camera`].
    pub sensor_size: (usize, usize),
    pub demosaic: Demosaic,
}

/// The `raw` object of a JSON value with every key prefixed `raw.` (so problems name `raw.key`).
fn prefixed(object: &Map<String, Value>) -> Map<String, Value> {
    object
        .iter()
        .map(|(k, v)| (format!("raw.{k}"), v.clone()))
        .collect()
}

fn unknown_keys(fields: &Fields, allowed: &[&str], problems: &mut Vec<Problem>) {
    for key in fields.object.keys() {
        let bare = key.trim_start_matches("raw.");
        if !allowed.contains(&bare) {
            problems.push(fields.problem(
                key,
                format!("unknown key (expected {})", allowed.join(", ")),
            ));
        }
    }
}

/// A whole number in `min..=max`, or `None` (absent, or invalid with a problem recorded).
fn integer(
    fields: &Fields,
    key: &str,
    min: u32,
    max: u32,
    problems: &mut Vec<Problem>,
) -> Option<u32> {
    let v = fields.number(key, problems)?;
    if v.fract() == 0.0 && v >= min as f64 && v <= max as f64 {
        Some(v as u32)
    } else {
        problems.push(fields.problem(
            key,
            format!("expected a whole number in {min}..={max}, found {v}"),
        ));
        None
    }
}

fn sensor(fields: &Fields, key: &str, problems: &mut Vec<Problem>) -> Option<Sensor> {
    let name = fields.string(key, problems)?;
    let sensor = Sensor::from_name(name);
    if sensor.is_none() {
        problems.push(fields.problem(
            key,
            format!(
                "unknown sensor {name:?} (expected {})",
                Sensor::NAMES.map(|n| format!("{n:?}")).join(" or ")
            ),
        ));
    }
    sensor
}

/// Reads the top-level `demosaic`, `white_balance` and `raw` keys.
pub(crate) fn parse_settings(top: &Fields, problems: &mut Vec<Problem>) -> RawSettings {
    let demosaic = match top.string("demosaic", problems) {
        None => Demosaic::default(),
        Some(name) => Demosaic::from_name(name).unwrap_or_else(|| {
            problems.push(top.problem(
                "demosaic",
                format!("unknown demosaic mode {name:?} (expected \"half\" or \"bilinear\")"),
            ));
            Demosaic::default()
        }),
    };
    let white_balance = match top.object.get("white_balance") {
        None => WhiteBalance::GrayWorld,
        Some(Value::String(s)) if s == "gray_world" => WhiteBalance::GrayWorld,
        Some(value) => {
            let gains: Option<Vec<f64>> = value
                .as_array()
                .filter(|a| a.len() == 3)
                .and_then(|a| a.iter().map(Value::as_f64).collect());
            match gains {
                Some(g) if g.iter().all(|v| v.is_finite() && *v > 0.0) => {
                    WhiteBalance::Gains([g[0], g[1], g[2]])
                }
                _ => {
                    problems.push(top.problem(
                        "white_balance",
                        format!(
                            "expected \"gray_world\" or three positive gains [r, g, b], found {value}"
                        ),
                    ));
                    WhiteBalance::GrayWorld
                }
            }
        }
    };
    let mut defaults = RawDefaults::default();
    match top.object.get("raw") {
        None => {}
        Some(Value::Object(object)) => {
            let object = prefixed(object);
            let fields = Fields::new(&object, TOP_LEVEL);
            unknown_keys(&fields, &RAW_KEYS[1..], problems);
            defaults.sensor = sensor(&fields, "raw.sensor", problems);
            defaults.bit_depth = integer(&fields, "raw.bit_depth", 1, 16, problems);
            defaults.black_level = integer(&fields, "raw.black_level", 0, 65534, problems);
            for (key, valid) in [
                ("sensor", defaults.sensor.is_some()),
                ("bit_depth", defaults.bit_depth.is_some()),
                ("black_level", defaults.black_level.is_some()),
            ] {
                if fields.has(&format!("raw.{key}")) && !valid {
                    defaults.invalid.push(key);
                }
            }
            defaults.width = integer(&fields, "raw.width", 1, u32::MAX, problems);
            defaults.height = integer(&fields, "raw.height", 1, u32::MAX, problems);
        }
        Some(other) => problems.push(top.problem(
            "raw",
            format!("expected an object of defaults for the frames' raw keys, found {other}"),
        )),
    }
    RawSettings {
        demosaic,
        white_balance,
        defaults,
    }
}

/// The file a frame's `raw` key names, for the frame's label.
pub(crate) fn file_name(frame: &Map<String, Value>) -> Option<&str> {
    match frame.get("raw")? {
        Value::String(s) => Some(s),
        Value::Object(o) => o.get("file").and_then(Value::as_str),
        _ => None,
    }
}

/// Parses a frame's `raw` key (a path, or an object with `file` and the other keys, each falling
/// back to the top-level `raw` object).
pub(crate) fn parse_frame(
    root: &Path,
    frame: &Fields,
    settings: &RawSettings,
    problems: &mut Vec<Problem>,
) -> Option<RawFrame> {
    let object = match frame.object.get("raw")? {
        Value::String(file) => {
            let mut o = Map::new();
            o.insert("raw.file".into(), Value::String(file.clone()));
            o
        }
        Value::Object(o) => prefixed(o),
        other => {
            problems.push(frame.problem(
                "raw",
                format!("expected an object with `file` (or a path), found {other}"),
            ));
            return None;
        }
    };
    let fields = Fields::new(&object, frame.frame.clone());
    let before = problems.len();
    unknown_keys(&fields, &RAW_KEYS, problems);
    let file = if fields.has("raw.file") {
        fields.path("raw.file", problems).map(|relative| KeyedPath {
            key: "raw.file",
            path: root.join(&relative),
            relative,
        })
    } else {
        problems.push(fields.problem("raw.file", "missing required key"));
        None
    };
    if let Some(file) = &file {
        let ext = file
            .relative
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .unwrap_or_default();
        if !RAW_EXTENSIONS.contains(&ext.as_str()) {
            problems.push(fields.problem(
                "raw.file",
                format!(
                    "unsupported raw frame type {} (expected .png, .tif, .tiff or .raw)",
                    file.relative.display()
                ),
            ));
        }
    }
    let defaults = &settings.defaults;
    let required = |key: &'static str,
                    value: Option<u32>,
                    default: Option<u32>,
                    problems: &mut Vec<Problem>| {
        let full = format!("raw.{key}");
        match (value, default) {
            (Some(v), _) => Some(v),
            (None, Some(d)) if !fields.has(&full) => Some(d),
            (None, _) if fields.has(&full) || defaults.invalid.contains(&key) => None,
            (None, _) => {
                problems.push(fields.problem(
                    &full,
                    "missing required key (give it in the frame's raw object or in the top-level raw object)",
                ));
                None
            }
        }
    };
    let sensor = match (sensor(&fields, "raw.sensor", problems), defaults.sensor) {
        (Some(s), _) => Some(s),
        (None, Some(d)) if !fields.has("raw.sensor") => Some(d),
        (None, _) if fields.has("raw.sensor") || defaults.invalid.contains(&"sensor") => None,
        (None, _) => {
            problems.push(fields.problem(
                "raw.sensor",
                format!(
                    "missing required key: the sensor ({}) in the frame's raw object or in the top-level raw object",
                    Sensor::NAMES.join(" or ")
                ),
            ));
            None
        }
    };
    let bit_depth = integer(&fields, "raw.bit_depth", 1, 16, problems);
    let bit_depth = required("bit_depth", bit_depth, defaults.bit_depth, problems);
    let black_level = integer(&fields, "raw.black_level", 0, 65534, problems);
    let black_level = if fields.has("raw.black_level") {
        black_level
    } else {
        Some(defaults.black_level.unwrap_or(0))
    };
    let width = integer(&fields, "raw.width", 1, u32::MAX, problems).or(defaults.width);
    let height = integer(&fields, "raw.height", 1, u32::MAX, problems).or(defaults.height);
    if let (Some(bits), Some(black)) = (bit_depth, black_level) {
        if black as f64 >= mosaic::max_count(bits) {
            problems.push(fields.problem(
                "raw.black_level",
                format!(
                    "black level {black} leaves no range below the {bits}-bit maximum {}",
                    mosaic::max_count(bits)
                ),
            ));
        }
    }
    if problems.len() > before {
        return None;
    }
    Some(RawFrame {
        file: file?,
        sensor: sensor?,
        bit_depth: bit_depth?,
        black_level: black_level?,
        given_size: (width, height),
        sensor_size: (0, 0),
        demosaic: settings.demosaic,
    })
}

/// Checks the camera (at the sensor's resolution, as written) against the raw frame and returns
/// the camera of the demosaiced view: the same, or every intrinsic halved in `half` mode.
pub(crate) fn attach_camera(
    raw: &mut RawFrame,
    camera: Camera,
    frame: &Fields,
    problems: &mut Vec<Problem>,
) -> Option<Camera> {
    let (w, h) = (camera.width, camera.height);
    let before = problems.len();
    for (key, given, own) in [
        ("raw.width", raw.given_size.0, w),
        ("raw.height", raw.given_size.1, h),
    ] {
        if let Some(given) = given.filter(|g| *g != own) {
            problems.push(frame.problem(
                key,
                format!(
                    "{key} is {given} but the camera's {} is {own}; the intrinsics are those of the sensor's full resolution",
                    if key == "raw.width" { "w" } else { "h" }
                ),
            ));
        }
    }
    let block = raw.sensor.block() as u32;
    if !w.is_multiple_of(block) || !h.is_multiple_of(block) {
        problems.push(frame.problem(
            "w",
            format!(
                "a raw {} frame needs w and h that are multiples of {block} (whole {block}×{block} blocks), found {w}×{h}",
                raw.sensor.name()
            ),
        ));
    }
    if problems.len() > before {
        return None;
    }
    raw.sensor_size = (w as usize, h as usize);
    Some(match raw.demosaic {
        Demosaic::Bilinear => camera,
        Demosaic::Half => Camera {
            width: w / 2,
            height: h / 2,
            fx: camera.fx / 2.0,
            fy: camera.fy / 2.0,
            cx: camera.cx / 2.0,
            cy: camera.cy / 2.0,
            c2w: camera.c2w,
        },
    })
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
    if !(1..=2).contains(&image.channels) {
        return Err(problem(format!(
            "{shown} has {} channel(s); expected a single-channel (grey) mask ([1, 2] channels)",
            image.channels
        )));
    }
    let mask = binarize(&image.channel(0));
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

//! What a raw polarization-mosaic frame declares in `transforms.json`: the `raw` keys (per frame,
//! with defaults in a top-level `raw` object) and the capture-wide `demosaic` and `white_balance`
//! keys, parsed and checked against the frame's camera. Reading the files is [`super::raw`]'s.
//!
//! Validation records a [`Problem`] (frame, key, what is wrong) for every broken rule, like the
//! rest of the loader. Called per frame from the loader's rayon iterator.

use std::path::Path;

use serde_json::{Map, Value};

use super::error::Problem;
use super::json::{Fields, KeyedPath, TOP_LEVEL};
use super::mosaic::{self, Demosaic, Sensor};
use crate::core::camera::Camera;

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

/// One frame's raw mosaic, parsed but not read.
#[derive(Clone, Debug)]
pub(crate) struct RawFrame {
    pub file: KeyedPath,
    pub sensor: Sensor,
    pub bit_depth: u32,
    pub black_level: u32,
    /// `width`/`height` as given (they must agree with the camera's `w`/`h`).
    pub(super) given_size: (Option<u32>, Option<u32>),
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

//! Parsing `transforms.json` (CAPTURE_FORMAT.md §1) into per-frame load plans: cameras with
//! intrinsics resolved (top level, per-frame overrides, `camera_angle_x`), the measurement kind and
//! its files, the mask source, the split and the ground-truth paths. No image is read here.

use std::path::Path;

use glam::DVec3;
use serde_json::Value;

use super::error::Problem;
use super::json::Fields;
pub(crate) use super::json::{KeyedPath, TOP_LEVEL};
use super::raw_frame::{self as raw, RawFrame, RawSettings};
use super::{GroundTruth, PolarizerAngle, Split};
use crate::core::camera::{is_rigid, Camera, CameraConvention, Intrinsics};

/// Tolerance of the rigidity test of `transform_matrix` (6-decimal JSON rounding passes).
const RIGIDITY_TOLERANCE: f64 = 1e-4;

pub(crate) const STOKES_KEYS: [&str; 3] = ["s0_path", "s1_path", "s2_path"];
pub(crate) const POLARIZER_KEYS: [&str; 4] =
    ["pol000_path", "pol045_path", "pol090_path", "pol135_path"];

/// Direction in which polarization angles are counted (CAPTURE_FORMAT.md §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum StokesConvention {
    ImageYUp,
    ImageYDown,
}

/// The `color_space` key: how 8/16-bit images are encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ColorSpace {
    Linear,
    Srgb,
}

/// Capture-wide settings from the top level of the JSON.
#[derive(Clone, Debug)]
pub(crate) struct Header {
    pub stokes_convention: StokesConvention,
    /// `None`: the default of each file type (EXR/HDR linear, PNG/JPEG sRGB).
    pub color_space: Option<ColorSpace>,
    pub world_up: DVec3,
    /// `demosaic`, `white_balance` and the defaults of the frames' `raw` keys.
    pub raw: RawSettings,
}

/// The measurement files of a frame.
#[derive(Clone, Debug)]
pub(crate) enum Source {
    /// `s0_path`, `s1_path`, `s2_path`.
    Stokes([KeyedPath; 3]),
    /// `pol000_path` … `pol135_path`, as written (before any convention swap).
    Polarizer4([KeyedPath; 4]),
    /// `file_path` with `polarizer_deg` (already in the image_y_up convention) or `polarizer_group`.
    Partial {
        file: KeyedPath,
        angle: PolarizerAngle,
    },
    /// `file_path` alone.
    Rgb(KeyedPath),
    /// A raw polarization-mosaic frame (`raw`).
    Raw(Box<RawFrame>),
}

impl Source {
    pub fn files(&self) -> Vec<&KeyedPath> {
        match self {
            Source::Stokes(files) => files.iter().collect(),
            Source::Polarizer4(files) => files.iter().collect(),
            Source::Partial { file, .. } | Source::Rgb(file) => vec![file],
            Source::Raw(raw) => vec![&raw.file],
        }
    }
}

/// Everything needed to load one view.
#[derive(Clone, Debug)]
pub(crate) struct FrameSpec {
    pub index: usize,
    pub name: String,
    pub split: Split,
    pub camera: Camera,
    pub source: Source,
    pub mask: Option<KeyedPath>,
    pub ground_truth: GroundTruth,
}

/// The parse result: the header (if the top level is usable), every frame that parsed, and all problems.
pub(crate) struct Parsed {
    pub header: Header,
    pub frames: Vec<FrameSpec>,
    pub problems: Vec<Problem>,
}

/// Top-level intrinsics, each possibly overridden per frame.
struct IntrinsicDefaults {
    w: Option<u32>,
    h: Option<u32>,
    fl_x: Option<f64>,
    fl_y: Option<f64>,
    cx: Option<f64>,
    cy: Option<f64>,
    camera_angle_x: Option<f64>,
}

/// The top level of a capture document: conventions, intrinsics defaults and the frame list.
struct Top<'a> {
    header: Header,
    camera_convention: CameraConvention,
    stokes_convention: StokesConvention,
    defaults: IntrinsicDefaults,
    frames: &'a [Value],
}

fn parse_top<'a>(document: &'a Value, problems: &mut Vec<Problem>) -> Option<Top<'a>> {
    let Some(top) = document.as_object() else {
        problems.push(Problem::new(
            TOP_LEVEL,
            "(document)",
            "expected a JSON object with `frames`",
        ));
        return None;
    };
    let top = Fields::new(top, TOP_LEVEL);
    let camera_convention = match top.string("camera_convention", problems) {
        None | Some("OpenGL") | Some("opengl") => CameraConvention::OpenGL,
        Some("OpenCV") | Some("opencv") => CameraConvention::OpenCV,
        Some(other) => {
            problems.push(top.problem(
                "camera_convention",
                format!("unknown convention {other:?} (expected \"OpenGL\" or \"OpenCV\")"),
            ));
            CameraConvention::OpenGL
        }
    };
    let stokes_convention = match top.string("stokes_convention", problems) {
        None | Some("image_y_up") => StokesConvention::ImageYUp,
        Some("image_y_down") => StokesConvention::ImageYDown,
        Some(other) => {
            problems.push(top.problem(
                "stokes_convention",
                format!(
                    "unknown convention {other:?} (expected \"image_y_up\" or \"image_y_down\")"
                ),
            ));
            StokesConvention::ImageYUp
        }
    };
    let color_space = match top.string("color_space", problems) {
        None => None,
        Some("linear") => Some(ColorSpace::Linear),
        Some("srgb") | Some("sRGB") => Some(ColorSpace::Srgb),
        Some(other) => {
            problems.push(top.problem(
                "color_space",
                format!("unknown colour space {other:?} (expected \"linear\" or \"srgb\")"),
            ));
            None
        }
    };
    let world_up = parse_world_up(&top, problems);
    let header = Header {
        stokes_convention,
        color_space,
        world_up,
        raw: raw::parse_settings(&top, problems),
    };
    let defaults = IntrinsicDefaults {
        w: top.positive_int("w", problems),
        h: top.positive_int("h", problems),
        fl_x: top.number("fl_x", problems),
        fl_y: top.number("fl_y", problems),
        cx: top.number("cx", problems),
        cy: top.number("cy", problems),
        camera_angle_x: top.number("camera_angle_x", problems),
    };
    let frames = match top.object.get("frames") {
        None => {
            problems.push(top.problem("frames", "missing required key"));
            &[][..]
        }
        Some(Value::Array(frames)) if frames.is_empty() => {
            problems.push(top.problem("frames", "the list of frames is empty"));
            &[][..]
        }
        Some(Value::Array(frames)) => &frames[..],
        Some(other) => {
            problems.push(top.problem("frames", format!("expected a list, found {other}")));
            &[][..]
        }
    };
    Some(Top {
        header,
        camera_convention,
        stokes_convention,
        defaults,
        frames,
    })
}

/// Parses the whole JSON document of a capture rooted at `root`.
pub(crate) fn parse(root: &Path, document: &Value) -> Parsed {
    let mut problems = Vec::new();
    let Some(top) = parse_top(document, &mut problems) else {
        return Parsed {
            header: default_header(),
            frames: Vec::new(),
            problems,
        };
    };
    let explicit_split = top.frames.iter().any(|f| f.get("split").is_some());
    let frames = top
        .frames
        .iter()
        .enumerate()
        .filter_map(|(index, json)| {
            parse_frame(
                root,
                index,
                json,
                &top.defaults,
                top.camera_convention,
                top.stokes_convention,
                &top.header.raw,
                explicit_split,
                &mut problems,
            )
        })
        .collect();
    Parsed {
        header: top.header,
        frames,
        problems,
    }
}

/// The camera of every frame (name, camera), ignoring image keys: what `phygap render --cameras`
/// and relighting need from a transforms file.
pub(crate) fn parse_cameras(document: &Value) -> (Vec<(String, Camera)>, Vec<Problem>) {
    let mut problems = Vec::new();
    let Some(top) = parse_top(document, &mut problems) else {
        return (Vec::new(), problems);
    };
    let mut cameras = Vec::new();
    for (index, json) in top.frames.iter().enumerate() {
        let Some(object) = json.as_object() else {
            problems.push(Problem::new(
                format!("frame {index}"),
                "(frame)",
                format!("expected a JSON object, found {json}"),
            ));
            continue;
        };
        let name = frame_name(index, &Fields::new(object, String::new()));
        let fields = Fields::new(object, name.clone());
        if let Some(camera) =
            parse_camera(&fields, &top.defaults, top.camera_convention, &mut problems)
        {
            cameras.push((name, camera));
        }
    }
    (cameras, problems)
}

fn default_header() -> Header {
    Header {
        stokes_convention: StokesConvention::ImageYUp,
        color_space: None,
        world_up: DVec3::Z,
        raw: RawSettings::default(),
    }
}

fn parse_world_up(top: &Fields, problems: &mut Vec<Problem>) -> DVec3 {
    let Some(value) = top.object.get("world_up") else {
        return DVec3::Z;
    };
    let numbers: Option<Vec<f64>> = value
        .as_array()
        .map(|a| a.iter().map(Value::as_f64).collect::<Option<Vec<f64>>>())
        .unwrap_or(None);
    match numbers.as_deref() {
        Some([x, y, z]) if DVec3::new(*x, *y, *z) == DVec3::Z => DVec3::Z,
        Some([x, y, z]) if DVec3::new(*x, *y, *z) == DVec3::Y => DVec3::Y,
        _ => {
            problems.push(top.problem(
                "world_up",
                format!("expected [0, 0, 1] or [0, 1, 0], found {value}"),
            ));
            DVec3::Z
        }
    }
}

/// The frame's label: its index and the path of its main image.
fn frame_name(index: usize, fields: &Fields) -> String {
    let main = raw::file_name(fields.object).or_else(|| {
        ["s0_path", "pol000_path", "file_path"]
            .iter()
            .find_map(|k| fields.object.get(*k).and_then(Value::as_str))
    });
    match main {
        Some(path) => format!("frame {index} ({path})"),
        None => format!("frame {index}"),
    }
}

#[allow(clippy::too_many_arguments)]
fn parse_frame(
    root: &Path,
    index: usize,
    json: &Value,
    defaults: &IntrinsicDefaults,
    convention: CameraConvention,
    stokes_convention: StokesConvention,
    raw_settings: &RawSettings,
    explicit_split: bool,
    problems: &mut Vec<Problem>,
) -> Option<FrameSpec> {
    let Some(object) = json.as_object() else {
        problems.push(Problem::new(
            format!("frame {index}"),
            "(frame)",
            format!("expected a JSON object, found {json}"),
        ));
        return None;
    };
    let before = problems.len();
    let fields = Fields::new(object, String::new());
    let name = frame_name(index, &fields);
    let fields = Fields::new(object, name.clone());

    let camera = parse_camera(&fields, defaults, convention, problems);
    let mut source = if fields.has("raw") {
        raw::parse_frame(root, &fields, raw_settings, problems).map(|r| Source::Raw(Box::new(r)))
    } else {
        parse_source(root, &fields, stokes_convention, problems)
    };
    let camera = match (camera, &mut source) {
        (Some(camera), Some(Source::Raw(raw))) => {
            raw::attach_camera(raw, camera, &fields, problems)
        }
        (camera, _) => camera,
    };
    let mask = keyed_path(root, &fields, "mask_path", problems);
    let split = match fields.string("split", problems) {
        Some("train") => Split::Train,
        Some("test") => Split::Test,
        Some(other) => {
            problems.push(fields.problem(
                "split",
                format!("unknown split {other:?} (expected \"train\" or \"test\")"),
            ));
            Split::Train
        }
        None if explicit_split => Split::Train,
        None if index.is_multiple_of(8) => Split::Test,
        None => Split::Train,
    };
    let gt = |key: &'static str, problems: &mut Vec<Problem>| {
        keyed_path(root, &fields, key, problems).map(|k| k.path)
    };
    let ground_truth = GroundTruth {
        normal: gt("normal_path", problems),
        depth: gt("depth_path", problems),
        albedo: gt("albedo_path", problems),
        roughness: gt("roughness_path", problems),
        ior: gt("ior_path", problems),
        relight_s0: gt("relight_s0_path", problems),
        s0: gt("s0_path", problems),
        s1: gt("s1_path", problems),
        s2: gt("s2_path", problems),
    };
    if problems.len() > before {
        return None;
    }
    Some(FrameSpec {
        index,
        name,
        split,
        camera: camera?,
        source: source?,
        mask,
        ground_truth,
    })
}

fn keyed_path(
    root: &Path,
    fields: &Fields,
    key: &'static str,
    problems: &mut Vec<Problem>,
) -> Option<KeyedPath> {
    let relative = fields.path(key, problems)?;
    Some(KeyedPath {
        key,
        path: root.join(&relative),
        relative,
    })
}

fn parse_camera(
    fields: &Fields,
    defaults: &IntrinsicDefaults,
    convention: CameraConvention,
    problems: &mut Vec<Problem>,
) -> Option<Camera> {
    let size = |key: &str, default: Option<u32>, problems: &mut Vec<Problem>| {
        let value = if fields.has(key) {
            fields.positive_int(key, problems)
        } else {
            default
        };
        if value.is_none() && !fields.has(key) {
            problems.push(fields.problem(
                key,
                "missing required key (neither the frame nor the top level gives it)",
            ));
        }
        value
    };
    let width = size("w", defaults.w, problems);
    let height = size("h", defaults.h, problems);
    let number = |key: &str, default: Option<f64>, problems: &mut Vec<Problem>| {
        if fields.has(key) {
            fields.number(key, problems)
        } else {
            default
        }
    };
    let fl_x = number("fl_x", defaults.fl_x, problems);
    let fl_y = number("fl_y", defaults.fl_y, problems);
    let cx = number("cx", defaults.cx, problems);
    let cy = number("cy", defaults.cy, problems);
    let matrix = if fields.has("transform_matrix") {
        fields.matrix4("transform_matrix", problems)
    } else {
        problems.push(fields.problem("transform_matrix", "missing required key"));
        None
    };
    let (width, height) = (width?, height?);
    let from_angle = defaults.camera_angle_x.and_then(|angle| {
        (angle > 0.0 && angle < std::f64::consts::PI)
            .then(|| 0.5 * width as f64 / (0.5 * angle).tan())
    });
    if defaults.camera_angle_x.is_some() && from_angle.is_none() {
        problems.push(Problem::new(
            TOP_LEVEL,
            "camera_angle_x",
            "field of view must lie in (0, π) radians",
        ));
    }
    let (fx, fy) = match (fl_x, fl_y, from_angle) {
        (Some(fx), Some(fy), _) => (fx, fy),
        (Some(fx), None, _) => (fx, fx),
        (None, Some(fy), _) => (fy, fy),
        (None, None, Some(f)) => (f, f),
        (None, None, None) => {
            problems.push(fields.problem(
                "fl_x",
                "missing focal length: give `fl_x`/`fl_y` or `camera_angle_x`",
            ));
            return None;
        }
    };
    if !(fx > 0.0 && fy > 0.0) {
        problems.push(fields.problem(
            "fl_x",
            format!("focal lengths must be positive, found fl_x = {fx}, fl_y = {fy}"),
        ));
        return None;
    }
    if width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
        let key = if width > MAX_IMAGE_SIDE { "w" } else { "h" };
        problems.push(fields.problem(
            key,
            format!("{width}×{height} pixels: an image side is at most {MAX_IMAGE_SIDE} pixels"),
        ));
        return None;
    }
    let (cx, cy) = (
        cx.unwrap_or(width as f64 / 2.0),
        cy.unwrap_or(height as f64 / 2.0),
    );
    if let Some((key, message)) = intrinsics_problem(width, height, [fx, fy, cx, cy]) {
        problems.push(fields.problem(key, message));
        return None;
    }
    let c2w = matrix?;
    if !is_rigid(&c2w, RIGIDITY_TOLERANCE) {
        problems.push(fields.problem(
            "transform_matrix",
            "not a rigid camera-to-world transform (rotation must be orthonormal with determinant +1, last row 0 0 0 1)",
        ));
        return None;
    }
    if c2w.w_axis.truncate().abs().max_element() > MAX_CAMERA_DISTANCE {
        problems.push(fields.problem(
            "transform_matrix",
            format!(
                "the camera sits at {:?}, farther than {MAX_CAMERA_DISTANCE:e} units from the origin",
                c2w.w_axis.truncate().to_array()
            ),
        ));
        return None;
    }
    let intrinsics = Intrinsics {
        width,
        height,
        fx,
        fy,
        cx,
        cy,
    };
    Some(Camera::new(intrinsics, c2w, convention))
}

/// Longest image side accepted (pixels).
pub(crate) const MAX_IMAGE_SIDE: u32 = 1 << 16;

/// Focal lengths per pixel of image side accepted: from a 171° field of view (0.04) to a
/// 0.006° one (10⁴); outside, the numbers are a unit mistake (millimetres for pixels), not a lens.
const FOCAL_PER_SIDE: std::ops::RangeInclusive<f64> = 0.04..=1.0e4;

/// Farthest a camera may sit from the origin, in world units.
const MAX_CAMERA_DISTANCE: f64 = 1.0e6;

/// What is wrong with a camera's intrinsics `[fx, fy, cx, cy]` for a `width × height` image, if
/// anything: focal lengths the image size allows, and a principal point within one image width
/// (height) of the image.
pub(crate) fn intrinsics_problem(
    width: u32,
    height: u32,
    [fx, fy, cx, cy]: [f64; 4],
) -> Option<(&'static str, String)> {
    let (w, h) = (f64::from(width), f64::from(height));
    for (key, focal, side) in [("fl_x", fx, w), ("fl_y", fy, h)] {
        if !FOCAL_PER_SIDE.contains(&(focal / side)) {
            return Some((
                key,
                format!(
                    "focal length {} pixels for an image side of {side}: it must lie between \
                     {} and {} pixels (a field of view between 171° and 0.006°)",
                    readable(focal),
                    FOCAL_PER_SIDE.start() * side,
                    FOCAL_PER_SIDE.end() * side
                ),
            ));
        }
    }
    for (key, centre, side) in [("cx", cx, w), ("cy", cy, h)] {
        if !(-side..=2.0 * side).contains(&centre) {
            return Some((
                key,
                format!(
                    "principal point {key} = {} lies more than an image side ({side}) outside \
                     the image",
                    readable(centre)
                ),
            ));
        }
    }
    None
}

/// A number as people read it: plain, or in scientific notation when very large or small.
fn readable(value: f64) -> String {
    if value != 0.0 && !(1e-3..1e6).contains(&value.abs()) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

fn parse_source(
    root: &Path,
    fields: &Fields,
    stokes_convention: StokesConvention,
    problems: &mut Vec<Problem>,
) -> Option<Source> {
    let present = |keys: &[&'static str]| -> Vec<&'static str> {
        keys.iter().copied().filter(|k| fields.has(k)).collect()
    };
    let complete_set = |keys: &[&'static str], problems: &mut Vec<Problem>| {
        let have = present(keys);
        let missing: Vec<&str> = keys.iter().copied().filter(|k| !have.contains(k)).collect();
        if have.is_empty() {
            return None;
        }
        if !missing.is_empty() {
            problems.push(fields.problem(
                missing[0],
                format!(
                    "incomplete set: the frame has {} but not {}",
                    have.join(", "),
                    missing.join(", ")
                ),
            ));
            return Some(None);
        }
        let paths: Option<Vec<KeyedPath>> = keys
            .iter()
            .map(|k| keyed_path(root, fields, k, problems))
            .collect();
        Some(paths)
    };
    if let Some(stokes) = complete_set(&STOKES_KEYS, problems) {
        let [s0, s1, s2]: [KeyedPath; 3] = stokes?.try_into().ok()?;
        return Some(Source::Stokes([s0, s1, s2]));
    }
    if let Some(pol) = complete_set(&POLARIZER_KEYS, problems) {
        let files: [KeyedPath; 4] = pol?.try_into().ok()?;
        return Some(Source::Polarizer4(files));
    }
    if !fields.has("file_path") {
        problems.push(fields.problem(
            "file_path",
            "no image: give s0_path/s1_path/s2_path, pol000_path…pol135_path or file_path",
        ));
        return None;
    }
    let file = keyed_path(root, fields, "file_path", problems)?;
    let degrees = fields.number("polarizer_deg", problems);
    let group = fields.string("polarizer_group", problems);
    match (degrees, group) {
        (Some(_), Some(_)) => {
            problems.push(fields.problem(
                "polarizer_group",
                "give either polarizer_deg (known angle) or polarizer_group (learned angle), not both",
            ));
            None
        }
        (Some(degrees), None) => {
            let degrees = match stokes_convention {
                StokesConvention::ImageYUp => degrees,
                StokesConvention::ImageYDown => -degrees,
            }
            .rem_euclid(180.0);
            Some(Source::Partial {
                file,
                angle: PolarizerAngle::Known { degrees },
            })
        }
        (None, Some("")) => {
            problems.push(fields.problem("polarizer_group", "empty group name"));
            None
        }
        (None, Some(group)) => Some(Source::Partial {
            file,
            angle: PolarizerAngle::Group(group.to_owned()),
        }),
        (None, None) if fields.has("polarizer_deg") || fields.has("polarizer_group") => None,
        (None, None) => Some(Source::Rgb(file)),
    }
}

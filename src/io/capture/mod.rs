//! Loading and validating a capture (CAPTURE_FORMAT.md): a `transforms.json` with cameras and, per
//! view, a full-Stokes, four-polarizer, partial-polarization or plain RGB measurement and a mask.
//!
//! [`load`] parses the JSON, then reads every view's images in parallel (rayon, one task per frame)
//! and either returns the complete [`Capture`] or a [`CaptureError`] listing every problem found:
//! nothing is half-imported. All images come back as linear RGB in the image_y_up Stokes convention.
//! Views may also come from raw polarization-mosaic frames (`raw.rs`, `mosaic.rs`), and a folder
//! holding a COLMAP model instead of `transforms.json` is read by `colmap/`, one in the IDR/NeuS
//! or LLFF layout by `layouts/`.

pub mod backdrop;
pub mod colmap;
pub mod conventions;
pub mod degrade;
pub mod dolp;
mod error;
mod frame;
mod hull;
mod images;
mod json;
pub mod layouts;
mod lens;
mod limits;
pub mod mosaic;
pub mod npy;
mod raw;
mod raw_frame;
pub mod resample;
mod scene;
pub mod simulate;
pub mod undistort;

#[cfg(test)]
mod raw_tests;
#[cfg(test)]
mod shared_data_tests;
#[cfg(test)]
mod tests;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use glam::DVec3;
use rayon::prelude::*;
use serde::Serialize;

use crate::core::background::{background_level, measured_sums};
use crate::core::camera::Camera;
use crate::core::polarization_confidence::polarization_confidence;
use crate::formats::image_io::Image;

pub use colmap::{ColmapError, ColmapReport, SparsePoint};
pub use dolp::DolpStats;
pub use error::{CaptureError, Problem};
pub use hull::{Bounds, VisualHull};
pub use limits::{CaptureLimits, LimitExceeded};

use crate::core::resolution::Resolution;
pub use raw::RawReport;
pub use scene::SceneMaps;

/// Training or held-out view.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Split {
    Train,
    Test,
}

/// The angle of the linear polarizer in front of a partial-polarization view.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum PolarizerAngle {
    /// Known angle in degrees, image_y_up convention, in [0, 180).
    Known { degrees: f64 },
    /// Unknown angle shared by every view of the named group; learned.
    Group(String),
}

/// What a view measured. Every image is linear RGB (3 channels), image_y_up convention.
#[derive(Clone, Debug, PartialEq)]
pub enum Measurement {
    /// Full Stokes S0, S1, S2 (from Stokes files or from four polarizer images).
    Stokes { s0: Image, s1: Image, s2: Image },
    /// One image behind a linear polarizer: I(θ) = ½ (S0 + S1 cos 2θ + S2 sin 2θ).
    Polarizer { image: Image, angle: PolarizerAngle },
    /// An ordinary image (S0 only).
    Rgb { image: Image },
}

/// Ground-truth files named by the frame (`*_path` keys), joined to the capture folder; not loaded.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GroundTruth {
    pub normal: Option<PathBuf>,
    pub depth: Option<PathBuf>,
    pub albedo: Option<PathBuf>,
    pub roughness: Option<PathBuf>,
    pub ior: Option<PathBuf>,
    pub relight_s0: Option<PathBuf>,
    pub s0: Option<PathBuf>,
    pub s1: Option<PathBuf>,
    pub s2: Option<PathBuf>,
}

/// One posed view with its measurement and mask.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// E.g. `frame 3 (train/s0/003.exr)`.
    pub name: String,
    /// Position in the JSON `frames` list.
    pub frame_index: usize,
    pub split: Split,
    pub camera: Camera,
    pub measurement: Measurement,
    /// One channel, values in [0, 1] (binary from a mask file, soft from an alpha channel).
    pub mask: Image,
    pub ground_truth: GroundTruth,
}

/// A loaded, validated capture.
#[derive(Clone, Debug)]
pub struct Capture {
    /// The folder holding the JSON file; every path of the capture is relative to it.
    pub root: PathBuf,
    pub views: Vec<View>,
    /// The world's up axis (+Z or +Y), which orients lat-long environment maps.
    pub world_up: DVec3,
    pub warnings: Vec<String>,
    /// Sparse 3D points of a structure-from-motion model (COLMAP's `points3D`), empty otherwise;
    /// they seed the surfels.
    pub points: Vec<SparsePoint>,
    /// The views read from raw mosaic frames and how; `None` without raw frames.
    pub raw: Option<RawReport>,
    /// The COLMAP model the capture was read from; `None` for a `transforms.json` capture.
    pub colmap: Option<ColmapReport>,
    /// The whole factor the views were shrunk by at load (1: as the files are;
    /// [`resample`]). Ground-truth files named by the views are shrunk by it when read.
    pub downscale: u32,
    /// The views' size before shrinking.
    pub full_size: (u32, u32),
}

/// How a capture is loaded: its limits, and the size its views are loaded at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoadOptions {
    pub limits: CaptureLimits,
    /// The working resolution ([`Resolution::Full`]: the files' size).
    pub resolution: Resolution,
    /// Pixels a view may have under [`Resolution::Auto`] (the engine's budget).
    pub pixel_budget: u64,
}

impl Default for LoadOptions {
    /// [`CaptureLimits::DEFAULT`], full resolution.
    fn default() -> Self {
        LoadOptions {
            limits: CaptureLimits::DEFAULT,
            resolution: Resolution::Full,
            pixel_budget: Resolution::HOST_PIXEL_BUDGET,
        }
    }
}

/// What `phygap inspect` prints.
#[derive(Clone, Debug, Serialize)]
pub struct CaptureSummary {
    pub views: usize,
    pub train_views: usize,
    pub test_views: usize,
    /// Measurement kinds present: `stokes`, `polarizer4` (Stokes from four polarizer images),
    /// `raw` (Stokes from raw mosaic frames), `partial`, `rgb`.
    pub kinds: Vec<String>,
    pub width: u32,
    pub height: u32,
    pub polarizer_groups: Vec<String>,
    pub bounds: Bounds,
    pub world_up: DVec3,
    pub warnings: Vec<String>,
    /// DoLP over the masked pixels of every full-Stokes view; `None` without one.
    pub dolp: Option<DolpStats>,
    /// The mean over those pixels of how far their polarization rises above their view's own
    /// noise (the AoLP prior's confidence, `core::polarization_confidence`, in [0, 1]).
    pub polarization_above_noise: Option<f64>,
    /// The images' mean beyond the masks (farther than `core::background::MEASURED_BEYOND_PX`)
    /// over their mean on the object: 0 for a rendered capture; a photograph's background, which
    /// training makes black unless it is dark (`core::background::DARK_BACKGROUND_LEVEL`). `None`
    /// when no view has pixels beyond its mask.
    pub background_level: Option<f64>,
    pub raw: Option<RawReport>,
    pub colmap: Option<ColmapReport>,
    /// Sparse points that seed the surfels (COLMAP `points3D`).
    pub sparse_points: usize,
    /// One entry per view.
    pub frames: Vec<FrameSummary>,
}

/// What `phygap inspect --json` says about one view.
#[derive(Clone, Debug, Serialize)]
pub struct FrameSummary {
    pub name: String,
    pub frame_index: usize,
    pub split: Split,
    pub kind: String,
    /// DoLP over the view's masked pixels (full-Stokes views only).
    pub dolp: Option<DolpStats>,
}

/// A raw frame with more than this fraction of its samples at the sensor's maximum gets a warning
/// (a few hot pixels do not).
const CLIPPED_WARNING_FRACTION: f64 = 1e-3;

/// Loads a capture within [`CaptureLimits::DEFAULT`]: `path` is a folder holding
/// `transforms.json`, or a JSON file (e.g. `transforms_partial.json`); image paths are relative
/// to the JSON file's folder. A folder without `transforms.json` but with a COLMAP model
/// (`sparse/0/`) is read by [`colmap::load`].
pub fn load(path: &Path) -> Result<Capture, CaptureError> {
    load_with(path, &LoadOptions::default())
}

/// [`load`] with the given limits: a capture declaring more views, pixels or decoded bytes is
/// [`CaptureError::TooLarge`] before any image is read.
pub fn load_within(path: &Path, limits: &CaptureLimits) -> Result<Capture, CaptureError> {
    load_with(
        path,
        &LoadOptions {
            limits: *limits,
            ..LoadOptions::default()
        },
    )
}

/// [`load`] with the given limits and working resolution: each view is decoded at its files'
/// size and shrunk at once ([`resample`]), so the capture holds its views at the working size
/// only; the limits' decoded bytes count them at that size.
pub fn load_with(path: &Path, options: &LoadOptions) -> Result<Capture, CaptureError> {
    if let Some(model) = colmap::find_model(path) {
        return colmap::load(path, &model, options);
    }
    if let Some(location) = layouts::find_layout(path) {
        return layouts::load(path, &location, options);
    }
    let json_path = transforms_path(path);
    let _span = tracing::info_span!("load_capture", path = %json_path.display()).entered();
    let document = read_document(&json_path)?;
    let folder = json_path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let root = folder.canonicalize().unwrap_or_else(|_| folder.to_owned());
    let (distortions, lens_problems) = lens::frame_distortions(&document);
    let mut capture = load_document(&json_path, root, &document, lens_problems, options)?;
    lens::undistort_views(&mut capture, &distortions);
    Ok(capture)
}

/// Validates and loads a transforms document whose paths are relative to `root`; `problems`
/// found before (by a caller that built the document) join the ones found here.
pub(crate) fn load_document(
    json_path: &Path,
    root: PathBuf,
    document: &serde_json::Value,
    earlier: Vec<Problem>,
    options: &LoadOptions,
) -> Result<Capture, CaptureError> {
    let frame::Parsed {
        header,
        frames,
        mut problems,
    } = frame::parse(&root, document);
    problems.splice(0..0, earlier);
    let full_size = frames
        .first()
        .map_or((0, 0), |f| (f.camera.width, f.camera.height));
    let downscale =
        options
            .resolution
            .factor(full_size.0.max(1), full_size.1.max(1), options.pixel_budget);
    options
        .limits
        .check_frames(&frames, downscale)
        .map_err(|exceeded| CaptureError::TooLarge {
            path: json_path.to_owned(),
            exceeded,
        })?;

    if let Some(first) = frames.first() {
        let size = (first.camera.width, first.camera.height);
        for spec in &frames[1..] {
            if (spec.camera.width, spec.camera.height) != size {
                problems.push(Problem::new(
                    spec.name.clone(),
                    "w",
                    format!(
                        "mixed sizes: this frame is {}×{} but {} is {}×{}; all views of a capture must have one size",
                        spec.camera.width, spec.camera.height, first.name, size.0, size.1
                    ),
                ));
            }
        }
    }
    if problems.is_empty() {
        let train = frames.iter().filter(|f| f.split == Split::Train).count();
        if train < 2 {
            problems.push(Problem::new(
                frame::TOP_LEVEL,
                "split",
                format!(
                    "only {train} training view(s) among {} frames; at least 2 are needed",
                    frames.len()
                ),
            ));
        }
    }

    let loaded: Vec<Result<images::LoadedView, Vec<Problem>>> = {
        let _span = tracing::info_span!("load_images", frames = frames.len()).entered();
        frames
            .par_iter()
            .map(|spec| {
                let loaded = match &spec.source {
                    frame::Source::Raw(raw) => raw::load_view(spec, &header, raw),
                    _ => images::load_view(spec, &header),
                };
                loaded.map(|loaded| images::LoadedView {
                    view: resample::downscale_view(loaded.view, downscale),
                    ..loaded
                })
            })
            .collect()
    };
    let mut views = Vec::with_capacity(loaded.len());
    let mut unmasked = Vec::new();
    let mut clipped = Vec::new();
    for result in loaded {
        match result {
            Ok(loaded) => {
                if loaded.whole_image_mask {
                    unmasked.push(loaded.view.frame_index.to_string());
                }
                if loaded.clipped_fraction > CLIPPED_WARNING_FRACTION {
                    clipped.push(format!(
                        "{} ({:.2} %)",
                        loaded.view.frame_index,
                        100.0 * loaded.clipped_fraction
                    ));
                }
                views.push(loaded.view);
            }
            Err(frame_problems) => problems.extend(frame_problems),
        }
    }
    if !problems.is_empty() {
        // A key read twice (as measurement and as ground truth) reports its problem once.
        let mut seen = std::collections::HashSet::new();
        problems.retain(|p| seen.insert(p.clone()));
        return Err(CaptureError::Invalid {
            path: json_path.to_owned(),
            problems,
        });
    }
    let raw = raw::balance_white(&frames, &mut views, &header.raw).map_err(|problem| {
        CaptureError::Invalid {
            path: json_path.to_owned(),
            problems: vec![problem],
        }
    })?;
    let mut warnings = conventions::check(&frames, &header, &views).warnings();
    if !unmasked.is_empty() {
        warnings.push(format!(
            "{} view(s) have no mask_path and no alpha channel; the whole image is treated as object (frames {})",
            unmasked.len(),
            unmasked.join(", ")
        ));
    }
    if !clipped.is_empty() {
        warnings.push(format!(
            "{} raw frame(s) have samples at the sensor's maximum, where the four polarizer \
             channels saturate and the Stokes estimate is biased: lower the exposure (frames {})",
            clipped.len(),
            clipped.join(", ")
        ));
    }
    for warning in &warnings {
        tracing::warn!("{warning}");
    }
    Ok(Capture {
        root,
        views,
        world_up: header.world_up,
        warnings,
        points: Vec::new(),
        raw,
        colmap: None,
        downscale,
        full_size,
    })
}

/// Whether `dir` is the root of a capture folder: it holds `transforms.json`, a COLMAP model, or
/// the camera file of a dataset layout ([`layouts::find_layout`]).
pub fn is_capture_folder(dir: &Path) -> bool {
    dir.join("transforms.json").is_file()
        || colmap::find_model(dir).is_some()
        || layouts::find_layout(dir).is_some()
}

/// The JSON file of a capture given as a folder (its `transforms.json`) or as the file itself.
pub fn transforms_path(path: &Path) -> PathBuf {
    if path.is_dir() {
        path.join("transforms.json")
    } else {
        path.to_owned()
    }
}

/// Largest transforms JSON file read (a 2,000-frame capture's is about 2 MB).
const MAX_DOCUMENT_BYTES: u64 = 64 << 20;

/// Reads and parses a transforms JSON file (NaN/Infinity tolerated, reported later per key).
fn read_document(json_path: &Path) -> Result<serde_json::Value, CaptureError> {
    let read_error = |message: String| CaptureError::Read {
        path: json_path.to_owned(),
        message,
    };
    let length = std::fs::metadata(json_path)
        .map_err(|e| read_error(e.to_string()))?
        .len();
    if length > MAX_DOCUMENT_BYTES {
        return Err(read_error(format!(
            "{length} bytes, over the limit of {} MiB for a transforms file",
            MAX_DOCUMENT_BYTES >> 20
        )));
    }
    let text = std::fs::read_to_string(json_path).map_err(|e| read_error(e.to_string()))?;
    json::parse_lenient(&text).map_err(|e| CaptureError::Json {
        path: json_path.to_owned(),
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
    })
}

/// Reads only the cameras of a transforms file (a capture folder or a JSON file): one
/// `(frame name, camera)` per frame, in order. Image keys are not needed and not checked. A
/// COLMAP capture folder gives one `(image name, camera)` per image, sorted by name.
///
/// The cameras are checked against [`CaptureLimits::DEFAULT`]'s views and pixels per view (what
/// a render from them allocates), before anything is rendered.
pub fn load_cameras(path: &Path) -> Result<Vec<(String, Camera)>, CaptureError> {
    load_cameras_within(path, &CaptureLimits::DEFAULT)
}

/// [`load_cameras`] within `limits` (their views and pixels per view).
pub fn load_cameras_within(
    path: &Path,
    limits: &CaptureLimits,
) -> Result<Vec<(String, Camera)>, CaptureError> {
    let json_path = transforms_path(path);
    let cameras = match (colmap::find_model(path), layouts::find_layout(path)) {
        (Some(model), _) => colmap::load_cameras(&model)?,
        (None, Some(location)) => layouts::load_cameras(path, &location)?,
        (None, None) => {
            let document = read_document(&json_path)?;
            let (cameras, problems) = frame::parse_cameras(&document);
            if !problems.is_empty() {
                return Err(CaptureError::Invalid {
                    path: json_path,
                    problems,
                });
            }
            cameras
        }
    };
    let sizes = cameras
        .iter()
        .map(|(_, c)| (u64::from(c.width), u64::from(c.height)));
    limits
        .check(cameras.len(), sizes, std::iter::empty())
        .map_err(|exceeded| CaptureError::TooLarge {
            path: json_path,
            exceeded,
        })?;
    Ok(cameras)
}

/// A transforms document holding only cameras (OpenGL convention), readable by
/// [`load_cameras`]: what a model folder keeps of its capture's test views.
pub fn cameras_to_json(cameras: &[(String, Camera)]) -> serde_json::Value {
    let frames: Vec<serde_json::Value> = cameras
        .iter()
        .map(|(name, c)| {
            serde_json::json!({
                "name": name,
                "w": c.width, "h": c.height,
                "fl_x": c.fx, "fl_y": c.fy, "cx": c.cx, "cy": c.cy,
                "transform_matrix": c.c2w.transpose().to_cols_array_2d(),
            })
        })
        .collect();
    serde_json::json!({ "camera_convention": "OpenGL", "frames": frames })
}

impl Capture {
    /// Checks what training needs beyond a valid capture: a test view, which measures the model
    /// and is what its renders show (a capture whose frames all say `"split": "train"` has none).
    pub fn check_trainable(&self) -> Result<(), CaptureError> {
        if self.test_views().next().is_some() {
            return Ok(());
        }
        Err(CaptureError::Invalid {
            path: transforms_path(&self.root),
            problems: vec![Problem::new(
                frame::TOP_LEVEL,
                "split",
                format!(
                    "none of the {} frames is a test view: give at least one frame \
                     \"split\": \"test\", or leave out every `split` to hold out every 8th frame",
                    self.views.len()
                ),
            )],
        })
    }

    /// The views' size as loaded and how it came about, e.g. `306×256 (1224×1024 ÷ 4)`, or
    /// `256×256` at full resolution.
    pub fn working_resolution(&self) -> String {
        let (width, height) = self
            .views
            .first()
            .map_or((0, 0), |v| (v.camera.width, v.camera.height));
        match self.downscale {
            1 => format!("{width}×{height}"),
            k => format!(
                "{width}×{height} ({}×{} ÷ {k})",
                self.full_size.0, self.full_size.1
            ),
        }
    }

    pub fn train_views(&self) -> impl Iterator<Item = &View> {
        self.views.iter().filter(|v| v.split == Split::Train)
    }

    pub fn test_views(&self) -> impl Iterator<Item = &View> {
        self.views.iter().filter(|v| v.split == Split::Test)
    }

    /// The visual hull of the training views' masks.
    pub fn visual_hull(&self) -> VisualHull<'_> {
        VisualHull::new(self.train_views())
    }

    /// Bounding box, centre and radius of the object, estimated from the training masks and cameras.
    pub fn object_bounds(&self) -> Bounds {
        self.visual_hull().bounds()
    }

    /// Counts, kinds, resolution, polarizer groups, bounds, DoLP statistics and warnings.
    pub fn summary(&self) -> CaptureSummary {
        const KIND_NAMES: [&str; 5] = ["stokes", "polarizer4", "raw", "partial", "rgb"];
        let mut kinds = BTreeSet::new();
        let mut groups = BTreeSet::new();
        let raw_frames = self.raw.as_ref().map_or(&[][..], |r| &r.frames[..]);
        let view_kinds: Vec<usize> = self
            .views
            .iter()
            .map(|view| match &view.measurement {
                Measurement::Stokes { .. } if raw_frames.contains(&view.frame_index) => 2,
                // Stokes images are also recorded as ground truth (`s0_path`); a Stokes view
                // without one was computed from the four polarizer images.
                Measurement::Stokes { .. } if view.ground_truth.s0.is_some() => 0,
                Measurement::Stokes { .. } => 1,
                Measurement::Polarizer { angle, .. } => {
                    if let PolarizerAngle::Group(g) = angle {
                        groups.insert(g.clone());
                    }
                    3
                }
                Measurement::Rgb { .. } => 4,
            })
            .collect();
        kinds.extend(view_kinds.iter().copied());
        let histograms: Vec<Option<dolp::DolpHistogram>> = self
            .views
            .par_iter()
            .map(|view| match &view.measurement {
                Measurement::Stokes { s0, s1, s2 } => {
                    Some(dolp::DolpHistogram::of_view(s0, s1, s2, &view.mask))
                }
                _ => None,
            })
            .collect();
        let above_noise: (f64, usize) = self
            .views
            .par_iter()
            .map(|view| match &view.measurement {
                Measurement::Stokes { s0, s1, s2 } => {
                    let mask = &view.mask.data;
                    let confidence = polarization_confidence(
                        &s0.to_rgb().data,
                        &s1.to_rgb().data,
                        &s2.to_rgb().data,
                        mask,
                        view.mask.width,
                        view.mask.height,
                    );
                    let object = mask.iter().filter(|&&m| m >= 0.5).count();
                    (confidence.iter().map(|&w| f64::from(w)).sum(), object)
                }
                _ => (0.0, 0),
            })
            .reduce(|| (0.0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
        let background_sums = self
            .views
            .par_iter()
            .map(|view| {
                let mask = &view.mask;
                let image = match &view.measurement {
                    Measurement::Stokes { s0: image, .. }
                    | Measurement::Polarizer { image, .. }
                    | Measurement::Rgb { image } => image,
                };
                measured_sums(&image.data, &mask.data, mask.width, mask.height)
            })
            .reduce(
                || [(0.0, 0); 2],
                |a, b| [0, 1].map(|k| (a[k].0 + b[k].0, a[k].1 + b[k].1)),
            );
        let background_level = background_level(background_sums);
        let mut total: Option<dolp::DolpHistogram> = None;
        for h in histograms.iter().flatten() {
            total.get_or_insert_with(Default::default).merge(h);
        }
        let frames = self
            .views
            .iter()
            .zip(&view_kinds)
            .zip(&histograms)
            .map(|((view, &kind), h)| FrameSummary {
                name: view.name.clone(),
                frame_index: view.frame_index,
                split: view.split,
                kind: KIND_NAMES[kind].to_owned(),
                dolp: h.as_ref().and_then(|h| h.stats()),
            })
            .collect();
        let (width, height) = self
            .views
            .first()
            .map_or((0, 0), |v| (v.camera.width, v.camera.height));
        CaptureSummary {
            views: self.views.len(),
            train_views: self.train_views().count(),
            test_views: self.test_views().count(),
            kinds: kinds.iter().map(|&k| KIND_NAMES[k].to_owned()).collect(),
            width,
            height,
            polarizer_groups: groups.into_iter().collect(),
            bounds: self.object_bounds(),
            world_up: self.world_up,
            warnings: self.warnings.clone(),
            dolp: total.and_then(|h| h.stats()),
            polarization_above_noise: (above_noise.1 > 0)
                .then(|| above_noise.0 / above_noise.1 as f64),
            background_level,
            raw: self.raw.clone(),
            colmap: self.colmap.clone(),
            sparse_points: self.points.len(),
            frames,
        }
    }
}

//! The loss budget of a trained model (`phygap diagnose`): where its error comes from. Each
//! test view is rendered as the model renders it, then again with one learned component
//! replaced by the capture's ground truth — the geometry (normals, depth and coverage), the
//! albedo, the roughness, the IoR, the light — and with all of them; the S0 PSNR of each
//! variant against the captured view, and against the relit ground truth under the relighting
//! map, says what each component costs. The normals' errors are given as a distribution (mean,
//! median, 90th and 99th percentiles, cosine distance) and by distance to the silhouette, where
//! heavy tails live; the depths' as offsets from the true surface, which tell a surface seen
//! through a hole in the learned one (far behind) from a normal that is merely tilted. Each
//! test view's normal error is also kept as an image ([`NormalErrorMap`]), to see where the
//! tail lives.
//!
//! Every variant shades through the same path as rendering (`Backend::shade` on G-buffers, the
//! light GridMap over an environment with the model's mesh for occlusion), so a variant differs
//! from the learned render only in what it replaces.

use std::path::PathBuf;

use glam::DVec3;
use serde::Serialize;
use thiserror::Error;

use crate::core::camera::Camera;
use crate::core::envmap::{CubeMap, EnvMapError};
use crate::core::light::LightProbe;
use crate::core::metrics::{self, MetricsError};
use crate::core::raster::{GBuffers, RasterError};
use crate::core::render::ShadingInputs;
use crate::core::shading::ShadingError;
use crate::formats::image_io::{Image, ImageError};
use crate::io::capture::{Capture, Measurement, SceneMaps, View};
use crate::pipeline::evaluate::{read_truth, Truth};
use crate::pipeline::reconstruction::{Reconstruction, ReconstructionError};

/// Ground truth a diagnosis uses beyond the capture's views.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DiagnoseTruth {
    /// The lat-long map that lit the capture (`scene.json` → `env_map.train_test`).
    pub light: Option<PathBuf>,
    /// The lat-long map of the views' `relight_s0` (`scene.json` → `env_map.relight`).
    pub relight: Option<PathBuf>,
}

impl DiagnoseTruth {
    /// The maps `capture_dir/scene.json` names, where they exist.
    pub fn discover(capture_dir: &std::path::Path) -> DiagnoseTruth {
        let maps = SceneMaps::read(capture_dir);
        DiagnoseTruth {
            light: maps.train_test,
            relight: maps.relight,
        }
    }
}

#[derive(Debug, Error)]
pub enum DiagnoseError {
    #[error(transparent)]
    Reconstruction(#[from] ReconstructionError),
    #[error(transparent)]
    Raster(#[from] RasterError),
    #[error(transparent)]
    Shading(#[from] ShadingError),
    #[error(transparent)]
    Image(#[from] ImageError),
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
    #[error("{view}: {source}")]
    Metrics { view: String, source: MetricsError },
    #[error("the capture has no test view with full Stokes and ground-truth G-buffers (normal, depth, albedo, roughness, ior)")]
    NoGroundTruth,
}

/// One variant of the renders: what was replaced, and its S0 PSNR against the captured views
/// and against the relit ground truth.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Variant {
    pub name: &'static str,
    pub s0_psnr: f64,
    /// Under the relighting map (where the capture has one and relit ground truth).
    pub relit_psnr: Option<f64>,
}

/// Normal errors at pixels within a band of distances to the silhouette.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SilhouetteBand {
    /// Distances to the nearest background pixel, pixels: `[from, to)`.
    pub from: f64,
    pub to: f64,
    pub pixels: usize,
    pub mae_degrees: f64,
}

/// How the learned normals err against the ground truth, over every test view's object pixels.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NormalStats {
    pub pixels: usize,
    pub mae_degrees: f64,
    pub median_degrees: f64,
    pub p90_degrees: f64,
    pub p99_degrees: f64,
    pub cosine_distance: f64,
    pub by_silhouette_distance: Vec<SilhouetteBand>,
    /// The errors at the object's contours against those elsewhere.
    pub contours: ContourStats,
}

/// The normal errors within one pixel of a contour: the silhouette (an object pixel next to
/// the background) or a jump of the true depth by more than [`DEPTH_JUMP`] of itself between
/// neighbouring object pixels (where one part of the object passes in front of another, and
/// surfaces seen within about 15° of grazing). There a pixel straddles two surfaces, and the
/// true normal, sampled at its centre, is the one of whichever the centre hits.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContourStats {
    /// Share of the pixels within one pixel (4-neighbourhood) of a contour.
    pub pixel_share: f64,
    /// Share of the summed cosine distance those pixels carry.
    pub cosine_distance_share: f64,
    /// The cosine distance over the other pixels.
    pub cosine_distance_elsewhere: f64,
}

/// Relative jump of the true depth between neighbouring object pixels that [`ContourStats`]
/// counts as a contour.
pub const DEPTH_JUMP: f64 = 0.05;

/// How the learned depth departs from the true surface, over every test view's pixels that both
/// cover (the object's mask and `α ≥ ½`), in units of the object's radius.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DepthStats {
    pub pixels: usize,
    /// Median of the learned minus the true z-depth: positive behind the surface.
    pub median_offset: f64,
    /// Median of its absolute value.
    pub median_abs_offset: f64,
    /// Share of the pixels more than [`FAR_OFFSET`] behind the true surface: the learned surface
    /// has a hole there, or layers that average to a depth inside the object.
    pub far_behind_share: f64,
    /// Share of the pixels more than [`FAR_OFFSET`] in front of it.
    pub far_in_front_share: f64,
    /// Normal MAE at the pixels far behind.
    pub far_behind_normal_mae_degrees: f64,
}

/// Depth offset, in object radii, beyond which [`DepthStats`] counts a pixel as far off.
pub const FAR_OFFSET: f64 = 0.05;

/// The loss budget.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Diagnosis {
    pub test_views: usize,
    /// `learned` first, then each replacement.
    pub variants: Vec<Variant>,
    pub normals: NormalStats,
    pub depths: DepthStats,
    /// One per test view, in the capture's order (images: not in the JSON report).
    #[serde(skip)]
    pub normal_error_maps: Vec<NormalErrorMap>,
}

/// One test view's normal error, pixel by pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct NormalErrorMap {
    /// The view's name, e.g. `frame 3 (test/s0/003.exr)`.
    pub view: String,
    /// Its position in the capture's `frames` list.
    pub frame_index: usize,
    /// One channel: the angle between the learned and the true normal in degrees (sign-blind,
    /// as `phygap eval` measures it) on the object's pixels where both exist; NaN elsewhere (the
    /// background, and object pixels the model leaves without a normal).
    pub degrees: Image,
}

/// The false colours of [`NormalErrorMap::colored`]: (degrees, display RGB), linear between
/// stops, the last colour beyond the last stop.
const ERROR_COLORS: [(f32, [f32; 3]); 5] = [
    (0.0, [0.02, 0.02, 0.25]),
    (5.0, [0.10, 0.35, 0.90]),
    (15.0, [0.15, 0.80, 0.35]),
    (30.0, [1.00, 0.85, 0.10]),
    (45.0, [1.00, 0.10, 0.10]),
];

impl NormalErrorMap {
    /// The errors in false colour, for people (display RGB, to be written as it is): dark
    /// blue at 0°, blue at 5°, green at 15°, yellow at 30°, red from 45° on; black where the
    /// error is undefined.
    pub fn colored(&self) -> Image {
        let d = &self.degrees;
        Image::from_fn(d.width, d.height, 3, |x, y, rgb| {
            rgb.copy_from_slice(&error_color(d.data[y * d.width + x]));
        })
    }
}

/// The colour of an error of `degrees` ([`ERROR_COLORS`]).
fn error_color(degrees: f32) -> [f32; 3] {
    if degrees.is_nan() {
        return [0.0; 3];
    }
    match ERROR_COLORS.windows(2).find(|pair| degrees < pair[1].0) {
        Some(&[(d0, c0), (d1, c1)]) => {
            let t = ((degrees - d0) / (d1 - d0)).clamp(0.0, 1.0);
            std::array::from_fn(|k| c0[k] + t * (c1[k] - c0[k]))
        }
        _ => ERROR_COLORS[ERROR_COLORS.len() - 1].1,
    }
}

/// Distance bands of [`NormalStats::by_silhouette_distance`], pixels.
const BANDS: [(f64, f64); 5] = [
    (0.0, 1.5),
    (1.5, 3.0),
    (3.0, 6.0),
    (6.0, 12.0),
    (12.0, f64::INFINITY),
];

/// What a variant replaces.
#[derive(Clone, Copy, Debug, Default)]
struct Replace {
    geometry: bool,
    albedo: bool,
    roughness: bool,
    ior: bool,
    light: bool,
}

/// Every variant: the learned render, each component alone, the two that trade off (albedo and
/// light: a learned albedo too dark is compensated by a brighter learned light, so replacing
/// either alone can look worse than both), the materials with the light, and everything.
const VARIANTS: [(&str, Replace); 9] = [
    ("learned", Replace::NONE),
    (
        "geometry",
        Replace {
            geometry: true,
            ..Replace::NONE
        },
    ),
    (
        "albedo",
        Replace {
            albedo: true,
            ..Replace::NONE
        },
    ),
    (
        "roughness",
        Replace {
            roughness: true,
            ..Replace::NONE
        },
    ),
    (
        "ior",
        Replace {
            ior: true,
            ..Replace::NONE
        },
    ),
    (
        "light",
        Replace {
            light: true,
            ..Replace::NONE
        },
    ),
    (
        "albedo+light",
        Replace {
            albedo: true,
            light: true,
            ..Replace::NONE
        },
    ),
    (
        "materials+light",
        Replace {
            albedo: true,
            roughness: true,
            ior: true,
            light: true,
            geometry: false,
        },
    ),
    (
        "all",
        Replace {
            geometry: true,
            albedo: true,
            roughness: true,
            ior: true,
            light: true,
        },
    ),
];

impl Replace {
    const NONE: Replace = Replace {
        geometry: false,
        albedo: false,
        roughness: false,
        ior: false,
        light: false,
    };
}

/// A test view's ground truth at the capture's working resolution.
struct TruthView<'a> {
    view: &'a View,
    normal: Vec<f64>,
    depth: Vec<f64>,
    albedo: Vec<f64>,
    /// Disney r (= √ of the GGX α the files hold).
    roughness: Vec<f64>,
    ior: Vec<f64>,
    s0: Vec<f64>,
    relit: Option<Vec<f64>>,
    mask: Vec<bool>,
}

impl<'a> TruthView<'a> {
    fn read(view: &'a View, capture: &Capture) -> Result<Option<Self>, ImageError> {
        let gt = &view.ground_truth;
        let (Some(normal), Some(depth), Some(albedo), Some(roughness), Some(ior)) =
            (&gt.normal, &gt.depth, &gt.albedo, &gt.roughness, &gt.ior)
        else {
            return Ok(None);
        };
        let Measurement::Stokes { s0, .. } = &view.measurement else {
            return Ok(None);
        };
        Ok(Some(TruthView {
            view,
            normal: read_truth(normal, 3, capture, Truth::Normal)?,
            depth: read_truth(depth, 1, capture, Truth::GBuffer)?,
            albedo: read_truth(albedo, 3, capture, Truth::GBuffer)?,
            roughness: read_truth(roughness, 1, capture, Truth::GBuffer)?
                .into_iter()
                .map(|a| a.max(0.0).sqrt())
                .collect(),
            ior: read_truth(ior, 1, capture, Truth::GBuffer)?,
            s0: s0.data.iter().map(|&v| f64::from(v)).collect(),
            relit: gt
                .relight_s0
                .as_ref()
                .map(|path| read_truth(path, 3, capture, Truth::Radiance))
                .transpose()?,
            mask: view.mask.data.iter().map(|&m| m > 0.5).collect(),
        }))
    }

    /// `g` with the replaced components taken from the ground truth (object pixels only).
    fn apply(&self, g: &GBuffers, replace: Replace) -> GBuffers {
        let mut g = g.clone();
        for p in 0..g.alpha.len() {
            if !self.mask[p] {
                continue;
            }
            let rgb = |v: &[f64]| [v[3 * p], v[3 * p + 1], v[3 * p + 2]];
            if replace.geometry {
                g.normal[p] = rgb(&self.normal);
                g.depth[p] = self.depth[p];
                g.alpha[p] = 1.0;
            }
            if replace.albedo {
                g.albedo[p] = rgb(&self.albedo);
            }
            if replace.roughness {
                g.roughness[p] = self.roughness[p];
            }
            if replace.ior {
                g.ior[p] = self.ior[p];
            }
        }
        g
    }
}

/// The loss budget of `reconstruction` on `capture`'s test views that have full Stokes and
/// ground-truth G-buffers (the capture loaded at the model's working resolution).
pub fn diagnose(
    reconstruction: &Reconstruction,
    capture: &Capture,
    truth: &DiagnoseTruth,
) -> Result<Diagnosis, DiagnoseError> {
    let _span = tracing::info_span!("diagnose").entered();
    let views: Vec<TruthView> = capture
        .test_views()
        .map(|view| TruthView::read(view, capture))
        .collect::<Result<Vec<_>, _>>()?
        .into_iter()
        .flatten()
        .collect();
    if views.is_empty() {
        return Err(DiagnoseError::NoGroundTruth);
    }
    let up = reconstruction.model().world_up()?;
    let size = reconstruction.model().envmap.size;
    let load = |path: &PathBuf| CubeMap::load_latlong(path, up, size);
    let truth_lit = truth
        .light
        .as_ref()
        .map(|path| {
            reconstruction
                .relit(load(path)?)
                .map_err(DiagnoseError::from)
        })
        .transpose()?;
    let relit = truth
        .relight
        .as_ref()
        .map(|path| {
            reconstruction
                .relit(load(path)?)
                .map_err(DiagnoseError::from)
        })
        .transpose()?;
    let scene = reconstruction.scene();
    // Per variant: summed S0 PSNR and views, summed relit PSNR and views.
    let mut sums = [(0.0, 0usize, 0.0, 0usize); VARIANTS.len()];
    let mut normal_errors: Vec<PixelNormalError> = Vec::new();
    let mut normal_error_maps = Vec::with_capacity(views.len());
    let mut depth_offsets: Vec<(f64, f64)> = Vec::new();
    let radius = capture.object_bounds().radius;
    for truth_view in &views {
        let camera = &truth_view.view.camera;
        let raster = scene
            .backend
            .forward(scene.surfels, camera, &scene.settings)?;
        let g = &raster.gbuffers;
        normal_error_maps.push(collect_normal_errors(truth_view, g, &mut normal_errors));
        collect_depth_offsets(truth_view, g, radius, &mut depth_offsets);
        for ((name, replace), sum) in VARIANTS.iter().zip(sums.iter_mut()) {
            let light: &dyn LightProbe = match (replace.light, &truth_lit) {
                (true, Some(lit)) => lit.light(),
                (true, None) => continue,
                (false, _) => scene.light,
            };
            let variant_g = truth_view.apply(g, *replace);
            let psnr = |light: &dyn LightProbe, target: &[f64]| {
                shaded_psnr(
                    reconstruction,
                    camera,
                    &variant_g,
                    light,
                    target,
                    truth_view,
                )
            };
            sum.0 += psnr(light, &truth_view.s0)?;
            sum.1 += 1;
            // Relit, the light is the relighting map's: the light alone has no relit
            // counterpart; the variants that replace more keep their replacements under it.
            if let (Some(relit), Some(target)) = (&relit, &truth_view.relit) {
                if *name != "light" {
                    sum.2 += psnr(relit.light(), target)?;
                    sum.3 += 1;
                }
            }
        }
    }
    let variants = VARIANTS
        .iter()
        .zip(sums)
        .filter(|(_, sum)| sum.1 > 0)
        .map(|((name, _), (s0, n, relit, relit_n))| Variant {
            name,
            s0_psnr: s0 / n as f64,
            relit_psnr: (relit_n > 0).then(|| relit / relit_n as f64),
        })
        .collect();
    Ok(Diagnosis {
        test_views: views.len(),
        variants,
        normals: normal_stats(normal_errors),
        depths: depth_stats(depth_offsets),
        normal_error_maps,
    })
}

/// S0 PSNR (sRGB 8-bit inside the mask, as `phygap eval`) of `g` shaded under `light`.
fn shaded_psnr(
    reconstruction: &Reconstruction,
    camera: &Camera,
    g: &GBuffers,
    light: &dyn LightProbe,
    target: &[f64],
    truth: &TruthView,
) -> Result<f64, DiagnoseError> {
    let scene = reconstruction.scene();
    let inputs = ShadingInputs::new(g, camera);
    let shaded = scene
        .backend
        .shade(camera, &inputs.buffers(g), light, scene.lut)?;
    let pred: Vec<f64> = shaded
        .s0
        .iter()
        .zip(&g.alpha)
        .flat_map(|(v, &a)| (*v * a.clamp(0.0, 1.0)).to_array())
        .collect();
    metrics::psnr_srgb8(&pred, target, 3, Some(&truth.mask)).map_err(|source| {
        DiagnoseError::Metrics {
            view: truth.view.name.clone(),
            source,
        }
    })
}

/// `|cos|` of the angle between pixel `p`'s true and learned normals (sign-blind, as `phygap
/// eval`), or `None` where either is absent.
fn normal_agreement(truth: &TruthView, g: &GBuffers, p: usize) -> Option<f64> {
    let gt = DVec3::from_slice(&truth.normal[3 * p..3 * p + 3]);
    let learned = DVec3::from_array(g.normal[p]);
    (gt.length_squared() > 0.0 && learned.length_squared() > 0.0)
        .then(|| gt.normalize().dot(learned.normalize()).abs().min(1.0))
}

/// One object pixel's normal error.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PixelNormalError {
    degrees: f64,
    cosine_distance: f64,
    /// To the nearest background pixel, pixels.
    silhouette_distance: f64,
    /// Within one pixel of a contour ([`ContourStats`]).
    contour: bool,
}

/// Each object pixel's normal error, added to `out`, and the view's errors as an image.
fn collect_normal_errors(
    truth: &TruthView,
    g: &GBuffers,
    out: &mut Vec<PixelNormalError>,
) -> NormalErrorMap {
    let distance = silhouette_distance(&truth.mask, g.width, g.height);
    let contour = near_contours(&truth.mask, &truth.depth, g.width, g.height);
    let mut degrees = Image::filled(g.width, g.height, 1, f32::NAN);
    for (p, (&object, silhouette_distance)) in truth.mask.iter().zip(distance).enumerate() {
        if let Some(cos) = normal_agreement(truth, g, p).filter(|_| object) {
            let error = PixelNormalError {
                degrees: cos.acos().to_degrees(),
                cosine_distance: 1.0 - cos,
                silhouette_distance,
                contour: contour[p],
            };
            degrees.data[p] = error.degrees as f32;
            out.push(error);
        }
    }
    NormalErrorMap {
        view: truth.view.name.clone(),
        frame_index: truth.view.frame_index,
        degrees,
    }
}

/// The object pixels within one pixel (4-neighbourhood) of a contour ([`ContourStats`]).
fn near_contours(mask: &[bool], depth: &[f64], width: usize, height: usize) -> Vec<bool> {
    let neighbours = |p: usize| {
        let (x, y) = (p % width, p / width);
        [
            (x > 0).then(|| p - 1),
            (x + 1 < width).then(|| p + 1),
            (y > 0).then(|| p - width),
            (y + 1 < height).then(|| p + width),
        ]
    };
    let on_contour: Vec<bool> = (0..mask.len())
        .map(|p| {
            mask[p]
                && neighbours(p).iter().any(|n| match *n {
                    None => true,
                    Some(n) if !mask[n] => true,
                    Some(n) => (depth[n] - depth[p]).abs() > DEPTH_JUMP * depth[p].abs(),
                })
        })
        .collect();
    (0..mask.len())
        .map(|p| {
            mask[p]
                && (on_contour[p]
                    || neighbours(p)
                        .iter()
                        .any(|n| n.is_some_and(|n| on_contour[n])))
        })
        .collect()
}

/// Each covered object pixel's depth offset from the truth (object radii, positive behind) and
/// its normal error (degrees).
fn collect_depth_offsets(truth: &TruthView, g: &GBuffers, radius: f64, out: &mut Vec<(f64, f64)>) {
    let scale = if radius > 0.0 { 1.0 / radius } else { 1.0 };
    for p in 0..g.alpha.len() {
        let true_depth = truth.depth[p];
        if !truth.mask[p] || true_depth <= 0.0 || g.alpha[p] < 0.5 {
            continue;
        }
        let error = normal_agreement(truth, g, p).map_or(f64::NAN, |cos| cos.acos().to_degrees());
        out.push(((g.depth[p] - true_depth) * scale, error));
    }
}

fn depth_stats(offsets: Vec<(f64, f64)>) -> DepthStats {
    let n = offsets.len();
    let share = |f: &dyn Fn(f64) -> bool| {
        offsets.iter().filter(|o| f(o.0)).count() as f64 / n.max(1) as f64
    };
    let behind: Vec<f64> = offsets
        .iter()
        .filter(|o| o.0 > FAR_OFFSET && o.1.is_finite())
        .map(|o| o.1)
        .collect();
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(0.0)
    };
    DepthStats {
        pixels: n,
        median_offset: median(offsets.iter().map(|o| o.0).collect()),
        median_abs_offset: median(offsets.iter().map(|o| o.0.abs()).collect()),
        far_behind_share: share(&|d| d > FAR_OFFSET),
        far_in_front_share: share(&|d| d < -FAR_OFFSET),
        far_behind_normal_mae_degrees: behind.iter().sum::<f64>() / behind.len().max(1) as f64,
    }
}

/// Each pixel's distance to the nearest background pixel (two-pass chamfer distance, 1 and √2
/// steps; the image border counts as background).
fn silhouette_distance(mask: &[bool], width: usize, height: usize) -> Vec<f64> {
    let big = (width + height) as f64;
    let mut d: Vec<f64> = mask.iter().map(|&m| if m { big } else { 0.0 }).collect();
    let at = |x: isize, y: isize, d: &[f64]| {
        if x < 0 || y < 0 || x >= width as isize || y >= height as isize {
            0.0
        } else {
            d[y as usize * width + x as usize]
        }
    };
    let diagonal = std::f64::consts::SQRT_2;
    for y in 0..height as isize {
        for x in 0..width as isize {
            let i = y as usize * width + x as usize;
            let best = [
                at(x - 1, y, &d) + 1.0,
                at(x, y - 1, &d) + 1.0,
                at(x - 1, y - 1, &d) + diagonal,
                at(x + 1, y - 1, &d) + diagonal,
            ]
            .into_iter()
            .fold(d[i], f64::min);
            d[i] = best;
        }
    }
    for y in (0..height as isize).rev() {
        for x in (0..width as isize).rev() {
            let i = y as usize * width + x as usize;
            let best = [
                at(x + 1, y, &d) + 1.0,
                at(x, y + 1, &d) + 1.0,
                at(x + 1, y + 1, &d) + diagonal,
                at(x - 1, y + 1, &d) + diagonal,
            ]
            .into_iter()
            .fold(d[i], f64::min);
            d[i] = best;
        }
    }
    d
}

fn normal_stats(mut errors: Vec<PixelNormalError>) -> NormalStats {
    let n = errors.len().max(1);
    let mae_degrees = errors.iter().map(|e| e.degrees).sum::<f64>() / n as f64;
    let total_cosine: f64 = errors.iter().map(|e| e.cosine_distance).sum();
    let by_silhouette_distance = BANDS
        .iter()
        .map(|&(from, to)| {
            let band: Vec<f64> = errors
                .iter()
                .filter(|e| e.silhouette_distance >= from && e.silhouette_distance < to)
                .map(|e| e.degrees)
                .collect();
            SilhouetteBand {
                from,
                to,
                pixels: band.len(),
                mae_degrees: band.iter().sum::<f64>() / band.len().max(1) as f64,
            }
        })
        .collect();
    let at_contours = errors.iter().filter(|e| e.contour).count();
    let contour_cosine: f64 = errors
        .iter()
        .filter(|e| e.contour)
        .map(|e| e.cosine_distance)
        .sum();
    let contours = ContourStats {
        pixel_share: at_contours as f64 / n as f64,
        cosine_distance_share: if total_cosine > 0.0 {
            contour_cosine / total_cosine
        } else {
            0.0
        },
        cosine_distance_elsewhere: (total_cosine - contour_cosine)
            / (errors.len() - at_contours).max(1) as f64,
    };
    errors.sort_by(|a, b| a.degrees.total_cmp(&b.degrees));
    let quantile = |q: f64| {
        errors
            .get(((errors.len() as f64 - 1.0) * q).round().max(0.0) as usize)
            .map_or(0.0, |e| e.degrees)
    };
    NormalStats {
        pixels: errors.len(),
        mae_degrees,
        median_degrees: quantile(0.5),
        p90_degrees: quantile(0.9),
        p99_degrees: quantile(0.99),
        cosine_distance: total_cosine / n as f64,
        by_silhouette_distance,
        contours,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_colours_follow_their_stops() {
        assert_eq!(error_color(f32::NAN), [0.0; 3]);
        assert_eq!(error_color(0.0), ERROR_COLORS[0].1);
        assert_eq!(error_color(15.0), ERROR_COLORS[2].1);
        assert_eq!(error_color(90.0), ERROR_COLORS[4].1);
        // Half-way between 5° and 15°.
        let mid = error_color(10.0);
        let (a, b) = (ERROR_COLORS[1].1, ERROR_COLORS[2].1);
        for k in 0..3 {
            assert!((mid[k] - 0.5 * (a[k] + b[k])).abs() < 1e-6, "{mid:?}");
        }
        let map = NormalErrorMap {
            view: "v".into(),
            frame_index: 0,
            degrees: Image {
                width: 2,
                height: 1,
                channels: 1,
                data: vec![f32::NAN, 45.0],
            },
        };
        assert_eq!(map.colored().data, [0.0, 0.0, 0.0, 1.0, 0.1, 0.1]);
    }

    #[test]
    fn silhouette_distances_grow_inwards() {
        // A 7 × 5 image, object in the 5 × 3 middle.
        let (w, h) = (7, 5);
        let mask: Vec<bool> = (0..w * h)
            .map(|p| (1..6).contains(&(p % w)) && (1..4).contains(&(p / w)))
            .collect();
        let d = silhouette_distance(&mask, w, h);
        assert_eq!(d[0], 0.0);
        assert_eq!(d[w + 1], 1.0, "an edge pixel");
        assert_eq!(d[2 * w + 3], 2.0, "the centre");
    }

    #[test]
    fn normal_statistics_report_the_tail() {
        let error = |degrees: f64, silhouette_distance: f64, contour: bool| PixelNormalError {
            degrees,
            cosine_distance: 1.0 - degrees.to_radians().cos(),
            silhouette_distance,
            contour,
        };
        let mut errors: Vec<PixelNormalError> = (0..100)
            .map(|i| error(1.0, 12.0 + i as f64, false))
            .collect();
        errors[0] = error(91.0, 0.5, true);
        errors[1] = error(1.0, 13.0, true);
        let stats = normal_stats(errors);
        assert_eq!(stats.pixels, 100);
        assert!((stats.mae_degrees - 1.9).abs() < 1e-9);
        assert_eq!((stats.median_degrees, stats.p99_degrees), (1.0, 1.0));
        assert_eq!(stats.by_silhouette_distance[0].pixels, 1);
        assert_eq!(stats.by_silhouette_distance[0].mae_degrees, 91.0);
        assert_eq!(stats.by_silhouette_distance[4].pixels, 99);
        let (small, large) = (
            1.0 - 1f64.to_radians().cos(),
            1.0 - 91f64.to_radians().cos(),
        );
        let contours = &stats.contours;
        assert_eq!(contours.pixel_share, 0.02);
        assert!(
            (contours.cosine_distance_share - (large + small) / (large + 99.0 * small)).abs()
                < 1e-12
        );
        assert!((contours.cosine_distance_elsewhere - small).abs() < 1e-15);
    }

    #[test]
    fn contours_are_silhouettes_and_depth_jumps() {
        // A 13 × 5 image: background in column 0, object elsewhere, a nearer part (depth 1)
        // in columns 7–12 in front of a farther one in columns 1–6 that slopes away smoothly
        // (2% a pixel, below the jump).
        let (w, h) = (13, 5);
        let mask: Vec<bool> = (0..w * h).map(|p| p % w != 0).collect();
        let depth: Vec<f64> = (0..w * h)
            .map(|p| match p % w {
                0 => 0.0,
                x @ 1..=6 => 2.0 + 0.04 * x as f64,
                _ => 1.0,
            })
            .collect();
        let near = near_contours(&mask, &depth, w, h);
        let row = &near[2 * w..3 * w];
        // Contours: column 1 (next to the background), 6 and 7 (the jump), 12 (the image's
        // border counts as background); their neighbours are within one pixel; 3, 4, 9 and
        // 10 are not, the slope notwithstanding.
        let expected: Vec<bool> = (0..w).map(|x| ![0, 3, 4, 9, 10].contains(&x)).collect();
        assert_eq!(row, expected.as_slice());
        assert!(near[w + 3] && !near[2 * w + 3]);
    }

    #[test]
    fn depth_statistics_find_the_pixels_seen_through_a_hole() {
        // 90 pixels on the surface (a little behind it), 10 far behind with 40° normals, 5 far
        // in front.
        let mut offsets: Vec<(f64, f64)> = (0..90).map(|_| (0.01, 2.0)).collect();
        offsets.extend((0..10).map(|_| (0.5, 40.0)));
        offsets.extend((0..5).map(|_| (-0.2, 10.0)));
        let stats = depth_stats(offsets);
        assert_eq!(stats.pixels, 105);
        assert_eq!(stats.median_offset, 0.01);
        assert_eq!(stats.median_abs_offset, 0.01);
        assert!((stats.far_behind_share - 10.0 / 105.0).abs() < 1e-12);
        assert!((stats.far_in_front_share - 5.0 / 105.0).abs() < 1e-12);
        assert_eq!(stats.far_behind_normal_mae_degrees, 40.0);
    }
}

//! Evaluation of a reconstruction on the held-out views of a capture (METHOD.md §8): S0 PSNR/SSIM
//! (sRGB 8-bit, inside the mask), normal MAE and cosine distance, Stokes, DoLP and AoLP errors and
//! material errors where the capture carries ground truth. Every figure is the mean over test views;
//! a figure without ground truth is `None` (JSON `null`).

use std::collections::BTreeMap;
use std::path::Path;

use glam::DVec3;
use serde::Serialize;
use thiserror::Error;

use crate::core::camera::Camera;
use crate::core::metrics::{self, MetricsError};
use crate::core::pose::pose_error;
use crate::core::render::{RenderError, RenderedView, Scene};
use crate::formats::image_io::{self, Image, ImageError};
use crate::io::capture::{resample, Capture, Measurement, PolarizerAngle, View};

/// The JSON printed by `phygap eval` (keys fixed by the CLI contract).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct EvalReport {
    pub psnr: Option<f64>,
    pub ssim: Option<f64>,
    pub normal_mae_deg: Option<f64>,
    pub normal_cos_dist: Option<f64>,
    pub s1_l1: Option<f64>,
    pub s2_l1: Option<f64>,
    pub dolp_mae: Option<f64>,
    pub aolp_mae_deg: Option<f64>,
    pub albedo_mae: Option<f64>,
    pub roughness_mae: Option<f64>,
    pub ior_mae: Option<f64>,
    /// S0 PSNR / SSIM (sRGB 8-bit, inside the mask) of the model relit by the capture's relight
    /// map against each test view's `relight_s0` ground truth (`phygap eval --relight-envmap`).
    pub relight_psnr: Option<f64>,
    pub relight_ssim: Option<f64>,
    /// Chamfer-L1 from the model's extracted mesh to a ground-truth mesh (`--gt-mesh`).
    pub chamfer: Option<f64>,
    /// The model's (refined) training cameras against the capture's ([`pose_errors`]): the mean
    /// angle between their rotations in degrees, and the mean distance between their centres as a
    /// fraction of the object's radius.
    pub pose_error_deg: Option<f64>,
    pub pose_error_radius: Option<f64>,
    /// The mean image distance, in the capture's pixels, between where the model's training
    /// cameras and the capture's see the model's opaque surfels.
    pub pose_error_px: Option<f64>,
    pub num_surfels: usize,
    pub train_seconds: Option<f64>,
    /// Learned angle per `polarizer_group`, degrees in [0, 180).
    pub polarizer_angles_deg: BTreeMap<String, f64>,
    pub test_views: usize,
}

#[derive(Debug, Error)]
pub enum EvalError {
    #[error("the capture has no test views to evaluate on")]
    NoTestViews,
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error("ground truth: {0}")]
    GroundTruth(#[from] ImageError),
    #[error("{view}: {source}")]
    Metrics { view: String, source: MetricsError },
    #[error("Chamfer distance: {0}")]
    Mesh(#[from] crate::core::mesh::MeshError),
}

/// How far a model's training cameras are from a capture's ([`pose_errors`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseErrors {
    /// The mean angle between the paired cameras' rotations, in degrees.
    pub angle_deg: f64,
    /// The mean distance between their centres, as a fraction of the object's radius.
    pub distance_radius: f64,
    /// The mean distance, in the capture's pixels, between where the two cameras of a pair see
    /// the same points of the object: what the errors do to the images, in which a rotation and a
    /// translation that shift the object alike cancel. `None` without points in front of both.
    pub image_px: Option<f64>,
}

/// The errors of a model's training cameras against the training views of `capture`, paired by
/// name, or in order where the names differ but the counts agree (a copy of the capture written by
/// `phygap degrade`, evaluated against the clean one); `None` when they cannot be paired. The
/// image distance is taken over `points` (the object's, in world units).
pub fn pose_errors(
    cameras: &[(String, Camera)],
    capture: &Capture,
    points: &[DVec3],
) -> Option<PoseErrors> {
    let train: Vec<&View> = capture.train_views().collect();
    let by_name: Option<Vec<&View>> = cameras
        .iter()
        .map(|(name, _)| train.iter().copied().find(|v| &v.name == name))
        .collect();
    let pairs = match by_name {
        Some(views) => views,
        None if train.len() == cameras.len() => train,
        None => return None,
    };
    if pairs.is_empty() {
        return None;
    }
    let radius = capture.object_bounds().radius;
    let (angle, distance) = cameras
        .iter()
        .zip(&pairs)
        .map(|((_, camera), view)| pose_error(camera, &view.camera))
        .fold((0.0, 0.0), |(a, d), (da, dd)| (a + da, d + dd));
    let image: Vec<f64> = cameras
        .iter()
        .zip(&pairs)
        .filter_map(|((_, camera), view)| image_displacement(camera, &view.camera, points))
        .collect();
    let n = pairs.len() as f64;
    Some(PoseErrors {
        angle_deg: angle / n,
        distance_radius: distance / n / radius,
        image_px: (!image.is_empty()).then(|| image.iter().sum::<f64>() / image.len() as f64),
    })
}

/// The mean distance in `truth`'s pixels between where `camera` (at any resolution of the same
/// view) and `truth` see `points`; `None` when no point is in front of both.
fn image_displacement(camera: &Camera, truth: &Camera, points: &[DVec3]) -> Option<f64> {
    let sx = f64::from(truth.width) / f64::from(camera.width);
    let sy = f64::from(truth.height) / f64::from(camera.height);
    let (sum, count) = points
        .iter()
        .filter_map(|&x| {
            let (u, v, _) = camera.project(x)?;
            let (ut, vt, _) = truth.project(x)?;
            Some((u * sx - ut).hypot(v * sy - vt))
        })
        .fold((0.0, 0usize), |(s, c), d| (s + d, c + 1));
    (count > 0).then(|| sum / count as f64)
}

/// Mean S0 PSNR and SSIM (sRGB 8-bit, inside the mask) of `relit` — a scene lit by the capture's
/// relighting map — against the `relight_s0` ground truth of every test view that has one
/// (`None` when no test view has it).
pub fn relight_metrics(
    relit: &Scene,
    capture: &Capture,
) -> Result<(Option<f64>, Option<f64>), EvalError> {
    let _span = tracing::info_span!("relight_metrics").entered();
    let mut means = Means::default();
    for view in capture.test_views() {
        let Some(path) = &view.ground_truth.relight_s0 else {
            continue;
        };
        let metric_err = |source| EvalError::Metrics {
            view: view.name.clone(),
            source,
        };
        let target = read_truth(path, 3, capture, Truth::Radiance)?;
        let rendered = relit.render(&view.camera)?;
        let pred = rendered.premultiplied(&rendered.shaded.s0);
        let g = rendered.gbuffers();
        let mask: Vec<bool> = view.mask.data.iter().map(|&m| m > 0.5).collect();
        let mask = Some(mask.as_slice());
        means.add(
            "psnr",
            Some(metrics::psnr_srgb8(&pred, &target, 3, mask).map_err(metric_err)?),
        );
        means.add(
            "ssim",
            Some(
                metrics::ssim_srgb8(&pred, &target, g.width, g.height, 3, mask)
                    .map_err(metric_err)?,
            ),
        );
    }
    Ok((means.get("psnr"), means.get("ssim")))
}

/// Chamfer-L1 from a predicted mesh to the ground-truth mesh at `gt_path` (PLY), METHOD.md §8.
pub fn chamfer_to_gt(
    pred: &crate::core::mesh::TriangleMesh,
    gt_path: &Path,
) -> Result<f64, EvalError> {
    let gt = crate::core::mesh::TriangleMesh::read_ply(gt_path)?;
    Ok(crate::core::mesh::chamfer_l1(pred, &gt)?)
}

/// Running means of the per-view figures.
#[derive(Default)]
struct Means(BTreeMap<&'static str, (f64, usize)>);

impl Means {
    fn add(&mut self, key: &'static str, value: Option<f64>) {
        if let Some(v) = value.filter(|v| v.is_finite()) {
            let e = self.0.entry(key).or_insert((0.0, 0));
            e.0 += v;
            e.1 += 1;
        }
    }
    fn get(&self, key: &str) -> Option<f64> {
        self.0.get(key).map(|(s, n)| s / *n as f64)
    }
}

/// What a ground-truth file holds, which decides how it is shrunk to a working resolution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Truth {
    /// Radiance (Stokes, relit S0): block means, as the views themselves.
    Radiance,
    /// A G-buffer, zero on the background: means over the object's pixels.
    GBuffer,
    /// Unit normals: means over the object's pixels, made unit again.
    Normal,
}

/// A ground-truth image of a view of `capture` as `channels` f64 per pixel, at the capture's
/// working resolution (shrunk by `capture.downscale` as its views were).
pub(crate) fn read_truth(
    path: &Path,
    channels: usize,
    capture: &Capture,
    truth: Truth,
) -> Result<Vec<f64>, ImageError> {
    let (img, _) = image_io::read_image(path)?;
    let img = if channels == 3 {
        img.to_rgb()
    } else {
        img.channel(0)
    };
    let k = capture.downscale as usize;
    let img = match truth {
        Truth::Radiance => resample::downscale_image(&img, k),
        Truth::GBuffer | Truth::Normal => resample::downscale_gbuffer(&img, k),
    };
    let mut values: Vec<f64> = img.data.iter().map(|&v| f64::from(v)).collect();
    if truth == Truth::Normal && k > 1 {
        for n in values.chunks_exact_mut(3) {
            let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            if length > 0.0 {
                n.iter_mut().for_each(|v| *v /= length);
            }
        }
    }
    Ok(values)
}

fn to_f64(img: &Image) -> Vec<f64> {
    img.to_rgb().data.iter().map(|&v| f64::from(v)).collect()
}

/// Where a test view's Stokes ground truth is: its own Stokes measurement, else its `s*_path`
/// ground-truth files when it names all three.
enum StokesTruth<'a> {
    Measured([&'a Image; 3]),
    Files([&'a Path; 3]),
}

impl<'a> StokesTruth<'a> {
    fn of(view: &'a View) -> Option<Self> {
        if let Measurement::Stokes { s0, s1, s2 } = &view.measurement {
            return Some(StokesTruth::Measured([s0, s1, s2]));
        }
        let gt = &view.ground_truth;
        match (&gt.s0, &gt.s1, &gt.s2) {
            (Some(a), Some(b), Some(c)) => Some(StokesTruth::Files([a, b, c])),
            _ => None,
        }
    }

    /// Component `k` (0 = S0) as interleaved RGB at the capture's working resolution.
    fn read(&self, k: usize, capture: &Capture) -> Result<Vec<f64>, ImageError> {
        match self {
            StokesTruth::Measured(images) => Ok(to_f64(images[k])),
            StokesTruth::Files(paths) => read_truth(paths[k], 3, capture, Truth::Radiance),
        }
    }
}

/// Ground-truth Stokes of a test view ([`StokesTruth`]), `None` where it has none.
fn ground_truth_stokes(
    view: &View,
    capture: &Capture,
) -> Result<Option<[Vec<f64>; 3]>, ImageError> {
    StokesTruth::of(view)
        .map(|t| {
            Ok([
                t.read(0, capture)?,
                t.read(1, capture)?,
                t.read(2, capture)?,
            ])
        })
        .transpose()
}

/// Per-pixel grey (channel mean) of an interleaved RGB image.
fn grey(rgb: &[f64]) -> Vec<f64> {
    rgb.chunks_exact(3)
        .map(|c| (c[0] + c[1] + c[2]) / 3.0)
        .collect()
}

/// Photometric target and prediction of a view without Stokes ground truth: the image itself,
/// compared with S0 (plain RGB) or with I(θ) (behind a polarizer).
fn image_comparison(
    view: &View,
    rendered: &RenderedView,
    angles: &BTreeMap<String, f64>,
) -> (Vec<f64>, Vec<f64>) {
    let s = &rendered.shaded;
    match &view.measurement {
        Measurement::Polarizer { image, angle } => {
            let theta = match angle {
                PolarizerAngle::Known { degrees } => degrees.to_radians(),
                PolarizerAngle::Group(g) => angles.get(g).copied().unwrap_or(0.0),
            };
            let (c, sn) = ((2.0 * theta).cos(), (2.0 * theta).sin());
            let intensity: Vec<DVec3> = (0..s.s0.len())
                .map(|p| 0.5 * (s.s0[p] + s.s1[p] * c + s.s2[p] * sn))
                .collect();
            (rendered.premultiplied(&intensity), to_f64(image))
        }
        Measurement::Rgb { image } => (rendered.premultiplied(&s.s0), to_f64(image)),
        Measurement::Stokes { s0, .. } => (rendered.premultiplied(&s.s0), to_f64(s0)),
    }
}

/// The photometric prediction of a test view and its target, interleaved RGB: S0 against the
/// Stokes ground truth's S0 where there is one (`gt_s0`), else [`image_comparison`].
fn photometric_pair(
    view: &View,
    rendered: &RenderedView,
    gt_s0: Option<Vec<f64>>,
    angles: &BTreeMap<String, f64>,
) -> (Vec<f64>, Vec<f64>) {
    match gt_s0 {
        Some(t0) => (rendered.premultiplied(&rendered.shaded.s0), t0),
        None => image_comparison(view, rendered, angles),
    }
}

/// The mask of a test view as the metrics take it.
fn view_mask(view: &View) -> Vec<bool> {
    view.mask.data.iter().map(|&m| m > 0.5).collect()
}

/// The mean test-view S0 PSNR of [`evaluate_scaled`] (the same figure, bit for bit), without the
/// rest of its metrics: what a run reports as it trains. It renders each test view and reads no
/// ground-truth file besides S0 where S0 is not the view's own measurement (the full evaluation
/// also reads each view's normal, albedo, roughness and IoR maps at the capture's full size).
/// `None` when the capture has no test views.
pub fn test_psnr_scaled(
    scene: &Scene,
    radiance_scale: f64,
    capture: &Capture,
    angles: &BTreeMap<String, f64>,
) -> Result<Option<f64>, EvalError> {
    let _span = tracing::info_span!("test_psnr").entered();
    let mut means = Means::default();
    for view in capture.test_views() {
        let mut rendered = scene.render(&view.camera)?;
        rendered.shaded.scale_radiance(radiance_scale);
        let gt_s0 = StokesTruth::of(view)
            .map(|t| t.read(0, capture))
            .transpose()?;
        let (pred, target) = photometric_pair(view, &rendered, gt_s0, angles);
        let mask = view_mask(view);
        let psnr = metrics::psnr_srgb8(&pred, &target, 3, Some(&mask)).map_err(|source| {
            EvalError::Metrics {
                view: view.name.clone(),
                source,
            }
        })?;
        means.add("psnr", Some(psnr));
    }
    Ok(means.get("psnr"))
}

/// Evaluates `scene` on every test view of `capture`. `angles` are the learned polarizer angles in
/// radians (for partial test views without S0 ground truth).
pub fn evaluate(
    scene: &Scene,
    capture: &Capture,
    angles: &BTreeMap<String, f64>,
) -> Result<EvalReport, EvalError> {
    evaluate_scaled(scene, 1.0, capture, angles)
}

/// [`evaluate`] of a scene whose light is in units of `radiance_scale` of the capture's (a
/// training run's, `train::exposure`): its renders are multiplied by the scale (shading is linear
/// in the light) before they are compared.
pub fn evaluate_scaled(
    scene: &Scene,
    radiance_scale: f64,
    capture: &Capture,
    angles: &BTreeMap<String, f64>,
) -> Result<EvalReport, EvalError> {
    let _span = tracing::info_span!("evaluate").entered();
    let tests: Vec<&View> = capture.test_views().collect();
    if tests.is_empty() {
        return Err(EvalError::NoTestViews);
    }
    let mut means = Means::default();
    for view in &tests {
        let metric_err = |source| EvalError::Metrics {
            view: view.name.clone(),
            source,
        };
        let mut rendered = scene.render(&view.camera)?;
        rendered.shaded.scale_radiance(radiance_scale);
        let g = rendered.gbuffers();
        let (w, h) = (g.width, g.height);
        let mask_pixels = view_mask(view);
        let mask = Some(mask_pixels.as_slice());
        let s = &rendered.shaded;
        let gt_stokes = ground_truth_stokes(view, capture)?;
        let gt_s0 = gt_stokes.as_ref().map(|[t0, _, _]| t0.clone());
        let (pred0, target0) = photometric_pair(view, &rendered, gt_s0, angles);
        means.add(
            "psnr",
            Some(metrics::psnr_srgb8(&pred0, &target0, 3, mask).map_err(metric_err)?),
        );
        means.add(
            "ssim",
            Some(metrics::ssim_srgb8(&pred0, &target0, w, h, 3, mask).map_err(metric_err)?),
        );
        if let Some([t0, t1, t2]) = &gt_stokes {
            let (p1, p2) = (rendered.premultiplied(&s.s1), rendered.premultiplied(&s.s2));
            means.add("s1_l1", metrics::masked_mae(&p1, t1, 3, mask).ok());
            means.add("s2_l1", metrics::masked_mae(&p2, t2, 3, mask).ok());
            let (gp0, gp1, gp2) = (grey(&pred0), grey(&p1), grey(&p2));
            let (gt0, gt1, gt2) = (grey(t0), grey(t1), grey(t2));
            let pred_dolp = metrics::dolp(&gp0, &gp1, &gp2).map_err(metric_err)?;
            let gt_dolp = metrics::dolp(&gt0, &gt1, &gt2).map_err(metric_err)?;
            means.add(
                "dolp_mae",
                metrics::masked_mae(&pred_dolp, &gt_dolp, 1, mask).ok(),
            );
            let polarized: Vec<bool> = gt_dolp
                .iter()
                .zip(&mask_pixels)
                .map(|(&d, &m)| m && d > 0.05)
                .collect();
            let pred_aolp = metrics::aolp(&gp1, &gp2).map_err(metric_err)?;
            let gt_aolp = metrics::aolp(&gt1, &gt2).map_err(metric_err)?;
            means.add(
                "aolp_mae_deg",
                metrics::aolp_mae_degrees(&pred_aolp, &gt_aolp, 1, Some(&polarized)).ok(),
            );
        }
        let gt = &view.ground_truth;
        if let Some(path) = &gt.normal {
            let truth = read_truth(path, 3, capture, Truth::Normal)?;
            let errors = metrics::normal_errors(g.normal.as_flattened(), &truth, mask);
            if let Ok(e) = errors {
                means.add("normal_mae_deg", Some(e.mae_degrees));
                means.add("normal_cos_dist", Some(e.cosine_distance));
            }
        }
        if let Some(path) = &gt.albedo {
            let pred = g.albedo.as_flattened();
            means.add(
                "albedo_mae",
                metrics::masked_mae(
                    pred,
                    &read_truth(path, 3, capture, Truth::GBuffer)?,
                    3,
                    mask,
                )
                .ok(),
            );
        }
        if let Some(path) = &gt.roughness {
            // Ground truth stores GGX α; our roughness r has α = r².
            let gt_r: Vec<f64> = read_truth(path, 1, capture, Truth::GBuffer)?
                .iter()
                .map(|a| a.max(0.0).sqrt())
                .collect();
            means.add(
                "roughness_mae",
                metrics::masked_mae(&g.roughness, &gt_r, 1, mask).ok(),
            );
        }
        if let Some(path) = &gt.ior {
            means.add(
                "ior_mae",
                metrics::masked_mae(
                    &g.ior,
                    &read_truth(path, 1, capture, Truth::GBuffer)?,
                    1,
                    mask,
                )
                .ok(),
            );
        }
    }
    Ok(EvalReport {
        psnr: means.get("psnr"),
        ssim: means.get("ssim"),
        normal_mae_deg: means.get("normal_mae_deg"),
        normal_cos_dist: means.get("normal_cos_dist"),
        s1_l1: means.get("s1_l1"),
        s2_l1: means.get("s2_l1"),
        dolp_mae: means.get("dolp_mae"),
        aolp_mae_deg: means.get("aolp_mae_deg"),
        albedo_mae: means.get("albedo_mae"),
        roughness_mae: means.get("roughness_mae"),
        ior_mae: means.get("ior_mae"),
        relight_psnr: None,
        pose_error_deg: None,
        pose_error_radius: None,
        pose_error_px: None,
        relight_ssim: None,
        chamfer: None,
        num_surfels: scene.surfels.len(),
        train_seconds: None,
        polarizer_angles_deg: angles
            .iter()
            .map(|(k, v)| (k.clone(), v.to_degrees().rem_euclid(180.0)))
            .collect(),
        test_views: tests.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points() -> Vec<DVec3> {
        (0..50)
            .map(|k| {
                let a = f64::from(k) * 0.7;
                DVec3::new(0.5 * a.cos(), 0.5 * a.sin(), 0.3 * (a * 1.3).sin())
            })
            .collect()
    }

    #[test]
    fn the_image_displacement_is_in_the_true_cameras_pixels() {
        let eye = DVec3::new(0.4, -3.0, 1.2);
        let truth = Camera::look_at(64, 48, 0.8, eye, DVec3::ZERO, DVec3::Z);
        let d = |camera: &Camera| image_displacement(camera, &truth, &points()).unwrap();
        assert!(d(&truth) < 1e-12);
        // The same view at half the resolution sees every point where the truth does.
        let half = Camera {
            width: 32,
            height: 24,
            fx: truth.fx / 2.0,
            fy: truth.fy / 2.0,
            cx: truth.cx / 2.0,
            cy: truth.cy / 2.0,
            ..truth
        };
        assert!(d(&half) < 1e-12);
        // A principal point 1.5 px right and 2 px down moves every point by 2.5 px; at half the
        // resolution the same move in the half-size image is 5 px in the truth's.
        let moved = Camera {
            cx: truth.cx + 1.5,
            cy: truth.cy + 2.0,
            ..truth
        };
        assert!((d(&moved) - 2.5).abs() < 1e-9);
        let moved_half = Camera {
            cx: half.cx + 1.5,
            cy: half.cy + 2.0,
            ..half
        };
        assert!((d(&moved_half) - 5.0).abs() < 1e-9);
        // Points behind either camera count for nothing.
        assert_eq!(image_displacement(&truth, &truth, &[eye * 2.0]), None);
    }
}

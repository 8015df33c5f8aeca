//! Differentiable rasterization of 2D Gaussian surfels into G-buffers (METHOD.md §3).
//!
//! A rasterizer turns surfels and a camera into [`GBuffers`] (forward) and turns upstream
//! gradients on every buffer back into gradients on the raw surfel parameters (backward); the
//! engines offer it through [`crate::core::engine::Backend`]. [`cpu::CpuBackend`] is the f64
//! reference implementation, [`fast::FastBackend`] the same computation in f32 SIMD on the host.
//! The buffers' types, the depth-derived normal map and the α-normalization are defined here,
//! once, so every engine produces the same buffers.
//!
//! α-normalization: the composited depth, normal, albedo, roughness and IoR are divided by the
//! accumulated opacity α where `α > RasterSettings::normalize_alpha_min` (ε = 1e-6 by default) and
//! are zero elsewhere. With the default `alpha_min = 1/255` any pixel that any surfel reaches has
//! `α ≥ 1/255 ≫ ε`, so ε only separates covered pixels from empty ones and the buffers are smooth
//! wherever the compositing itself is.

pub mod cpu;
pub mod fast;
pub mod project;
mod tiles;

use std::any::Any;

use glam::DVec3;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::core::camera::Camera;
use crate::core::filled::filled;
use crate::core::surfels::{SurfelGrads, Surfels};

/// Thresholds of the rasterizer (2DGS defaults).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RasterSettings {
    /// Tile edge in pixels (tiles are `tile_size × tile_size`).
    pub tile_size: u32,
    /// Surfels whose centre, and ray–surfel intersections whose z-depth, are not beyond this are
    /// skipped (scene units).
    pub near: f64,
    /// A pixel stops compositing before the surfel that would bring its transmittance below this.
    pub transmittance_min: f64,
    /// Surfel contributions with α below this are skipped.
    pub alpha_min: f64,
    /// α is clamped to at most this.
    pub alpha_max: f64,
    /// Standard deviation (pixels) of the screen-space low-pass filter `ρ_2d = |x − μ|² / σ²`
    /// (2DGS: 1/√2, i.e. `ρ_2d = 2 |x − μ|²`); 0 turns the filter off.
    pub lowpass_sigma_px: f64,
    /// ε of the α-normalization: normalized buffers are zero where `α ≤ ε`.
    pub normalize_alpha_min: f64,
}

impl Default for RasterSettings {
    fn default() -> Self {
        RasterSettings {
            tile_size: 16,
            near: 0.01,
            transmittance_min: 1e-4,
            alpha_min: 1.0 / 255.0,
            alpha_max: 0.99,
            lowpass_sigma_px: std::f64::consts::FRAC_1_SQRT_2,
            normalize_alpha_min: 1e-6,
        }
    }
}

impl RasterSettings {
    /// Checks the settings; names the first bad field.
    pub fn validate(&self) -> Result<(), RasterError> {
        let bad = |name: &'static str| Err(RasterError::InvalidSetting(name));
        if self.tile_size == 0 || self.tile_size > 64 {
            return bad("tile_size (1..=64)");
        }
        if !(self.near >= 0.0 && self.near.is_finite()) {
            return bad("near (finite, ≥ 0)");
        }
        if !(0.0..1.0).contains(&self.transmittance_min) {
            return bad("transmittance_min ([0, 1))");
        }
        if !(self.alpha_max > 0.0 && self.alpha_max < 1.0) {
            return bad("alpha_max ((0, 1))");
        }
        if !(self.alpha_min >= 0.0 && self.alpha_min < self.alpha_max) {
            return bad("alpha_min ([0, alpha_max))");
        }
        if !(self.lowpass_sigma_px >= 0.0 && self.lowpass_sigma_px.is_finite()) {
            return bad("lowpass_sigma_px (finite, ≥ 0)");
        }
        if !(self.normalize_alpha_min >= 0.0 && self.normalize_alpha_min.is_finite()) {
            return bad("normalize_alpha_min (finite, ≥ 0)");
        }
        Ok(())
    }
}

/// Errors of the rasterizer.
#[derive(Debug, Error)]
pub enum RasterError {
    #[error("camera has an empty image ({width}×{height})")]
    EmptyImage { width: u32, height: u32 },
    #[error("camera is not finite")]
    NonFiniteCamera,
    #[error("invalid raster setting: {0}")]
    InvalidSetting(&'static str),
    #[error("surfel parameter groups have different lengths ({0})")]
    RaggedSurfels(&'static str),
    #[error("upstream gradient buffers are {got_width}×{got_height} (field {field}), the render is {width}×{height}")]
    GradSizeMismatch {
        field: &'static str,
        got_width: usize,
        got_height: usize,
        width: usize,
        height: usize,
    },
    #[error("backward was given a forward result of another backend or another scene: {0}")]
    ForwardMismatch(&'static str),
    #[error("gpu backend: {0}")]
    Gpu(String),
}

/// Per-pixel G-buffers, row-major (index `y * width + x`), row 0 on top.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct GBuffers {
    pub width: usize,
    pub height: usize,
    /// Accumulated opacity `Σ α_i T_i`.
    pub alpha: Vec<f64>,
    /// α-normalized expected OpenCV z-depth of the ray–surfel intersections.
    pub depth: Vec<f64>,
    /// World-frame normal, α-normalized, not unit-normalized; each surfel normal faces the camera.
    pub normal: Vec<[f64; 3]>,
    /// α-normalized albedo.
    pub albedo: Vec<[f64; 3]>,
    /// α-normalized roughness.
    pub roughness: Vec<f64>,
    /// α-normalized index of refraction.
    pub ior: Vec<f64>,
    /// α-normalized second moment of the intersection depths, `Σ w_i z_i² / α`: with `depth` it
    /// gives how far the composited depths spread along the ray (the depth-distortion loss,
    /// [`crate::core::loss::depth_distortion`]).
    pub depth_sq: Vec<f64>,
    /// Unit world normal from central differences of the back-projected depth map, facing the
    /// camera; zero on the border and where the pixel or one of its 4 neighbours has `α ≤ ε`.
    pub depth_normal: Vec<[f64; 3]>,
}

/// Upstream gradients `dL/d(buffer)`, laid out like [`GBuffers`].
pub type GBufferGrads = GBuffers;

impl GBuffers {
    /// All buffers zero (also the zero upstream gradient).
    pub fn zeros(width: usize, height: usize) -> Self {
        let n = width * height;
        GBuffers {
            width,
            height,
            alpha: filled(n, 0.0),
            depth: filled(n, 0.0),
            normal: filled(n, [0.0; 3]),
            albedo: filled(n, [0.0; 3]),
            roughness: filled(n, 0.0),
            ior: filled(n, 0.0),
            depth_sq: filled(n, 0.0),
            depth_normal: filled(n, [0.0; 3]),
        }
    }

    /// Checks every buffer has `width × height` entries; names the first one that does not.
    pub fn check_size(&self, width: usize, height: usize) -> Result<(), RasterError> {
        let n = width * height;
        let lens = [
            ("alpha", self.alpha.len()),
            ("depth", self.depth.len()),
            ("normal", self.normal.len()),
            ("albedo", self.albedo.len()),
            ("roughness", self.roughness.len()),
            ("ior", self.ior.len()),
            ("depth_sq", self.depth_sq.len()),
            ("depth_normal", self.depth_normal.len()),
        ];
        for (field, len) in lens {
            if len != n || self.width != width || self.height != height {
                return Err(RasterError::GradSizeMismatch {
                    field,
                    got_width: self.width,
                    got_height: len.checked_div(self.width).unwrap_or(0),
                    width,
                    height,
                });
            }
        }
        Ok(())
    }

    /// `Σ self · other` over every buffer (the loss `Σ upstream · buffer` of the gradient tests).
    pub fn dot(&self, other: &GBuffers) -> f64 {
        fn d1(a: &[f64], b: &[f64]) -> f64 {
            a.iter().zip(b).map(|(x, y)| x * y).sum()
        }
        fn d3(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
            d1(a.as_flattened(), b.as_flattened())
        }
        d1(&self.alpha, &other.alpha)
            + d1(&self.depth, &other.depth)
            + d3(&self.normal, &other.normal)
            + d3(&self.albedo, &other.albedo)
            + d1(&self.roughness, &other.roughness)
            + d1(&self.ior, &other.ior)
            + d1(&self.depth_sq, &other.depth_sq)
            + d3(&self.depth_normal, &other.depth_normal)
    }

    /// True when every value is finite.
    pub fn is_finite(&self) -> bool {
        let f1 = |v: &[f64]| v.iter().all(|x| x.is_finite());
        f1(&self.alpha)
            && f1(&self.depth)
            && f1(self.normal.as_flattened())
            && f1(self.albedo.as_flattened())
            && f1(&self.roughness)
            && f1(&self.ior)
            && f1(&self.depth_sq)
            && f1(self.depth_normal.as_flattened())
    }
}

/// Counters of one forward pass.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct RasterStats {
    /// Surfels that survived projection and culling.
    pub visible_surfels: usize,
    /// (tile, surfel) pairs after binning.
    pub tile_entries: usize,
    /// (pixel, surfel) pairs evaluated by the per-pixel loop.
    pub pixel_evaluations: u64,
}

/// A forward result: the G-buffers plus whatever the backend keeps for its backward pass.
pub struct Rasterized {
    pub gbuffers: GBuffers,
    pub stats: RasterStats,
    /// Backend-private state for [`crate::core::engine::Backend::backward`].
    pub saved: Box<dyn Any + Send + Sync>,
}

/// Gradients of a loss with respect to the raw surfel parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct RasterGrads {
    pub surfels: SurfelGrads,
    /// `|dL/dμ|` per surfel, in 1/pixels: the gradient with respect to a screen-space translation
    /// of the projected surfel (3DGS measures the same in NDC units, i.e. this × width / 2 along x).
    pub mean2d_grad_norm: Vec<f64>,
    /// The gradient on the view's pose correction at zero ([`crate::core::pose`]), summed over
    /// the surfels in index order; `None` from an engine that does not compute it.
    pub pose: Option<crate::core::pose::PoseGrad>,
}

/// Device time spent in one kind of compute pass
/// ([`crate::core::engine::Backend::take_stage_times`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageTime {
    pub name: String,
    /// Passes run.
    pub calls: usize,
    pub total_ms: f64,
}

/// What a backend keeps from its forward pass for the backward pass (the `saved` of
/// [`Rasterized`]): at least the scene it was computed for.
pub trait SavedForward: Any {
    /// The error message when `backward` is given another backend's forward result.
    const NOT_THIS_BACKEND: &'static str;
    /// The surfel count, camera and settings of the forward pass.
    fn scene(&self) -> (usize, &Camera, &RasterSettings);
}

/// The checks every backend's `backward` starts with, in order: the inputs are valid
/// ([`validate_inputs`]), `forward` was computed by this backend (its saved state is an `S`, else
/// `ForwardMismatch(S::NOT_THIS_BACKEND)`) for the same scene ([`check_same_scene`]), and `upstream`
/// has the size of the forward G-buffers. Returns the backend's saved state.
pub fn begin_backward<'a, S: SavedForward>(
    surfels: &Surfels,
    camera: &Camera,
    settings: &RasterSettings,
    forward: &'a Rasterized,
    upstream: &GBufferGrads,
) -> Result<&'a S, RasterError> {
    validate_inputs(surfels, camera, settings)?;
    let saved = forward
        .saved
        .downcast_ref::<S>()
        .ok_or(RasterError::ForwardMismatch(S::NOT_THIS_BACKEND))?;
    check_same_scene(saved.scene(), surfels, camera, settings)?;
    upstream.check_size(forward.gbuffers.width, forward.gbuffers.height)?;
    Ok(saved)
}

/// Checks that a saved forward pass — its surfel count, camera and settings — belongs to this
/// backward call; [`begin_backward`] runs it for every backend.
pub fn check_same_scene(
    saved: (usize, &Camera, &RasterSettings),
    surfels: &Surfels,
    camera: &Camera,
    settings: &RasterSettings,
) -> Result<(), RasterError> {
    let (num_surfels, saved_camera, saved_settings) = saved;
    if num_surfels != surfels.len() {
        return Err(RasterError::ForwardMismatch("surfel count differs"));
    }
    if saved_camera != camera {
        return Err(RasterError::ForwardMismatch("camera differs"));
    }
    if saved_settings != settings {
        return Err(RasterError::ForwardMismatch("settings differ"));
    }
    Ok(())
}

/// Checks the inputs every backend needs.
pub fn validate_inputs(
    surfels: &Surfels,
    camera: &Camera,
    settings: &RasterSettings,
) -> Result<(), RasterError> {
    settings.validate()?;
    if camera.width == 0 || camera.height == 0 {
        return Err(RasterError::EmptyImage {
            width: camera.width,
            height: camera.height,
        });
    }
    let finite = [camera.fx, camera.fy, camera.cx, camera.cy]
        .iter()
        .chain(camera.c2w.to_cols_array().iter())
        .all(|v| v.is_finite());
    if !finite || camera.fx == 0.0 || camera.fy == 0.0 {
        return Err(RasterError::NonFiniteCamera);
    }
    let n = surfels.len();
    let groups = [
        ("log_scale", surfels.log_scale.len()),
        ("rotation", surfels.rotation.len()),
        ("opacity", surfels.opacity.len()),
        ("albedo", surfels.albedo.len()),
        ("roughness", surfels.roughness.len()),
        ("ior", surfels.ior.len()),
    ];
    for (name, len) in groups {
        if len != n {
            return Err(RasterError::RaggedSurfels(name));
        }
    }
    Ok(())
}

/// Camera-space (OpenCV, z = 1) direction of pixel `(i, j)`'s centre.
fn pixel_camera_dir(camera: &Camera, i: usize, j: usize) -> DVec3 {
    camera.camera_dir(i as f64 + 0.5, j as f64 + 0.5)
}

/// True where the depth-derived normal of pixel `(i, j)` is defined (interior, pixel and its 4
/// neighbours covered).
fn depth_normal_defined(alpha: &[f64], w: usize, h: usize, i: usize, j: usize, eps: f64) -> bool {
    i >= 1
        && j >= 1
        && i + 1 < w
        && j + 1 < h
        && [(i, j), (i - 1, j), (i + 1, j), (i, j - 1), (i, j + 1)]
            .iter()
            .all(|&(x, y)| alpha[y * w + x] > eps)
}

/// Intermediate values of one pixel's depth normal, shared by forward and backward.
struct DepthNormalPixel {
    /// Central differences of the camera-space back-projected points along x and y.
    dx: DVec3,
    dy: DVec3,
    /// `±(dx × dy)`, the sign chosen so it faces the camera.
    v: DVec3,
    sign: f64,
    len: f64,
}

fn depth_normal_pixel(
    camera: &Camera,
    depth: &[f64],
    w: usize,
    i: usize,
    j: usize,
) -> Option<DepthNormalPixel> {
    let point = |x: usize, y: usize| pixel_camera_dir(camera, x, y) * depth[y * w + x];
    let dx = point(i + 1, j) - point(i - 1, j);
    let dy = point(i, j + 1) - point(i, j - 1);
    let cross = dx.cross(dy);
    // For a depth map seen from the camera dx × dy points away from it (x right, y down, z ahead).
    let sign = if cross.dot(pixel_camera_dir(camera, i, j)) > 0.0 {
        -1.0
    } else {
        1.0
    };
    let v = sign * cross;
    let len = v.length();
    (len > 1e-300 && len.is_finite()).then_some(DepthNormalPixel {
        dx,
        dy,
        v,
        sign,
        len,
    })
}

/// Unit world normals from central differences of the back-projected depth map, facing the
/// camera; zero where undefined (see [`GBuffers::depth_normal`]). Pixels in parallel (rayon).
pub fn depth_normals(camera: &Camera, depth: &[f64], alpha: &[f64], eps: f64) -> Vec<[f64; 3]> {
    let (w, h) = (camera.width as usize, camera.height as usize);
    let rot = camera.rotation_opencv();
    (0..w * h)
        .into_par_iter()
        .map(|k| {
            let (i, j) = (k % w, k / w);
            if !depth_normal_defined(alpha, w, h, i, j, eps) {
                return [0.0; 3];
            }
            match depth_normal_pixel(camera, depth, w, i, j) {
                Some(px) => (rot * (px.v / px.len)).to_array(),
                None => [0.0; 3],
            }
        })
        .collect()
}

/// Gradient on the (α-normalized) depth buffer of `Σ upstream · depth_normals(depth)`; pixels in
/// parallel (rayon), each a sum of its neighbours' terms in a fixed order.
pub fn depth_normals_backward(
    camera: &Camera,
    depth: &[f64],
    alpha: &[f64],
    eps: f64,
    upstream: &[[f64; 3]],
) -> Vec<f64> {
    let (w, h) = (camera.width as usize, camera.height as usize);
    let rot_t = camera.rotation_opencv().transpose();
    // Gradients on dx and dy of every pixel.
    let (gdx, gdy): (Vec<DVec3>, Vec<DVec3>) = (0..w * h)
        .into_par_iter()
        .map(|k| {
            let (i, j) = (k % w, k / w);
            let g = DVec3::from_array(upstream[k]);
            if g == DVec3::ZERO || !depth_normal_defined(alpha, w, h, i, j, eps) {
                return (DVec3::ZERO, DVec3::ZERO);
            }
            let Some(px) = depth_normal_pixel(camera, depth, w, i, j) else {
                return (DVec3::ZERO, DVec3::ZERO);
            };
            let gc = rot_t * g;
            let n = px.v / px.len;
            let gv = px.sign * (gc - n * n.dot(gc)) / px.len;
            (px.dy.cross(gv), gv.cross(px.dx))
        })
        .unzip();
    (0..w * h)
        .into_par_iter()
        .map(|k| {
            let (i, j) = (k % w, k / w);
            // dx(i, j) = P(i+1, j) − P(i−1, j): P(i, j) receives +gdx(i−1, j) − gdx(i+1, j).
            let mut gp = DVec3::ZERO;
            if i >= 1 {
                gp += gdx[k - 1];
            }
            if i + 1 < w {
                gp -= gdx[k + 1];
            }
            if j >= 1 {
                gp += gdy[k - w];
            }
            if j + 1 < h {
                gp -= gdy[k + w];
            }
            pixel_camera_dir(camera, i, j).dot(gp)
        })
        .collect()
}

/// The upstream gradient on the α-normalized depth buffer: the depth's own plus the depth-normal
/// map's, chained through [`depth_normals_backward`] (every backend's backward starts with it).
pub fn depth_upstream(
    camera: &Camera,
    gbuffers: &GBuffers,
    upstream: &GBufferGrads,
    eps: f64,
) -> Vec<f64> {
    let _span = tracing::info_span!("depth_normal_backward").entered();
    let mut grad = depth_normals_backward(
        camera,
        &gbuffers.depth,
        &gbuffers.alpha,
        eps,
        &upstream.depth_normal,
    );
    for (g, own) in grad.iter_mut().zip(&upstream.depth) {
        *g += own;
    }
    grad
}

/// Running sums a host engine composites per pixel: α, depth, the features of
/// [`project::Projected::features`], then the squared depth.
pub const NUM_PIXEL_SUMS: usize = 3 + project::NUM_FEATURES;

/// Pixel `k`'s upstream gradients before the α-normalization: `dL/dα` (the accumulated
/// opacity's own, less `Σ_c g_c · out_c / α` where the pixel is normalized) and `dL/dS_c = g_c / α`
/// on the running sums of depth, normal, albedo, roughness, IoR and squared depth (zero where
/// `α ≤ eps`).
/// `depth_grad` is [`depth_upstream`]'s. Every host backend's backward starts each pixel here.
pub fn unnormalize_upstream(
    gbuffers: &GBuffers,
    upstream: &GBufferGrads,
    depth_grad: &[f64],
    k: usize,
    eps: f64,
) -> (f64, [f64; NUM_PIXEL_SUMS - 1]) {
    let a = gbuffers.alpha[k];
    let mut g_alpha = upstream.alpha[k];
    let mut g_sums = [0.0; NUM_PIXEL_SUMS - 1];
    if a > eps {
        let (n, al) = (upstream.normal[k], upstream.albedo[k]);
        let g = [
            depth_grad[k],
            n[0],
            n[1],
            n[2],
            al[0],
            al[1],
            al[2],
            upstream.roughness[k],
            upstream.ior[k],
            upstream.depth_sq[k],
        ];
        let (n, al) = (gbuffers.normal[k], gbuffers.albedo[k]);
        let out = [
            gbuffers.depth[k],
            n[0],
            n[1],
            n[2],
            al[0],
            al[1],
            al[2],
            gbuffers.roughness[k],
            gbuffers.ior[k],
            gbuffers.depth_sq[k],
        ];
        let inv = 1.0 / a;
        let mut dot = 0.0;
        for c in 0..NUM_PIXEL_SUMS - 1 {
            dot += g[c] * out[c];
            g_sums[c] = g[c] * inv;
        }
        g_alpha -= dot * inv;
    }
    (g_alpha, g_sums)
}

/// Chains per-surfel gradients on the projections (`grad_of(i, p)` for visible surfel `i`, whose
/// engine kept `p` of its projection, holding its [`project::Activations`]) to the raw surfel
/// parameters through [`project::project_backward`] (rayon over surfels); culled surfels, and
/// those whose projection received no gradient, get zero gradients.
pub fn chain_to_raw<P: Sync>(
    surfels: &Surfels,
    camera: &Camera,
    projected: &[Option<P>],
    activations: impl Fn(&P) -> project::Activations + Sync,
    grad_of: impl Fn(usize, &P) -> project::ProjectedGrad + Sync,
) -> RasterGrads {
    use rayon::prelude::*;
    let _span = tracing::info_span!("project_backward").entered();
    let cam = project::ProjectionCamera::new(camera);
    let mut grads = SurfelGrads::zeros(surfels.len());
    let mut mean2d = vec![0.0; surfels.len()];
    let mut pose = vec![[0.0; 6]; surfels.len()];
    (
        grads.position.par_iter_mut(),
        grads.log_scale.par_iter_mut(),
        grads.rotation.par_iter_mut(),
        grads.opacity.par_iter_mut(),
        grads.albedo.par_iter_mut(),
        grads.roughness.par_iter_mut(),
        grads.ior.par_iter_mut(),
        mean2d.par_iter_mut(),
        pose.par_iter_mut(),
        projected.par_iter(),
    )
        .into_par_iter()
        .enumerate()
        .for_each(|(i, (pos, ls, rot, op, alb, rough, ior, m2d, pose, p))| {
            let Some(p) = p else {
                return;
            };
            let grad = grad_of(i, p);
            // A surfel this view's pixels did not reach (all behind opaque ones) chains nothing.
            if grad == project::ProjectedGrad::default() {
                return;
            }
            let r = project::project_backward(surfels, i, &activations(p), &cam, &grad);
            *pos = r.position;
            *ls = r.log_scale;
            *rot = r.rotation;
            *op = r.opacity;
            *alb = r.albedo;
            *rough = r.roughness;
            *ior = r.ior;
            *m2d = r.mean2d_norm;
            *pose = r.pose;
        });
    // Summed in index order, so that the sum does not depend on the thread count.
    let pose = pose.iter().fold([0.0; 6], |mut sum, g| {
        for (s, v) in sum.iter_mut().zip(g) {
            *s += v;
        }
        sum
    });
    RasterGrads {
        surfels: grads,
        mean2d_grad_norm: mean2d,
        pose: Some(pose),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_forward_pass_of_another_scene_is_refused_by_name() {
        let camera = Camera::look_at(8, 6, 0.7, DVec3::new(0.0, -3.0, 0.0), DVec3::ZERO, DVec3::Z);
        let other = Camera::look_at(8, 6, 0.7, DVec3::new(0.0, -4.0, 0.0), DVec3::ZERO, DVec3::Z);
        let settings = RasterSettings::default();
        let surfels = Surfels::zeros(2);
        assert!(check_same_scene((2, &camera, &settings), &surfels, &camera, &settings).is_ok());
        let cases = [
            (
                check_same_scene((3, &camera, &settings), &surfels, &camera, &settings),
                "surfel count",
            ),
            (
                check_same_scene((2, &other, &settings), &surfels, &camera, &settings),
                "camera",
            ),
            (
                check_same_scene(
                    (
                        2,
                        &camera,
                        &RasterSettings {
                            near: 0.5,
                            ..settings
                        },
                    ),
                    &surfels,
                    &camera,
                    &settings,
                ),
                "settings",
            ),
        ];
        for (result, what) in cases {
            match result {
                Err(RasterError::ForwardMismatch(message)) => {
                    assert!(message.contains(what), "{message}")
                }
                other => panic!("{what}: expected a mismatch, got {other:?}"),
            }
        }
    }

    #[test]
    fn backward_starts_by_checking_backend_scene_and_upstream_size() {
        struct Ours(usize, Camera, RasterSettings);
        impl SavedForward for Ours {
            const NOT_THIS_BACKEND: &'static str = "not ours";
            fn scene(&self) -> (usize, &Camera, &RasterSettings) {
                (self.0, &self.1, &self.2)
            }
        }
        struct Theirs;
        let camera = Camera::look_at(8, 6, 0.7, DVec3::new(0.0, -3.0, 0.0), DVec3::ZERO, DVec3::Z);
        let settings = RasterSettings::default();
        let surfels = Surfels::zeros(2);
        let forward = |saved: Box<dyn Any + Send + Sync>| Rasterized {
            gbuffers: GBuffers::zeros(8, 6),
            stats: RasterStats::default(),
            saved,
        };
        let ours = forward(Box::new(Ours(2, camera, settings)));
        let upstream = GBuffers::zeros(8, 6);
        let begin = |forward: &Rasterized, upstream: &GBufferGrads, settings: &RasterSettings| {
            begin_backward::<Ours>(&surfels, &camera, settings, forward, upstream)
                .map(|saved| saved.0)
        };
        assert_eq!(begin(&ours, &upstream, &settings).unwrap(), 2);
        assert!(matches!(
            begin(&forward(Box::new(Theirs)), &upstream, &settings),
            Err(RasterError::ForwardMismatch("not ours"))
        ));
        assert!(matches!(
            begin(
                &forward(Box::new(Ours(3, camera, settings))),
                &upstream,
                &settings
            ),
            Err(RasterError::ForwardMismatch("surfel count differs"))
        ));
        assert!(matches!(
            begin(&ours, &GBuffers::zeros(6, 8), &settings),
            Err(RasterError::GradSizeMismatch { .. })
        ));
        let invalid = RasterSettings {
            alpha_max: 1.5,
            ..settings
        };
        assert!(matches!(
            begin(&ours, &upstream, &invalid),
            Err(RasterError::InvalidSetting(_))
        ));
    }

    use crate::core::gradcheck::assert_gradient;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn depth_normal_of_a_tilted_plane_is_its_normal() {
        let camera = Camera::look_at(
            20,
            16,
            0.9,
            DVec3::new(0.3, -4.0, 0.5),
            DVec3::ZERO,
            DVec3::Z,
        );
        // Plane through the origin with normal n (toward the camera side).
        let n = DVec3::new(0.2, -1.0, 0.3).normalize();
        let (w, h) = (20usize, 16usize);
        let rot = camera.rotation_opencv();
        // origin + t d on the plane: (o + t d)·n = 0, depth = t (z of d is 1).
        let depth: Vec<f64> = (0..w * h)
            .map(|k| {
                let d = rot * pixel_camera_dir(&camera, k % w, k / w);
                -camera.origin().dot(n) / d.dot(n)
            })
            .collect();
        let alpha = vec![1.0; w * h];
        let normals = depth_normals(&camera, &depth, &alpha, 1e-6);
        for j in 0..h {
            for i in 0..w {
                let got = DVec3::from_array(normals[j * w + i]);
                if i == 0 || j == 0 || i == w - 1 || j == h - 1 {
                    assert_eq!(got, DVec3::ZERO);
                } else {
                    assert!(got.abs_diff_eq(n, 1e-9), "pixel ({i},{j}): {got} vs {n}");
                }
            }
        }
    }

    #[test]
    fn depth_normal_backward_matches_finite_differences() {
        for seed in 0..4u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let (w, h) = (9usize, 7usize);
            let camera = Camera::look_at(
                w as u32,
                h as u32,
                0.8,
                DVec3::new(1.0, -3.0, 1.0),
                DVec3::ZERO,
                DVec3::Z,
            );
            let depth: Vec<f64> = (0..w * h).map(|_| rng.random_range(2.5..3.5)).collect();
            let mut alpha = vec![1.0; w * h];
            alpha[3 * w + 4] = 0.0; // one hole: its neighbours are undefined
            let up: Vec<[f64; 3]> = (0..w * h)
                .map(|_| std::array::from_fn(|_| rng.random_range(-1.0..1.0)))
                .collect();
            let analytic = depth_normals_backward(&camera, &depth, &alpha, 1e-6, &up);
            let mut f = |d: &[f64]| {
                depth_normals(&camera, d, &alpha, 1e-6)
                    .iter()
                    .zip(&up)
                    .map(|(n, g)| n[0] * g[0] + n[1] * g[1] + n[2] * g[2])
                    .sum::<f64>()
            };
            assert_gradient("depth normal", &mut f, &depth, &analytic, 1e-6, 1e-6, 1e-6);
        }
    }
}

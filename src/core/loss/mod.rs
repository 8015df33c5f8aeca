//! Training losses of the PolarDR stage (METHOD.md §6), each returning its value and its gradient
//! with respect to every differentiable input.
//!
//! Images are interleaved `f64` slices of `width × height × channels`, row 0 on top. Every loss is
//! a mean, so its gradient scales as 1 / (number of terms); the trainer multiplies values and
//! gradients by the weights of [`LossWeights`] and sums them.
//!
//! Threading: [`ssim()`] (and so [`photometric`]) uses rayon over channels and rows; [`l1`],
//! [`stokes_l1_premultiplied`], [`mask_mse`], [`depth_normal_consistency`], [`depth_distortion`]
//! and [`aolp_normal`] over fixed chunks of [`CHUNK`] elements whose partial sums are added in
//! chunk order, so every value is the same whatever the thread count; [`normal_smoothness`]
//! (pairs of neighbours) is a single-threaded pass.

pub mod ssim;

pub use ssim::{ssim, ssim_in, ssim_map};

use glam::DVec3;
use rayon::prelude::*;

use crate::core::camera::Camera;
use crate::core::config::TrainConfig;
use crate::core::filled::filled;

/// The float type a loss computes in where an engine may choose it (SSIM: [`ssim_in`]); inputs
/// and gradients are `f64` either way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LossPrecision {
    /// The reference's precision.
    F64,
    /// Single precision, for the fast host engine.
    F32,
}

/// A scalar loss and its gradient with respect to the (first) differentiable input.
#[derive(Clone, Debug, PartialEq)]
pub struct LossValue {
    pub value: f64,
    pub grad: Vec<f64>,
}

/// Value of the Stokes loss and its gradients with respect to the predicted S1 and S2.
#[derive(Clone, Debug, PartialEq)]
pub struct StokesLossValue {
    pub value: f64,
    pub grad_s1: Vec<f64>,
    pub grad_s2: Vec<f64>,
}

/// Value of the depth–normal consistency loss and its gradients with respect to the raw rendered
/// normal and the depth-derived normal.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthNormalLossValue {
    pub value: f64,
    pub grad_normal: Vec<f64>,
    pub grad_depth_normal: Vec<f64>,
}

/// Value of the depth-distortion loss and its gradients with respect to the accumulated opacity,
/// the α-normalized depth and the α-normalized squared depth.
#[derive(Clone, Debug, PartialEq)]
pub struct DistortionLossValue {
    pub value: f64,
    pub grad_alpha: Vec<f64>,
    pub grad_depth: Vec<f64>,
    pub grad_depth_sq: Vec<f64>,
}

/// Weights of the loss terms (METHOD.md §6). Plain data; the trainer combines the terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LossWeights {
    /// λ of the photometric term: (1 − λ)·L1 + λ·(1 − SSIM).
    pub lambda_ssim: f64,
    /// Weight of the S1/S2 L1 term (or of the extra L1 on Î(θ) for partial data).
    pub lambda_stokes: f64,
    pub lambda_mask: f64,
    pub lambda_normal_smooth: f64,
    pub lambda_depth_normal: f64,
    pub lambda_distortion: f64,
    /// Weight of the AoLP normal-azimuth prior ([`aolp_normal`]).
    pub lambda_aolp: f64,
    /// The length the depth distortion is measured in (the object's radius), so that its weight
    /// does not depend on the capture's units.
    pub distortion_scale: f64,
}

impl From<&TrainConfig> for LossWeights {
    fn from(config: &TrainConfig) -> Self {
        LossWeights {
            lambda_ssim: config.lambda_ssim,
            lambda_stokes: config.lambda_stokes,
            lambda_mask: config.lambda_mask,
            lambda_normal_smooth: config.lambda_normal_smooth,
            lambda_depth_normal: config.lambda_depth_normal,
            lambda_distortion: config.lambda_distortion,
            lambda_aolp: config.lambda_aolp,
            distortion_scale: 1.0,
        }
    }
}

impl LossWeights {
    /// The depth distortion's weight on depths in scene units: λ / radius².
    pub fn distortion_per_scene_unit(&self) -> f64 {
        self.lambda_distortion / (self.distortion_scale * self.distortion_scale)
    }

    /// The weights of `config` for an object of radius `radius` (the depth distortion's unit).
    pub fn for_object(config: &TrainConfig, radius: f64) -> Self {
        LossWeights {
            distortion_scale: if radius > 0.0 && radius.is_finite() {
                radius
            } else {
                1.0
            },
            ..LossWeights::from(config)
        }
    }
}

/// Weight of element `i` when `weight` is per element (same length as the image) or per pixel
/// (broadcast over `channels` = image length / weight length).
fn element_weight(weight: Option<&[f64]>, i: usize, channels: usize) -> f64 {
    weight.map_or(1.0, |w| w[i / channels])
}

/// Channels a per-pixel weight broadcasts over; panics when the lengths do not fit.
fn weight_channels(len: usize, weight: Option<&[f64]>, what: &str) -> usize {
    match weight {
        None => 1,
        Some(w) => {
            assert!(
                !w.is_empty() && len.is_multiple_of(w.len()),
                "{what}: weight has {} entries, which is neither one per element nor one per pixel of {len} elements",
                w.len()
            );
            len / w.len()
        }
    }
}

/// Elements (or pixels) per chunk of a parallel pass whose sums must not depend on the thread
/// count ([`sum_in_chunk_order`]).
pub const CHUNK: usize = 4096;

/// Runs `chunk_sum(index, chunk)` on the chunks of one pass in parallel and adds their results in
/// chunk order: with chunks of a fixed size, the same value whatever the thread count.
pub fn sum_in_chunk_order<I: IndexedParallelIterator>(
    chunks: I,
    chunk_sum: impl Fn(usize, I::Item) -> f64 + Sync + Send,
) -> f64 {
    let sums: Vec<f64> = chunks
        .enumerate()
        .map(|(index, chunk)| chunk_sum(index, chunk))
        .collect();
    sums.iter().sum()
}

/// Fills `grad` in parallel chunks of [`CHUNK`]: `term(i, &mut grad[i])` writes element `i`'s
/// gradient and returns its term of the loss, summed in order within a chunk and across chunks
/// ([`sum_in_chunk_order`]).
fn chunked_sum(grad: &mut [f64], term: impl Fn(usize, &mut f64) -> f64 + Sync) -> f64 {
    sum_in_chunk_order(grad.par_chunks_mut(CHUNK), |chunk, grad| {
        let first = chunk * CHUNK;
        let mut sum = 0.0;
        for (j, g) in grad.iter_mut().enumerate() {
            sum += term(first + j, g);
        }
        sum
    })
}

/// The subgradient of |d|: its sign, and 0 at d = 0 (`f64::signum(0.0)` is 1).
fn abs_subgradient(d: f64) -> f64 {
    if d > 0.0 {
        1.0
    } else if d < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// Mean absolute error `Σ w·|p − t| / n` over all `n` elements, where the optional `weight_mask`
/// holds one weight per element or one per pixel (broadcast over channels). The divisor is the
/// element count, not the weight sum, as `(|p − t| · m).mean()` in the reference code. The
/// subgradient at `p = t` is 0.
///
/// # Panics
/// If the lengths differ or the weight length divides neither.
pub fn l1(pred: &[f64], target: &[f64], weight_mask: Option<&[f64]>) -> LossValue {
    assert_eq!(
        pred.len(),
        target.len(),
        "l1: prediction and target lengths differ"
    );
    let channels = weight_channels(pred.len(), weight_mask, "l1");
    let inv_n = 1.0 / pred.len().max(1) as f64;
    let mut grad = filled(pred.len(), 0.0);
    let value = chunked_sum(&mut grad, |i, g| {
        let w = element_weight(weight_mask, i, channels);
        let d = pred[i] - target[i];
        *g = w * abs_subgradient(d) * inv_n;
        w * d.abs()
    });
    LossValue {
        value: value * inv_n,
        grad,
    }
}

/// Photometric loss `(1 − λ)·L1 + λ·(1 − SSIM)` (METHOD.md §6, λ = 0.2) and its gradient with
/// respect to `pred`, SSIM computed in `precision`.
///
/// # Panics
/// If either image is not `width · height · channels` long.
pub fn photometric(
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
    lambda_ssim: f64,
    precision: LossPrecision,
) -> LossValue {
    let l1_term = l1(pred, target, None);
    let ssim_term = ssim_in(precision, pred, target, width, height, channels);
    let mut grad = l1_term.grad;
    grad.par_iter_mut()
        .zip(&ssim_term.grad)
        .for_each(|(g, gs)| *g = (1.0 - lambda_ssim) * *g - lambda_ssim * gs);
    LossValue {
        value: (1.0 - lambda_ssim) * l1_term.value + lambda_ssim * (1.0 - ssim_term.value),
        grad,
    }
}

/// Stokes loss `L1(Ŝ1, S1) + L1(Ŝ2, S2)` (each a mean as in [`l1`], with the same optional weight).
///
/// # Panics
/// If the lengths differ.
pub fn stokes_l1(
    pred_s1: &[f64],
    target_s1: &[f64],
    pred_s2: &[f64],
    target_s2: &[f64],
    weight_mask: Option<&[f64]>,
) -> StokesLossValue {
    let s1 = l1(pred_s1, target_s1, weight_mask);
    let s2 = l1(pred_s2, target_s2, weight_mask);
    StokesLossValue {
        value: s1.value + s2.value,
        grad_s1: s1.grad,
        grad_s2: s2.grad,
    }
}

/// [`stokes_l1`] of the α-premultiplied prediction (`α · S1`, `α · S2`: one RGB value per pixel
/// times the pixel's `alpha`) against targets held as the capture's f32 samples, each times its
/// channel's `gains` and widened to f64 (as [`crate::core::step::ViewTarget::fitted_in`] does):
/// the same value and gradients bit for bit, in one parallel pass without the premultiplied and
/// widened copies.
///
/// # Panics
/// If the lengths differ (three targets per pixel, one `alpha` per pixel).
pub fn stokes_l1_premultiplied(
    (s1, s2): (&[DVec3], &[DVec3]),
    alpha: &[f64],
    (t1, t2): (&[f32], &[f32]),
    gains: [f32; 3],
) -> StokesLossValue {
    let pixels = alpha.len();
    assert!(
        s1.len() == pixels
            && s2.len() == pixels
            && t1.len() == 3 * pixels
            && t2.len() == 3 * pixels,
        "stokes_l1_premultiplied: S1, S2, alpha and the targets do not match"
    );
    let n = 3 * pixels;
    let inv_n = 1.0 / n.max(1) as f64;
    // |p − t| and the subgradient of element i, exactly as `l1` computes them.
    let term = |pred: &[DVec3], target: &[f32], i: usize, g: &mut f64| {
        let d = pred[i / 3][i % 3] * alpha[i / 3] - f64::from(target[i] * gains[i % 3]);
        *g = abs_subgradient(d) * inv_n;
        d.abs()
    };
    let mut grad_s1 = filled(n, 0.0);
    let mut grad_s2 = filled(n, 0.0);
    // Chunks of `CHUNK` elements summed in order, as `l1` sums each component.
    let sums: Vec<(f64, f64)> = (grad_s1.par_chunks_mut(CHUNK), grad_s2.par_chunks_mut(CHUNK))
        .into_par_iter()
        .enumerate()
        .map(|(chunk, (g1, g2))| {
            let first = chunk * CHUNK;
            let (mut sum1, mut sum2) = (0.0, 0.0);
            for (j, g) in g1.iter_mut().enumerate() {
                sum1 += term(s1, t1, first + j, g);
            }
            for (j, g) in g2.iter_mut().enumerate() {
                sum2 += term(s2, t2, first + j, g);
            }
            (sum1, sum2)
        })
        .collect();
    let value1: f64 = sums.iter().map(|s| s.0).sum();
    let value2: f64 = sums.iter().map(|s| s.1).sum();
    StokesLossValue {
        value: value1 * inv_n + value2 * inv_n,
        grad_s1,
        grad_s2,
    }
}

/// Mask loss `mean(w (α − M)²)` and its gradient with respect to the accumulated opacity α; the
/// weights `w` (1 without them) leave pixels out (0 near the mask's edge,
/// [`crate::core::mask_band`]) without changing the mean's denominator.
///
/// # Panics
/// If the lengths differ.
pub fn mask_mse(alpha: &[f64], mask: &[f64], weight: Option<&[f32]>) -> LossValue {
    assert!(
        alpha.len() == mask.len() && weight.is_none_or(|w| w.len() == alpha.len()),
        "mask_mse: alpha, mask and weight lengths differ"
    );
    let inv_n = 1.0 / alpha.len().max(1) as f64;
    let mut grad = filled(alpha.len(), 0.0);
    let value = chunked_sum(&mut grad, |i, g| {
        let w = weight.map_or(1.0, |w| f64::from(w[i]));
        let d = alpha[i] - mask[i];
        *g = 2.0 * w * d * inv_n;
        w * d * d
    });
    LossValue {
        value: value * inv_n,
        grad,
    }
}

/// 2DGS's depth distortion `mean_p Σ_i Σ_j w_i w_j (z_i − z_j)² / 2` over the composited
/// surfels of every pixel (weights `w_i = α_i T_i`, ray–surfel intersection depths `z_i`), in
/// units of `scale²`: small where a pixel's weight sits at one depth, large where it is spread
/// along the ray (semi-transparent layers, surfels seen through a hole). From the G-buffers alone:
/// with `A = Σ w_i = alpha`, `E[z] = depth` and `E[z²] = depth_sq`, the double sum is
/// `A² (E[z²] − E[z]²)`.
///
/// # Panics
/// If the lengths differ.
pub fn depth_distortion(
    alpha: &[f64],
    depth: &[f64],
    depth_sq: &[f64],
    scale: f64,
) -> DistortionLossValue {
    assert!(
        alpha.len() == depth.len() && alpha.len() == depth_sq.len(),
        "depth_distortion: alpha, depth and depth_sq lengths differ"
    );
    let norm = 1.0 / (alpha.len().max(1) as f64 * scale * scale);
    let mut grad_alpha = filled(alpha.len(), 0.0);
    let mut grad_depth = filled(alpha.len(), 0.0);
    let mut grad_depth_sq = filled(alpha.len(), 0.0);
    let chunks = (
        grad_alpha.par_chunks_mut(CHUNK),
        grad_depth.par_chunks_mut(CHUNK),
        grad_depth_sq.par_chunks_mut(CHUNK),
    )
        .into_par_iter();
    let value = sum_in_chunk_order(chunks, |chunk, (ga, gd, gq)| {
        let first = chunk * CHUNK;
        let mut sum = 0.0;
        for j in 0..ga.len() {
            let (a, z) = (alpha[first + j], depth[first + j]);
            let spread = depth_sq[first + j] - z * z;
            sum += a * a * spread;
            ga[j] = 2.0 * a * spread * norm;
            gd[j] = -2.0 * a * a * z * norm;
            gq[j] = a * a * norm;
        }
        sum
    });
    DistortionLossValue {
        value: value * norm,
        grad_alpha,
        grad_depth,
        grad_depth_sq,
    }
}

/// ε of the smoothed vector norm `‖d‖_ε = sqrt(‖d‖² + ε) − sqrt(ε)` used by [`normal_smoothness`]:
/// differentiable at d = 0, zero there, and within 1e-3 of ‖d‖ once ‖d‖ > 0.03.
pub const NORMAL_SMOOTH_EPS: f64 = 1e-6;

/// Edge-aware normal smoothness `mean(|∇N̂| · exp(−|∇S0|))` (METHOD.md §6) with forward
/// differences, and its gradient with respect to the normal map (`s0` is the captured image and
/// constant).
///
/// Precisely, with `Δx N = N(x+1, y) − N(x, y)` (a 3-vector) and likewise `Δy`:
/// `L = (1 / (w·h)) · Σ_pixels [ ‖Δx N‖_ε · exp(−mean_c |Δx S0_c|) + ‖Δy N‖_ε · exp(−mean_c |Δy S0_c|) ]`
/// where a term is absent on the last column (Δx) or last row (Δy), and `‖·‖_ε` is
/// [`NORMAL_SMOOTH_EPS`]-smoothed Euclidean norm. `normal` has 3 channels; `s0` any number of channels
/// (its length / (w·h)).
///
/// # Panics
/// If `normal` is not `w·h·3` long or `s0` is not a whole number of channels of `w·h` pixels.
pub fn normal_smoothness(normal: &[f64], s0: &[f64], width: usize, height: usize) -> LossValue {
    let pixels = width * height;
    assert_eq!(
        normal.len(),
        pixels * 3,
        "normal_smoothness: normal is not w·h·3"
    );
    assert!(
        pixels > 0 && s0.len().is_multiple_of(pixels) && !s0.is_empty(),
        "normal_smoothness: s0 is not a whole number of w·h channels"
    );
    let sc = s0.len() / pixels;
    let inv_n = 1.0 / pixels as f64;
    let sqrt_eps = NORMAL_SMOOTH_EPS.sqrt();
    let mut grad = filled(normal.len(), 0.0);
    let mut value = 0.0;
    let mut pair = |a: usize, b: usize| {
        let d = [
            normal[b * 3] - normal[a * 3],
            normal[b * 3 + 1] - normal[a * 3 + 1],
            normal[b * 3 + 2] - normal[a * 3 + 2],
        ];
        if d == [0.0; 3] {
            // ‖0‖_ε = 0 and its gradient is 0 (the background's pairs): nothing to add.
            return;
        }
        // Edge weight from the captured image.
        let image_grad = (0..sc)
            .map(|c| (s0[b * sc + c] - s0[a * sc + c]).abs())
            .sum::<f64>()
            / sc as f64;
        let weight = (-image_grad).exp();
        let norm = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + NORMAL_SMOOTH_EPS).sqrt();
        value += weight * (norm - sqrt_eps);
        let scale = weight * inv_n / norm;
        for k in 0..3 {
            grad[b * 3 + k] += scale * d[k];
            grad[a * 3 + k] -= scale * d[k];
        }
    };
    for y in 0..height {
        for x in 0..width {
            let i = y * width + x;
            if x + 1 < width {
                pair(i, i + 1);
            }
            if y + 1 < height {
                pair(i, i + width);
            }
        }
    }
    LossValue {
        value: value * inv_n,
        grad,
    }
}

/// Below this norm a normal counts as absent (background) in [`depth_normal_consistency`].
pub const MIN_NORMAL_NORM: f64 = 1e-12;

/// Depth–normal consistency `mean(w · (1 − N̂ · N_d))` (METHOD.md §6) where N̂ = N / ‖N‖ is the
/// unit rendered normal and N_d the depth-derived normal as given (unit, or scaled by opacity as
/// 2DGS does). Pixels where either normal is (near) zero are excluded from the sum and from the
/// count, so the mean is over the valid pixels. The optional per-pixel `weight` (e.g. the
/// accumulated opacity) is treated as constant. Gradients are with respect to the raw rendered
/// normal (through the normalization) and to `depth_normal`.
///
/// # Panics
/// If the normals are not the same length, not 3-channel, or the weight is not one per pixel.
pub fn depth_normal_consistency(
    normal: &[f64],
    depth_normal: &[f64],
    weight: Option<&[f64]>,
) -> DepthNormalLossValue {
    assert_eq!(
        normal.len(),
        depth_normal.len(),
        "depth_normal_consistency: normal and depth normal lengths differ"
    );
    assert_eq!(
        normal.len() % 3,
        0,
        "depth_normal_consistency: normals are not 3-channel"
    );
    let pixels = normal.len() / 3;
    if let Some(w) = weight {
        assert_eq!(
            w.len(),
            pixels,
            "depth_normal_consistency: weight is not one per pixel"
        );
    }
    let norm3 = |v: &[f64]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let valid = |p: usize| {
        norm3(&normal[p * 3..p * 3 + 3]) > MIN_NORMAL_NORM
            && norm3(&depth_normal[p * 3..p * 3 + 3]) > MIN_NORMAL_NORM
    };
    let count = (0..pixels).into_par_iter().filter(|&p| valid(p)).count();
    let mut grad_normal = filled(normal.len(), 0.0);
    let mut grad_depth_normal = filled(normal.len(), 0.0);
    if count == 0 {
        return DepthNormalLossValue {
            value: 0.0,
            grad_normal,
            grad_depth_normal,
        };
    }
    let inv_n = 1.0 / count as f64;
    let chunks = grad_normal
        .par_chunks_mut(3 * CHUNK)
        .zip(grad_depth_normal.par_chunks_mut(3 * CHUNK));
    let value = sum_in_chunk_order(chunks, |chunk, (grad_n, grad_d)| {
        let mut sum = 0.0;
        for j in (0..grad_n.len() / 3).filter(|&j| valid(chunk * CHUNK + j)) {
            let p = chunk * CHUNK + j;
            let w = weight.map_or(1.0, |w| w[p]);
            let n = &normal[p * 3..p * 3 + 3];
            let nd = &depth_normal[p * 3..p * 3 + 3];
            let len = norm3(n);
            let unit = [n[0] / len, n[1] / len, n[2] / len];
            let dot = unit[0] * nd[0] + unit[1] * nd[1] + unit[2] * nd[2];
            sum += w * (1.0 - dot);
            for k in 0..3 {
                // ∂(N̂·v)/∂N = (v − N̂ (N̂·v)) / ‖N‖.
                grad_n[j * 3 + k] = -w * inv_n * (nd[k] - unit[k] * dot) / len;
                grad_d[j * 3 + k] = -w * inv_n * unit[k];
            }
        }
        sum
    });
    DepthNormalLossValue {
        value: value * inv_n,
        grad_normal,
        grad_depth_normal,
    }
}

#[cfg(test)]
mod tests;

/// The floor of S0 in the DoLP of [`measured_polarization`] (a black pixel's S1 and S2 are noise).
pub const POLARIZATION_MIN_S0: f64 = 1e-4;

/// The measured `DoLP (cos 2ψ, sin 2ψ) = (S1, S2) / S0` of each pixel from a view's interleaved
/// RGB Stokes targets, each sample times `gain` (the run's exposure,
/// [`crate::core::step::ViewTarget::gain`]; the channel means; the DoLP clamped to 1, S0 floored
/// at [`POLARIZATION_MIN_S0`]), times the pixel's `confidence` where given
/// ([`crate::core::polarization_confidence`]), and zero where the mask is below ½ (not the
/// object's).
pub fn measured_polarization(
    s0: &[f32],
    s1: &[f32],
    s2: &[f32],
    mask: &[f32],
    gain: f32,
    confidence: Option<&[f32]>,
) -> Vec<[f64; 2]> {
    let mean = |v: &[f32], p: usize| {
        (f64::from(v[3 * p] * gain)
            + f64::from(v[3 * p + 1] * gain)
            + f64::from(v[3 * p + 2] * gain))
            / 3.0
    };
    (0..mask.len())
        .into_par_iter()
        .map(|p| {
            if mask[p] < 0.5 {
                return [0.0, 0.0];
            }
            let s0 = mean(s0, p).max(POLARIZATION_MIN_S0);
            let (c, s) = (mean(s1, p) / s0, mean(s2, p) / s0);
            let dolp = c.hypot(s);
            let k = if dolp > 1.0 { 1.0 / dolp } else { 1.0 };
            let k = k * confidence.map_or(1.0, |w| f64::from(w[p]));
            [c * k, s * k]
        })
        .collect()
}

/// The normal azimuth prior of polarization (PolGS, PANDORA): a surface reflects light polarized
/// along its normal's azimuth φ in the pixel's Stokes frame (diffuse) or across it (specular),
/// so the measured AoLP ψ satisfies ψ ≡ φ (mod 90°) for any mix of the two, whatever the light
/// and the material. The residual `r = DoLP (sin 2ψ cos 2φ − cos 2ψ sin 2φ) = DoLP sin 2(ψ − φ)`
/// vanishes there and weighs each pixel by how polarized it is; the loss is `mean(r²)` over all
/// pixels.
///
/// `normal` is the rendered normal (3 per pixel, any length: φ depends on its direction only),
/// seen by `camera` (each pixel's Stokes frame, [`Camera::stokes_frame`]), and `polarization`
/// the measured `DoLP (cos 2ψ, sin 2ψ)` ([`measured_polarization`]). Returns the gradient with
/// respect to `normal`.
///
/// # Panics
/// If the lengths differ from the camera's pixel count.
pub fn aolp_normal(normal: &[f64], camera: &Camera, polarization: &[[f64; 2]]) -> LossValue {
    let pixels = camera.num_pixels();
    assert!(
        normal.len() == 3 * pixels && polarization.len() == pixels,
        "aolp_normal: normal and polarization do not match the camera"
    );
    let width = camera.width as usize;
    let norm = 1.0 / pixels.max(1) as f64;
    let mut grad = filled(normal.len(), 0.0);
    let value = sum_in_chunk_order(
        grad.par_chunks_mut(3 * CHUNK).into_par_iter(),
        |chunk, g| {
            let first = chunk * CHUNK;
            let mut sum = 0.0;
            for (j, g) in g.chunks_exact_mut(3).enumerate() {
                let p = first + j;
                let [c, s] = polarization[p];
                if c == 0.0 && s == 0.0 {
                    continue;
                }
                let (x, y) =
                    camera.stokes_frame(camera.pixel_dir((p % width) as u32, (p / width) as u32));
                let n = DVec3::from_slice(&normal[3 * p..3 * p + 3]);
                let (a, b) = (n.dot(x), n.dot(y));
                let q = a * a + b * b;
                if q < 1e-24 {
                    continue;
                }
                // r = (s (a² − b²) − 2 c a b) / q, with cos 2φ = (a² − b²) / q, sin 2φ = 2ab / q.
                let r = (s * (a * a - b * b) - 2.0 * c * a * b) / q;
                sum += r * r;
                let dr_da = (2.0 * s * a - 2.0 * c * b - 2.0 * r * a) / q;
                let dr_db = (-2.0 * s * b - 2.0 * c * a - 2.0 * r * b) / q;
                g.copy_from_slice(&((x * dr_da + y * dr_db) * (2.0 * r * norm)).to_array());
            }
            sum
        },
    );
    LossValue {
        value: value * norm,
        grad,
    }
}

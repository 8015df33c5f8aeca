//! Evaluation metrics of held-out views (METHOD.md §8): PSNR and SSIM on sRGB 8-bit S0 inside the
//! object mask (and PSNR on linear values), normal angular error and cosine distance, DoLP/AoLP
//! from Stokes images with the AoLP error modulo 180°, and a generic masked MAE.
//!
//! Images are interleaved `f64` slices (row 0 on top); masks are one `bool` per pixel (`None`:
//! every pixel). Masked SSIM (**decision**): both images are set to 0 outside the mask, the SSIM
//! map of the full image is computed (so background content never enters a window), and the map
//! is averaged over the masked pixels only (so the trivially perfect background does not inflate
//! the score). Single-threaded except the SSIM map (rayon, see `loss::ssim`).

use thiserror::Error;

use crate::core::loss::ssim_map;
use crate::formats::image_io::linear_to_srgb;

/// A metric whose inputs do not fit together.
#[derive(Debug, Error, PartialEq)]
pub enum MetricsError {
    #[error("{what}: {got} values, expected {expected}")]
    LengthMismatch {
        what: &'static str,
        expected: usize,
        got: usize,
    },
    #[error("{what}: no valid pixel inside the mask")]
    EmptyMask { what: &'static str },
}

fn check_len(what: &'static str, expected: usize, got: usize) -> Result<(), MetricsError> {
    if expected == got {
        Ok(())
    } else {
        Err(MetricsError::LengthMismatch {
            what,
            expected,
            got,
        })
    }
}

/// Checks `pred`/`target` lengths and a per-pixel mask against `channels`.
fn check_image(
    what: &'static str,
    pred: &[f64],
    target: &[f64],
    channels: usize,
    mask: Option<&[bool]>,
) -> Result<(), MetricsError> {
    check_len(what, pred.len(), target.len())?;
    if channels == 0 || !pred.len().is_multiple_of(channels) {
        return Err(MetricsError::LengthMismatch {
            what,
            expected: pred.len().next_multiple_of(channels.max(1)),
            got: pred.len(),
        });
    }
    if let Some(m) = mask {
        check_len(what, pred.len() / channels, m.len())?;
    }
    Ok(())
}

fn inside(mask: Option<&[bool]>, pixel: usize) -> bool {
    mask.is_none_or(|m| m[pixel])
}

/// Per-pixel mask from a float mask image (e.g. the capture's alpha): `value > threshold`.
pub fn mask_from_values(values: &[f64], threshold: f64) -> Vec<bool> {
    values.iter().map(|&v| v > threshold).collect()
}

/// A linear value encoded as 8-bit sRGB (clamped to [0, 1], rounded).
pub fn srgb8(linear: f64) -> u8 {
    let encoded = f64::from(linear_to_srgb(linear as f32));
    (encoded * 255.0).round().clamp(0.0, 255.0) as u8
}

/// Every value quantized to 8-bit sRGB and returned as code / 255 in [0, 1].
pub fn quantize_srgb8(linear: &[f64]) -> Vec<f64> {
    linear
        .iter()
        .map(|&v| f64::from(srgb8(v)) / 255.0)
        .collect()
}

/// PSNR `10 log10(peak² / MSE)` over the masked pixels (all channels); +∞ when identical.
pub fn psnr(
    pred: &[f64],
    target: &[f64],
    channels: usize,
    mask: Option<&[bool]>,
    peak: f64,
) -> Result<f64, MetricsError> {
    check_image("psnr", pred, target, channels, mask)?;
    let (mut sum, mut count) = (0.0, 0usize);
    for (i, (p, t)) in pred.iter().zip(target).enumerate() {
        if inside(mask, i / channels) {
            sum += (p - t) * (p - t);
            count += 1;
        }
    }
    if count == 0 {
        return Err(MetricsError::EmptyMask { what: "psnr" });
    }
    let mse = sum / count as f64;
    Ok(if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (peak * peak / mse).log10()
    })
}

/// PSNR of linear images after both are quantized to 8-bit sRGB (the paper's S0 PSNR).
pub fn psnr_srgb8(
    pred_linear: &[f64],
    target_linear: &[f64],
    channels: usize,
    mask: Option<&[bool]>,
) -> Result<f64, MetricsError> {
    psnr(
        &quantize_srgb8(pred_linear),
        &quantize_srgb8(target_linear),
        channels,
        mask,
        1.0,
    )
}

/// Masked SSIM (see the module doc for the decision): images zeroed outside the mask, SSIM map of
/// the full image (11×11 Gaussian, as the loss), mean over masked pixels and all channels.
pub fn ssim_masked(
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
    mask: Option<&[bool]>,
) -> Result<f64, MetricsError> {
    check_image("ssim", pred, target, channels, mask)?;
    check_len("ssim", width * height * channels, pred.len())?;
    let zero_outside = |img: &[f64]| -> Vec<f64> {
        img.iter()
            .enumerate()
            .map(|(i, &v)| if inside(mask, i / channels) { v } else { 0.0 })
            .collect()
    };
    let map = ssim_map(
        &zero_outside(pred),
        &zero_outside(target),
        width,
        height,
        channels,
    );
    let (mut sum, mut count) = (0.0, 0usize);
    for (i, s) in map.iter().enumerate() {
        if inside(mask, i / channels) {
            sum += s;
            count += 1;
        }
    }
    if count == 0 {
        return Err(MetricsError::EmptyMask { what: "ssim" });
    }
    Ok(sum / count as f64)
}

/// [`ssim_masked`] on linear images quantized to 8-bit sRGB (the paper's S0 SSIM).
pub fn ssim_srgb8(
    pred_linear: &[f64],
    target_linear: &[f64],
    width: usize,
    height: usize,
    channels: usize,
    mask: Option<&[bool]>,
) -> Result<f64, MetricsError> {
    ssim_masked(
        &quantize_srgb8(pred_linear),
        &quantize_srgb8(target_linear),
        width,
        height,
        channels,
        mask,
    )
}

/// Normals shorter than this are "no normal" and skipped by [`normal_errors`].
pub const MIN_NORMAL_NORM: f64 = 1e-12;

/// Normal accuracy over masked pixels where both normals are valid (non-zero).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalErrors {
    /// Mean of arccos(|n̂·n|) in degrees (sign-agnostic, as the paper).
    pub mae_degrees: f64,
    /// Mean of 1 − |n̂·n|.
    pub cosine_distance: f64,
    /// Pixels that entered the means.
    pub pixels: usize,
}

/// Angular error and cosine distance between predicted and ground-truth 3-channel normal maps
/// (both normalized per pixel first).
pub fn normal_errors(
    pred: &[f64],
    ground_truth: &[f64],
    mask: Option<&[bool]>,
) -> Result<NormalErrors, MetricsError> {
    check_image("normal_errors", pred, ground_truth, 3, mask)?;
    let (mut angle_sum, mut distance_sum, mut pixels) = (0.0, 0.0, 0usize);
    for (p, (a, b)) in pred
        .chunks_exact(3)
        .zip(ground_truth.chunks_exact(3))
        .enumerate()
    {
        let norm_a = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        let norm_b = (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt();
        if !inside(mask, p) || norm_a <= MIN_NORMAL_NORM || norm_b <= MIN_NORMAL_NORM {
            continue;
        }
        let cos = ((a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (norm_a * norm_b))
            .abs()
            .min(1.0);
        angle_sum += cos.acos().to_degrees();
        distance_sum += 1.0 - cos;
        pixels += 1;
    }
    if pixels == 0 {
        return Err(MetricsError::EmptyMask {
            what: "normal_errors",
        });
    }
    Ok(NormalErrors {
        mae_degrees: angle_sum / pixels as f64,
        cosine_distance: distance_sum / pixels as f64,
        pixels,
    })
}

/// Below this S0 the degree of polarization is reported as 0 (no light, no polarization).
pub const DOLP_MIN_S0: f64 = 1e-8;

/// Degree of linear polarization `sqrt(S1² + S2²) / S0` per element; 0 where S0 ≤ [`DOLP_MIN_S0`].
pub fn dolp(s0: &[f64], s1: &[f64], s2: &[f64]) -> Result<Vec<f64>, MetricsError> {
    check_len("dolp S1", s0.len(), s1.len())?;
    check_len("dolp S2", s0.len(), s2.len())?;
    Ok(s0
        .iter()
        .zip(s1.iter().zip(s2))
        .map(
            |(&i, (&a, &b))| {
                if i > DOLP_MIN_S0 {
                    a.hypot(b) / i
                } else {
                    0.0
                }
            },
        )
        .collect())
}

/// Angle of linear polarization `½ atan2(S2, S1)` in radians, in (−π/2, π/2].
pub fn aolp(s1: &[f64], s2: &[f64]) -> Result<Vec<f64>, MetricsError> {
    check_len("aolp", s1.len(), s2.len())?;
    Ok(s1.iter().zip(s2).map(|(&a, &b)| 0.5 * b.atan2(a)).collect())
}

/// The smaller angular difference between two AoLPs (radians) modulo 180°, in degrees in [0, 90].
pub fn aolp_difference_degrees(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::PI);
    d.min(std::f64::consts::PI - d).to_degrees()
}

/// Mean AoLP error (degrees, modulo 180°) over masked pixels and all channels.
pub fn aolp_mae_degrees(
    pred_aolp: &[f64],
    target_aolp: &[f64],
    channels: usize,
    mask: Option<&[bool]>,
) -> Result<f64, MetricsError> {
    masked_mean(
        "aolp_mae",
        pred_aolp,
        target_aolp,
        channels,
        mask,
        aolp_difference_degrees,
    )
}

/// Mean absolute error over masked pixels and all channels.
pub fn masked_mae(
    pred: &[f64],
    target: &[f64],
    channels: usize,
    mask: Option<&[bool]>,
) -> Result<f64, MetricsError> {
    masked_mean("masked_mae", pred, target, channels, mask, |a, b| {
        (a - b).abs()
    })
}

fn masked_mean(
    what: &'static str,
    pred: &[f64],
    target: &[f64],
    channels: usize,
    mask: Option<&[bool]>,
    error: impl Fn(f64, f64) -> f64,
) -> Result<f64, MetricsError> {
    check_image(what, pred, target, channels, mask)?;
    let (mut sum, mut count) = (0.0, 0usize);
    for (i, (&p, &t)) in pred.iter().zip(target).enumerate() {
        if inside(mask, i / channels) {
            sum += error(p, t);
            count += 1;
        }
    }
    if count == 0 {
        return Err(MetricsError::EmptyMask { what });
    }
    Ok(sum / count as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::loss::ssim::{gaussian_kernel, SSIM_C1, SSIM_C2};
    use crate::formats::image_io::srgb_to_linear;

    #[test]
    fn srgb8_quantization_of_known_values() {
        assert_eq!(srgb8(0.0), 0);
        assert_eq!(srgb8(-0.3), 0);
        assert_eq!(srgb8(1.0), 255);
        assert_eq!(srgb8(7.0), 255);
        // 1.055 · 0.5^(1/2.4) − 0.055 = 0.73536 → 187.52 → 188.
        assert_eq!(srgb8(0.5), 188);
        // Linear segment: 12.92 · 0.002 · 255 = 6.59 → 7.
        assert_eq!(srgb8(0.002), 7);
        for code in [0u8, 1, 17, 128, 254, 255] {
            let linear = f64::from(srgb_to_linear(f32::from(code) / 255.0));
            assert_eq!(srgb8(linear), code);
        }
    }

    #[test]
    fn psnr_of_known_errors_inside_the_mask() {
        let pred = [0.5, 0.5, 0.0, 0.9];
        let target = [0.6, 0.4, 1.0, 0.9];
        // Pixels 0 and 1 (1 channel): MSE 0.01 → 20 dB; pixel 2 (error 1) masked out.
        let mask = [true, true, false, true];
        let p = psnr(&pred, &target, 1, Some(&mask), 1.0).unwrap();
        assert!((p - 10.0 * (1.0f64 / (0.02 / 3.0)).log10()).abs() < 1e-12);
        let p = psnr(&pred[..2], &target[..2], 1, None, 1.0).unwrap();
        assert!((p - 20.0).abs() < 1e-12);
        assert_eq!(psnr(&pred, &pred, 2, None, 1.0).unwrap(), f64::INFINITY);
        assert_eq!(
            psnr(&pred, &target, 1, Some(&[false; 4]), 1.0),
            Err(MetricsError::EmptyMask { what: "psnr" })
        );
        assert!(matches!(
            psnr(&pred, &target, 1, Some(&[true; 3]), 1.0),
            Err(MetricsError::LengthMismatch { .. })
        ));
    }

    #[test]
    fn psnr_srgb8_measures_code_differences() {
        // Linear 0.5 encodes to 188; a target 10 codes lower differs by 10/255 everywhere.
        let target = f64::from(srgb_to_linear(178.0 / 255.0));
        let p = psnr_srgb8(&[0.5; 6], &[target; 6], 3, None).unwrap();
        assert!((p - 20.0 * 25.5f64.log10()).abs() < 1e-9, "{p}");
        // Differences below half a code vanish in 8 bits.
        assert_eq!(
            psnr_srgb8(&[0.5; 3], &[0.5005; 3], 3, None).unwrap(),
            f64::INFINITY
        );
    }

    #[test]
    fn masked_ssim_ignores_the_background_and_averages_inside() {
        let (w, h) = (9, 7);
        let a: Vec<f64> = (0..w * h)
            .map(|i| (i as f64 * 0.37).sin() * 0.5 + 0.5)
            .collect();
        let mut b = a.clone();
        let mut mask = vec![true; w * h];
        for p in [0, 1, 2, 30, 62] {
            mask[p] = false;
            b[p] = 1.0 - a[p];
        }
        assert_eq!(ssim_masked(&a, &b, w, h, 1, Some(&mask)).unwrap(), 1.0);
        assert!(ssim_masked(&a, &b, w, h, 1, None).unwrap() < 0.99);

        // One masked pixel holding x and y: every window sees it alone among zeros, so with the
        // centre weight g = k₅² the moments are μ = g·x, σ² = g(1 − g)x², σxy = g(1 − g)xy.
        let (x, y) = (0.8, 0.3);
        let (mut pa, mut pb, mut one) = (vec![0.7; w * h], vec![0.2; w * h], vec![false; w * h]);
        pa[31] = x;
        pb[31] = y;
        one[31] = true;
        let g = gaussian_kernel()[5].powi(2);
        let expected = (2.0 * g * g * x * y + SSIM_C1) * (2.0 * g * (1.0 - g) * x * y + SSIM_C2)
            / ((g * g * (x * x + y * y) + SSIM_C1) * (g * (1.0 - g) * (x * x + y * y) + SSIM_C2));
        let s = ssim_masked(&pa, &pb, w, h, 1, Some(&one)).unwrap();
        assert!((s - expected).abs() < 1e-12, "{s} vs {expected}");
        // The same through 8-bit sRGB: identical inputs give exactly 1.
        assert_eq!(ssim_srgb8(&pa, &pa, w, h, 1, Some(&one)).unwrap(), 1.0);
    }

    #[test]
    fn normal_errors_of_known_angles() {
        let s = 30f64.to_radians().sin();
        let c = 30f64.to_radians().cos();
        let pred = [0.0, 0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0];
        // 30° apart; flipped (0° by |·|); no GT normal (skipped); masked out.
        let gt = [0.0, s, c, 0.0, 0.0, -3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        let mask = [true, true, true, false];
        let e = normal_errors(&pred, &gt, Some(&mask)).unwrap();
        assert_eq!(e.pixels, 2);
        assert!((e.mae_degrees - 15.0).abs() < 1e-9, "{e:?}");
        assert!((e.cosine_distance - (1.0 - c) / 2.0).abs() < 1e-12);
        let all = normal_errors(&pred, &gt, None).unwrap();
        assert!((all.mae_degrees - 40.0).abs() < 1e-9, "{all:?}");
        assert!(normal_errors(&pred[..3], &[0.0; 3], None).is_err());
    }

    #[test]
    fn dolp_and_aolp_from_stokes() {
        let d = dolp(&[2.0, 0.0, 1.0], &[0.6, 0.5, 0.0], &[0.8, 0.5, -0.25]).unwrap();
        assert_eq!(d, vec![0.5, 0.0, 0.25]);
        let a = aolp(&[0.0, -1.0, 1.0, 0.0], &[1.0, 0.0, 0.0, -1.0]).unwrap();
        let degrees: Vec<f64> = a.iter().map(|v| v.to_degrees()).collect();
        for (got, want) in degrees.iter().zip([45.0, 90.0, 0.0, -45.0]) {
            assert!((got - want).abs() < 1e-12, "{degrees:?}");
        }
        assert!(dolp(&[1.0], &[0.0, 1.0], &[0.0]).is_err());
    }

    #[test]
    fn aolp_error_is_the_smaller_difference_modulo_180() {
        let r = f64::to_radians;
        assert!((aolp_difference_degrees(r(170.0), r(10.0)) - 20.0).abs() < 1e-9);
        assert!((aolp_difference_degrees(r(0.0), r(90.0)) - 90.0).abs() < 1e-9);
        assert!((aolp_difference_degrees(r(-89.0), r(89.0)) - 2.0).abs() < 1e-9);
        assert!((aolp_difference_degrees(r(30.0), r(30.0 + 180.0))).abs() < 1e-9);
        assert!((aolp_difference_degrees(r(12.0), r(5.0)) - 7.0).abs() < 1e-9);
        let e = aolp_mae_degrees(
            &[r(170.0), r(0.0)],
            &[r(10.0), r(45.0)],
            1,
            Some(&[true, false]),
        );
        assert!((e.unwrap() - 20.0).abs() < 1e-9);
    }

    #[test]
    fn masked_mae_of_known_arrays() {
        // Two pixels × two channels; pixel 1 masked out.
        let m = masked_mae(
            &[1.0, 2.0, 3.0, 4.0],
            &[0.0, 4.0, 0.0, 0.0],
            2,
            Some(&[true, false]),
        );
        assert_eq!(m, Ok(1.5));
        assert_eq!(masked_mae(&[1.0, 2.0], &[0.0, 0.0], 1, None), Ok(1.5));
        assert_eq!(
            mask_from_values(&[0.2, 0.5, 0.9], 0.5),
            vec![false, false, true]
        );
    }
}

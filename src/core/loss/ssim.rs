//! Differentiable structural similarity (SSIM) with the 3DGS reference conventions: an 11×11
//! Gaussian window (σ = 1.5), C1 = 0.01², C2 = 0.03², zero-padded "same" convolution per channel,
//! and the mean of the SSIM map over every pixel and channel.
//!
//! The window is separable, so every local statistic is two 1D passes (rows, then columns). The
//! backward pass is analytic: the SSIM map is differentiated with respect to the five local moments
//! (μx, μy, E(x²), E(y²), E(xy)) and those adjoints are blurred back (the zero-padded "same"
//! convolution with a symmetric kernel is its own adjoint).
//!
//! All five moments of all channels are blurred in one pass (three adjoints per channel on the way
//! back). Threading: image rows run in parallel (rayon) in every pass; results do not depend on the
//! thread count (each output sample is summed in a fixed order, row sums are added in row order).

use rayon::prelude::*;

use super::LossValue;
use crate::core::simd::avx2_available;

/// Side of the square Gaussian window.
pub const SSIM_WINDOW: usize = 11;
/// Standard deviation of the Gaussian window, in pixels.
pub const SSIM_SIGMA: f64 = 1.5;
/// Stabilizer of the luminance term, (0.01 · dynamic range 1)².
pub const SSIM_C1: f64 = 0.01 * 0.01;
/// Stabilizer of the contrast-structure term, (0.03 · dynamic range 1)².
pub const SSIM_C2: f64 = 0.03 * 0.03;

const RADIUS: usize = SSIM_WINDOW / 2;

/// The normalized 1D Gaussian of the window (the 2D window is its outer product).
pub fn gaussian_kernel() -> [f64; SSIM_WINDOW] {
    let mut k = [0.0; SSIM_WINDOW];
    for (i, v) in k.iter_mut().enumerate() {
        let d = i as f64 - RADIUS as f64;
        *v = (-d * d / (2.0 * SSIM_SIGMA * SSIM_SIGMA)).exp();
    }
    let sum: f64 = k.iter().sum();
    k.iter_mut().for_each(|v| *v /= sum);
    k
}

/// Zero-padded "same" 2D Gaussian blur of `planes` row-major `width × height` planes at once.
///
/// `fill_row(y, k, row)` writes row `y` of input plane `k` into `row` (`width` values), so inputs
/// can be read straight from interleaved images or formed on the fly (products). The result is laid
/// out row-interleaved: value (plane k, x, y) at `(y · planes + k) · width + x`. Rows run in
/// parallel; every output is a fixed-order sum, so results do not depend on the thread count.
fn separable_blur(
    planes: usize,
    width: usize,
    height: usize,
    fill_row: impl Fn(usize, usize, &mut [f64]) + Sync,
) -> Vec<f64> {
    let kernel = gaussian_kernel();
    let avx2 = avx2_available();
    let stride = planes * width;
    let mut rows = vec![0.0; stride * height];
    rows.par_chunks_mut(stride).enumerate().for_each_init(
        || vec![0.0; width + 2 * RADIUS],
        |padded, (y, out)| {
            for (k, out) in out.chunks_exact_mut(width).enumerate() {
                // Zero padding made explicit.
                fill_row(y, k, &mut padded[RADIUS..RADIUS + width]);
                out.fill(0.0);
                for (tap, &weight) in kernel.iter().enumerate() {
                    add_scaled(avx2, out, weight, &padded[tap..tap + width]);
                }
            }
        },
    );
    let mut out = vec![0.0; stride * height];
    out.par_chunks_mut(stride)
        .enumerate()
        .for_each(|(y, out_row)| {
            let lo = y.saturating_sub(RADIUS);
            let hi = (y + RADIUS).min(height - 1);
            for yi in lo..=hi {
                let weight = kernel[yi + RADIUS - y];
                add_scaled(avx2, out_row, weight, &rows[yi * stride..(yi + 1) * stride]);
            }
        });
    out
}

/// `out[i] += weight · src[i]`: the blur's one loop, on the AVX2 path where the CPU has it (the
/// same bits either way, see [`crate::core::simd`]).
fn add_scaled(avx2: bool, out: &mut [f64], weight: f64, src: &[f64]) {
    #[inline(always)]
    fn body(out: &mut [f64], weight: f64, src: &[f64]) {
        for (o, &v) in out.iter_mut().zip(src) {
            *o += weight * v;
        }
    }
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn body_avx2(out: &mut [f64], weight: f64, src: &[f64]) {
        body(out, weight, src)
    }
    #[cfg(target_arch = "x86_64")]
    if avx2 {
        // SAFETY: `avx2` comes from `avx2_available()`, so this CPU runs every instruction
        // `body_avx2` is compiled with.
        return unsafe { body_avx2(out, weight, src) };
    }
    let _ = avx2; // (read only on x86-64)
    body(out, weight, src)
}

/// Zero-padded "same" 2D Gaussian blur of one row-major `width × height` plane.
pub fn blur_plane(src: &[f64], width: usize, height: usize) -> Vec<f64> {
    assert_eq!(src.len(), width * height, "blur_plane: plane size");
    separable_blur(1, width, height, |y, _, row| {
        row.copy_from_slice(&src[y * width..(y + 1) * width])
    })
}

/// Number of local moments per channel: μx, μy, E[x²], E[y²], E[xy].
const MOMENTS: usize = 5;

/// Local moments of every channel, row-interleaved as [`separable_blur`] returns them (plane
/// `MOMENTS · c + q` holds moment q of channel c).
fn moments(pred: &[f64], target: &[f64], width: usize, height: usize, channels: usize) -> Vec<f64> {
    separable_blur(MOMENTS * channels, width, height, |y, k, row| {
        let (c, q) = (k / MOMENTS, k % MOMENTS);
        let start = y * width * channels + c;
        let pixels = pred[start..]
            .iter()
            .step_by(channels)
            .zip(target[start..].iter().step_by(channels))
            .zip(row.iter_mut());
        // One loop per moment, so each is a plain loop the compiler can unroll (no call per
        // sample).
        match q {
            0 => pixels.for_each(|((&a, _), r)| *r = a),
            1 => pixels.for_each(|((_, &b), r)| *r = b),
            2 => pixels.for_each(|((&a, _), r)| *r = a * a),
            3 => pixels.for_each(|((_, &b), r)| *r = b * b),
            _ => pixels.for_each(|((&a, &b), r)| *r = a * b),
        }
    })
}

/// The per-pixel factors of SSIM = (A·B) / (C·D).
struct Terms {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    mu_x: f64,
    mu_y: f64,
}

impl Terms {
    /// From the moments [μx, μy, E[x²], E[y²], E[xy]] of one pixel and channel.
    fn new([mu_x, mu_y, e_xx, e_yy, e_xy]: [f64; MOMENTS]) -> Self {
        let var_x = e_xx - mu_x * mu_x;
        let var_y = e_yy - mu_y * mu_y;
        let cov = e_xy - mu_x * mu_y;
        Terms {
            a: 2.0 * mu_x * mu_y + SSIM_C1,
            b: 2.0 * cov + SSIM_C2,
            c: mu_x * mu_x + mu_y * mu_y + SSIM_C1,
            d: var_x + var_y + SSIM_C2,
            mu_x,
            mu_y,
        }
    }

    fn ssim(&self) -> f64 {
        self.a * self.b / (self.c * self.d)
    }
}

/// Moment q of channel c at (x, y) in the row-interleaved layout.
fn moment_at(
    m: &[f64],
    width: usize,
    channels: usize,
    x: usize,
    y: usize,
    c: usize,
) -> [f64; MOMENTS] {
    let base = (y * MOMENTS * channels + MOMENTS * c) * width + x;
    std::array::from_fn(|q| m[base + q * width])
}

fn check_shapes(pred: &[f64], target: &[f64], width: usize, height: usize, channels: usize) {
    let n = width * height * channels;
    assert!(
        width > 0 && height > 0 && channels > 0,
        "ssim: empty image shape"
    );
    assert_eq!(
        pred.len(),
        n,
        "ssim: prediction is not width·height·channels"
    );
    assert_eq!(target.len(), n, "ssim: target is not width·height·channels");
}

/// The SSIM map (interleaved like the inputs): one value per pixel and channel.
///
/// # Panics
/// If either image is not `width · height · channels` long.
pub fn ssim_map(
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
) -> Vec<f64> {
    check_shapes(pred, target, width, height, channels);
    let m = moments(pred, target, width, height, channels);
    let mut map = vec![0.0; pred.len()];
    map.par_chunks_mut(width * channels)
        .enumerate()
        .for_each(|(y, row)| {
            for (j, v) in row.iter_mut().enumerate() {
                let (x, c) = (j / channels, j % channels);
                *v = Terms::new(moment_at(&m, width, channels, x, y, c)).ssim();
            }
        });
    map
}

/// Adjoints per channel: of μx, of E[x²] and of E[xy].
const ADJOINTS: usize = 3;

/// Mean SSIM over all pixels and channels, and its gradient with respect to `pred` (the target is
/// treated as constant).
///
/// Only the part of the image within [`CROP_MARGIN`] pixels of a nonzero value of either image is
/// computed (the object, for α-premultiplied views on black): beyond `RADIUS` of every nonzero
/// value the local moments are exactly zero, so SSIM is exactly 1 there, and beyond twice that
/// the gradient is exactly zero. Inside the crop every value is the same sum in the same order as
/// over the whole image (the zeros outside add nothing), so the gradient is bit-identical to the
/// uncropped computation; the mean adds the pixels outside as exact ones.
///
/// # Panics
/// If either image is not `width · height · channels` long.
pub fn ssim(
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
) -> LossValue {
    check_shapes(pred, target, width, height, channels);
    let _span = tracing::debug_span!("ssim", width, height, channels).entered();
    let inv_n = 1.0 / pred.len() as f64;
    let Some(crop) = Crop::around_nonzero(pred, target, width, height, channels) else {
        return LossValue {
            value: 1.0,
            grad: vec![0.0; pred.len()],
        };
    };
    if crop.is_whole(width, height) {
        let (sum, grad) = ssim_sum(pred, target, width, height, channels, inv_n);
        return LossValue {
            value: sum * inv_n,
            grad,
        };
    }
    let (pred_crop, target_crop) = (
        crop.cut(pred, width, channels),
        crop.cut(target, width, channels),
    );
    let (sum, grad_crop) = ssim_sum(
        &pred_crop,
        &target_crop,
        crop.width,
        crop.height,
        channels,
        inv_n,
    );
    let outside = (width * height - crop.width * crop.height) * channels;
    let mut grad = vec![0.0; pred.len()];
    let row = crop.width * channels;
    for (y, values) in grad_crop.chunks_exact(row).enumerate() {
        let start = ((crop.y0 + y) * width + crop.x0) * channels;
        grad[start..start + row].copy_from_slice(values);
    }
    LossValue {
        value: (sum + outside as f64) * inv_n,
        grad,
    }
}

/// Pixels of margin around the nonzero values that [`ssim`] computes: one window radius for the
/// moments, one more for the blurred adjoints.
const CROP_MARGIN: usize = 2 * RADIUS;

/// A rectangle of an image: pixels `[x0, x0 + width) × [y0, y0 + height)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Crop {
    x0: usize,
    y0: usize,
    width: usize,
    height: usize,
}

impl Crop {
    /// The bounding box of the pixels where either image is nonzero (in any channel), grown by
    /// [`CROP_MARGIN`] and clipped to the image; `None` when both images are zero.
    fn around_nonzero(
        pred: &[f64],
        target: &[f64],
        width: usize,
        height: usize,
        channels: usize,
    ) -> Option<Crop> {
        let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
        for y in 0..height {
            let row = (y * width * channels)..((y + 1) * width * channels);
            let nonzero = |j: &usize| pred[row.start + j] != 0.0 || target[row.start + j] != 0.0;
            let Some(first) = (0..row.len()).find(nonzero) else {
                continue;
            };
            let last = (0..row.len()).rev().find(nonzero).unwrap_or(first);
            x0 = x0.min(first / channels);
            x1 = x1.max(last / channels + 1);
            y0 = y0.min(y);
            y1 = y + 1;
        }
        (x0 < x1).then(|| {
            let (x0, y0) = (
                x0.saturating_sub(CROP_MARGIN),
                y0.saturating_sub(CROP_MARGIN),
            );
            let (x1, y1) = (
                (x1 + CROP_MARGIN).min(width),
                (y1 + CROP_MARGIN).min(height),
            );
            Crop {
                x0,
                y0,
                width: x1 - x0,
                height: y1 - y0,
            }
        })
    }

    fn is_whole(&self, width: usize, height: usize) -> bool {
        self.width == width && self.height == height
    }

    /// The crop's pixels of an interleaved `width`-wide image.
    fn cut(&self, image: &[f64], width: usize, channels: usize) -> Vec<f64> {
        let row = self.width * channels;
        (self.y0..self.y0 + self.height)
            .flat_map(|y| {
                let start = (y * width + self.x0) * channels;
                &image[start..start + row]
            })
            .copied()
            .collect()
    }
}

/// The sum of the SSIM map over all pixels and channels, and the gradient of `inv_n` times it
/// with respect to `pred`.
fn ssim_sum(
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
    inv_n: f64,
) -> (f64, Vec<f64>) {
    let m = moments(pred, target, width, height, channels);
    // Adjoints of the moments, row-interleaved like the blur output (plane ADJOINTS · c + q).
    let stride = ADJOINTS * channels * width;
    let mut adjoints = vec![0.0; stride * height];
    let row_sums: Vec<f64> = adjoints
        .par_chunks_mut(stride)
        .enumerate()
        .map(|(y, out)| {
            let mut sum = 0.0;
            for c in 0..channels {
                for x in 0..width {
                    let t = Terms::new(moment_at(&m, width, channels, x, y, c));
                    // One division: 1/C = D/(CD) and 1/D = C/(CD).
                    let inv_cd = 1.0 / (t.c * t.d);
                    let s = t.a * t.b * inv_cd;
                    sum += s;
                    let scaled = inv_cd * inv_n;
                    let ds_da = t.b * scaled;
                    let ds_db = t.a * scaled;
                    let ds_dc = -s * t.d * scaled;
                    let ds_dd = -s * t.c * scaled;
                    // A = 2μxμy + C1, B = 2(E[xy] − μxμy) + C2, C = μx² + μy² + C1,
                    // D = E[x²] − μx² + E[y²] − μy² + C2.
                    let base = ADJOINTS * c * width + x;
                    out[base] = 2.0 * t.mu_y * (ds_da - ds_db) + 2.0 * t.mu_x * (ds_dc - ds_dd);
                    out[base + width] = ds_dd;
                    out[base + 2 * width] = 2.0 * ds_db;
                }
            }
            sum
        })
        .collect();
    let blurred = separable_blur(ADJOINTS * channels, width, height, |y, k, row| {
        let start = y * stride + k * width;
        row.copy_from_slice(&adjoints[start..start + width]);
    });
    let mut grad = vec![0.0; pred.len()];
    grad.par_chunks_mut(width * channels)
        .enumerate()
        .for_each(|(y, row)| {
            for (j, g) in row.iter_mut().enumerate() {
                let (x, c) = (j / channels, j % channels);
                let i = y * width * channels + j;
                let base = y * stride + ADJOINTS * c * width + x;
                *g = blurred[base]
                    + 2.0 * pred[i] * blurred[base + width]
                    + target[i] * blurred[base + 2 * width];
            }
        });
    (row_sums.iter().sum::<f64>(), grad)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// An image that is zero outside `[x0, x1) × [y0, y1)` and random inside.
    fn object(rng: &mut ChaCha8Rng, size: (usize, usize), rect: [usize; 4]) -> Vec<f64> {
        let (w, h) = size;
        let [x0, y0, x1, y1] = rect;
        (0..w * h * 3)
            .map(|i| {
                let (x, y) = ((i / 3) % w, i / 3 / w);
                let inside = (x0..x1).contains(&x) && (y0..y1).contains(&y);
                if inside {
                    rng.random_range(0.0..1.0)
                } else {
                    0.0
                }
            })
            .collect()
    }

    #[test]
    fn the_cropped_ssim_equals_the_whole_image_computation() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let (w, h) = (61, 47);
        // In the middle, against an edge, in a corner, one pixel, and the prediction and the
        // target covering different parts.
        let cases = [
            ([20, 15, 35, 30], [22, 14, 37, 29]),
            ([0, 10, 12, 40], [0, 12, 10, 41]),
            ([50, 38, 61, 47], [52, 40, 61, 47]),
            ([30, 20, 31, 21], [30, 20, 31, 21]),
            ([5, 5, 15, 15], [40, 30, 55, 44]),
        ];
        for (pred_rect, target_rect) in cases {
            let pred = object(&mut rng, (w, h), pred_rect);
            let target = object(&mut rng, (w, h), target_rect);
            let cropped = ssim(&pred, &target, w, h, 3);
            let inv_n = 1.0 / pred.len() as f64;
            let (sum, grad) = ssim_sum(&pred, &target, w, h, 3, inv_n);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(
                bits(&cropped.grad),
                bits(&grad),
                "{pred_rect:?} {target_rect:?}"
            );
            assert!((cropped.value - sum * inv_n).abs() < 1e-14);
            assert!(cropped.value < 1.0);
        }
        let black = vec![0.0; w * h * 3];
        let nothing = ssim(&black, &black, w, h, 3);
        assert_eq!(nothing.value, 1.0);
        assert!(nothing.grad.iter().all(|&g| g == 0.0));
    }
}

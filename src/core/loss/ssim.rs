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
//!
//! Inputs and gradients are `f64`; the computation runs in the [`LossPrecision`] the engine asks
//! for: `f64` (the reference) or `f32` (the fast engine: twice the SIMD lanes and half the memory
//! traffic; tested within 1e-5 of the reference's value and 1e-4 of its gradient, relative in L2
//! norm, on smooth noisy objects, where the variances' cancellation is worst).

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

use rayon::prelude::*;

use super::{LossPrecision, LossValue};
use crate::core::filled::filled;
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

/// A float type SSIM computes in (`f32` or `f64`).
trait Sample:
    Copy
    + Send
    + Sync
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + 'static
{
    const ZERO: Self;
    /// The value nearest to `v`.
    fn of(v: f64) -> Self;
    fn widen(self) -> f64;
}

impl Sample for f64 {
    const ZERO: Self = 0.0;
    fn of(v: f64) -> Self {
        v
    }
    fn widen(self) -> f64 {
        self
    }
}

impl Sample for f32 {
    const ZERO: Self = 0.0;
    fn of(v: f64) -> Self {
        v as f32
    }
    fn widen(self) -> f64 {
        f64::from(self)
    }
}

/// Zero-padded "same" 2D Gaussian blur of `planes` row-major `width × height` planes at once.
///
/// `fill_row(y, k, row)` writes row `y` of input plane `k` into `row` (`width` values), so inputs
/// can be read straight from interleaved images or formed on the fly (products). The result is laid
/// out row-interleaved: value (plane k, x, y) at `(y · planes + k) · width + x`. Rows run in
/// parallel; every output is a fixed-order sum, so results do not depend on the thread count.
fn separable_blur<T: Sample>(
    planes: usize,
    width: usize,
    height: usize,
    fill_row: impl Fn(usize, usize, &mut [T]) + Sync,
) -> Vec<T> {
    let kernel = gaussian_kernel().map(T::of);
    let avx2 = avx2_available();
    let stride = planes * width;
    let mut rows = filled(stride * height, T::ZERO);
    rows.par_chunks_mut(stride).enumerate().for_each_init(
        || vec![T::ZERO; width + 2 * RADIUS],
        |padded, (y, out)| {
            for (k, out) in out.chunks_exact_mut(width).enumerate() {
                // Zero padding made explicit.
                fill_row(y, k, &mut padded[RADIUS..RADIUS + width]);
                out.fill(T::ZERO);
                for (tap, &weight) in kernel.iter().enumerate() {
                    add_scaled(avx2, out, weight, &padded[tap..tap + width]);
                }
            }
        },
    );
    let mut out = filled(stride * height, T::ZERO);
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
fn add_scaled<T: Sample>(avx2: bool, out: &mut [T], weight: T, src: &[T]) {
    #[inline(always)]
    fn body<T: Sample>(out: &mut [T], weight: T, src: &[T]) {
        for (o, &v) in out.iter_mut().zip(src) {
            *o += weight * v;
        }
    }
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn body_avx2<T: Sample>(out: &mut [T], weight: T, src: &[T]) {
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
fn moments<T: Sample>(
    pred: &[T],
    target: &[T],
    width: usize,
    height: usize,
    channels: usize,
) -> Vec<T> {
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
struct Terms<T> {
    a: T,
    b: T,
    c: T,
    d: T,
    mu_x: T,
    mu_y: T,
}

impl<T: Sample> Terms<T> {
    /// From the moments [μx, μy, E[x²], E[y²], E[xy]] of one pixel and channel.
    fn new([mu_x, mu_y, e_xx, e_yy, e_xy]: [T; MOMENTS]) -> Self {
        let two = T::of(2.0);
        let var_x = e_xx - mu_x * mu_x;
        let var_y = e_yy - mu_y * mu_y;
        let cov = e_xy - mu_x * mu_y;
        Terms {
            a: two * mu_x * mu_y + T::of(SSIM_C1),
            b: two * cov + T::of(SSIM_C2),
            c: mu_x * mu_x + mu_y * mu_y + T::of(SSIM_C1),
            d: var_x + var_y + T::of(SSIM_C2),
            mu_x,
            mu_y,
        }
    }

    fn ssim(&self) -> T {
        self.a * self.b / (self.c * self.d)
    }
}

/// Moment q of channel c at (x, y) in the row-interleaved layout.
fn moment_at<T: Sample>(
    m: &[T],
    width: usize,
    channels: usize,
    x: usize,
    y: usize,
    c: usize,
) -> [T; MOMENTS] {
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
/// treated as constant), in f64: [`ssim_in`] with [`LossPrecision::F64`].
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
    ssim_in(LossPrecision::F64, pred, target, width, height, channels)
}

/// Mean SSIM over all pixels and channels, and its gradient with respect to `pred` (the target is
/// treated as constant), computed in `precision`.
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
pub fn ssim_in(
    precision: LossPrecision,
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
) -> LossValue {
    check_shapes(pred, target, width, height, channels);
    let _span = tracing::debug_span!("ssim", width, height, channels).entered();
    match precision {
        LossPrecision::F64 => ssim_cropped::<f64>(pred, target, width, height, channels),
        LossPrecision::F32 => ssim_cropped::<f32>(pred, target, width, height, channels),
    }
}

/// [`ssim_in`] in `T`.
fn ssim_cropped<T: Sample>(
    pred: &[f64],
    target: &[f64],
    width: usize,
    height: usize,
    channels: usize,
) -> LossValue {
    let inv_n = 1.0 / pred.len() as f64;
    let Some(crop) = Crop::around_nonzero(pred, target, width, height, channels) else {
        return LossValue {
            value: 1.0,
            grad: vec![0.0; pred.len()],
        };
    };
    let (pred_crop, target_crop) = (
        crop.cut::<T>(pred, width, channels),
        crop.cut::<T>(target, width, channels),
    );
    let (sum, grad_crop) = ssim_sum(
        &pred_crop,
        &target_crop,
        crop.width,
        crop.height,
        channels,
        T::of(inv_n),
    );
    let outside = (width * height - crop.width * crop.height) * channels;
    let mut grad = filled(pred.len(), 0.0);
    let row = crop.width * channels;
    grad.par_chunks_mut(width * channels)
        .skip(crop.y0)
        .zip(grad_crop.par_chunks_exact(row))
        .for_each(|(image_row, values)| {
            let start = crop.x0 * channels;
            for (g, v) in image_row[start..start + row].iter_mut().zip(values) {
                *g = v.widen();
            }
        });
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
        // Per row with a nonzero value: its first and last such pixel; then their extent.
        let (x0, y0, x1, y1) = (0..height)
            .into_par_iter()
            .filter_map(|y| {
                let row = (y * width * channels)..((y + 1) * width * channels);
                let nonzero =
                    |j: &usize| pred[row.start + j] != 0.0 || target[row.start + j] != 0.0;
                let first = (0..row.len()).find(nonzero)?;
                let last = (0..row.len()).rev().find(nonzero).unwrap_or(first);
                Some((first / channels, y, last / channels + 1, y + 1))
            })
            .reduce(
                || (usize::MAX, usize::MAX, 0, 0),
                |a, b| (a.0.min(b.0), a.1.min(b.1), a.2.max(b.2), a.3.max(b.3)),
            );
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

    /// The crop's pixels of an interleaved `width`-wide image, in `T`.
    fn cut<T: Sample>(&self, image: &[f64], width: usize, channels: usize) -> Vec<T> {
        let row = self.width * channels;
        let mut out = filled(row * self.height, T::ZERO);
        out.par_chunks_mut(row).enumerate().for_each(|(y, out)| {
            let start = ((self.y0 + y) * width + self.x0) * channels;
            for (o, &v) in out.iter_mut().zip(&image[start..start + row]) {
                *o = T::of(v);
            }
        });
        out
    }
}

/// The sum of the SSIM map over all pixels and channels (added in f64), and the gradient of
/// `inv_n` times it with respect to `pred`.
fn ssim_sum<T: Sample>(
    pred: &[T],
    target: &[T],
    width: usize,
    height: usize,
    channels: usize,
    inv_n: T,
) -> (f64, Vec<T>) {
    let two = T::of(2.0);
    let m = moments(pred, target, width, height, channels);
    // Adjoints of the moments, row-interleaved like the blur output (plane ADJOINTS · c + q).
    let stride = ADJOINTS * channels * width;
    let mut adjoints = filled(stride * height, T::ZERO);
    let row_sums: Vec<f64> = adjoints
        .par_chunks_mut(stride)
        .enumerate()
        .map(|(y, out)| {
            let mut sum = 0.0;
            for c in 0..channels {
                for x in 0..width {
                    let t = Terms::new(moment_at(&m, width, channels, x, y, c));
                    // One division: 1/C = D/(CD) and 1/D = C/(CD).
                    let inv_cd = T::of(1.0) / (t.c * t.d);
                    let s = t.a * t.b * inv_cd;
                    sum += s.widen();
                    let scaled = inv_cd * inv_n;
                    let ds_da = t.b * scaled;
                    let ds_db = t.a * scaled;
                    let ds_dc = -s * t.d * scaled;
                    let ds_dd = -s * t.c * scaled;
                    // A = 2μxμy + C1, B = 2(E[xy] − μxμy) + C2, C = μx² + μy² + C1,
                    // D = E[x²] − μx² + E[y²] − μy² + C2.
                    let base = ADJOINTS * c * width + x;
                    out[base] = two * t.mu_y * (ds_da - ds_db) + two * t.mu_x * (ds_dc - ds_dd);
                    out[base + width] = ds_dd;
                    out[base + 2 * width] = two * ds_db;
                }
            }
            sum
        })
        .collect();
    let blurred = separable_blur(ADJOINTS * channels, width, height, |y, k, row| {
        let start = y * stride + k * width;
        row.copy_from_slice(&adjoints[start..start + width]);
    });
    let mut grad = filled(pred.len(), T::ZERO);
    grad.par_chunks_mut(width * channels)
        .enumerate()
        .for_each(|(y, row)| {
            for (j, g) in row.iter_mut().enumerate() {
                let (x, c) = (j / channels, j % channels);
                let i = y * width * channels + j;
                let base = y * stride + ADJOINTS * c * width + x;
                *g = blurred[base]
                    + two * pred[i] * blurred[base + width]
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

    #[test]
    fn the_cropped_f32_ssim_equals_its_whole_image_computation() {
        let mut rng = ChaCha8Rng::seed_from_u64(6);
        let (w, h) = (61, 47);
        let pred = object(&mut rng, (w, h), [12, 9, 40, 33]);
        let target = object(&mut rng, (w, h), [10, 11, 38, 35]);
        let cropped = ssim_in(LossPrecision::F32, &pred, &target, w, h, 3);
        let narrow = |v: &[f64]| v.iter().map(|&x| x as f32).collect::<Vec<f32>>();
        let inv_n = 1.0 / pred.len() as f64;
        let (sum, grad) = ssim_sum(&narrow(&pred), &narrow(&target), w, h, 3, inv_n as f32);
        let widened: Vec<u64> = grad.iter().map(|&g| f64::from(g).to_bits()).collect();
        let cropped_bits: Vec<u64> = cropped.grad.iter().map(|g| g.to_bits()).collect();
        assert_eq!(cropped_bits, widened);
        assert!((cropped.value - sum * inv_n).abs() < 1e-12);
    }

    /// Images like a training view's: a smooth object (where the variances are small and f32's
    /// cancellation in E[x²] − μ² is largest) with noise, on black.
    fn smooth_object(rng: &mut ChaCha8Rng, w: usize, h: usize, noise: f64) -> Vec<f64> {
        (0..w * h * 3)
            .map(|i| {
                let (x, y, c) = ((i / 3) % w, i / 3 / w, i % 3);
                let (u, v) = (x as f64 / w as f64 - 0.5, y as f64 / h as f64 - 0.5);
                if u * u + v * v > 0.16 {
                    return 0.0;
                }
                let shade = 0.3 + 0.5 * (3.0 * u + c as f64).sin() * (2.0 * v).cos();
                (shade + noise * rng.random_range(-1.0..1.0)).clamp(0.0, 1.0)
            })
            .collect()
    }

    #[test]
    fn the_f32_ssim_follows_the_f64_reference() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let (w, h) = (96, 80);
        for (noise_pred, noise_target) in [(0.0, 0.01), (0.05, 0.02), (0.3, 0.3)] {
            let pred = smooth_object(&mut rng, w, h, noise_pred);
            let target = smooth_object(&mut rng, w, h, noise_target);
            let reference = ssim_in(LossPrecision::F64, &pred, &target, w, h, 3);
            let single = ssim_in(LossPrecision::F32, &pred, &target, w, h, 3);
            assert!(
                (single.value - reference.value).abs() < 1e-5,
                "value {} vs {}",
                single.value,
                reference.value
            );
            let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
            let diff: Vec<f64> = single
                .grad
                .iter()
                .zip(&reference.grad)
                .map(|(a, b)| a - b)
                .collect();
            let relative = norm(&diff) / norm(&reference.grad);
            assert!(
                relative < 1e-4,
                "gradient off by {relative:e} (L2, relative)"
            );
        }
    }
}

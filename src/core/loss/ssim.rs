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
    let stride = planes * width;
    let mut rows = vec![0.0; stride * height];
    rows.par_chunks_mut(stride).enumerate().for_each_init(
        || vec![0.0; width + 2 * RADIUS],
        |padded, (y, out)| {
            for (k, out) in out.chunks_exact_mut(width).enumerate() {
                // Zero padding made explicit; accumulated tap by tap, which vectorizes.
                fill_row(y, k, &mut padded[RADIUS..RADIUS + width]);
                out.fill(0.0);
                for (tap, &weight) in kernel.iter().enumerate() {
                    for (o, &v) in out.iter_mut().zip(&padded[tap..tap + width]) {
                        *o += weight * v;
                    }
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
                let k = kernel[yi + RADIUS - y];
                for (o, &v) in out_row
                    .iter_mut()
                    .zip(&rows[yi * stride..(yi + 1) * stride])
                {
                    *o += k * v;
                }
            }
        });
    out
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
        for (x, r) in row.iter_mut().enumerate() {
            let i = (y * width + x) * channels + c;
            let (a, b) = (pred[i], target[i]);
            *r = match q {
                0 => a,
                1 => b,
                2 => a * a,
                3 => b * b,
                _ => a * b,
            };
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
    let _span = tracing::trace_span!("ssim", width, height, channels).entered();
    let inv_n = 1.0 / pred.len() as f64;
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
                    let s = t.ssim();
                    sum += s;
                    let ds_da = t.b / (t.c * t.d) * inv_n;
                    let ds_db = t.a / (t.c * t.d) * inv_n;
                    let ds_dc = -s / t.c * inv_n;
                    let ds_dd = -s / t.d * inv_n;
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
    LossValue {
        value: row_sums.iter().sum::<f64>() * inv_n,
        grad,
    }
}

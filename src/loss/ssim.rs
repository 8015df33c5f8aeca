//! Differentiable structural similarity (SSIM) with the 3DGS reference conventions: an 11×11
//! Gaussian window (σ = 1.5), C1 = 0.01², C2 = 0.03², zero-padded "same" convolution per channel,
//! and the mean of the SSIM map over every pixel and channel.
//!
//! The window is separable, so every local statistic is two 1D passes (rows, then columns). The
//! backward pass is analytic: the SSIM map is differentiated with respect to the five local moments
//! (μx, μy, E[x²], E[y²], E[xy]) and those adjoints are blurred back (the zero-padded "same"
//! convolution with a symmetric kernel is its own adjoint).
//!
//! Threading: channels run in parallel (rayon), and inside each blur the rows of a pass run in
//! parallel; results do not depend on the thread count (each output sample is summed in a fixed
//! order).

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

/// Zero-padded "same" 2D Gaussian blur of one row-major `width × height` plane.
pub fn blur_plane(src: &[f64], width: usize, height: usize) -> Vec<f64> {
    assert_eq!(src.len(), width * height, "plane size");
    let kernel = gaussian_kernel();
    let mut rows = vec![0.0; src.len()];
    rows.par_chunks_mut(width.max(1))
        .zip(src.par_chunks(width.max(1)))
        .for_each_init(
            || vec![0.0; width + 2 * RADIUS],
            |padded, (out, row)| {
                // Zero padding made explicit, so every output is the same fixed 11-tap sum
                // (accumulated tap by tap, which vectorizes across the row).
                padded[RADIUS..RADIUS + width].copy_from_slice(row);
                out.fill(0.0);
                for (k, &weight) in kernel.iter().enumerate() {
                    for (o, &v) in out.iter_mut().zip(&padded[k..k + width]) {
                        *o += weight * v;
                    }
                }
            },
        );
    let mut out = vec![0.0; src.len()];
    out.par_chunks_mut(width.max(1))
        .enumerate()
        .for_each(|(y, out_row)| {
            let lo = y.saturating_sub(RADIUS);
            let hi = (y + RADIUS).min(height - 1);
            for yi in lo..=hi {
                let k = kernel[yi + RADIUS - y];
                let in_row = &rows[yi * width..(yi + 1) * width];
                for (o, &v) in out_row.iter_mut().zip(in_row) {
                    *o += k * v;
                }
            }
        });
    out
}

/// Local statistics of one channel.
struct Moments {
    mu_x: Vec<f64>,
    mu_y: Vec<f64>,
    /// Blurred x², y², xy.
    e_xx: Vec<f64>,
    e_yy: Vec<f64>,
    e_xy: Vec<f64>,
}

/// The per-pixel factors of SSIM = (A·B) / (C·D).
struct Terms {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
}

impl Moments {
    fn new(x: &[f64], y: &[f64], width: usize, height: usize) -> Self {
        let products: [Vec<f64>; 3] = [
            x.iter().map(|v| v * v).collect(),
            y.iter().map(|v| v * v).collect(),
            x.iter().zip(y).map(|(a, b)| a * b).collect(),
        ];
        let inputs: [&[f64]; 5] = [x, y, &products[0], &products[1], &products[2]];
        let blurred: Vec<Vec<f64>> = inputs
            .par_iter()
            .map(|p| blur_plane(p, width, height))
            .collect();
        let [mu_x, mu_y, e_xx, e_yy, e_xy]: [Vec<f64>; 5] =
            blurred.try_into().expect("one blurred plane per moment");
        Moments {
            mu_x,
            mu_y,
            e_xx,
            e_yy,
            e_xy,
        }
    }

    fn terms(&self, i: usize) -> Terms {
        let (mx, my) = (self.mu_x[i], self.mu_y[i]);
        let var_x = self.e_xx[i] - mx * mx;
        let var_y = self.e_yy[i] - my * my;
        let cov = self.e_xy[i] - mx * my;
        Terms {
            a: 2.0 * mx * my + SSIM_C1,
            b: 2.0 * cov + SSIM_C2,
            c: mx * mx + my * my + SSIM_C1,
            d: var_x + var_y + SSIM_C2,
        }
    }
}

/// Splits an interleaved image into `channels` planes.
fn planes(image: &[f64], channels: usize) -> Vec<Vec<f64>> {
    (0..channels)
        .map(|c| image.iter().skip(c).step_by(channels).copied().collect())
        .collect()
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
    let (xs, ys) = (planes(pred, channels), planes(target, channels));
    let per_channel: Vec<Vec<f64>> = xs
        .par_iter()
        .zip(ys.par_iter())
        .map(|(x, y)| {
            let m = Moments::new(x, y, width, height);
            (0..x.len())
                .map(|i| {
                    let t = m.terms(i);
                    t.a * t.b / (t.c * t.d)
                })
                .collect()
        })
        .collect();
    let mut map = vec![0.0; pred.len()];
    for (c, plane) in per_channel.iter().enumerate() {
        for (i, &v) in plane.iter().enumerate() {
            map[i * channels + c] = v;
        }
    }
    map
}

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
    let (xs, ys) = (planes(pred, channels), planes(target, channels));
    let per_channel: Vec<(f64, Vec<f64>)> = xs
        .par_iter()
        .zip(ys.par_iter())
        .map(|(x, y)| {
            let m = Moments::new(x, y, width, height);
            let len = x.len();
            let (mut g_mu, mut g_xx, mut g_xy) = (vec![0.0; len], vec![0.0; len], vec![0.0; len]);
            let mut sum = 0.0;
            for i in 0..len {
                let t = m.terms(i);
                let s = t.a * t.b / (t.c * t.d);
                sum += s;
                let ds_da = t.b / (t.c * t.d) * inv_n;
                let ds_db = t.a / (t.c * t.d) * inv_n;
                let ds_dc = -s / t.c * inv_n;
                let ds_dd = -s / t.d * inv_n;
                let (mx, my) = (m.mu_x[i], m.mu_y[i]);
                // A = 2μxμy + C1, B = 2(E[xy] − μxμy) + C2, C = μx² + μy² + C1,
                // D = E[x²] − μx² + E[y²] − μy² + C2.
                g_mu[i] = 2.0 * my * (ds_da - ds_db) + 2.0 * mx * (ds_dc - ds_dd);
                g_xx[i] = ds_dd;
                g_xy[i] = 2.0 * ds_db;
            }
            let adjoints: Vec<Vec<f64>> = [&g_mu, &g_xx, &g_xy]
                .par_iter()
                .map(|g| blur_plane(g, width, height))
                .collect();
            let grad = (0..len)
                .map(|i| adjoints[0][i] + 2.0 * x[i] * adjoints[1][i] + y[i] * adjoints[2][i])
                .collect();
            (sum, grad)
        })
        .collect();
    let mut grad = vec![0.0; pred.len()];
    let mut total = 0.0;
    for (c, (sum, plane)) in per_channel.iter().enumerate() {
        total += sum;
        for (i, &g) in plane.iter().enumerate() {
            grad[i * channels + c] = g;
        }
    }
    LossValue {
        value: total * inv_n,
        grad,
    }
}

//! A Gaussian blur of one row-major plane with its edges clamped (beyond the image the nearest
//! row or column repeats, so a mask touching the border does not fade there), separable: along
//! the rows, then along the columns. The kernel reaches 3σ each way and sums to 1. For masks and
//! silhouettes (SSIM's fixed, zero-padded window is `core::loss::ssim`). Threading: none.

/// `image` (`width × height`) blurred by a Gaussian of standard deviation `sigma` pixels.
pub fn gaussian_blur(image: &[f64], width: usize, height: usize, sigma: f64) -> Vec<f64> {
    assert_eq!(image.len(), width * height, "one value per pixel");
    assert!(sigma > 0.0, "a blur of positive width");
    let radius = (3.0 * sigma).ceil() as usize;
    let weights: Vec<f64> = (0..=2 * radius)
        .map(|k| (-0.5 * ((k as f64 - radius as f64) / sigma).powi(2)).exp())
        .collect();
    let total: f64 = weights.iter().sum();
    let kernel: Vec<f64> = weights.iter().map(|w| w / total).collect();
    let rows = blur_along(image, &kernel, width, height, Axis::Rows);
    blur_along(&rows, &kernel, width, height, Axis::Columns)
}

#[derive(Clone, Copy)]
enum Axis {
    Rows,
    Columns,
}

/// One pass of the separable blur along `axis`, the coordinate clamped to the image.
fn blur_along(src: &[f64], kernel: &[f64], width: usize, height: usize, axis: Axis) -> Vec<f64> {
    let radius = kernel.len() / 2;
    (0..src.len())
        .map(|p| {
            let (x, y) = (p % width, p / width);
            kernel
                .iter()
                .enumerate()
                .map(|(k, w)| {
                    let shifted = |i: usize, n: usize| (i + k).saturating_sub(radius).min(n - 1);
                    let q = match axis {
                        Axis::Rows => y * width + shifted(x, width),
                        Axis::Columns => shifted(y, height) * width + x,
                    };
                    w * src[q]
                })
                .sum()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constant_stays_and_a_point_spreads_as_the_gaussian() {
        let (w, h) = (15, 11);
        let flat = gaussian_blur(&vec![0.7; w * h], w, h, 1.5);
        assert!(
            flat.iter().all(|v| (v - 0.7).abs() < 1e-12),
            "clamped edges keep a constant"
        );
        let mut point = vec![0.0; w * h];
        point[5 * w + 7] = 1.0;
        let spread = gaussian_blur(&point, w, h, 1.0);
        assert!((spread.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        let g = |d: f64| (-0.5 * d * d).exp();
        let ratio = spread[5 * w + 8] / spread[5 * w + 7];
        assert!((ratio - g(1.0)).abs() < 1e-12, "{ratio}");
        let diagonal = spread[6 * w + 8] / spread[5 * w + 7];
        assert!((diagonal - g(1.0) * g(1.0)).abs() < 1e-12, "{diagonal}");
    }

    #[test]
    fn beyond_the_border_the_edge_repeats() {
        // A step at the left border: clamping repeats the 1s, so the first column stays 1.
        let (w, h) = (12, 3);
        let step: Vec<f64> = (0..w * h).map(|p| f64::from(u8::from(p % w < 4))).collect();
        let blurred = gaussian_blur(&step, w, h, 1.0);
        assert!((blurred[0] - 1.0).abs() < 1e-3, "{}", blurred[0]);
        assert!((blurred[3] - 0.5).abs() < 0.2 && blurred[3] > blurred[4]);
    }
}

//! Per-view exposure and white balance: a camera whose exposure or white balance changes from
//! view to view records the same object brighter or bluer in some views. Without a correction
//! the model averages them, and every view is off by its own factor (a spread of ±20 % costs the
//! knot 1.6 dB of S0 PSNR).
//!
//! Each training view has a *colour* `c_v`, one factor per channel (`TrainState::colours`): the
//! view's recorded values over what the run's model predicts for them. A step fits the view's
//! samples divided by it ([`crate::core::step::ViewTarget::channel_gains`]), and reports the
//! least-squares ratio of those samples to its prediction over the object ([`ratio`]), the
//! minimizer of the squared photometric error over one factor per channel given the model. The
//! view's colour moves halfway toward the colour that ratio implies (in logarithms: a ratio of 2
//! and one of ½ are equally far), and the colours of all views are then normalized to a
//! geometric mean of 1 per channel: the capture's own average exposure and white balance stay
//! the model's (the albedo and the light hold them), and only the differences between views are
//! learned. Each factor stays within [½, 2].

use rayon::prelude::*;

/// How far a view's colour moves toward a new estimate (in logarithms).
const STEP: f64 = 0.5;

/// The largest correction, either way: a factor of 2.
const MAX_LOG: f64 = std::f64::consts::LN_2;

/// Pixels with less coverage or mask than this do not enter the estimate.
const MIN_COVERAGE: f64 = 0.5;

/// Per channel, `Σ t·p / Σ p²` over the pixels where both `alpha` and `mask` are at least ½:
/// how much brighter the fitted `target` is than the prediction `pred` (both interleaved RGB,
/// α-premultiplied); `None` for a channel with no prediction to compare.
pub fn ratio(pred: &[f64], target: &[f64], alpha: &[f64], mask: &[f32]) -> [Option<f64>; 3] {
    // Sums over fixed chunks of pixels, added in order: the same bits whatever the thread count
    // (a resumed run must follow the uninterrupted one bit for bit).
    const CHUNK_PIXELS: usize = 4096;
    let chunks: Vec<[f64; 6]> = (
        pred.par_chunks(3 * CHUNK_PIXELS),
        target.par_chunks(3 * CHUNK_PIXELS),
        alpha.par_chunks(CHUNK_PIXELS),
        mask.par_chunks(CHUNK_PIXELS),
    )
        .into_par_iter()
        .map(|(pred, target, alpha, mask)| {
            let mut s = [0.0; 6];
            let pixels = pred.chunks_exact(3).zip(target.chunks_exact(3));
            for ((p, t), (&a, &m)) in pixels.zip(alpha.iter().zip(mask)) {
                if a < MIN_COVERAGE || f64::from(m) < MIN_COVERAGE {
                    continue;
                }
                for c in 0..3 {
                    if p[c].is_finite() && t[c].is_finite() {
                        s[c] += t[c] * p[c];
                        s[3 + c] += p[c] * p[c];
                    }
                }
            }
            s
        })
        .collect();
    let mut sums = [0.0; 6];
    for chunk in &chunks {
        for (sum, v) in sums.iter_mut().zip(chunk) {
            *sum += v;
        }
    }
    std::array::from_fn(|c| (sums[3 + c] > 1e-12).then(|| sums[c] / sums[3 + c]))
}

/// Moves view `view`'s colour toward `ratio` times itself (the colour a step's [`ratio`]
/// implies), then normalizes all colours to a geometric mean of 1 per channel.
pub fn update(colours: &mut [[f64; 3]], view: usize, ratio: [Option<f64>; 3]) {
    for (c, r) in ratio.into_iter().enumerate() {
        let Some(r) = r.filter(|r| r.is_finite() && *r > 0.0) else {
            continue;
        };
        let log = colours[view][c].ln() + STEP * r.ln();
        colours[view][c] = log.clamp(-MAX_LOG, MAX_LOG).exp();
    }
    let n = colours.len() as f64;
    for c in 0..3 {
        let mean_log = colours.iter().map(|v| v[c].ln()).sum::<f64>() / n;
        for v in colours.iter_mut() {
            v[c] = (v[c].ln() - mean_log).clamp(-MAX_LOG, MAX_LOG).exp();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ratio_is_the_least_squares_factor_over_the_object() {
        let pred = [1.0, 2.0, 0.5, 2.0, 1.0, 0.0, 9.0, 9.0, 9.0];
        let target = [1.2, 2.4, 0.5, 2.4, 1.2, 0.3, 0.0, 0.0, 0.0];
        // The third pixel is outside the mask; the blue channel has prediction 0.5 and 0.
        let r = ratio(&pred, &target, &[1.0, 0.8, 1.0], &[1.0, 1.0, 0.0]);
        assert!((r[0].unwrap() - 1.2).abs() < 1e-12);
        assert!((r[1].unwrap() - 1.2).abs() < 1e-12);
        assert!((r[2].unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(ratio(&pred, &target, &[0.0; 3], &[1.0; 3]), [None; 3]);
    }

    /// Views recorded at known exposures, each estimated against a model at their mean: the
    /// colours converge to the exposures over their geometric mean.
    #[test]
    fn repeated_updates_recover_the_views_exposures() {
        let exposures = [
            [1.2, 1.0, 0.9],
            [0.8, 1.1, 1.0],
            [1.0, 0.9, 1.1],
            [1.05, 1.0, 1.0],
        ];
        let mut colours = vec![[1.0; 3]; 4];
        for round in 0..60 {
            let view = round % 4;
            // The model predicts the geometric-mean view; the step's ratio is the view's exposure
            // over the colour it is already divided by.
            let r = std::array::from_fn(|c| {
                let mean = exposures.iter().map(|e| e[c]).map(f64::ln).sum::<f64>() / 4.0;
                Some(exposures[view][c] / mean.exp() / colours[view][c])
            });
            update(&mut colours, view, r);
        }
        for (v, e) in exposures.iter().enumerate() {
            for c in 0..3 {
                let mean = exposures.iter().map(|e| e[c]).map(f64::ln).sum::<f64>() / 4.0;
                let expected = e[c] / mean.exp();
                assert!(
                    (colours[v][c] - expected).abs() < 1e-3,
                    "view {v} channel {c}: {} vs {expected}",
                    colours[v][c]
                );
            }
        }
        let mut clamped = vec![[1.0; 3]; 2];
        update(&mut clamped, 0, [Some(100.0), None, Some(f64::NAN)]);
        assert!(clamped[0][0] <= 2.0 + 1e-12 && clamped[1][0] >= 0.5 - 1e-12);
        assert_eq!(clamped[0][1], 1.0);
        assert_eq!(clamped[0][2], 1.0);
    }
}

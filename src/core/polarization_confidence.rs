//! How far each pixel's measured linear polarization can be trusted, from the view's own noise.
//!
//! The AoLP prior ([`crate::core::loss::aolp_normal`]) weighs each pixel by its measured DoLP.
//! Under sensor noise that weight is biased: with independent noise of variance σ² on S1 and S2,
//! `E[S1² + S2²] = P² + 2σ²` for a true polarized intensity `P`, so a pixel with no polarization
//! at all shows a DoLP of about `√2 σ / S0` at a random angle, and the prior pulls its normal
//! toward that angle. The confidence of a pixel is the positive-part shrinkage
//! `w = max(0, 1 − 2σ² / (S1² + S2²))`: the share of its measured polarized power that is signal.
//! A noise-free view has w = 1 wherever it is polarized.
//!
//! σ² is measured on the view itself ([`NoiseCurve::estimate`]), as a function of the intensity
//! (shot noise grows with it): the high-pass residual of S1 and S2 (each pixel minus the mean of
//! its four neighbours) over the object's pixels, binned by S0, each bin's robust variance from
//! the median of the squared residuals. Edges and texture raise a bin's residuals only where they
//! are a large share of its pixels, and then the estimate errs toward trusting less.
//! All values are the channel means of the RGB samples, as the prior uses them.
//!
//! Threading: single-threaded passes over a view's pixels; a run computes it once per view.

/// Bins of S0 levels the noise curve is measured in.
pub const NOISE_BINS: usize = 16;

/// Residuals a bin needs for its variance to count (fewer: the bin borrows its neighbours').
pub const MIN_BIN_SAMPLES: usize = 64;

/// The median of χ²₁ (the square of a standard normal variable): a median of squared residuals
/// over this is their variance.
const CHI2_1_MEDIAN: f64 = 0.454_936_423_119_572_7;

/// Variance of the residual `x − mean(4 neighbours)` of independent samples of variance 1.
const RESIDUAL_VARIANCE: f64 = 1.25;

/// The noise variance of a view's S1 and S2 (channel means) as a function of its S0, piecewise
/// linear between bin centres and constant beyond the first and last.
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseCurve {
    /// (S0 at the bin's median, the variance there), in increasing S0.
    knots: Vec<(f64, f64)>,
}

impl NoiseCurve {
    /// The curve of a `width × height` view from its interleaved RGB `s0`, `s1`, `s2` and its mask
    /// (object where ≥ ½). A pixel contributes where it and its four neighbours are object. `None`
    /// when fewer than [`MIN_BIN_SAMPLES`] pixels qualify.
    pub fn estimate(
        s0: &[f32],
        s1: &[f32],
        s2: &[f32],
        mask: &[f32],
        width: usize,
        height: usize,
    ) -> Option<Self> {
        let pixels = width * height;
        assert!(
            s0.len() == 3 * pixels
                && s1.len() == 3 * pixels
                && s2.len() == 3 * pixels
                && mask.len() == pixels,
            "NoiseCurve::estimate: images do not match {width}×{height}"
        );
        let m0 = channel_means(s0);
        let m1 = channel_means(s1);
        let m2 = channel_means(s2);
        let inside = |p: usize| mask[p] >= 0.5;
        // (S0, squared residual of S1, squared residual of S2) of each interior object pixel.
        let mut samples: Vec<(f64, f64, f64)> = Vec::new();
        for y in 1..height.saturating_sub(1) {
            for x in 1..width - 1 {
                let p = y * width + x;
                let around = [p - 1, p + 1, p - width, p + width];
                if !inside(p) || !around.iter().all(|&q| inside(q)) {
                    continue;
                }
                let residual = |m: &[f64]| m[p] - around.iter().map(|&q| m[q]).sum::<f64>() / 4.0;
                let (r1, r2) = (residual(&m1), residual(&m2));
                if m0[p].is_finite() && r1.is_finite() && r2.is_finite() {
                    samples.push((m0[p], r1 * r1, r2 * r2));
                }
            }
        }
        if samples.len() < MIN_BIN_SAMPLES {
            return None;
        }
        samples.sort_by(|a, b| a.0.total_cmp(&b.0));
        let bins = NOISE_BINS.min(samples.len() / MIN_BIN_SAMPLES).max(1);
        let knots = (0..bins)
            .map(|b| {
                let bin = &samples[b * samples.len() / bins..(b + 1) * samples.len() / bins];
                let level = bin[bin.len() / 2].0;
                let mut squares: Vec<f64> = bin.iter().flat_map(|s| [s.1, s.2]).collect();
                let median = median_in_place(&mut squares);
                (level, median / (CHI2_1_MEDIAN * RESIDUAL_VARIANCE))
            })
            .collect();
        Some(Self { knots })
    }

    /// The noise variance of S1 (and of S2) at intensity `s0`.
    pub fn variance(&self, s0: f64) -> f64 {
        let first = self.knots[0];
        let last = self.knots[self.knots.len() - 1];
        if s0 <= first.0 {
            return first.1;
        }
        if s0 >= last.0 {
            return last.1;
        }
        let i = self.knots.partition_point(|k| k.0 <= s0);
        let ((x0, y0), (x1, y1)) = (self.knots[i - 1], self.knots[i]);
        if x1 <= x0 {
            return y1;
        }
        y0 + (y1 - y0) * (s0 - x0) / (x1 - x0)
    }
}

/// The confidence of each pixel's measured polarization (see the module comment), 0 outside the
/// mask, and 1 everywhere on the object when the view has too few object pixels to measure its
/// noise.
pub fn polarization_confidence(
    s0: &[f32],
    s1: &[f32],
    s2: &[f32],
    mask: &[f32],
    width: usize,
    height: usize,
) -> Vec<f32> {
    let curve = NoiseCurve::estimate(s0, s1, s2, mask, width, height);
    let (m0, m1, m2) = (channel_means(s0), channel_means(s1), channel_means(s2));
    (0..width * height)
        .map(|p| {
            if mask[p] < 0.5 {
                return 0.0;
            }
            let Some(curve) = &curve else {
                return 1.0;
            };
            let power = m1[p] * m1[p] + m2[p] * m2[p];
            if power.is_nan() || power <= 0.0 {
                return 0.0;
            }
            (1.0 - 2.0 * curve.variance(m0[p]) / power).clamp(0.0, 1.0) as f32
        })
        .collect()
}

/// The mean of each pixel's three channels, in f64.
fn channel_means(rgb: &[f32]) -> Vec<f64> {
    rgb.chunks_exact(3)
        .map(|c| (f64::from(c[0]) + f64::from(c[1]) + f64::from(c[2])) / 3.0)
        .collect()
}

/// The median of `values` (the upper one of an even count), reordering them.
fn median_in_place(values: &mut [f64]) -> f64 {
    let middle = values.len() / 2;
    *values.select_nth_unstable_by(middle, f64::total_cmp).1
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// A standard normal sample (Box–Muller).
    fn gaussian(rng: &mut StdRng) -> f64 {
        let u: f64 = rng.random_range(f64::EPSILON..1.0);
        let v: f64 = rng.random();
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }

    /// A `size × size` view, all object but a one-pixel frame, whose S0 ramps from 0.1 to 1.1
    /// across x and whose S1/S2 hold a smooth polarization of `dolp` at an angle that turns
    /// along y; Gaussian noise of variance `k · S0` on every channel of S1 and S2.
    fn noisy_view(size: usize, dolp: f64, k: f64, seed: u64) -> [Vec<f32>; 4] {
        let mut rng = StdRng::seed_from_u64(seed);
        let (mut s0, mut s1, mut s2) = (Vec::new(), Vec::new(), Vec::new());
        let mut mask = Vec::new();
        for y in 0..size {
            for x in 0..size {
                let level = 0.1 + x as f64 / size as f64;
                let angle = y as f64 / size as f64 * std::f64::consts::PI;
                let sigma = (k * level).sqrt();
                for _ in 0..3 {
                    s0.push(level as f32);
                    s1.push((dolp * level * angle.cos() + sigma * gaussian(&mut rng)) as f32);
                    s2.push((dolp * level * angle.sin() + sigma * gaussian(&mut rng)) as f32);
                }
                let frame = x == 0 || y == 0 || x == size - 1 || y == size - 1;
                mask.push(if frame { 0.0 } else { 1.0 });
            }
        }
        [s0, s1, s2, mask]
    }

    /// The confidences of the object's pixels (mask ≥ ½).
    fn on_the_object(confidence: &[f32], mask: &[f32]) -> Vec<f32> {
        confidence
            .iter()
            .zip(mask)
            .filter(|(_, &m)| m >= 0.5)
            .map(|(&w, _)| w)
            .collect()
    }

    #[test]
    fn the_noise_curve_recovers_shot_noise_that_grows_with_intensity() {
        let k = 1e-4;
        let [s0, s1, s2, mask] = noisy_view(160, 0.2, k, 1);
        let curve = NoiseCurve::estimate(&s0, &s1, &s2, &mask, 160, 160).unwrap();
        // The channel mean of three independent channels has a third of their variance.
        for level in [0.2, 0.5, 0.9] {
            let expected = k * level / 3.0;
            let got = curve.variance(level);
            assert!(
                (got / expected - 1.0).abs() < 0.15,
                "at S0 {level}: variance {got:e}, expected {expected:e}"
            );
        }
    }

    #[test]
    fn noise_free_polarization_is_fully_trusted_and_pure_noise_is_mostly_not() {
        let [s0, s1, s2, mask] = noisy_view(96, 0.3, 0.0, 2);
        let clean = polarization_confidence(&s0, &s1, &s2, &mask, 96, 96);
        for (p, &w) in clean.iter().enumerate() {
            let expected = if mask[p] >= 0.5 { 1.0 } else { 0.0 };
            assert!((w - expected).abs() < 1e-3, "pixel {p}: {w}");
        }
        // No polarization at all: the measured power is noise, E = 2σ², and the shrinkage
        // zeroes the pixels below it (about 63 % of a χ²₂) and keeps the rest small.
        let [s0, s1, s2, mask] = noisy_view(96, 0.0, 1e-4, 3);
        let noise = polarization_confidence(&s0, &s1, &s2, &mask, 96, 96);
        let object = on_the_object(&noise, &mask);
        let zero = object.iter().filter(|&&w| w == 0.0).count() as f64 / object.len() as f64;
        let mean = object.iter().sum::<f32>() / object.len() as f32;
        assert!((0.5..0.75).contains(&zero), "share zeroed {zero}");
        assert!(mean < 0.25, "mean confidence {mean}");
    }

    #[test]
    fn strong_polarization_under_noise_keeps_most_of_its_weight() {
        // DoLP 0.3 at S0 ≈ 0.6: P ≈ 0.18 against σ ≈ 0.0045 (channel mean): w ≈ 1 − 2σ²/P².
        let [s0, s1, s2, mask] = noisy_view(96, 0.3, 1e-4, 4);
        let w = polarization_confidence(&s0, &s1, &s2, &mask, 96, 96);
        let object = on_the_object(&w, &mask);
        let mean = object.iter().sum::<f32>() / object.len() as f32;
        assert!(mean > 0.95 && mean < 1.0, "mean confidence {mean}");
    }

    #[test]
    fn too_small_a_view_trusts_its_object_pixels() {
        let [s0, s1, s2, mask] = noisy_view(6, 0.3, 1e-4, 5);
        let w = polarization_confidence(&s0, &s1, &s2, &mask, 6, 6);
        assert!(w
            .iter()
            .zip(&mask)
            .all(|(&w, &m)| w == if m >= 0.5 { 1.0 } else { 0.0 }));
    }
}

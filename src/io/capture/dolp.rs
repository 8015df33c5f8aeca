//! Degree-of-linear-polarization statistics of full-Stokes views, so `phygap inspect` shows that a
//! capture's polarization is there: per view and over the capture, the mean, median and 90th
//! percentile of DoLP = √(S1² + S2²) / S0 over the masked pixels.
//!
//! Per pixel the RGB channels are averaged first (a grey Stokes vector); pixels with S0 ≤ 0 are
//! skipped, and DoLP above 1 (noise in dark pixels) counts as 1. Quantiles come from a histogram
//! of [`BINS`] bins over [0, 1], so they are exact to 1 / `BINS`; the mean is exact.

use serde::Serialize;

use crate::formats::image_io::Image;

/// Histogram bins over [0, 1].
pub const BINS: usize = 10_000;

/// DoLP statistics over a set of pixels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DolpStats {
    /// Masked pixels with S0 > 0 that the statistics cover.
    pub pixels: u64,
    pub mean: f64,
    pub median: f64,
    pub p90: f64,
}

/// A histogram of DoLP values that views add into and captures merge.
#[derive(Clone, Debug)]
pub struct DolpHistogram {
    counts: Vec<u64>,
    sum: f64,
    total: u64,
}

impl Default for DolpHistogram {
    fn default() -> Self {
        DolpHistogram {
            counts: vec![0; BINS],
            sum: 0.0,
            total: 0,
        }
    }
}

impl DolpHistogram {
    /// The DoLP of every pixel of a view where `mask` > 0.5.
    pub fn of_view(s0: &Image, s1: &Image, s2: &Image, mask: &Image) -> Self {
        let mut h = DolpHistogram::default();
        let c = s0.channels;
        for p in 0..s0.num_pixels() {
            if mask.data[p * mask.channels] <= 0.5 {
                continue;
            }
            let mean = |img: &Image| {
                img.data[p * c..(p + 1) * c]
                    .iter()
                    .map(|v| *v as f64)
                    .sum::<f64>()
                    / c as f64
            };
            let a = mean(s0);
            if a > 0.0 {
                h.add((mean(s1).hypot(mean(s2)) / a).min(1.0));
            }
        }
        h
    }

    pub fn add(&mut self, dolp: f64) {
        let bin = ((dolp * BINS as f64) as usize).min(BINS - 1);
        self.counts[bin] += 1;
        self.sum += dolp;
        self.total += 1;
    }

    pub fn merge(&mut self, other: &DolpHistogram) {
        for (a, b) in self.counts.iter_mut().zip(&other.counts) {
            *a += b;
        }
        self.sum += other.sum;
        self.total += other.total;
    }

    /// The statistics, or `None` when no pixel was added.
    pub fn stats(&self) -> Option<DolpStats> {
        (self.total > 0).then(|| DolpStats {
            pixels: self.total,
            mean: self.sum / self.total as f64,
            median: self.quantile(0.5),
            p90: self.quantile(0.9),
        })
    }

    /// The centre of the bin holding the `q`-quantile.
    fn quantile(&self, q: f64) -> f64 {
        let rank = ((q * self.total as f64).ceil() as u64).max(1);
        let mut seen = 0;
        for (bin, count) in self.counts.iter().enumerate() {
            seen += count;
            if seen >= rank {
                return (bin as f64 + 0.5) / BINS as f64;
            }
        }
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statistics_of_known_values() {
        // DoLP k / 100 for k = 1..=100 on a 10×10 view, S0 = 2, angle varying; one masked-out
        // pixel with DoLP 1 and one with S0 < 0 are skipped.
        let (w, h) = (12, 10);
        let dolp = |x: usize, y: usize| ((y * 10 + x) as f32 + 1.0) / 100.0;
        let s0 = Image::from_fn(w, h, 3, |x, _, o| o.fill(if x == 11 { -1.0 } else { 2.0 }));
        let angle = |x: usize, y: usize| 0.3 * x as f32 + 0.1 * y as f32;
        let s1 = Image::from_fn(w, h, 3, |x, y, o| {
            o.fill(if x < 10 {
                2.0 * dolp(x, y) * (2.0 * angle(x, y)).cos()
            } else {
                2.0
            })
        });
        let s2 = Image::from_fn(w, h, 3, |x, y, o| {
            o.fill(if x < 10 {
                2.0 * dolp(x, y) * (2.0 * angle(x, y)).sin()
            } else {
                0.0
            })
        });
        let mask = Image::from_fn(w, h, 1, |x, _, o| o[0] = if x == 10 { 0.0 } else { 1.0 });
        let stats = DolpHistogram::of_view(&s0, &s1, &s2, &mask)
            .stats()
            .unwrap();
        assert_eq!(stats.pixels, 100);
        assert!((stats.mean - 0.505).abs() < 1e-6, "{stats:?}");
        assert!((stats.median - 0.50).abs() < 1.0 / BINS as f64, "{stats:?}");
        assert!((stats.p90 - 0.90).abs() < 1.0 / BINS as f64, "{stats:?}");
        let mut merged = DolpHistogram::default();
        merged.merge(&DolpHistogram::of_view(&s0, &s1, &s2, &mask));
        merged.add(1.0);
        assert_eq!(merged.stats().unwrap().pixels, 101);
        assert_eq!(DolpHistogram::default().stats(), None);
    }
}

//! The split-sum BRDF table (Karis 2013): for μ = n·o and Disney roughness r (GGX α = r²),
//! `A(μ, r) = ∫ (1 − F_c) G_vis` and `B(μ, r) = ∫ F_c G_vis` with `F_c = (1 − v·h)^5`, so that the
//! directional albedo of a GGX lobe with Schlick Fresnel is `F0 · A + B`. Integrated by GGX importance
//! sampling on a Hammersley set with the exact separable Smith G of GGX
//! (`G1(x) = 2x / (x + √(α² + (1 − α²) x²))`, as Mitsuba's microfacet model), on a size × size grid of
//! cell centres `μ_i = (i + ½)/size`, `r_j = (j + ½)/size`; looked up bilinearly (clamped) with
//! derivatives. Built in parallel over roughness rows with rayon; [`BrdfLut::shared`] builds the
//! default table once per process.

use std::sync::OnceLock;

use rayon::prelude::*;

/// A split-sum table.
#[derive(Clone, Debug, PartialEq)]
pub struct BrdfLut {
    /// Cells per axis.
    pub size: usize,
    /// A at (μ_i, r_j), index `j · size + i`.
    pub a: Vec<f64>,
    /// B at (μ_i, r_j).
    pub b: Vec<f64>,
}

/// A bilinear lookup with its partial derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutSample {
    pub a: f64,
    pub b: f64,
    pub da_dmu: f64,
    pub db_dmu: f64,
    pub da_dr: f64,
    pub db_dr: f64,
}

/// Radical inverse in base 2 (the second Hammersley coordinate).
fn radical_inverse(mut bits: u32) -> f64 {
    bits = bits.rotate_right(16);
    bits = ((bits & 0x5555_5555) << 1) | ((bits & 0xAAAA_AAAA) >> 1);
    bits = ((bits & 0x3333_3333) << 2) | ((bits & 0xCCCC_CCCC) >> 2);
    bits = ((bits & 0x0F0F_0F0F) << 4) | ((bits & 0xF0F0_F0F0) >> 4);
    bits = ((bits & 0x00FF_00FF) << 8) | ((bits & 0xFF00_FF00) >> 8);
    bits as f64 * (1.0 / 4_294_967_296.0)
}

/// GGX-distributed half vectors (x and z components; v lies in the xz-plane so y never matters) with
/// quadrature weights. The GGX CDF variable ξ is itself substituted as ξ = 1 − (1 − s)² (weight
/// 2(1 − s)): at grazing view the integrand grows like 1/√(1 − ξ) in the lobe's tail, which plain
/// sampling in ξ converges to only as 1/√N.
fn ggx_half_vectors(alpha: f64, samples: usize) -> Vec<(f64, f64, f64)> {
    let a2 = alpha * alpha;
    (0..samples)
        .map(|i| {
            // v lies in the xz-plane, so φ and −φ give the same integrand: cover [0, π] only.
            let phi = std::f64::consts::PI * (i as f64 + 0.5) / samples as f64;
            // Centre of the stratum [k/N, (k + 1)/N) rather than its edge.
            let s = radical_inverse(i as u32) + 0.5 / samples as f64;
            let xi = 1.0 - (1.0 - s) * (1.0 - s);
            let cos_h = ((1.0 - xi) / (1.0 + (a2 - 1.0) * xi)).sqrt();
            let sin_h = (1.0 - cos_h * cos_h).max(0.0).sqrt();
            (sin_h * phi.cos(), cos_h, 2.0 * (1.0 - s))
        })
        .collect()
}

/// Smith G1 of GGX divided by x: `2 / (x + √(α² + (1 − α²) x²))`.
fn smith_g1_over_cos(x: f64, a2: f64) -> f64 {
    2.0 / (x + (a2 + (1.0 - a2) * x * x).sqrt())
}

/// (A, B) at one (μ, α) with precomputed half vectors.
fn integrate_with(mu: f64, alpha: f64, halves: &[(f64, f64, f64)]) -> (f64, f64) {
    let a2 = alpha * alpha;
    let (vx, vz) = ((1.0 - mu * mu).max(0.0).sqrt(), mu);
    let g1v = smith_g1_over_cos(vz, a2);
    let (mut a, mut b) = (0.0, 0.0);
    for &(hx, hz, weight) in halves {
        let voh = vx * hx + vz * hz;
        if voh <= 0.0 {
            continue;
        }
        let nol = 2.0 * voh * hz - vz;
        if nol <= 0.0 {
            continue;
        }
        // G · (v·h) / ((n·h)(n·v)) with G = G1(v) G1(l).
        let g_vis = weight * g1v * smith_g1_over_cos(nol, a2) * nol * voh / hz;
        let fc = (1.0 - voh).powi(5);
        a += (1.0 - fc) * g_vis;
        b += fc * g_vis;
    }
    (a / halves.len() as f64, b / halves.len() as f64)
}

impl BrdfLut {
    /// Cells per axis of the default table.
    pub const DEFAULT_SIZE: usize = 256;
    /// Importance samples per cell of the default table.
    pub const DEFAULT_SAMPLES: usize = 512;

    /// Integrates the table (size ≥ 2).
    pub fn compute(size: usize, samples: usize) -> Self {
        let _span = tracing::info_span!("brdf_lut", size, samples).entered();
        let size = size.max(2);
        let rows: Vec<(Vec<f64>, Vec<f64>)> = (0..size)
            .into_par_iter()
            .map(|j| {
                let r = (j as f64 + 0.5) / size as f64;
                let halves = ggx_half_vectors(r * r, samples.max(1));
                (0..size)
                    .map(|i| integrate_with((i as f64 + 0.5) / size as f64, r * r, &halves))
                    .unzip()
            })
            .collect();
        let (mut a, mut b) = (
            Vec::with_capacity(size * size),
            Vec::with_capacity(size * size),
        );
        for (ra, rb) in rows {
            a.extend(ra);
            b.extend(rb);
        }
        BrdfLut { size, a, b }
    }

    /// The default 256 × 256 table, built on first use and shared by the whole process.
    pub fn shared() -> &'static BrdfLut {
        static LUT: OnceLock<BrdfLut> = OnceLock::new();
        LUT.get_or_init(|| BrdfLut::compute(Self::DEFAULT_SIZE, Self::DEFAULT_SAMPLES))
    }

    /// The integral at one point (for reference checks), with `samples` importance samples.
    pub fn integrate(mu: f64, roughness: f64, samples: usize) -> (f64, f64) {
        let alpha = roughness * roughness;
        integrate_with(mu, alpha, &ggx_half_vectors(alpha, samples.max(1)))
    }

    /// Bilinear (A, B) at (μ, r), both clamped to the cell-centre range.
    pub fn lookup(&self, mu: f64, roughness: f64) -> (f64, f64) {
        let s = self.lookup_with_grad(mu, roughness);
        (s.a, s.b)
    }

    /// Bilinear lookup with derivatives (zero along a clamped axis).
    pub fn lookup_with_grad(&self, mu: f64, roughness: f64) -> LutSample {
        let n = self.size;
        let axis = |v: f64| {
            let x = v * n as f64 - 0.5;
            let clamped = x.clamp(0.0, (n - 1) as f64);
            let i0 = (clamped.floor() as usize).min(n - 2);
            let scale = if x == clamped { n as f64 } else { 0.0 };
            (i0, clamped - i0 as f64, scale)
        };
        let (i0, fx, sx) = axis(mu);
        let (j0, fy, sy) = axis(roughness);
        let at = |t: &[f64], i: usize, j: usize| t[j * n + i];
        let bilinear = |t: &[f64]| {
            let (v00, v10) = (at(t, i0, j0), at(t, i0 + 1, j0));
            let (v01, v11) = (at(t, i0, j0 + 1), at(t, i0 + 1, j0 + 1));
            let value =
                (v00 * (1.0 - fx) + v10 * fx) * (1.0 - fy) + (v01 * (1.0 - fx) + v11 * fx) * fy;
            let d_mu = ((v10 - v00) * (1.0 - fy) + (v11 - v01) * fy) * sx;
            let d_r = ((v01 - v00) * (1.0 - fx) + (v11 - v10) * fx) * sy;
            (value, d_mu, d_r)
        };
        let (a, da_dmu, da_dr) = bilinear(&self.a);
        let (b, db_dmu, db_dr) = bilinear(&self.b);
        LutSample {
            a,
            b,
            da_dmu,
            db_dmu,
            da_dr,
            db_dr,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::gradcheck::assert_gradient;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn default_table_builds_fast_and_is_physical() {
        let start = std::time::Instant::now();
        let lut = BrdfLut::compute(BrdfLut::DEFAULT_SIZE, BrdfLut::DEFAULT_SAMPLES);
        println!(
            "brdf lut 256² × 512 samples: {:.0} ms",
            start.elapsed().as_secs_f64() * 1e3
        );
        for (a, b) in lut.a.iter().zip(&lut.b) {
            assert!(*a >= 0.0 && *b >= 0.0);
            assert!(a + b <= 1.0 + 5e-3, "A + B = {}", a + b);
        }
        // Smooth surface seen head-on: the lobe reflects everything, Fresnel weight ≈ F0.
        let (a, b) = lut.lookup(1.0, 0.0);
        assert!((a + b - 1.0).abs() < 2e-3 && b < 1e-3, "{a} {b}");
        // At grazing view, rougher lobes lose more to shadowing and masking.
        for mu in [0.05, 0.15, 0.3] {
            let sums: Vec<f64> = [0.1, 0.3, 0.5, 0.7, 0.9]
                .iter()
                .map(|&r| {
                    let (a, b) = lut.lookup(mu, r);
                    a + b
                })
                .collect();
            assert!(sums.windows(2).all(|w| w[1] < w[0]), "μ = {mu}: {sums:?}");
        }
        // B (the Schlick term) grows toward grazing angles for a smooth surface.
        assert!(lut.lookup(0.1, 0.2).1 > 5.0 * lut.lookup(0.9, 0.2).1);
        // Table entries agree with a much better-converged integral.
        for (mu, r) in [
            (0.5 / 256.0 + 0.5, 0.5 / 256.0 + 0.25),
            (0.9, 0.6),
            (0.2, 0.8),
        ] {
            let (ra, rb) = BrdfLut::integrate(mu, r, 1 << 15);
            let (la, lb) = lut.lookup(mu, r);
            assert!(
                (la - ra).abs() < 5e-3 && (lb - rb).abs() < 5e-3,
                "({mu}, {r}): {la} {lb} vs {ra} {rb}"
            );
        }
    }

    #[test]
    fn smooth_normal_incidence_matches_the_closed_form() {
        // r → 0 at μ = 1: the lobe is a mirror and G = 1, so A = 1, B = 0.
        let (a, b) = BrdfLut::integrate(1.0, 1e-3, 256);
        assert!((a - 1.0).abs() < 1e-6 && b.abs() < 1e-6, "{a} {b}");
    }

    #[test]
    fn lookup_derivatives_match_finite_differences() {
        let lut = BrdfLut::compute(32, 64);
        for seed in 0..4u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            for _ in 0..10 {
                let x = [rng.random_range(0.03..0.97), rng.random_range(0.03..0.97)];
                let (wa, wb) = (rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
                let s = lut.lookup_with_grad(x[0], x[1]);
                let analytic = [wa * s.da_dmu + wb * s.db_dmu, wa * s.da_dr + wb * s.db_dr];
                let mut f = |x: &[f64]| {
                    let (a, b) = lut.lookup(x[0], x[1]);
                    wa * a + wb * b
                };
                assert_gradient("lut", &mut f, &x, &analytic, 1e-7, 1e-5, 1e-6);
            }
        }
        // Clamped outside the cell-centre range: zero derivative, finite values.
        let s = lut.lookup_with_grad(0.0, 1.0);
        assert_eq!((s.da_dmu, s.da_dr), (0.0, 0.0));
        assert!(s.a.is_finite() && s.b.is_finite());
    }
}

//! A convolution over a cube grid whose kernel depends only on the angle between two directions,
//! computed one orbit of the cube's symmetries at a time ([`super::symmetry`]).
//!
//! `out[o] = Σ_t k(d_o · d_t) · w_t · src[t]` over the texels with `d_o · d_t > cos_cut`. For
//! o = g·r, r its orbit's representative, `k(d_o · d_t) = k(d_r · d_{g⁻¹t})`, so
//! `out[g·r] = Σ_s k(d_r · d_s) · (w · src)[g·s]`: one stored row of weights (the representative's)
//! serves the up to 48 outputs of the orbit, and the source, laid out as `rows[s][g][rgb]` =
//! `(w · src)[g·s]`, is read with one weight for 48 × 3 contiguous values — a loop that vectorizes
//! fully, with no kernel evaluated per pair. The lobes of the prefilter's rough levels cover a
//! hemisphere; at D = 32 that is 19 million pairs a convolution, 3,100 per row here.
//!
//! Each output's sum runs over its representative's texels in ascending index order, whatever the
//! number of threads; it differs from the texel-by-texel sum in the last bits only (the weight
//! times the source is rounded before the sum, and the order differs), except that a pair whose
//! cosine equals the cut to rounding may fall on the other side of it.
//!
//! Threading: the source layout is filled in parallel over source texels, the rows are summed in
//! parallel over groups of [`ORBITS_PER_TASK`] orbits (rayon); the scatter to the outputs is serial
//! (one copy per output).

use rayon::prelude::*;

use super::grid::CubeGrid;
use super::symmetry::{CubeSymmetry, NUM_SYMMETRIES};

use crate::core::filled::filled;

/// Values of one source texel in the orbit layout: RGB for each of the 48 symmetries.
const ROW: usize = NUM_SYMMETRIES * 3;

/// Orbits summed together by one rayon task: their accumulators (1.1 KiB each) stay in L1.
const ORBITS_PER_TASK: usize = 8;

/// Source rows the task's orbits walk together (74 KiB: in L2) before the next ones.
const SOURCE_ROWS_PER_PASS: usize = 64;

/// A rotation-invariant kernel on one grid, stored one row per orbit (compressed rows).
#[derive(Clone, Debug)]
pub struct OrbitKernel {
    symmetry: CubeSymmetry,
    /// The source texels some row reads, ascending (the rest get no weight from any
    /// representative).
    support: Vec<u32>,
    /// Row r (orbit r) holds the entries `offsets[r]..offsets[r + 1]`.
    offsets: Vec<usize>,
    /// Per entry: the index into `support` of its source texel, ascending within a row.
    columns: Vec<u32>,
    /// Per entry: the kernel's weight k(d_r · d_s).
    weights: Vec<f64>,
}

impl OrbitKernel {
    /// The rows of kernel `k` on `grid`: a representative's entries are the texels with
    /// `d_r · d_t > cos_cut`.
    pub fn new(grid: &CubeGrid, k: impl Fn(f64) -> f64 + Sync, cos_cut: f64) -> Self {
        let symmetry = CubeSymmetry::new(grid.size);
        let rows: Vec<Vec<(u32, f64)>> = symmetry
            .representatives
            .par_iter()
            .map(|&r| {
                let n = grid.dirs[r as usize];
                grid.dirs
                    .iter()
                    .enumerate()
                    .filter_map(|(t, d)| {
                        let c = n.dot(*d);
                        (c > cos_cut).then(|| (t as u32, k(c)))
                    })
                    .collect()
            })
            .collect();
        let mut used = vec![false; grid.num_texels()];
        rows.iter()
            .flatten()
            .for_each(|&(t, _)| used[t as usize] = true);
        let support: Vec<u32> = (0..grid.num_texels() as u32)
            .filter(|&t| used[t as usize])
            .collect();
        let mut column_of = vec![0u32; grid.num_texels()];
        for (s, &t) in support.iter().enumerate() {
            column_of[t as usize] = s as u32;
        }
        let mut offsets = Vec::with_capacity(rows.len() + 1);
        offsets.push(0);
        let mut columns = Vec::new();
        let mut weights = Vec::new();
        for row in &rows {
            for &(t, w) in row {
                columns.push(column_of[t as usize]);
                weights.push(w);
            }
            offsets.push(columns.len());
        }
        OrbitKernel {
            symmetry,
            support,
            offsets,
            columns,
            weights,
        }
    }

    /// Number of (representative, texel) pairs stored: a 48th (or so) of the kernel's pairs.
    pub fn num_entries(&self) -> usize {
        self.weights.len()
    }

    /// `out[o] = Σ_t k(d_o · d_t) · w_t · src[t]` (RGB, `src[t · 3 + c]`), `w` = `weight` or 1.
    pub fn apply(&self, src: &[f64], weight: Option<&[f64]>) -> Vec<f64> {
        let sym = &self.symmetry;
        let mut rows = filled(self.support.len() * ROW, 0.0);
        rows.par_chunks_mut(ROW)
            .zip(&self.support)
            .for_each(|(row, &s)| {
                for (g, rgb) in row.chunks_exact_mut(3).enumerate() {
                    let t = sym.image(g, s as usize);
                    let w = weight.map_or(1.0, |w| w[t]);
                    for (c, v) in rgb.iter_mut().enumerate() {
                        *v = w * src[t * 3 + c];
                    }
                }
            });
        let avx2 = crate::core::simd::avx2_available();
        let orbits: Vec<usize> = (0..self.offsets.len() - 1).collect();
        let sums: Vec<[f64; ROW]> = orbits
            .par_chunks(ORBITS_PER_TASK)
            .flat_map_iter(|orbits| {
                #[cfg(target_arch = "x86_64")]
                if avx2 {
                    // SAFETY: `avx2_available()` returned true, so this CPU runs every
                    // instruction the function is compiled with.
                    return unsafe { self.row_sums_avx2(&rows, orbits) };
                }
                let _ = avx2; // (read only on x86-64)
                self.row_sums(&rows, orbits)
            })
            .collect();
        let mut out = Vec::with_capacity(sym.owner.len() * 3);
        for &(r, g) in &sym.owner {
            let g = g as usize * 3;
            out.extend_from_slice(&sums[r as usize][g..g + 3]);
        }
        out
    }
}

impl OrbitKernel {
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn row_sums_avx2(&self, rows: &[f64], orbits: &[usize]) -> Vec<[f64; ROW]> {
        self.row_sums(rows, orbits)
    }

    /// Σ weight · rows[column] over each of `orbits`' entries, 48 × RGB at once. The orbits walk
    /// the source rows together, [`SOURCE_ROWS_PER_PASS`] at a time, so each source row is read
    /// from memory once for them all; each sum still runs over its own entries in ascending order.
    /// Plain multiplies and adds (no fused operations), so the AVX2 copy computes the same bits.
    #[inline(always)]
    fn row_sums(&self, rows: &[f64], orbits: &[usize]) -> Vec<[f64; ROW]> {
        let mut sums = vec![[0.0; ROW]; orbits.len()];
        let mut next: Vec<usize> = orbits.iter().map(|&r| self.offsets[r]).collect();
        for pass_end in (SOURCE_ROWS_PER_PASS..)
            .step_by(SOURCE_ROWS_PER_PASS)
            .take(self.support.len().div_ceil(SOURCE_ROWS_PER_PASS))
        {
            for ((acc, k), &r) in sums.iter_mut().zip(&mut next).zip(orbits) {
                let end = self.offsets[r + 1];
                while *k < end && (self.columns[*k] as usize) < pass_end {
                    let (s, w) = (self.columns[*k] as usize, self.weights[*k]);
                    let row: &[f64; ROW] = rows[s * ROW..][..ROW]
                        .try_into()
                        .expect("a source row holds ROW values");
                    for (a, &v) in acc.iter_mut().zip(row) {
                        *a += w * v;
                    }
                    *k += 1;
                }
            }
        }
        sums
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The definition, one output and one texel at a time.
    fn direct(
        grid: &CubeGrid,
        k: impl Fn(f64) -> f64,
        cos_cut: f64,
        src: &[f64],
        weight: Option<&[f64]>,
    ) -> Vec<f64> {
        let mut out = vec![0.0; grid.num_texels() * 3];
        for (o, out) in out.chunks_exact_mut(3).enumerate() {
            for (t, d) in grid.dirs.iter().enumerate() {
                let c = grid.dirs[o].dot(*d);
                if c > cos_cut {
                    let w = k(c) * weight.map_or(1.0, |w| w[t]);
                    for (ch, v) in out.iter_mut().enumerate() {
                        *v += w * src[t * 3 + ch];
                    }
                }
            }
        }
        out
    }

    #[test]
    fn orbit_rows_equal_the_direct_sum() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let lobe = |c: f64| {
            let cos2h = 0.5 * (1.0 + c);
            let denom = cos2h * (0.3 - 1.0) + 1.0;
            0.3 / (denom * denom) * c
        };
        // Odd and even sizes, a narrow cut (sparse rows, a small support) and none (hemispheres).
        // The cuts are no round numbers: a pair of texel centres exactly at a round cosine (0.9
        // at D = 8) lies on either side of it by the order of its dot product's rounding.
        for (size, cos_cut) in [(3, 0.2113), (4, 0.0), (8, 0.9137), (8, -1.0)] {
            let grid = CubeGrid::new(size);
            let kernel = OrbitKernel::new(&grid, lobe, cos_cut);
            let src: Vec<f64> = (0..grid.num_texels() * 3)
                .map(|_| rng.random_range(-1.0..2.0))
                .collect();
            for weight in [None, Some(&grid.solid_angle[..])] {
                let fast = kernel.apply(&src, weight);
                let slow = direct(&grid, lobe, cos_cut, &src, weight);
                for (o, (a, b)) in fast.iter().zip(&slow).enumerate() {
                    assert!(
                        (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                        "size {size}, cut {cos_cut}, value {o}: {a} vs {b}"
                    );
                }
            }
            // One row per orbit: an orbit has at most 48 texels, and at an even size at least 24.
            let pairs = (0..grid.num_texels())
                .map(|o| {
                    grid.dirs
                        .iter()
                        .filter(|d| grid.dirs[o].dot(**d) > cos_cut)
                        .count()
                })
                .sum::<usize>();
            assert!(kernel.num_entries() * NUM_SYMMETRIES >= pairs);
            if size % 2 == 0 {
                assert!(kernel.num_entries() * 24 <= pairs, "size {size}");
            }
        }
    }
}

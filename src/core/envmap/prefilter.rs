//! Prefiltering of the environment light (METHOD.md §4) as a linear operator with its transpose.
//!
//! From the *activated* base radiance: a box-downsampled pyramid down to `min_size`; level l of the
//! specular mip chain is pyramid level l convolved with a truncated, normalized GGX lobe
//! (`D(h) · cos`, with N = V = R as nvdiffrec's `specular_cubemap`; GGX α = r², r the Disney
//! roughness of that level); the diffuse irradiance map `E_d(n) = (1/π) Σ E(ω) max(n·ω, 0) ΔΩ` is
//! computed from the lowest pyramid level (optionally weighted by the Fresnel transmission of the
//! incoming light, for a few IoRs). Every kernel depends only on the angle between two
//! directions, so a convolution stores one row of weights per orbit of the cube's 48 symmetries
//! ([`super::orbit_kernel`]), built with the normalizers once per plan; the 8×8 texel blocks'
//! culling thresholds are kept for the gpu prefilter, which walks the grid instead. Threading:
//! every convolution and its transpose is parallel over orbits with rayon; lookups are read-only
//! and thread-safe; gradients of lookups are added into per-thread [`EnvGrad`] accumulators that
//! callers reduce with [`EnvGrad::add`].

use std::sync::Arc;

use glam::DVec3;
use rayon::prelude::*;

use super::grid::{add_rgb, rgb, CubeGrid, CubePoint};
use super::orbit_kernel::OrbitKernel;
use super::{activate, activate_derivative, CubeMap, EnvMapError};

/// Elements per rayon task of [`EnvGrad::add`].
const ADD_MIN_LEN: usize = 4096;

/// Shape and roughness schedule of the specular mip chain.
#[derive(Clone, Debug, PartialEq)]
pub struct MipChainSpec {
    /// Face size D of the base cube map (level 0 of the chain).
    pub base_size: usize,
    /// Face size of the last (coarsest) level; `base_size = min_size · 2^k`, k ≥ 1.
    pub min_size: usize,
    /// Roughness of level 0.
    pub min_roughness: f64,
    /// Roughness of the second-to-last level (the last one is filtered for roughness 1).
    pub max_roughness: f64,
    /// Fraction of the GGX lobe's energy kept by the truncated convolution.
    pub cutoff: f64,
    /// Weight the irradiance integral by the Fresnel transmission 1 − F(n·ω; η) of the incoming
    /// light (METHOD.md §4, known gap (2)); irradiance then depends on the IoR.
    pub fresnel_irradiance: bool,
    /// Roughness levels per resolution (all but the coarsest, which holds the r = 1 level only;
    /// see [`Self::level_sizes`] for where the base size's extra levels go). 1 is METHOD.md's
    /// chain; more levels sample the roughness axis more finely (the linear blend between a sharp
    /// and a blurry level over-brightens highlights of intermediate roughness).
    pub levels_per_size: usize,
}

impl Default for MipChainSpec {
    fn default() -> Self {
        MipChainSpec {
            base_size: 64,
            min_size: 16,
            min_roughness: 0.08,
            max_roughness: 0.5,
            cutoff: 0.99,
            fresnel_irradiance: false,
            levels_per_size: 1,
        }
    }
}

/// IoR nodes of the Fresnel-weighted irradiance maps (the surfel IoR range is (1.3, 2.3)).
pub const FRESNEL_IRRADIANCE_IORS: [f64; 5] = [1.3, 1.55, 1.8, 2.05, 2.3];

impl MipChainSpec {
    /// Checks the sizes and the roughness schedule.
    pub fn validate(&self) -> Result<(), EnvMapError> {
        let bad = |m: String| Err(EnvMapError::MipChain(m));
        if self.min_size == 0 || self.base_size <= self.min_size {
            return bad(format!(
                "base_size {} must exceed min_size {} ≥ 1 (at least two levels)",
                self.base_size, self.min_size
            ));
        }
        let mut s = self.base_size;
        while s > self.min_size && (s / 2) * 2 == s {
            s /= 2;
        }
        if s != self.min_size {
            return bad(format!(
                "base_size {} is not min_size {} times a power of two",
                self.base_size, self.min_size
            ));
        }
        if !(0.0 < self.min_roughness
            && self.min_roughness < self.max_roughness
            && self.max_roughness < 1.0)
        {
            return bad(format!(
                "need 0 < min_roughness ({}) < max_roughness ({}) < 1",
                self.min_roughness, self.max_roughness
            ));
        }
        if self.levels_per_size == 0 || self.levels_per_size > 8 {
            return bad(format!(
                "levels_per_size {} outside 1..=8",
                self.levels_per_size
            ));
        }
        if !(0.5..1.0).contains(&self.cutoff) {
            return bad(format!("cutoff {} outside [0.5, 1)", self.cutoff));
        }
        Ok(())
    }

    /// Face size of every level, finest first: `levels_per_size` levels for each size above the
    /// coarsest, which holds the r = 1 level alone. When half the base size is above the
    /// coarsest, the base keeps only the sharpest of its levels and filters the others at half
    /// its size: their lobes span several base texels, so half the size resolves them, at a
    /// sixteenth of the texel pairs (D = 64, two levels per size: a rebuild of 74–79 ms against
    /// 200–217 ms with both at 64², and the same agreement with Mitsuba; docs/design/experiments.md, *A finer
    /// roughness chain*).
    pub fn level_sizes(&self) -> Vec<usize> {
        let per_size = self.levels_per_size.max(1);
        let half = self.base_size / 2;
        let move_down = half > self.min_size;
        let mut sizes = Vec::new();
        let mut size = self.base_size;
        while size > self.min_size && size >= 2 {
            let count = if !move_down {
                per_size
            } else if size == self.base_size {
                1
            } else if size == half {
                2 * per_size - 1
            } else {
                per_size
            };
            sizes.extend(std::iter::repeat_n(size, count));
            size /= 2;
        }
        sizes.push(size);
        sizes
    }

    /// Disney roughness each level is prefiltered for: linear from `min_roughness` at level 0 to
    /// `max_roughness` at the second-to-last level, 1 at the last.
    pub fn level_roughness(&self) -> Vec<f64> {
        let n = self.level_sizes().len();
        (0..n)
            .map(|l| {
                if l + 1 == n {
                    1.0
                } else if n == 2 {
                    self.min_roughness
                } else {
                    self.min_roughness
                        + (self.max_roughness - self.min_roughness) * l as f64 / (n - 2) as f64
                }
            })
            .collect()
    }

    /// Continuous mip level for a roughness (the inverse of [`Self::level_roughness`], clamped) and
    /// its derivative with respect to the roughness.
    pub fn level_of(&self, roughness: f64, num_levels: usize) -> (f64, f64) {
        let second_last = (num_levels - 2) as f64;
        if roughness < self.max_roughness {
            if roughness <= self.min_roughness {
                return (0.0, 0.0);
            }
            let scale = second_last / (self.max_roughness - self.min_roughness);
            ((roughness - self.min_roughness) * scale, scale)
        } else {
            if roughness >= 1.0 {
                return (second_last + 1.0, 0.0);
            }
            let scale = 1.0 / (1.0 - self.max_roughness);
            (
                (roughness - self.max_roughness) * scale + second_last,
                scale,
            )
        }
    }
}

/// A convolution kernel of the prefilter, as a function of c = cos(angle between directions).
/// The kernel of one convolution of a plan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kernel {
    /// GGX lobe with N = V = R: D(h) · c with cos²θ_h = (1 + c)/2 (the 1/π of D cancels in the
    /// normalization).
    Ggx { alpha2: f64 },
    /// Lambert irradiance: c / π.
    Cosine,
    /// Lambert irradiance through a smooth dielectric interface: c (1 − F(c; η)) / π.
    FresnelCosine { ior: f64 },
}

impl Kernel {
    /// The kernel's weight at cos(angle) = `c`.
    #[inline]
    pub fn eval(self, c: f64) -> f64 {
        match self {
            Kernel::Ggx { alpha2 } => ggx_lobe(alpha2, c),
            Kernel::Cosine => cosine_lobe(c),
            Kernel::FresnelCosine { ior } => fresnel_cosine_lobe(ior, c),
        }
    }
}

/// [`Kernel::Ggx`] at cos(angle) = `c`.
#[inline(always)]
fn ggx_lobe(alpha2: f64, c: f64) -> f64 {
    let cos2h = 0.5 * (1.0 + c);
    let denom = cos2h * (alpha2 - 1.0) + 1.0;
    alpha2 / (denom * denom) * c
}

/// [`Kernel::Cosine`] at cos(angle) = `c`.
#[inline(always)]
fn cosine_lobe(c: f64) -> f64 {
    c * std::f64::consts::FRAC_1_PI
}

/// [`Kernel::FresnelCosine`] at cos(angle) = `c`.
#[inline(always)]
fn fresnel_cosine_lobe(ior: f64, c: f64) -> f64 {
    c * (1.0 - fresnel_unpolarized(c, ior)) * std::f64::consts::FRAC_1_PI
}

/// Unpolarized Fresnel reflectance (R⊥ + R∥)/2 of light arriving from air at cos θ = `c` on a
/// dielectric of index `ior` > 1.
pub fn fresnel_unpolarized(c: f64, ior: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let ct = (1.0 - (1.0 - c * c) / (ior * ior)).max(0.0).sqrt();
    let rs = (c - ior * ct) / (c + ior * ct);
    let rp = (ct - ior * c) / (ct + ior * c);
    0.5 * (rs * rs + rp * rp)
}

/// One convolution of a plan: kernel, angular cutoff, its weights one row per orbit, per-block
/// culling thresholds (for the gpu's walk of the grid) and (for lobes) per-output normalizers.
#[derive(Clone, Debug)]
struct Convolution {
    kernel: Kernel,
    /// Texels with cos(angle) ≤ `cos_cut` get no weight.
    cos_cut: f64,
    /// A block can contribute to output direction n only if n · centre ≥ threshold.
    thresholds: Vec<f64>,
    /// Σ_i k(n_o · ω_i) ΔΩ_i per output texel; `None` for the (unnormalized) irradiance.
    normalizer: Option<Vec<f64>>,
    /// The kernel's weights, one row per orbit of the cube's symmetries.
    orbits: OrbitKernel,
}

impl Convolution {
    fn new(grid: &CubeGrid, kernel: Kernel, cos_cut: f64, normalized: bool) -> Self {
        let gamma = cos_cut.clamp(-1.0, 1.0).acos();
        let thresholds = grid
            .blocks
            .iter()
            .map(|b| (gamma + b.radius).min(std::f64::consts::PI).cos())
            .collect();
        let mut conv = Convolution {
            kernel,
            cos_cut,
            thresholds,
            normalizer: None,
            orbits: OrbitKernel::new(grid, |c| kernel.eval(c), cos_cut),
        };
        if normalized {
            let ones = vec![1.0; grid.num_texels() * 3];
            let sums = conv.apply(&ones, Some(&grid.solid_angle));
            conv.normalizer = Some(sums.iter().step_by(3).copied().collect());
        }
        conv
    }

    /// out[o] = Σ_i k(dir_o · dir_i) · weight_i · src[i] over the texels of one grid, RGB, for the
    /// texels with dir_o · dir_i > `cos_cut` ([`OrbitKernel::apply`]).
    fn apply(&self, src: &[f64], weight: Option<&[f64]>) -> Vec<f64> {
        self.orbits.apply(src, weight)
    }

    /// The operator: `src` radiance → filtered radiance.
    fn forward(&self, grid: &CubeGrid, src: &[f64]) -> Vec<f64> {
        let mut out = self.apply(src, Some(&grid.solid_angle));
        if let Some(z) = &self.normalizer {
            for (o, v) in out.chunks_mut(3).enumerate() {
                v.iter_mut().for_each(|x| *x /= z[o]);
            }
        }
        out
    }

    /// The transpose: gradient w.r.t. the output → gradient w.r.t. `src` (the kernel is symmetric).
    fn transpose(&self, grid: &CubeGrid, grad_out: &[f64]) -> Vec<f64> {
        let scaled: Vec<f64>;
        let g = match &self.normalizer {
            Some(z) => {
                scaled = grad_out
                    .iter()
                    .enumerate()
                    .map(|(k, g)| g / z[k / 3])
                    .collect();
                &scaled
            }
            None => grad_out,
        };
        let mut out = self.apply(g, None);
        for (t, v) in out.chunks_mut(3).enumerate() {
            v.iter_mut().for_each(|x| *x *= grid.solid_angle[t]);
        }
        out
    }
}

/// One convolution of a plan as another implementation of it needs it (the gpu prefilter):
/// `out[o] = Σ_i k(n_o · d_i) ΔΩ_i src[i] / Z_o` over the texels with `n_o · d_i > cos_cut`, the
/// 8×8 blocks of the grid culled where `n_o · centre < thresholds[block]`; no `Z` for irradiance.
#[derive(Clone, Copy, Debug)]
pub struct ConvolutionTable<'a> {
    pub kernel: Kernel,
    pub cos_cut: f64,
    /// Per block of the grid ([`CubeGrid::blocks`]).
    pub thresholds: &'a [f64],
    /// Per texel of the grid.
    pub normalizer: Option<&'a [f64]>,
}

impl Convolution {
    fn table(&self) -> ConvolutionTable<'_> {
        ConvolutionTable {
            kernel: self.kernel,
            cos_cut: self.cos_cut,
            thresholds: &self.thresholds,
            normalizer: self.normalizer.as_deref(),
        }
    }
}

/// cos of the angle between N and the reflected direction below which a GGX lobe of `alpha2` holds
/// less than `1 − cutoff` of its energy (θ_ω = 2 θ_h, cos²θ_h from the GGX sampling CDF).
fn ggx_cos_cut(alpha2: f64, cutoff: f64) -> f64 {
    let cos2h = (1.0 - cutoff) / (1.0 + (alpha2 - 1.0) * cutoff);
    (2.0 * cos2h - 1.0).max(0.0)
}

/// Everything about prefiltering that depends only on the chain's shape: texel geometry per level,
/// kernels, culling thresholds and normalizers. Build once, share with `Arc`.
#[derive(Debug)]
pub struct PrefilterPlan {
    pub spec: MipChainSpec,
    /// Texel geometry of every level, finest first.
    pub grids: Vec<CubeGrid>,
    /// Roughness each level is filtered for.
    pub roughness: Vec<f64>,
    specular: Vec<Convolution>,
    irradiance: Vec<Convolution>,
    /// IoR of each irradiance map (empty: one plain map).
    pub irradiance_iors: Vec<f64>,
}

impl PrefilterPlan {
    /// Precomputes the plan for a chain.
    pub fn new(spec: MipChainSpec) -> Result<Arc<Self>, EnvMapError> {
        let _span = tracing::info_span!("prefilter_plan", base = spec.base_size).entered();
        spec.validate()?;
        let grids: Vec<CubeGrid> = spec.level_sizes().into_iter().map(CubeGrid::new).collect();
        let roughness = spec.level_roughness();
        let specular = grids
            .iter()
            .zip(&roughness)
            .map(|(grid, &r)| {
                let alpha2 = r.powi(4);
                Convolution::new(
                    grid,
                    Kernel::Ggx { alpha2 },
                    ggx_cos_cut(alpha2, spec.cutoff),
                    true,
                )
            })
            .collect();
        let last = &grids[grids.len() - 1];
        let (irradiance, irradiance_iors) = if spec.fresnel_irradiance {
            let iors = FRESNEL_IRRADIANCE_IORS.to_vec();
            let convs = iors
                .iter()
                .map(|&ior| Convolution::new(last, Kernel::FresnelCosine { ior }, 0.0, false))
                .collect();
            (convs, iors)
        } else {
            (
                vec![Convolution::new(last, Kernel::Cosine, 0.0, false)],
                vec![],
            )
        };
        Ok(Arc::new(PrefilterPlan {
            spec,
            grids,
            roughness,
            specular,
            irradiance,
            irradiance_iors,
        }))
    }

    /// The lobe convolution of mip level `level` (on `grids[level]`).
    pub fn specular_convolution(&self, level: usize) -> ConvolutionTable<'_> {
        self.specular[level].table()
    }

    /// The convolution of irradiance map `map` (on [`Self::irradiance_grid`]).
    pub fn irradiance_convolution(&self, map: usize) -> ConvolutionTable<'_> {
        self.irradiance[map].table()
    }

    /// Number of irradiance maps.
    pub fn num_irradiance_maps(&self) -> usize {
        self.irradiance.len()
    }

    /// Number of mip levels.
    pub fn num_levels(&self) -> usize {
        self.grids.len()
    }

    /// Texel geometry of the irradiance map(s): the coarsest level.
    pub fn irradiance_grid(&self) -> &CubeGrid {
        &self.grids[self.grids.len() - 1]
    }

    /// Interpolation of the irradiance maps at an IoR: (map a, map b, weight of b, d weight/d ior).
    pub fn irradiance_blend(&self, ior: f64) -> (usize, usize, f64, f64) {
        let iors = &self.irradiance_iors;
        if iors.len() < 2 {
            return (0, 0, 0.0, 0.0);
        }
        let k = iors
            .windows(2)
            .position(|w| ior < w[1])
            .unwrap_or(iors.len() - 2);
        let span = iors[k + 1] - iors[k];
        let t = (ior - iors[k]) / span;
        if t <= 0.0 {
            (k, k + 1, 0.0, 0.0)
        } else if t >= 1.0 {
            (k, k + 1, 1.0, 0.0)
        } else {
            (k, k + 1, t, 1.0 / span)
        }
    }
}

/// Gradient accumulators shaped like a [`PreparedEnv`]: one RGB buffer per mip level and per
/// irradiance map.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvGrad {
    pub levels: Vec<Vec<f64>>,
    pub irradiance: Vec<Vec<f64>>,
}

impl EnvGrad {
    /// Zero accumulators for a plan.
    pub fn zeros(plan: &PrefilterPlan) -> Self {
        EnvGrad {
            levels: plan
                .grids
                .iter()
                .map(|g| vec![0.0; g.num_texels() * 3])
                .collect(),
            irradiance: plan
                .irradiance
                .iter()
                .map(|_| vec![0.0; plan.irradiance_grid().num_texels() * 3])
                .collect(),
        }
    }

    /// Adds another accumulator of the same shape (the reduction of per-thread accumulators),
    /// element by element in parallel: each sum is the same whatever the thread count.
    pub fn add(&mut self, other: &EnvGrad) {
        let pairs = self
            .levels
            .iter_mut()
            .zip(&other.levels)
            .chain(self.irradiance.iter_mut().zip(&other.irradiance));
        for (a, b) in pairs {
            a.par_iter_mut()
                .zip(b)
                .with_min_len(ADD_MIN_LEN)
                .for_each(|(x, y)| *x += y);
        }
    }
}

/// The environment light prepared for shading: specular mip chain and irradiance map(s) of the
/// activated radiance of a [`CubeMap`]. Rebuild whenever the map changes.
#[derive(Clone, Debug)]
pub struct PreparedEnv {
    plan: Arc<PrefilterPlan>,
    /// Prefiltered radiance per level, RGB interleaved.
    pub levels: Vec<Vec<f64>>,
    /// Irradiance map(s) at the coarsest resolution.
    pub irradiance: Vec<Vec<f64>>,
    /// f′(raw) of the base texels, for the backward pass.
    activation_grad: Vec<f64>,
}

fn downsample(src: &[f64], size: usize) -> Vec<f64> {
    let half = size / 2;
    let mut out = vec![0.0; super::NUM_FACES * half * half * 3];
    out.par_chunks_mut(half * 3)
        .enumerate()
        .for_each(|(row, out)| {
            let (face, y) = (row / half, row % half);
            for x in 0..half {
                for (dy, dx) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                    let t = (face * size + 2 * y + dy) * size + 2 * x + dx;
                    for c in 0..3 {
                        out[x * 3 + c] += 0.25 * src[t * 3 + c];
                    }
                }
            }
        });
    out
}

/// Transpose of [`downsample`]: each fine texel receives a quarter of its parent's gradient.
fn downsample_transpose(grad_coarse: &[f64], size: usize, grad_fine: &mut [f64]) {
    let half = size / 2;
    grad_fine
        .par_chunks_mut(size * 3)
        .enumerate()
        .for_each(|(row, fine)| {
            let (face, y) = (row / size, row % size);
            for x in 0..size {
                let parent = (face * half + y / 2) * half + x / 2;
                for c in 0..3 {
                    fine[x * 3 + c] += 0.25 * grad_coarse[parent * 3 + c];
                }
            }
        });
}

/// The activated radiance of a cube map and its box-downsampled copies, one per level of the plan.
fn radiance_pyramid(cube: &CubeMap, plan: &PrefilterPlan) -> Vec<Vec<f64>> {
    let mut pyramid = vec![cube
        .raw
        .par_iter()
        .map(|&x| activate(x))
        .collect::<Vec<_>>()];
    for pair in plan.grids.windows(2) {
        let previous = &pyramid[pyramid.len() - 1];
        let next = if pair[1].size == pair[0].size {
            previous.clone()
        } else {
            downsample(previous, pair[0].size)
        };
        pyramid.push(next);
    }
    pyramid
}

impl PreparedEnv {
    /// Prefilters a cube map with a plan whose base size equals the map's face size.
    pub fn new(cube: &CubeMap, plan: Arc<PrefilterPlan>) -> Result<Self, EnvMapError> {
        let _span = tracing::info_span!("prefilter_env", size = cube.size).entered();
        if cube.size != plan.spec.base_size {
            return Err(EnvMapError::PlanMismatch {
                expected: plan.spec.base_size,
                found: cube.size,
            });
        }
        let pyramid = radiance_pyramid(cube, &plan);
        let levels = plan
            .specular
            .iter()
            .zip(&plan.grids)
            .zip(&pyramid)
            .map(|((conv, grid), src)| conv.forward(grid, src))
            .collect();
        let coarsest = &pyramid[pyramid.len() - 1];
        let irradiance = plan
            .irradiance
            .iter()
            .map(|conv| conv.forward(plan.irradiance_grid(), coarsest))
            .collect();
        let activation_grad = cube
            .raw
            .par_iter()
            .map(|&x| activate_derivative(x))
            .collect();
        Ok(PreparedEnv {
            plan,
            levels,
            irradiance,
            activation_grad,
        })
    }

    /// Prefilters many cube maps with one plan (GridMap's local probes): [`Self::new`] on each,
    /// after checking every map's size. Each prefilter is parallel within; one map's orbit layout
    /// (7 MiB at D = 32) is as much as stays in cache, so the maps go one after another.
    pub fn new_batch(
        cubes: &[CubeMap],
        plan: Arc<PrefilterPlan>,
    ) -> Result<Vec<Self>, EnvMapError> {
        let _span = tracing::info_span!("prefilter_env_batch", maps = cubes.len()).entered();
        if let Some(cube) = cubes.iter().find(|c| c.size != plan.spec.base_size) {
            return Err(EnvMapError::PlanMismatch {
                expected: plan.spec.base_size,
                found: cube.size,
            });
        }
        cubes
            .iter()
            .map(|cube| Self::new(cube, plan.clone()))
            .collect()
    }

    /// The plan this light was prepared with.
    pub fn plan(&self) -> &Arc<PrefilterPlan> {
        &self.plan
    }

    /// Zero gradient accumulators shaped like this light.
    pub fn zero_grad(&self) -> EnvGrad {
        EnvGrad::zeros(&self.plan)
    }

    /// Level pair and blend weight for a roughness: (l0, weight of l0 + 1, d weight / d r).
    pub fn level_blend(&self, roughness: f64) -> (usize, f64, f64) {
        let n = self.plan.num_levels();
        let (level, dlevel) = self.plan.spec.level_of(roughness, n);
        let l0 = (level.floor() as usize).min(n - 2);
        (l0, level - l0 as f64, dlevel)
    }

    /// Prefiltered radiance along `dir` (non-zero, need not be unit) for a Disney roughness:
    /// bilinear within the two nearest levels, linear between them.
    pub fn specular(&self, dir: DVec3, roughness: f64) -> DVec3 {
        let (l0, t, _) = self.level_blend(roughness);
        let point = CubePoint::of(dir);
        let sample = |level: usize| self.plan.grids[level].sample_at(&self.levels[level], &point);
        sample(l0) * (1.0 - t) + sample(l0 + 1) * t
    }

    /// Backward of [`Self::specular`]: adds dL/d(level texels) into `grad` and returns
    /// (dL/d dir, dL/d roughness) for the upstream gradient `grad_out` = dL/d radiance.
    pub fn specular_backward(
        &self,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        self.specular_backward_into(dir, roughness, grad_out, Some(grad))
    }

    /// (dL/d dir, dL/d roughness) of [`Self::specular`] alone, for a light that is not learned
    /// (GridMap's local probes): no texel gradient is accumulated.
    pub fn specular_input_grad(&self, dir: DVec3, roughness: f64, grad_out: DVec3) -> (DVec3, f64) {
        self.specular_backward_into(dir, roughness, grad_out, None)
    }

    fn specular_backward_into(
        &self,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        mut grad: Option<&mut EnvGrad>,
    ) -> (DVec3, f64) {
        let (l0, t, dt) = self.level_blend(roughness);
        let point = CubePoint::of(dir);
        let mut grad_dir = DVec3::ZERO;
        let mut values = [0.0; 2];
        for (k, (level, scale)) in [(l0, 1.0 - t), (l0 + 1, t)].into_iter().enumerate() {
            let (taps, dw) = self.plan.grids[level].taps_at(&point);
            for (&(texel, w), dw) in taps.iter().zip(dw) {
                let v = rgb(&self.levels[level], texel).dot(grad_out);
                values[k] += w * v;
                grad_dir += dw * (v * scale);
                if let Some(grad) = grad.as_deref_mut() {
                    add_rgb(&mut grad.levels[level], texel, grad_out * (w * scale));
                }
            }
        }
        (grad_dir, (values[1] - values[0]) * dt)
    }

    /// Diffuse irradiance E_d(n) (bilinear in the coarsest-level map; with Fresnel-weighted maps,
    /// linear in the IoR between the nodes of [`FRESNEL_IRRADIANCE_IORS`]).
    pub fn irradiance(&self, normal: DVec3, ior: f64) -> DVec3 {
        let grid = self.plan.irradiance_grid();
        let (a, b, t, _) = self.plan.irradiance_blend(ior);
        if t == 0.0 {
            return grid.sample(&self.irradiance[a], normal);
        }
        grid.sample(&self.irradiance[a], normal) * (1.0 - t)
            + grid.sample(&self.irradiance[b], normal) * t
    }

    /// Backward of [`Self::irradiance`]: adds into `grad`, returns (dL/d normal, dL/d ior).
    pub fn irradiance_backward(
        &self,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        self.irradiance_backward_into(normal, ior, grad_out, Some(grad))
    }

    /// (dL/d normal, dL/d ior) of [`Self::irradiance`] alone (no texel gradient accumulated).
    pub fn irradiance_input_grad(&self, normal: DVec3, ior: f64, grad_out: DVec3) -> (DVec3, f64) {
        self.irradiance_backward_into(normal, ior, grad_out, None)
    }

    fn irradiance_backward_into(
        &self,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        mut grad: Option<&mut EnvGrad>,
    ) -> (DVec3, f64) {
        let grid = self.plan.irradiance_grid();
        let (a, b, t, dt) = self.plan.irradiance_blend(ior);
        let (taps, dw) = grid.taps_with_grad(normal);
        let mut grad_n = DVec3::ZERO;
        let mut values = [0.0; 2];
        let maps: &[(usize, f64)] = if a == b {
            &[(a, 1.0)]
        } else {
            &[(a, 1.0 - t), (b, t)]
        };
        for (k, &(map, scale)) in maps.iter().enumerate() {
            for (&(texel, w), dw) in taps.iter().zip(dw) {
                let v = rgb(&self.irradiance[map], texel).dot(grad_out);
                values[k] += w * v;
                grad_n += dw * (v * scale);
                if let Some(grad) = grad.as_deref_mut() {
                    add_rgb(&mut grad.irradiance[map], texel, grad_out * (w * scale));
                }
            }
        }
        (grad_n, (values[1] - values[0]) * dt)
    }

    /// Gradient with respect to the raw (unconstrained) base texels of the cube map, through the
    /// irradiance convolution, the lobe convolutions, the box pyramid and the activation.
    pub fn backward(&self, grad: &EnvGrad) -> Vec<f64> {
        let _span = tracing::info_span!("prefilter_env_backward").entered();
        let plan = &self.plan;
        let n = plan.num_levels();
        let mut pyramid_grad: Vec<Vec<f64>> = plan
            .specular
            .iter()
            .zip(&plan.grids)
            .zip(&grad.levels)
            .map(|((conv, grid), g)| conv.transpose(grid, g))
            .collect();
        for (conv, g) in plan.irradiance.iter().zip(&grad.irradiance) {
            let back = conv.transpose(plan.irradiance_grid(), g);
            pyramid_grad[n - 1]
                .iter_mut()
                .zip(back)
                .for_each(|(a, b)| *a += b);
        }
        for l in (1..n).rev() {
            let (finer, coarser) = pyramid_grad.split_at_mut(l);
            if plan.grids[l].size == plan.grids[l - 1].size {
                finer[l - 1]
                    .iter_mut()
                    .zip(&coarser[0])
                    .for_each(|(a, b)| *a += b);
            } else {
                downsample_transpose(&coarser[0], plan.grids[l - 1].size, &mut finer[l - 1]);
            }
        }
        pyramid_grad[0]
            .iter()
            .zip(&self.activation_grad)
            .map(|(g, d)| g * d)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::gradcheck::assert_gradient;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn tiny_spec(fresnel: bool) -> MipChainSpec {
        MipChainSpec {
            base_size: 8,
            min_size: 2,
            min_roughness: 0.08,
            max_roughness: 0.5,
            cutoff: 0.99,
            fresnel_irradiance: fresnel,
            levels_per_size: if fresnel { 2 } else { 1 },
        }
    }

    fn random_cube(rng: &mut ChaCha8Rng, size: usize) -> CubeMap {
        let raw = (0..CubeMap::num_values(size))
            .map(|_| rng.random_range(-2.0..1.5))
            .collect();
        CubeMap::from_raw(size, raw).unwrap()
    }

    fn random_dir(rng: &mut ChaCha8Rng) -> DVec3 {
        DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
        .normalize()
    }

    /// Timing report (no timed assertion): `cargo test --release default_chain_timing -- --ignored --nocapture`.
    #[test]
    #[ignore = "timing report"]
    fn default_chain_timing() {
        let start = std::time::Instant::now();
        let plan = PrefilterPlan::new(MipChainSpec::default()).unwrap();
        let plan_time = start.elapsed().as_secs_f64();
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        let cube = random_cube(&mut rng, 64);
        let start = std::time::Instant::now();
        let env = PreparedEnv::new(&cube, plan).unwrap();
        let build = start.elapsed().as_secs_f64();
        let mut grad = env.zero_grad();
        grad.levels
            .iter_mut()
            .chain(grad.irradiance.iter_mut())
            .flatten()
            .for_each(|g| *g = 1.0);
        let start = std::time::Instant::now();
        let back = env.backward(&grad);
        let backward = start.elapsed().as_secs_f64();
        println!(
            "D = 64 chain on {} threads: plan {:.1} ms, rebuild {:.1} ms, backward {:.1} ms",
            rayon::current_num_threads(),
            plan_time * 1e3,
            build * 1e3,
            backward * 1e3
        );
        assert_eq!(back.len(), CubeMap::num_values(64));
    }

    #[test]
    fn schedule_matches_the_method() {
        let spec = MipChainSpec::default();
        assert_eq!(spec.level_sizes(), vec![64, 32, 16]);
        assert_eq!(spec.level_roughness(), vec![0.08, 0.5, 1.0]);
        let spec = MipChainSpec {
            base_size: 128,
            ..spec
        };
        let r = spec.level_roughness();
        assert_eq!(r.len(), 4);
        assert!((r[1] - 0.29).abs() < 1e-12 && r[2] == 0.5 && r[3] == 1.0);
        for (l, &rough) in r.iter().enumerate() {
            assert!((spec.level_of(rough, 4).0 - l as f64).abs() < 1e-12);
        }
        assert_eq!(spec.level_of(0.01, 4).0, 0.0);
        let two = MipChainSpec {
            levels_per_size: 2,
            ..MipChainSpec::default()
        };
        assert_eq!(two.level_sizes(), vec![64, 32, 32, 32, 16]);
        assert!((two.level_roughness()[1] - 0.22).abs() < 1e-12);
        assert!(MipChainSpec {
            base_size: 48,
            ..MipChainSpec::default()
        }
        .validate()
        .is_err());
        assert!(MipChainSpec {
            base_size: 16,
            ..MipChainSpec::default()
        }
        .validate()
        .is_err());
    }

    #[test]
    fn a_constant_map_stays_constant_and_irradiance_is_its_radiance() {
        let plan = PrefilterPlan::new(MipChainSpec {
            base_size: 16,
            min_size: 4,
            ..MipChainSpec::default()
        })
        .unwrap();
        let cube = CubeMap::constant(16, DVec3::new(0.3, 1.0, 2.5)).unwrap();
        let env = PreparedEnv::new(&cube, plan).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        for _ in 0..20 {
            let d = random_dir(&mut rng);
            let r: f64 = rng.random();
            assert!(env
                .specular(d, r)
                .abs_diff_eq(DVec3::new(0.3, 1.0, 2.5), 1e-9));
            // Σ cos ΔΩ over the hemisphere is π up to the texel discretization.
            let e = env.irradiance(d, 1.5);
            assert!(
                (e / DVec3::new(0.3, 1.0, 2.5) - DVec3::ONE)
                    .abs()
                    .max_element()
                    < 0.01,
                "{e}"
            );
        }
    }

    #[test]
    fn rougher_levels_spread_a_point_light() {
        let size = 32;
        let grid = CubeGrid::new(size);
        let light = DVec3::new(0.3, 0.4, 1.0).normalize();
        let radiance: Vec<f64> = grid
            .dirs
            .iter()
            .flat_map(|d| [if d.dot(light) > 0.999 { 50.0 } else { 0.01 }; 3])
            .collect();
        let cube = CubeMap::from_radiance(size, &radiance).unwrap();
        let env = PreparedEnv::new(
            &cube,
            PrefilterPlan::new(MipChainSpec {
                base_size: size,
                min_size: 8,
                ..MipChainSpec::default()
            })
            .unwrap(),
        )
        .unwrap();
        let off = DVec3::new(0.3, 0.4, 1.0).normalize() + DVec3::new(0.25, 0.0, 0.0);
        let peak: Vec<f64> = [0.08, 0.3, 0.5, 1.0]
            .iter()
            .map(|&r| env.specular(light, r).x)
            .collect();
        let side: Vec<f64> = [0.08, 0.3, 0.5, 1.0]
            .iter()
            .map(|&r| env.specular(off, r).x)
            .collect();
        assert!(
            peak.windows(2).all(|w| w[0] > w[1]),
            "peak falls with roughness: {peak:?}"
        );
        assert!(
            side[2] > side[0],
            "the lobe widens with roughness: {side:?}"
        );
        // The irradiance is brightest facing the light.
        assert!(env.irradiance(light, 1.5).x > 4.0 * env.irradiance(-light, 1.5).x);
    }

    /// The whole chain (activation → pyramid → lobe and irradiance convolutions → trilinear lookups)
    /// against finite differences in the raw base texels.
    #[test]
    fn env_gradient_matches_finite_differences() {
        for (seed, fresnel) in [(1u64, false), (2, false), (3, true)] {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let plan = PrefilterPlan::new(tiny_spec(fresnel)).unwrap();
            let cube = random_cube(&mut rng, 8);
            let queries: Vec<(DVec3, f64, f64, DVec3, DVec3)> = (0..6)
                .map(|_| {
                    (
                        random_dir(&mut rng),
                        rng.random_range(0.0..1.0),
                        rng.random_range(1.3..2.3),
                        DVec3::new(rng.random(), rng.random(), rng.random()),
                        DVec3::new(rng.random(), rng.random(), rng.random()),
                    )
                })
                .collect();
            let loss = |env: &PreparedEnv| -> f64 {
                queries
                    .iter()
                    .map(|(d, r, ior, gs, gd)| {
                        env.specular(*d, *r).dot(*gs) + env.irradiance(-*d, *ior).dot(*gd)
                    })
                    .sum()
            };
            let env = PreparedEnv::new(&cube, plan.clone()).unwrap();
            let mut grad = env.zero_grad();
            for (d, r, ior, gs, gd) in &queries {
                env.specular_backward(*d, *r, *gs, &mut grad);
                env.irradiance_backward(-*d, *ior, *gd, &mut grad);
            }
            let analytic = env.backward(&grad);
            let mut f = |x: &[f64]| {
                let cube = CubeMap::from_raw(8, x.to_vec()).unwrap();
                loss(&PreparedEnv::new(&cube, plan.clone()).unwrap())
            };
            assert_gradient("env texels", &mut f, &cube.raw, &analytic, 1e-6, 1e-5, 1e-7);
        }
    }

    #[test]
    fn lookup_gradients_in_direction_roughness_and_ior_match_finite_differences() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let plan = PrefilterPlan::new(tiny_spec(true)).unwrap();
        let env = PreparedEnv::new(&random_cube(&mut rng, 8), plan).unwrap();
        for _ in 0..30 {
            let d = random_dir(&mut rng);
            let r = rng.random_range(0.1..0.99);
            let ior = rng.random_range(1.35..2.25);
            let g = DVec3::new(0.2, 1.0, -0.5);
            let mut scratch = env.zero_grad();
            let (gd, gr) = env.specular_backward(d, r, g, &mut scratch);
            let x = [d.x, d.y, d.z, r];
            let mut f = |x: &[f64]| env.specular(DVec3::new(x[0], x[1], x[2]), x[3]).dot(g);
            assert_gradient(
                "specular(dir, r)",
                &mut f,
                &x,
                &[gd.x, gd.y, gd.z, gr],
                1e-7,
                1e-5,
                1e-6,
            );
            let (gn, gi) = env.irradiance_backward(d, ior, g, &mut scratch);
            let x = [d.x, d.y, d.z, ior];
            let mut f = |x: &[f64]| env.irradiance(DVec3::new(x[0], x[1], x[2]), x[3]).dot(g);
            assert_gradient(
                "irradiance(n, ior)",
                &mut f,
                &x,
                &[gn.x, gn.y, gn.z, gi],
                1e-7,
                1e-5,
                1e-6,
            );
        }
    }

    /// Every value of `a` within `tol` (relative, above 1) of `b`'s.
    fn assert_close(a: &[f64], b: &[f64], tol: f64, what: &str) {
        assert_eq!(a.len(), b.len(), "{what}");
        for (k, (x, y)) in a.iter().zip(b).enumerate() {
            assert!(
                (x - y).abs() <= tol * (1.0 + y.abs()),
                "{what}[{k}]: {x} vs {y}"
            );
        }
    }

    /// The convolution one output texel at a time, skipping culled blocks and texels beyond the
    /// cutoff, as the batch prefilter and the gpu's walk the grid.
    fn apply_one_at_a_time(
        conv: &Convolution,
        grid: &CubeGrid,
        src: &[f64],
        weight: Option<&[f64]>,
    ) -> Vec<f64> {
        let mut out = vec![0.0; grid.num_texels() * 3];
        for (o, out) in out.chunks_exact_mut(3).enumerate() {
            let n = grid.dirs[o];
            let mut acc = DVec3::ZERO;
            for (block, &threshold) in grid.blocks.iter().zip(&conv.thresholds) {
                if n.dot(block.center) < threshold {
                    continue;
                }
                for i in block.start..block.end {
                    let (t, d) = (grid.block_texels[i] as usize, grid.block_dirs[i]);
                    let c = n.dot(d);
                    if c > conv.cos_cut {
                        acc += conv.kernel.eval(c) * weight.map_or(1.0, |w| w[t]) * rgb(src, t);
                    }
                }
            }
            out.copy_from_slice(&acc.to_array());
        }
        out
    }

    #[test]
    fn orbit_apply_equals_the_block_culled_sum() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for fresnel in [false, true] {
            let plan = PrefilterPlan::new(tiny_spec(fresnel)).unwrap();
            let convs = plan.specular.iter().zip(&plan.grids);
            let irradiance = plan.irradiance.iter().map(|c| (c, plan.irradiance_grid()));
            // A 3×3 cube: texels on the symmetry planes, orbits of fewer than 24.
            let odd_grid = CubeGrid::new(3);
            let odd = Convolution::new(&odd_grid, Kernel::Ggx { alpha2: 0.3 }, 0.2, true);
            let ragged = std::iter::once((&odd, &odd_grid));
            for (conv, grid) in convs.chain(irradiance).chain(ragged) {
                let src: Vec<f64> = (0..grid.num_texels() * 3)
                    .map(|_| rng.random_range(-1.0..2.0))
                    .collect();
                for weight in [None, Some(&grid.solid_angle[..])] {
                    let orbits = conv.apply(&src, weight);
                    let culled = apply_one_at_a_time(conv, grid, &src, weight);
                    assert_close(&orbits, &culled, 1e-12, &format!("{:?}", conv.kernel));
                }
            }
        }
    }

    #[test]
    fn batch_refuses_a_map_of_another_size() {
        let plan = PrefilterPlan::new(tiny_spec(false)).unwrap();
        let wrong = CubeMap::constant(4, DVec3::ONE).unwrap();
        let right = CubeMap::constant(plan.spec.base_size, DVec3::ONE).unwrap();
        assert!(PreparedEnv::new_batch(&[right, wrong], plan).is_err());
    }

    /// Timing report (no timed assertion): `cargo test --release batch_of_56_timing -- --ignored --nocapture`.
    #[test]
    #[ignore = "timing report"]
    fn batch_of_56_timing() {
        let plan = PrefilterPlan::new(MipChainSpec::default()).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        let cubes: Vec<CubeMap> = (0..56).map(|_| random_cube(&mut rng, 64)).collect();
        let start = std::time::Instant::now();
        let batch = PreparedEnv::new_batch(&cubes, plan.clone()).unwrap();
        let batched = start.elapsed().as_secs_f64();
        let start = std::time::Instant::now();
        PreparedEnv::new(&cubes[0], plan).unwrap();
        let single = start.elapsed().as_secs_f64();
        println!(
            "56 D = 64 maps on {} threads: batched {:.0} ms ({:.1} ms per map), one alone {:.0} ms",
            rayon::current_num_threads(),
            batched * 1e3,
            batched * 1e3 / 56.0,
            single * 1e3
        );
        assert_eq!(batch.len(), 56);
    }

    #[test]
    fn input_gradients_equal_the_full_backward() {
        let mut rng = ChaCha8Rng::seed_from_u64(8);
        let plan = PrefilterPlan::new(tiny_spec(true)).unwrap();
        let env = PreparedEnv::new(&random_cube(&mut rng, 8), plan).unwrap();
        for _ in 0..10 {
            let d = random_dir(&mut rng);
            let (r, ior) = (rng.random_range(0.0..1.0), rng.random_range(1.3..2.3));
            let g = DVec3::new(rng.random(), rng.random(), rng.random());
            let mut scratch = env.zero_grad();
            assert_eq!(
                env.specular_input_grad(d, r, g),
                env.specular_backward(d, r, g, &mut scratch)
            );
            assert_eq!(
                env.irradiance_input_grad(d, ior, g),
                env.irradiance_backward(d, ior, g, &mut scratch)
            );
        }
    }

    #[test]
    fn fresnel_weighting_darkens_irradiance_more_for_higher_ior() {
        let plan = PrefilterPlan::new(tiny_spec(true)).unwrap();
        let env = PreparedEnv::new(&CubeMap::constant(8, DVec3::ONE).unwrap(), plan).unwrap();
        let low = env.irradiance(DVec3::Z, 1.3).x;
        let high = env.irradiance(DVec3::Z, 2.3).x;
        // Hemispherical average of 1 − F: about 0.93 at η = 1.3 and 0.82 at 2.3.
        assert!(low < 0.96 && low > 0.88, "{low}");
        assert!(high < low - 0.05, "{high} vs {low}");
        assert!((fresnel_unpolarized(1.0, 1.5) - 0.04).abs() < 1e-12);
    }
}

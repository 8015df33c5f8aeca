//! PolarDR: polarimetric deferred shading per pixel (METHOD.md §4), its hand-written backward
//! pass, the polarizer intensity, DoLP/AoLP helpers and image-level batch functions.
//!
//! Per pixel: split-sum specular `w_s · L_s` (w_s = F0·A + B from the [`BrdfLut`], L_s the
//! prefiltered light along the mirror direction 2μn − o), diffuse `(1 − F_schlick(μ)) · λ · E_d(n)`,
//! and Stokes factors from the Fresnel reflection (ρ_s = R⁻/R⁺) and exit transmission
//! (ρ_d = T⁻/T⁺) ratios, oriented by the azimuth φ = atan2(n·ŷ, n·x̂) of the normal in the pixel's
//! Stokes frame: `S = spec·[1, −ρ_s cos2φ, −ρ_s sin2φ] + diff·[1, −ρ_d cos2φ, −ρ_d sin2φ]`.
//! Signs are pinned down against the Mitsuba data by `tests/physics_check.rs`.
//!
//! Threading: [`shade_image`] and [`shade_image_backward`] are parallel over image rows with rayon;
//! the backward pass accumulates the light's gradient in one [`EnvGrad`] per block of rows and reduces
//! them at the end.

pub mod check;

use glam::DVec3;
use rayon::prelude::*;
use thiserror::Error;

use crate::core::brdf_lut::{BrdfLut, LutSample};
use crate::core::camera::Camera;
use crate::core::envmap::EnvGrad;
use crate::core::filled::filled;
use crate::core::light::{LightProbe, SavedLookup};

pub use check::{physics_check, GroundTruthView, ShadingCheck};

/// μ = n·o is clamped below at this value (grazing and back-facing pixels), so nothing divides by 0.
pub const MIN_COS_VIEW: f64 = 1e-4;

/// Errors of the image-level functions; each names the buffer at fault.
#[derive(Debug, Error)]
pub enum ShadingError {
    #[error("shading buffer `{name}` has {found} entries, expected {expected} (one per pixel)")]
    BufferLength {
        name: &'static str,
        expected: usize,
        found: usize,
    },
    #[error("ground-truth image `{name}` is {width}×{height}×{channels}, expected {expected_width}×{expected_height} with {expected_channels} channel(s)")]
    ImageShape {
        name: &'static str,
        width: usize,
        height: usize,
        channels: usize,
        expected_width: usize,
        expected_height: usize,
        expected_channels: usize,
    },
    /// The gpu backend could not shade (device error, or a buffer beyond the device's limits).
    #[error("gpu shading: {0}")]
    Gpu(String),
}

/// Everything the shader needs at one pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelInput {
    /// Surface point (used by position-dependent light such as GridMap; ignored by the global map).
    pub position: DVec3,
    /// Raw G-buffer normal: need not be unit; normalized inside and flipped to face the viewer.
    pub normal: DVec3,
    /// Unit direction from the surface toward the camera.
    pub view: DVec3,
    /// Stokes reference axes x̂, ŷ of the pixel ([`Camera::stokes_frame`]).
    pub stokes_x: DVec3,
    pub stokes_y: DVec3,
    /// Linear RGB diffuse albedo λ.
    pub albedo: DVec3,
    /// Disney roughness r (GGX α = r²).
    pub roughness: f64,
    /// Index of refraction η (> 1).
    pub ior: f64,
}

/// Shaded Stokes vector (S3 = 0) per colour channel, plus the unpolarized parts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelStokes {
    pub s0: DVec3,
    pub s1: DVec3,
    pub s2: DVec3,
    pub diffuse: DVec3,
    pub specular: DVec3,
}

/// Upstream gradient dL/dS of one pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelStokesGrad {
    pub s0: DVec3,
    pub s1: DVec3,
    pub s2: DVec3,
}

/// Gradient of the loss with respect to the differentiable inputs of one pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelInputGrad {
    /// With respect to the raw (unnormalized) G-buffer normal.
    pub normal: DVec3,
    pub albedo: DVec3,
    pub roughness: f64,
    pub ior: f64,
}

/// A value with its partial derivatives with respect to μ and η (forward-mode, for the Fresnel
/// ratios).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Dual {
    v: f64,
    dmu: f64,
    deta: f64,
}

impl Dual {
    fn constant(v: f64) -> Self {
        Dual {
            v,
            dmu: 0.0,
            deta: 0.0,
        }
    }
    fn sqrt(self) -> Self {
        let v = self.v.sqrt();
        let k = 0.5 / v;
        Dual {
            v,
            dmu: self.dmu * k,
            deta: self.deta * k,
        }
    }
    fn square(self) -> Self {
        self * self
    }
}

impl std::ops::Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        Dual {
            v: self.v + o.v,
            dmu: self.dmu + o.dmu,
            deta: self.deta + o.deta,
        }
    }
}
impl std::ops::Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual {
            v: self.v - o.v,
            dmu: self.dmu - o.dmu,
            deta: self.deta - o.deta,
        }
    }
}
impl std::ops::Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        Dual {
            v: self.v * o.v,
            dmu: self.dmu * o.v + self.v * o.dmu,
            deta: self.deta * o.v + self.v * o.deta,
        }
    }
}
impl std::ops::Div for Dual {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        let inv = 1.0 / o.v;
        let v = self.v * inv;
        Dual {
            v,
            dmu: (self.dmu - v * o.dmu) * inv,
            deta: (self.deta - v * o.deta) * inv,
        }
    }
}

/// (R⁻ − ... ) ratio helper: (x − y)/(x + y), zero when both vanish.
fn contrast(x: Dual, y: Dual) -> Dual {
    let sum = x + y;
    if sum.v.abs() < 1e-300 {
        return Dual::constant(0.0);
    }
    (x - y) / sum
}

/// Fresnel polarization ratios at cos θ = μ and index η: (ρ_s = R⁻/R⁺, ρ_d = T⁻/T⁺), each with its
/// derivatives in μ and η. The common factor (2η cosθ_t)² of T⊥ and T∥ cancels in ρ_d.
fn polarization_ratios(mu: f64, eta: f64) -> (Dual, Dual) {
    let m = Dual {
        v: mu,
        dmu: 1.0,
        deta: 0.0,
    };
    let e = Dual {
        v: eta,
        dmu: 0.0,
        deta: 1.0,
    };
    let one = Dual::constant(1.0);
    let sin2_t = (one - m * m) / (e * e);
    let cos_t = if one.v - sin2_t.v > 1e-300 {
        (one - sin2_t).sqrt()
    } else {
        Dual::constant(1e-150)
    };
    let r_perp = ((m - e * cos_t) / (m + e * cos_t)).square();
    let r_par = ((cos_t - e * m) / (cos_t + e * m)).square();
    // T⊥ ∝ 1/(η cosθ_t + cosθ)², T∥ ∝ 1/(η cosθ + cosθ_t)²  ⇒  ρ_d = (b² − a²)/(b² + a²).
    let a2 = (e * cos_t + m).square();
    let b2 = (e * m + cos_t).square();
    (contrast(r_perp, r_par), contrast(b2, a2))
}

/// Schlick's normal-incidence reflectance F0 = ((η − 1)/(η + 1))² and dF0/dη.
fn f0_of_ior(eta: f64) -> (f64, f64) {
    let k = (eta - 1.0) / (eta + 1.0);
    (k * k, 2.0 * k * 2.0 / ((eta + 1.0) * (eta + 1.0)))
}

/// cos 2φ, sin 2φ of the normal's azimuth in the Stokes frame from a = n·x̂, b = n·ŷ, with
/// their gradients [d/da, d/db].
fn double_azimuth(a: f64, b: f64) -> (f64, f64, [f64; 2], [f64; 2]) {
    let q = a * a + b * b;
    if q < 1e-24 {
        return (0.0, 0.0, [0.0; 2], [0.0; 2]);
    }
    let q2 = q * q;
    let cos2 = (a * a - b * b) / q;
    let sin2 = 2.0 * a * b / q;
    let dcos = [4.0 * a * b * b / q2, -4.0 * a * a * b / q2];
    let dsin = [
        2.0 * b * (b * b - a * a) / q2,
        2.0 * a * (a * a - b * b) / q2,
    ];
    (cos2, sin2, dcos, dsin)
}

/// Forward intermediates kept for the backward pass.
struct Forward {
    out: PixelStokes,
    unit_normal: DVec3,
    normal_length: f64,
    flip: f64,
    n: DVec3,
    mu: f64,
    mu_clamped: bool,
    lut: LutSample,
    f0: f64,
    df0: f64,
    w_s: f64,
    mirror: DVec3,
    radiance: DVec3,
    saved_radiance: SavedLookup,
    fresnel: f64,
    dfresnel_dmu: f64,
    dfresnel_df0: f64,
    irradiance: DVec3,
    saved_irradiance: SavedLookup,
    rho_s: Dual,
    rho_d: Dual,
    cos2: f64,
    sin2: f64,
    dcos2: [f64; 2],
    dsin2: [f64; 2],
}

fn forward(input: &PixelInput, light: &dyn LightProbe, lut: &BrdfLut) -> Forward {
    // A vanishing normal (an empty G-buffer pixel) shades as if it faced the viewer, with zero
    // normal gradient.
    let raw_length = input.normal.length();
    let degenerate = !(raw_length > 1e-150 && raw_length.is_finite());
    let (unit_normal, normal_length) = if degenerate {
        (input.view, f64::INFINITY)
    } else {
        (input.normal / raw_length, raw_length)
    };
    let flip = if unit_normal.dot(input.view) < 0.0 {
        -1.0
    } else {
        1.0
    };
    let n = unit_normal * flip;
    let raw_mu = n.dot(input.view);
    let mu_clamped = raw_mu < MIN_COS_VIEW;
    let mu = raw_mu.max(MIN_COS_VIEW);
    let eta = input.ior;

    let (f0, df0) = f0_of_ior(eta);
    let lut_sample = lut.lookup_with_grad(mu, input.roughness);
    let w_s = f0 * lut_sample.a + lut_sample.b;
    let mirror = 2.0 * mu * n - input.view;
    let (radiance, saved_radiance) = light.specular_saved(input.position, mirror, input.roughness);
    let specular = w_s * radiance;

    let one_minus_mu = 1.0 - mu;
    let pow5 = one_minus_mu.powi(5);
    let fresnel = f0 + (1.0 - f0) * pow5;
    let dfresnel_dmu = -5.0 * (1.0 - f0) * one_minus_mu.powi(4);
    let dfresnel_df0 = 1.0 - pow5;
    let (irradiance, saved_irradiance) = light.irradiance_saved(input.position, n, eta);
    let diffuse = (1.0 - fresnel) * input.albedo * irradiance;

    let (rho_s, rho_d) = polarization_ratios(mu, eta);
    let (cos2, sin2, dcos2, dsin2) = double_azimuth(n.dot(input.stokes_x), n.dot(input.stokes_y));
    let polarized = specular * rho_s.v + diffuse * rho_d.v;
    let out = PixelStokes {
        s0: specular + diffuse,
        s1: -polarized * cos2,
        s2: -polarized * sin2,
        diffuse,
        specular,
    };
    Forward {
        out,
        unit_normal,
        normal_length,
        flip,
        n,
        mu,
        mu_clamped,
        lut: lut_sample,
        f0,
        df0,
        w_s,
        mirror,
        radiance,
        saved_radiance,
        fresnel,
        dfresnel_dmu,
        dfresnel_df0,
        irradiance,
        saved_irradiance,
        rho_s,
        rho_d,
        cos2,
        sin2,
        dcos2,
        dsin2,
    }
}

/// Shades one pixel: Stokes S0–S2 per colour channel and the diffuse/specular parts.
pub fn shade(input: &PixelInput, light: &dyn LightProbe, lut: &BrdfLut) -> PixelStokes {
    forward(input, light, lut).out
}

/// Backward of [`shade`]: returns dL/d(raw normal, albedo, roughness, ior) and adds dL/d(light)
/// into `env_grad`. The view direction and the Stokes frame are constants.
pub fn shade_backward(
    input: &PixelInput,
    light: &dyn LightProbe,
    lut: &BrdfLut,
    upstream: &PixelStokesGrad,
    env_grad: &mut EnvGrad,
) -> PixelInputGrad {
    backward_from(
        &forward(input, light, lut),
        input,
        light,
        upstream,
        env_grad,
    )
}

/// [`shade_backward`] from the pixel's forward intermediates.
fn backward_from(
    f: &Forward,
    input: &PixelInput,
    light: &dyn LightProbe,
    upstream: &PixelStokesGrad,
    env_grad: &mut EnvGrad,
) -> PixelInputGrad {
    let (spec, diff) = (f.out.specular, f.out.diffuse);

    // Stokes assembly.
    let projected = upstream.s1 * f.cos2 + upstream.s2 * f.sin2;
    let g_spec = upstream.s0 - projected * f.rho_s.v;
    let g_diff = upstream.s0 - projected * f.rho_d.v;
    let g_rho_s = -spec.dot(projected);
    let g_rho_d = -diff.dot(projected);
    let polarized = spec * f.rho_s.v + diff * f.rho_d.v;
    let g_cos2 = -polarized.dot(upstream.s1);
    let g_sin2 = -polarized.dot(upstream.s2);
    let g_a = g_cos2 * f.dcos2[0] + g_sin2 * f.dsin2[0];
    let g_b = g_cos2 * f.dcos2[1] + g_sin2 * f.dsin2[1];
    let mut g_n = g_a * input.stokes_x + g_b * input.stokes_y;
    let mut g_mu = g_rho_s * f.rho_s.dmu + g_rho_d * f.rho_d.dmu;
    let mut g_eta = g_rho_s * f.rho_s.deta + g_rho_d * f.rho_d.deta;

    // Diffuse = (1 − F) λ E_d(n).
    let g_albedo = g_diff * (1.0 - f.fresnel) * f.irradiance;
    let g_irradiance = g_diff * (1.0 - f.fresnel) * input.albedo;
    let g_fresnel = -g_diff.dot(input.albedo * f.irradiance);
    let (g_n_irr, g_eta_irr) = light.irradiance_backward_saved(
        &f.saved_irradiance,
        input.position,
        f.n,
        input.ior,
        g_irradiance,
        env_grad,
    );
    g_n += g_n_irr;
    g_eta += g_eta_irr;
    g_mu += g_fresnel * f.dfresnel_dmu;
    let mut g_f0 = g_fresnel * f.dfresnel_df0;

    // Specular = (F0 A + B) L_s(2μn − o, r).
    let g_ws = g_spec.dot(f.radiance);
    let (g_mirror, mut g_roughness) = light.specular_backward_saved(
        &f.saved_radiance,
        input.position,
        f.mirror,
        input.roughness,
        g_spec * f.w_s,
        env_grad,
    );
    g_f0 += g_ws * f.lut.a;
    let (g_a_lut, g_b_lut) = (g_ws * f.f0, g_ws);
    g_mu += g_a_lut * f.lut.da_dmu + g_b_lut * f.lut.db_dmu;
    g_roughness += g_a_lut * f.lut.da_dr + g_b_lut * f.lut.db_dr;
    g_n += 2.0 * f.mu * g_mirror;
    g_mu += 2.0 * f.n.dot(g_mirror);

    if !f.mu_clamped {
        g_n += g_mu * input.view;
    }
    g_eta += g_f0 * f.df0;

    // n = flip · raw / |raw|.
    let g_unit = g_n * f.flip;
    let g_raw = (g_unit - f.unit_normal * f.unit_normal.dot(g_unit)) / f.normal_length;
    PixelInputGrad {
        normal: g_raw,
        albedo: g_albedo,
        roughness: g_roughness,
        ior: g_eta,
    }
}

/// Intensity behind an ideal linear polarizer at angle θ (radians, in the Stokes frame):
/// `I(θ) = ½ (S0 + S1 cos 2θ + S2 sin 2θ)` per channel.
pub fn polarizer_intensity(s: &PixelStokes, theta: f64) -> DVec3 {
    let (sin2, cos2) = (2.0 * theta).sin_cos();
    0.5 * (s.s0 + s.s1 * cos2 + s.s2 * sin2)
}

/// Backward of [`polarizer_intensity`]: (dL/dS, dL/dθ) for the upstream dL/dI.
pub fn polarizer_intensity_backward(
    s: &PixelStokes,
    theta: f64,
    grad_out: DVec3,
) -> (PixelStokesGrad, f64) {
    let (sin2, cos2) = (2.0 * theta).sin_cos();
    let grad = PixelStokesGrad {
        s0: 0.5 * grad_out,
        s1: 0.5 * cos2 * grad_out,
        s2: 0.5 * sin2 * grad_out,
    };
    let d_theta = grad_out.dot(-s.s1 * sin2 + s.s2 * cos2);
    (grad, d_theta)
}

/// Degree of linear polarization √(S1² + S2²)/S0 (0 where S0 ≤ 0).
pub fn dolp(s0: f64, s1: f64, s2: f64) -> f64 {
    if s0 <= 0.0 {
        return 0.0;
    }
    (s1 * s1 + s2 * s2).sqrt() / s0
}

/// Angle of linear polarization ½ atan2(S2, S1), radians in (−π/2, π/2], counted from x̂ toward ŷ.
pub fn aolp(s1: f64, s2: f64) -> f64 {
    0.5 * s2.atan2(s1)
}

/// Difference of two AoLPs modulo π, in [0, π/2].
pub fn aolp_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::PI);
    d.min(std::f64::consts::PI - d)
}

/// Per-pixel G-buffers of one view (row-major, `width × height` entries each).
#[derive(Clone, Copy, Debug)]
pub struct ShadingBuffers<'a> {
    /// Raw composited normals (need not be unit).
    pub normal: &'a [DVec3],
    pub albedo: &'a [DVec3],
    pub roughness: &'a [f64],
    pub ior: &'a [f64],
    /// Surface points (for position-dependent light); `None` passes the origin.
    pub position: Option<&'a [DVec3]>,
    /// Pixels to shade; `None` shades every pixel. Unshaded pixels are zero.
    pub active: Option<&'a [bool]>,
}

impl ShadingBuffers<'_> {
    /// Fails naming the first buffer that does not hold one entry per pixel.
    pub(crate) fn check(&self, pixels: usize) -> Result<(), ShadingError> {
        let lengths = [
            ("normal", self.normal.len()),
            ("albedo", self.albedo.len()),
            ("roughness", self.roughness.len()),
            ("ior", self.ior.len()),
            ("position", self.position.map_or(pixels, <[_]>::len)),
            ("active", self.active.map_or(pixels, <[_]>::len)),
        ];
        for (name, found) in lengths {
            if found != pixels {
                return Err(ShadingError::BufferLength {
                    name,
                    expected: pixels,
                    found,
                });
            }
        }
        Ok(())
    }

    pub(crate) fn is_active(&self, p: usize) -> bool {
        self.active.is_none_or(|a| a[p])
    }

    /// The shader input of pixel `p` seen by `camera`.
    pub fn pixel_input(&self, camera: &Camera, p: usize) -> PixelInput {
        let (x, y) = (
            (p % camera.width as usize) as u32,
            (p / camera.width as usize) as u32,
        );
        let d = camera.pixel_dir(x, y);
        let (stokes_x, stokes_y) = camera.stokes_frame(d);
        PixelInput {
            position: self.position.map_or(DVec3::ZERO, |q| q[p]),
            normal: self.normal[p],
            view: -d,
            stokes_x,
            stokes_y,
            albedo: self.albedo[p],
            roughness: self.roughness[p],
            ior: self.ior[p],
        }
    }
}

/// Shaded images of one view (row-major RGB per pixel).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StokesImage {
    pub width: usize,
    pub height: usize,
    pub s0: Vec<DVec3>,
    pub s1: Vec<DVec3>,
    pub s2: Vec<DVec3>,
    pub diffuse: Vec<DVec3>,
    pub specular: Vec<DVec3>,
}

impl StokesImage {
    /// The `width × height` image whose pixel `p` is `pixel(p)` (zero where it is `None`), its
    /// five planes written in one pass, parallel over rows.
    fn from_pixels<'a>(
        width: usize,
        height: usize,
        pixel: impl Fn(usize) -> Option<&'a PixelStokes> + Sync,
    ) -> StokesImage {
        let plane = || -> Vec<DVec3> {
            (0..width * height)
                .into_par_iter()
                .map(|_| DVec3::ZERO)
                .collect()
        };
        let mut image = StokesImage {
            width,
            height,
            s0: plane(),
            s1: plane(),
            s2: plane(),
            diffuse: plane(),
            specular: plane(),
        };
        let row = width.max(1);
        (
            image.s0.par_chunks_mut(row),
            image.s1.par_chunks_mut(row),
            image.s2.par_chunks_mut(row),
            image.diffuse.par_chunks_mut(row),
            image.specular.par_chunks_mut(row),
        )
            .into_par_iter()
            .enumerate()
            .for_each(|(y, (s0, s1, s2, diffuse, specular))| {
                for x in 0..s0.len() {
                    if let Some(o) = pixel(y * row + x) {
                        s0[x] = o.s0;
                        s1[x] = o.s1;
                        s2[x] = o.s2;
                        diffuse[x] = o.diffuse;
                        specular[x] = o.specular;
                    }
                }
            });
        image
    }

    /// Multiplies every radiance (Stokes, diffuse, specular) by `scale`.
    pub fn scale_radiance(&mut self, scale: f64) {
        if scale == 1.0 {
            return;
        }
        for image in [
            &mut self.s0,
            &mut self.s1,
            &mut self.s2,
            &mut self.diffuse,
            &mut self.specular,
        ] {
            image.iter_mut().for_each(|v| *v *= scale);
        }
    }
}

/// Upstream gradients of one view's Stokes images.
#[derive(Clone, Copy, Debug)]
pub struct StokesImageGrad<'a> {
    pub s0: &'a [DVec3],
    pub s1: &'a [DVec3],
    pub s2: &'a [DVec3],
}

impl StokesImageGrad<'_> {
    /// Fails naming the first image that does not hold one entry per pixel.
    pub(crate) fn check(&self, pixels: usize) -> Result<(), ShadingError> {
        for (name, found) in [
            ("grad s0", self.s0.len()),
            ("grad s1", self.s1.len()),
            ("grad s2", self.s2.len()),
        ] {
            if found != pixels {
                return Err(ShadingError::BufferLength {
                    name,
                    expected: pixels,
                    found,
                });
            }
        }
        Ok(())
    }
}

/// Gradients with respect to one view's G-buffers.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GBufferGrad {
    pub normal: Vec<DVec3>,
    pub albedo: Vec<DVec3>,
    pub roughness: Vec<f64>,
    pub ior: Vec<f64>,
}

/// Row blocks of [`shade_image_backward`], each with its own light-gradient accumulator.
const ENV_GRAD_BLOCKS: usize = 8;

/// Shades every active pixel of a view (parallel over pixels).
pub fn shade_image(
    camera: &Camera,
    buffers: &ShadingBuffers,
    light: &dyn LightProbe,
    lut: &BrdfLut,
) -> Result<StokesImage, ShadingError> {
    let _span = tracing::info_span!("shade_image").entered();
    let pixels = camera.num_pixels();
    buffers.check(pixels)?;
    let shaded: Vec<PixelStokes> = (0..pixels)
        .into_par_iter()
        .with_min_len(256)
        .map(|p| {
            if buffers.is_active(p) {
                shade(&buffers.pixel_input(camera, p), light, lut)
            } else {
                PixelStokes::default()
            }
        })
        .collect();
    Ok(StokesImage::from_pixels(
        camera.width as usize,
        camera.height as usize,
        |p| shaded.get(p),
    ))
}

/// The forward intermediates of every active pixel of one view ([`shade_image_saved`]), so that
/// the backward pass ([`shade_image_backward_saved`]) does not shade again; its light lookups
/// keep their input Jacobians where the light allows ([`SavedLookup`]: GridMap's blended probes and
/// their occlusion test are not repeated), the others ask the light for its own gradient.
pub struct SavedShading {
    /// The active pixels' intermediates, in pixel order.
    forwards: Vec<Forward>,
    /// Per pixel, its index in `forwards` (`u32::MAX`: not active).
    slot: Vec<u32>,
}

impl SavedShading {
    fn get(&self, pixel: usize) -> Option<&Forward> {
        self.forwards.get(self.slot[pixel] as usize)
    }
}

/// [`shade_image`] that also keeps what its backward needs.
pub fn shade_image_saved(
    camera: &Camera,
    buffers: &ShadingBuffers,
    light: &dyn LightProbe,
    lut: &BrdfLut,
) -> Result<(StokesImage, SavedShading), ShadingError> {
    let _span = tracing::info_span!("shade_image").entered();
    let pixels = camera.num_pixels();
    buffers.check(pixels)?;
    let mut slot = vec![u32::MAX; pixels];
    let mut active = Vec::new();
    for (p, slot) in slot.iter_mut().enumerate() {
        if buffers.is_active(p) {
            *slot = active.len() as u32;
            active.push(p);
        }
    }
    let forwards: Vec<Forward> = active
        .par_iter()
        .with_min_len(256)
        .map(|&p| forward(&buffers.pixel_input(camera, p), light, lut))
        .collect();
    let saved = SavedShading { forwards, slot };
    let _planes = tracing::info_span!("stokes_planes").entered();
    let image = StokesImage::from_pixels(camera.width as usize, camera.height as usize, |p| {
        saved.get(p).map(|f| &f.out)
    });
    Ok((image, saved))
}

/// Backward of [`shade_image`]: per-pixel G-buffer gradients and the light's gradient (one
/// accumulator per block of rows, reduced in a fixed order, so the result is deterministic).
pub fn shade_image_backward(
    camera: &Camera,
    buffers: &ShadingBuffers,
    light: &dyn LightProbe,
    lut: &BrdfLut,
    upstream: &StokesImageGrad,
) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
    image_backward(camera, buffers, light, lut, None, upstream)
}

/// Backward of [`shade_image_saved`] from its intermediates; the same numbers as
/// [`shade_image_backward`], bit for bit.
pub fn shade_image_backward_saved(
    camera: &Camera,
    buffers: &ShadingBuffers,
    light: &dyn LightProbe,
    lut: &BrdfLut,
    saved: &SavedShading,
    upstream: &StokesImageGrad,
) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
    let pixels = camera.num_pixels();
    if saved.slot.len() != pixels {
        return Err(ShadingError::BufferLength {
            name: "saved shading",
            expected: pixels,
            found: saved.slot.len(),
        });
    }
    image_backward(camera, buffers, light, lut, Some(saved), upstream)
}

fn image_backward(
    camera: &Camera,
    buffers: &ShadingBuffers,
    light: &dyn LightProbe,
    lut: &BrdfLut,
    saved: Option<&SavedShading>,
    upstream: &StokesImageGrad,
) -> Result<(GBufferGrad, EnvGrad), ShadingError> {
    let _span = tracing::info_span!("shade_image_backward").entered();
    let pixels = camera.num_pixels();
    buffers.check(pixels)?;
    upstream.check(pixels)?;
    let width = camera.width as usize;
    let mut grads = filled(pixels, PixelInputGrad::default());
    // A fixed number of row blocks, each with its own light-gradient accumulator, summed in block
    // order: the result does not depend on rayon's scheduling (bit-exact, resumable training).
    let rows = camera.height as usize;
    let block_rows = rows.div_ceil(ENV_GRAD_BLOCKS).max(1);
    let block_grads: Vec<EnvGrad> = grads
        .par_chunks_mut((width * block_rows).max(1))
        .enumerate()
        .map(|(block, out)| {
            let mut env = light.zero_grad();
            for (i, g) in out.iter_mut().enumerate() {
                let p = block * width * block_rows + i;
                if !buffers.is_active(p) {
                    continue;
                }
                let up = PixelStokesGrad {
                    s0: upstream.s0[p],
                    s1: upstream.s1[p],
                    s2: upstream.s2[p],
                };
                let input = buffers.pixel_input(camera, p);
                *g = match saved.and_then(|s| s.get(p)) {
                    Some(f) => backward_from(f, &input, light, &up, &mut env),
                    None => shade_backward(&input, light, lut, &up, &mut env),
                };
            }
            env
        })
        .collect();
    let mut env_grad = light.zero_grad();
    for g in &block_grads {
        env_grad.add(g);
    }
    let out = GBufferGrad {
        normal: grads.par_iter().map(|g| g.normal).collect(),
        albedo: grads.par_iter().map(|g| g.albedo).collect(),
        roughness: grads.par_iter().map(|g| g.roughness).collect(),
        ior: grads.par_iter().map(|g| g.ior).collect(),
    };
    Ok((out, env_grad))
}

#[cfg(test)]
mod tests;

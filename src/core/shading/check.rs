//! Physics check of the shading model: ground-truth geometry, materials and light are fed straight
//! into [`shade`] and the result is compared with independently rendered Stokes images
//! (METHOD.md §4, "measured ceiling"). Metrics are computed inside the mask: S0 PSNR on linear
//! radiance with peak 1 (and with the peak at the GT maximum), S1/S2 relative L1 (Σ|Ŝ − S| / Σ|S| over pixels and channels), and, on the
//! channel-summed (grey) Stokes vector, the fraction of pixels with GT DoLP > 0.05 whose AoLP lies
//! within 10° of the GT (mod 180°) and the DoLP mean absolute error. Parallel over pixels (rayon).

use glam::DVec3;
use rayon::prelude::*;

use super::{aolp, aolp_difference, dolp, shade, PixelInput, ShadingError};
use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::light::LightProbe;
use crate::formats::image_io::Image;

/// GT DoLP above which a pixel's AoLP is compared.
pub const AOLP_MIN_DOLP: f64 = 0.05;
/// AoLP tolerance of the agreement figure, degrees.
pub const AOLP_TOLERANCE_DEG: f64 = 10.0;

/// One ground-truth view: camera, G-buffers (world normals, linear albedo, GGX α, IoR), mask and
/// Stokes images, all `camera.width × camera.height`.
#[derive(Clone, Copy, Debug)]
pub struct GroundTruthView<'a> {
    pub camera: &'a Camera,
    /// RGB world-frame unit normals.
    pub normal: &'a Image,
    /// RGB linear albedo.
    pub albedo: &'a Image,
    /// One channel: GGX α (the shader's roughness is r = √α).
    pub alpha_ggx: &'a Image,
    /// One channel: index of refraction.
    pub ior: &'a Image,
    /// Row-major object mask.
    pub mask: &'a [bool],
    /// RGB Stokes images.
    pub s0: &'a Image,
    pub s1: &'a Image,
    pub s2: &'a Image,
}

/// Agreement between the shading model and ground truth inside the mask.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct ShadingCheck {
    /// Masked pixels compared.
    pub pixels: usize,
    /// PSNR of S0 on linear radiance, peak 1, dB.
    pub s0_psnr: f64,
    /// PSNR of S0 with the peak at the largest GT S0 value inside the mask (highlights above 1
    /// count as the peak), dB.
    pub s0_psnr_peak_max: f64,
    /// Σ Ŝ0 / Σ S0 − 1.
    pub s0_bias: f64,
    pub s1_rel_l1: f64,
    pub s2_rel_l1: f64,
    /// Fraction of pixels with GT DoLP > 0.05 whose AoLP is within 10° (mod 180°).
    pub aolp_agreement: f64,
    /// Mean |DoLP̂ − DoLP| over the mask.
    pub dolp_mae: f64,
    /// The factors (specular, diffuse) by which the model's two parts best fit the captured
    /// Stokes vectors (least squares over S0, S1 and S2 of every masked pixel and channel): 1
    /// where a part is as bright as the renderer's, above 1 where the model's is too dim.
    pub part_scales: PartScales,
}

/// Least-squares factors of the specular and the diffuse Stokes parts against the captured ones.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct PartScales {
    pub specular: f64,
    pub diffuse: f64,
}

/// Sums of the 2×2 normal equations of `captured ≈ a·specular + b·diffuse`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct PartFit {
    ss: f64,
    sd: f64,
    dd: f64,
    sg: f64,
    dg: f64,
}

impl PartFit {
    fn of(specular: [DVec3; 3], diffuse: [DVec3; 3], captured: [DVec3; 3]) -> PartFit {
        let mut f = PartFit::default();
        for k in 0..3 {
            f.ss += specular[k].dot(specular[k]);
            f.sd += specular[k].dot(diffuse[k]);
            f.dd += diffuse[k].dot(diffuse[k]);
            f.sg += specular[k].dot(captured[k]);
            f.dg += diffuse[k].dot(captured[k]);
        }
        f
    }

    fn add(self, o: PartFit) -> PartFit {
        PartFit {
            ss: self.ss + o.ss,
            sd: self.sd + o.sd,
            dd: self.dd + o.dd,
            sg: self.sg + o.sg,
            dg: self.dg + o.dg,
        }
    }

    /// The solution of the normal equations (zeros where they are singular).
    fn solve(&self) -> PartScales {
        let det = self.ss * self.dd - self.sd * self.sd;
        if det.abs() <= 1e-12 * (self.ss * self.dd).max(1e-300) {
            return PartScales::default();
        }
        PartScales {
            specular: (self.sg * self.dd - self.dg * self.sd) / det,
            diffuse: (self.dg * self.ss - self.sg * self.sd) / det,
        }
    }
}

fn rgb(img: &Image, p: usize) -> DVec3 {
    let c = img.channels;
    if c >= 3 {
        DVec3::new(
            img.data[p * c] as f64,
            img.data[p * c + 1] as f64,
            img.data[p * c + 2] as f64,
        )
    } else {
        DVec3::splat(img.data[p * c] as f64)
    }
}

fn check_shape(
    name: &'static str,
    img: &Image,
    camera: &Camera,
    rgb: bool,
) -> Result<(), ShadingError> {
    let (w, h) = (camera.width as usize, camera.height as usize);
    let ok_channels = if rgb {
        img.channels >= 3
    } else {
        img.channels >= 1
    };
    if img.width != w || img.height != h || !ok_channels {
        return Err(ShadingError::ImageShape {
            name,
            width: img.width,
            height: img.height,
            channels: img.channels,
            expected_width: w,
            expected_height: h,
            expected_channels: if rgb { 3 } else { 1 },
        });
    }
    Ok(())
}

#[derive(Clone, Copy, Default)]
struct Sums {
    pixels: usize,
    sq_err: f64,
    s0_pred: f64,
    s0_gt: f64,
    s1_err: f64,
    s1_abs: f64,
    s2_err: f64,
    s2_abs: f64,
    polarized: usize,
    aolp_ok: usize,
    dolp_err: f64,
    gt_max: f64,
    parts: PartFit,
}

impl Sums {
    fn add(mut self, o: Sums) -> Sums {
        self.pixels += o.pixels;
        self.sq_err += o.sq_err;
        self.s0_pred += o.s0_pred;
        self.s0_gt += o.s0_gt;
        self.s1_err += o.s1_err;
        self.s1_abs += o.s1_abs;
        self.s2_err += o.s2_err;
        self.s2_abs += o.s2_abs;
        self.polarized += o.polarized;
        self.aolp_ok += o.aolp_ok;
        self.dolp_err += o.dolp_err;
        self.gt_max = self.gt_max.max(o.gt_max);
        self.parts = self.parts.add(o.parts);
        self
    }
}

/// Shades every masked pixel of a ground-truth view with `light` and compares with its Stokes images.
pub fn physics_check(
    view: &GroundTruthView,
    light: &dyn LightProbe,
    lut: &BrdfLut,
) -> Result<ShadingCheck, ShadingError> {
    let _span = tracing::info_span!("physics_check").entered();
    let camera = view.camera;
    for (name, img, is_rgb) in [
        ("normal", view.normal, true),
        ("albedo", view.albedo, true),
        ("roughness", view.alpha_ggx, false),
        ("ior", view.ior, false),
        ("s0", view.s0, true),
        ("s1", view.s1, true),
        ("s2", view.s2, true),
    ] {
        check_shape(name, img, camera, is_rgb)?;
    }
    let pixels = camera.num_pixels();
    if view.mask.len() != pixels {
        return Err(ShadingError::BufferLength {
            name: "mask",
            expected: pixels,
            found: view.mask.len(),
        });
    }
    let width = camera.width as usize;
    let sums = (0..pixels)
        .into_par_iter()
        .filter(|&p| view.mask[p])
        .map(|p| {
            let d = camera.pixel_dir((p % width) as u32, (p / width) as u32);
            let (stokes_x, stokes_y) = camera.stokes_frame(d);
            let input = PixelInput {
                position: DVec3::ZERO,
                normal: rgb(view.normal, p),
                view: -d,
                stokes_x,
                stokes_y,
                albedo: rgb(view.albedo, p),
                roughness: (view.alpha_ggx.data[p * view.alpha_ggx.channels] as f64)
                    .max(0.0)
                    .sqrt(),
                ior: view.ior.data[p * view.ior.channels] as f64,
            };
            let s = shade(&input, light, lut);
            let specular = shade(
                &PixelInput {
                    albedo: DVec3::ZERO,
                    ..input
                },
                light,
                lut,
            );
            let (g0, g1, g2) = (rgb(view.s0, p), rgb(view.s1, p), rgb(view.s2, p));
            let e0 = s.s0 - g0;
            let grey = |v: DVec3| v.x + v.y + v.z;
            let gt_dolp = dolp(grey(g0), grey(g1), grey(g2));
            let pred_dolp = dolp(grey(s.s0), grey(s.s1), grey(s.s2));
            let polarized = gt_dolp > AOLP_MIN_DOLP;
            let agree = polarized
                && aolp_difference(aolp(grey(s.s1), grey(s.s2)), aolp(grey(g1), grey(g2)))
                    < AOLP_TOLERANCE_DEG.to_radians();
            Sums {
                pixels: 1,
                sq_err: e0.length_squared(),
                s0_pred: grey(s.s0),
                s0_gt: grey(g0),
                s1_err: grey((s.s1 - g1).abs()),
                s1_abs: grey(g1.abs()),
                s2_err: grey((s.s2 - g2).abs()),
                s2_abs: grey(g2.abs()),
                polarized: polarized as usize,
                aolp_ok: agree as usize,
                dolp_err: (pred_dolp - gt_dolp).abs(),
                gt_max: g0.max_element(),
                parts: PartFit::of(
                    [specular.s0, specular.s1, specular.s2],
                    [s.s0 - specular.s0, s.s1 - specular.s1, s.s2 - specular.s2],
                    [g0, g1, g2],
                ),
            }
        })
        .reduce(Sums::default, Sums::add);
    let n = sums.pixels.max(1) as f64;
    let mse = sums.sq_err / (3.0 * n);
    Ok(ShadingCheck {
        pixels: sums.pixels,
        s0_psnr: -10.0 * mse.max(1e-30).log10(),
        s0_psnr_peak_max: 10.0
            * (sums.gt_max * sums.gt_max / mse.max(1e-30))
                .max(1e-30)
                .log10(),
        s0_bias: sums.s0_pred / sums.s0_gt.max(1e-30) - 1.0,
        s1_rel_l1: sums.s1_err / sums.s1_abs.max(1e-30),
        s2_rel_l1: sums.s2_err / sums.s2_abs.max(1e-30),
        aolp_agreement: sums.aolp_ok as f64 / sums.polarized.max(1) as f64,
        dolp_mae: sums.dolp_err / n,
        part_scales: sums.parts.solve(),
    })
}

#[cfg(test)]
mod tests {
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    use super::*;

    fn random_stokes(rng: &mut ChaCha8Rng) -> [DVec3; 3] {
        std::array::from_fn(|_| {
            DVec3::from_array(std::array::from_fn(|_| rng.random_range(-1.0..1.0)))
        })
    }

    #[test]
    fn the_part_fit_recovers_the_scales_that_made_the_capture() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let fit = (0..50)
            .map(|_| {
                let (specular, diffuse) = (random_stokes(&mut rng), random_stokes(&mut rng));
                let captured = std::array::from_fn(|k| 1.8 * specular[k] + 0.6 * diffuse[k]);
                PartFit::of(specular, diffuse, captured)
            })
            .fold(PartFit::default(), PartFit::add);
        let scales = fit.solve();
        assert!((scales.specular - 1.8).abs() < 1e-9, "{scales:?}");
        assert!((scales.diffuse - 0.6).abs() < 1e-9, "{scales:?}");
    }

    #[test]
    fn parts_that_cannot_be_told_apart_give_no_scales() {
        let mut rng = ChaCha8Rng::seed_from_u64(6);
        let part = random_stokes(&mut rng);
        let doubled = part.map(|v| 2.0 * v);
        let fit = PartFit::of(part, doubled, part);
        assert_eq!(fit.solve(), PartScales::default());
    }
}

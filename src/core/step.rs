//! What one training step computes for one view, shared by the host step
//! ([`crate::pipeline::train`]) and the gpu engine's resident trainer (`crate::gpu::DeviceTrainer`),
//! so that both follow one plan: the view's training target ([`ViewTarget`]), which terms and
//! shading a stage applies ([`StepPlan`]), and the per-pixel loss sums ([`LossSums`]) that the plan
//! turns into the named, weighted losses of METHOD.md §6.

use std::borrow::Cow;
use std::collections::BTreeMap;

use rayon::prelude::*;

use crate::core::events::Stage;
use crate::core::loss::LossWeights;

/// The polarizer in front of a view, as the trainer uses it.
#[derive(Clone, Debug, PartialEq)]
pub enum Polarizer {
    /// Known angle, radians.
    Fixed(f64),
    /// Learned angle of the named group.
    Learned(String),
}

/// A plane of a view's f32 samples, borrowed from the capture or converted from it.
pub type Samples<'a> = Cow<'a, [f32]>;

/// Training data of one view, in the capture's f32 samples: borrowed from the capture's view
/// where its layout already fits (RGB images, the mask), so a run holds its views once; a step
/// widens the one view it fits to f64 ([`ViewTarget::fitted`], [`widen`]).
#[derive(Clone, Debug)]
pub struct ViewTarget<'a> {
    /// Index into `Capture::views`.
    pub view: usize,
    /// Linear RGB target of the photometric loss (interleaved, α-premultiplied like the capture).
    pub photometric: Samples<'a>,
    /// Captured S1 and S2 (RGB) when the Stokes loss applies to this view.
    pub stokes: Option<(Samples<'a>, Samples<'a>)>,
    /// The polarizer of a partial view (its photometric target is I(θ)).
    pub polarizer: Option<Polarizer>,
    /// Object mask in [0, 1], one value per pixel.
    pub mask: Samples<'a>,
    /// What the photometric and Stokes samples are multiplied by to give the values the run fits:
    /// the inverse of its radiance scale (`pipeline::train::exposure`), 1 in the capture's units.
    pub gain: f32,
    /// How far each pixel's measured polarization can be trusted, in [0, 1]
    /// ([`crate::core::polarization_confidence`]), multiplying its weight in the AoLP prior;
    /// `None`: fully.
    pub polarization_confidence: Option<Vec<f32>>,
    /// The mask loss's weight of each pixel ([`crate::core::mask_band`]: 0 near the mask's
    /// edge); `None`: 1 everywhere.
    pub mask_weight: Option<Vec<f32>>,
}

impl ViewTarget<'_> {
    /// The photometric or Stokes `samples` as the run fits them: times [`Self::gain`], in f64.
    pub fn fitted(&self, samples: &[f32]) -> Vec<f64> {
        self.fitted_in(samples, [self.gain; 3])
    }

    /// The factor each colour channel's samples are multiplied by when the view's own exposure
    /// and white balance are `colour` (the view's channel values over the run's): the gain over
    /// the colour.
    pub fn channel_gains(&self, colour: [f64; 3]) -> [f32; 3] {
        colour.map(|c| (f64::from(self.gain) / c) as f32)
    }

    /// Interleaved RGB `samples` times their channel's `gains`, in f64.
    pub fn fitted_in(&self, samples: &[f32], gains: [f32; 3]) -> Vec<f64> {
        samples
            .par_iter()
            .enumerate()
            .map(|(i, &v)| f64::from(v * gains[i % 3]))
            .collect()
    }
}

/// `samples` in f64, as the host step's losses take them.
pub fn widen(samples: &[f32]) -> Vec<f64> {
    samples.par_iter().map(|&v| f64::from(v)).collect()
}

/// What a step computes for one view in one stage, shared by [`run`] and the device trainer.
#[derive(Clone, Debug, PartialEq)]
pub struct StepPlan {
    /// PolarDR shading (every stage but plain 2DGS, where the colour is the albedo).
    pub shaded: bool,
    /// The polarizer angle the prediction is seen through: a view behind a polarizer in the
    /// PolarDR stage (known, or its group's learned angle).
    pub theta: Option<f64>,
    /// The learned angle's group, whose gradient the step reports.
    pub learned_angle: Option<String>,
    /// ½ for a view behind a polarizer that is fitted as unpolarized light (I = S0 / 2 on
    /// average over θ, before the PolarDR stage), else 1.
    pub unpolarized_scale: f64,
    /// The L1 on S1 and S2 applies (PolarDR stage, a view with Stokes targets).
    pub stokes_loss: bool,
    /// The extra L1 on Î(θ) applies (PolarDR stage, a view behind a polarizer without them).
    pub extra_l1: bool,
    /// Edge-aware normal smoothness applies (shaded stages, λ > 0).
    pub normal_smooth: bool,
    /// Depth–normal consistency applies (λ > 0).
    pub depth_normal: bool,
    /// The depth distortion applies (λ > 0).
    pub distortion: bool,
    /// The AoLP normal-azimuth prior applies (a view with Stokes targets, λ > 0).
    pub aolp: bool,
}

/// Sums of each loss term over a view's pixels (and channels), before their means and weights.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LossSums {
    /// Σ |prediction − target| over pixels and channels.
    pub l1: f64,
    /// Σ of the SSIM map over pixels and channels.
    pub ssim: f64,
    /// Σ (α − mask)².
    pub mask: f64,
    /// Σ |α S1 − S1*| + |α S2 − S2*| over pixels and channels.
    pub stokes: f64,
    /// Σ of the edge-weighted smoothed normal differences.
    pub normal_smooth: f64,
    /// Σ (1 − N̂ · N_d) over the pixels where both normals exist, and their number.
    pub depth_normal: f64,
    pub depth_normal_pixels: f64,
    /// Σ α² (E[z²] − E[z]²), the depth distortion in scene units².
    pub distortion: f64,
    /// Σ DoLP² sin² 2(ψ − φ), the AoLP residual of the rendered normal's azimuth φ.
    pub aolp: f64,
}

impl StepPlan {
    /// (cos 2θ, sin 2θ) of the polarizer angle the prediction is seen through, if any.
    pub fn polarizer_cos_sin(&self) -> Option<(f64, f64)> {
        self.theta.map(|t| ((2.0 * t).cos(), (2.0 * t).sin()))
    }

    pub fn new(
        target: &ViewTarget,
        stage: Stage,
        angles: &BTreeMap<String, f64>,
        weights: &LossWeights,
    ) -> Self {
        let polar = stage == Stage::Polar;
        let (theta, learned_angle) = match (&target.polarizer, polar) {
            (Some(Polarizer::Fixed(t)), true) => (Some(*t), None),
            (Some(Polarizer::Learned(name)), true) => (
                Some(angles.get(name).copied().unwrap_or(0.0)),
                Some(name.clone()),
            ),
            _ => (None, None),
        };
        let polarized_view = target.polarizer.is_some();
        let stokes_loss = polar && target.stokes.is_some();
        StepPlan {
            shaded: stage != Stage::Geometry,
            theta,
            learned_angle,
            unpolarized_scale: if polarized_view && theta.is_none() {
                0.5
            } else {
                1.0
            },
            stokes_loss,
            extra_l1: polar && !stokes_loss && polarized_view,
            normal_smooth: stage != Stage::Geometry && weights.lambda_normal_smooth > 0.0,
            depth_normal: weights.lambda_depth_normal > 0.0,
            distortion: weights.lambda_distortion > 0.0,
            aolp: target.stokes.is_some() && weights.lambda_aolp > 0.0,
        }
    }

    /// The named, weighted loss terms of a step over `pixels` pixels (3 channels) from their sums.
    pub fn losses(
        &self,
        sums: &LossSums,
        weights: &LossWeights,
        pixels: usize,
    ) -> BTreeMap<String, f64> {
        let elements = (3 * pixels).max(1) as f64;
        let pixels = pixels.max(1) as f64;
        let l1 = sums.l1 / elements;
        let mut losses = BTreeMap::new();
        let lambda = weights.lambda_ssim;
        losses.insert(
            "photometric".to_owned(),
            (1.0 - lambda) * l1 + lambda * (1.0 - sums.ssim / elements),
        );
        if self.stokes_loss {
            let value = weights.lambda_stokes * sums.stokes / elements;
            losses.insert("stokes".to_owned(), value);
        } else if self.extra_l1 {
            losses.insert("stokes".to_owned(), weights.lambda_stokes * l1);
        }
        losses.insert("mask".to_owned(), weights.lambda_mask * sums.mask / pixels);
        if self.normal_smooth {
            let value = weights.lambda_normal_smooth * sums.normal_smooth / pixels;
            losses.insert("normal_smooth".to_owned(), value);
        }
        if self.distortion {
            let value = weights.distortion_per_scene_unit() * sums.distortion / pixels;
            losses.insert("distortion".to_owned(), value);
        }
        if self.aolp {
            let value = weights.lambda_aolp * sums.aolp / pixels;
            losses.insert("aolp".to_owned(), value);
        }
        if self.depth_normal {
            let mean = if sums.depth_normal_pixels > 0.0 {
                sums.depth_normal / sums.depth_normal_pixels
            } else {
                0.0
            };
            losses.insert(
                "depth_normal".to_owned(),
                weights.lambda_depth_normal * mean,
            );
        }
        losses
    }
}

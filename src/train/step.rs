//! One optimization step's forward and backward pass on one view: rasterize, shade (PolarDR once
//! the geometry stage is over), evaluate the weighted losses of METHOD.md §6, and carry their
//! gradients back through shading and rasterization to the surfels, the environment map and the
//! learned polarizer angles.
//!
//! [`StepPlan`] holds what a step computes for a view in a stage (shading, the polarizer angle,
//! which loss terms apply) and turns per-pixel loss sums into the named terms; [`run`] is the
//! host's step over a rasterizer [`Backend`], and the gpu backend's resident trainer
//! (`phygap::gpu::DeviceTrainer`) follows the same plan on the device.

use std::collections::BTreeMap;

use glam::DVec3;

use crate::brdf_lut::BrdfLut;
use crate::envmap::{EnvGrad, LightProbe};
use crate::events::Stage;
use crate::loss::{self, LossWeights};
use crate::raster::{Backend, GBufferGrads, RasterSettings};
use crate::render::{Scene, ShadingInputs};
use crate::shading::StokesImageGrad;
use crate::surfels::{SurfelGrads, Surfels};

use super::targets::{Polarizer, ViewTarget};
use super::TrainError;

/// Gradients and loss values of one step.
pub struct StepResult {
    /// Named loss terms (weighted) and their sum under `total`.
    pub losses: BTreeMap<String, f64>,
    pub total: f64,
    pub surfels: SurfelGrads,
    /// Per-surfel screen-space gradient norm (pixels) for densification.
    pub mean2d_grad_norm: Vec<f64>,
    /// Gradient of the environment light (shading stages only).
    pub env: Option<EnvGrad>,
    /// Gradient of each learned polarizer angle.
    pub angles: BTreeMap<String, f64>,
    pub width: usize,
    pub height: usize,
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
}

impl StepPlan {
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

/// Fixed inputs of every step.
pub struct StepInputs<'a> {
    pub backend: &'a dyn Backend,
    pub settings: RasterSettings,
    pub lut: &'a BrdfLut,
    pub weights: LossWeights,
}

fn add_into(dst: &mut [f64], src: &[f64], scale: f64) {
    for (d, s) in dst.iter_mut().zip(src) {
        *d += scale * s;
    }
}

/// Runs forward and backward for `target` seen by `camera`, shading with `light` (the global
/// environment, or GridMap over it; the light gradient is shaped like the global environment).
#[allow(clippy::too_many_arguments)]
pub fn run(
    inputs: &StepInputs,
    surfels: &Surfels,
    light: &dyn LightProbe,
    angles: &BTreeMap<String, f64>,
    camera: &crate::camera::Camera,
    target: &ViewTarget,
    stage: Stage,
) -> Result<StepResult, TrainError> {
    let _span = tracing::debug_span!("step", ?stage).entered();
    let scene = Scene {
        surfels,
        light,
        lut: inputs.lut,
        backend: inputs.backend,
        settings: inputs.settings,
    };
    let raster = inputs.backend.forward(surfels, camera, &inputs.settings)?;
    let g = &raster.gbuffers;
    let (w, h) = (g.width, g.height);
    let pixels = w * h;
    let weights = &inputs.weights;
    let mut up = GBufferGrads::zeros(w, h);
    let mut losses = BTreeMap::new();

    let plan = StepPlan::new(target, stage, angles, weights);
    let (theta, unpolarized_scale) = (plan.theta, plan.unpolarized_scale);

    // Shading (not in the geometry stage, where colour = albedo).
    let shaded = if !plan.shaded {
        None
    } else {
        let inputs = ShadingInputs::new(g, camera);
        let (image, saved) =
            scene
                .backend
                .shade_saved(camera, &inputs.buffers(g), scene.light, scene.lut)?;
        Some((inputs, image, saved))
    };

    // Photometric prediction, α-premultiplied like the capture.
    let mut pred = vec![0.0; pixels * 3];
    for p in 0..pixels {
        let a = g.alpha[p];
        let colour = match &shaded {
            None => DVec3::from_array(g.albedo[p]) * unpolarized_scale,
            Some((_, s, _)) => match theta {
                None => s.s0[p] * unpolarized_scale,
                Some(t) => 0.5 * (s.s0[p] + s.s1[p] * (2.0 * t).cos() + s.s2[p] * (2.0 * t).sin()),
            },
        };
        pred[p * 3..p * 3 + 3].copy_from_slice(&(colour * a).to_array());
    }
    let photometric = loss::photometric(&pred, &target.photometric, w, h, 3, weights.lambda_ssim);
    losses.insert("photometric".to_owned(), photometric.value);
    let mut grad_pred = photometric.grad;

    // Stokes loss on S1/S2 (full views) or the extra L1 on I(θ) (partial views), PolarDR stage only.
    let mut grad_s12: Option<(Vec<f64>, Vec<f64>)> = None;
    if plan.stokes_loss || plan.extra_l1 {
        if let (Some((t1, t2)), Some((_, s, _))) = (&target.stokes, &shaded) {
            let premul = |v: &[DVec3]| -> Vec<f64> {
                v.iter()
                    .zip(&g.alpha)
                    .flat_map(|(x, &a)| (*x * a).to_array())
                    .collect()
            };
            let stokes = loss::stokes_l1(&premul(&s.s1), t1, &premul(&s.s2), t2, None);
            losses.insert("stokes".to_owned(), weights.lambda_stokes * stokes.value);
            let scale = |v: Vec<f64>| v.into_iter().map(|x| x * weights.lambda_stokes).collect();
            grad_s12 = Some((scale(stokes.grad_s1), scale(stokes.grad_s2)));
        } else {
            let extra = loss::l1(&pred, &target.photometric, None);
            losses.insert("stokes".to_owned(), weights.lambda_stokes * extra.value);
            add_into(&mut grad_pred, &extra.grad, weights.lambda_stokes);
        }
    }

    // Mask, normal smoothness and depth–normal consistency act on the G-buffers directly.
    let mask = loss::mask_mse(&g.alpha, &target.mask);
    losses.insert("mask".to_owned(), weights.lambda_mask * mask.value);
    add_into(&mut up.alpha, &mask.grad, weights.lambda_mask);
    if plan.normal_smooth {
        let smooth = loss::normal_smoothness(g.normal.as_flattened(), &target.photometric, w, h);
        losses.insert(
            "normal_smooth".to_owned(),
            weights.lambda_normal_smooth * smooth.value,
        );
        add_into(
            up.normal.as_flattened_mut(),
            &smooth.grad,
            weights.lambda_normal_smooth,
        );
    }
    if plan.depth_normal {
        let dn = loss::depth_normal_consistency(
            g.normal.as_flattened(),
            g.depth_normal.as_flattened(),
            None,
        );
        losses.insert(
            "depth_normal".to_owned(),
            weights.lambda_depth_normal * dn.value,
        );
        add_into(
            up.normal.as_flattened_mut(),
            &dn.grad_normal,
            weights.lambda_depth_normal,
        );
        add_into(
            up.depth_normal.as_flattened_mut(),
            &dn.grad_depth_normal,
            weights.lambda_depth_normal,
        );
    }

    // Chain the image gradients into the G-buffers.
    let mut angle_grad = 0.0;
    let mut env_grad = None;
    match &shaded {
        None => {
            let k = unpolarized_scale;
            for p in 0..pixels {
                let gp = DVec3::from_slice(&grad_pred[p * 3..p * 3 + 3]);
                let albedo = DVec3::from_array(g.albedo[p]);
                let d_albedo = DVec3::from_array(up.albedo[p]) + gp * (k * g.alpha[p]);
                up.albedo[p] = d_albedo.to_array();
                up.alpha[p] += k * albedo.dot(gp);
            }
        }
        Some((inputs_px, s, saved)) => {
            let mut d0 = vec![DVec3::ZERO; pixels];
            let mut d1 = vec![DVec3::ZERO; pixels];
            let mut d2 = vec![DVec3::ZERO; pixels];
            for p in 0..pixels {
                let a = g.alpha[p];
                let gp = DVec3::from_slice(&grad_pred[p * 3..p * 3 + 3]);
                match theta {
                    None => {
                        d0[p] = gp * (a * unpolarized_scale);
                        up.alpha[p] += unpolarized_scale * s.s0[p].dot(gp);
                    }
                    Some(t) => {
                        let (c, sn) = ((2.0 * t).cos(), (2.0 * t).sin());
                        d0[p] = gp * (0.5 * a);
                        d1[p] = gp * (0.5 * a * c);
                        d2[p] = gp * (0.5 * a * sn);
                        let intensity = 0.5 * (s.s0[p] + s.s1[p] * c + s.s2[p] * sn);
                        up.alpha[p] += intensity.dot(gp);
                        angle_grad += a * (s.s2[p] * c - s.s1[p] * sn).dot(gp);
                    }
                }
                if let Some((g1, g2)) = &grad_s12 {
                    let g1 = DVec3::from_slice(&g1[p * 3..p * 3 + 3]);
                    let g2 = DVec3::from_slice(&g2[p * 3..p * 3 + 3]);
                    d1[p] += g1 * a;
                    d2[p] += g2 * a;
                    up.alpha[p] += s.s1[p].dot(g1) + s.s2[p].dot(g2);
                }
            }
            let (gb, env_g) = scene.backend.shade_backward_saved(
                camera,
                &inputs_px.buffers(g),
                scene.light,
                scene.lut,
                saved.as_ref(),
                &StokesImageGrad {
                    s0: &d0,
                    s1: &d1,
                    s2: &d2,
                },
            )?;
            for p in 0..pixels {
                let add3 =
                    |dst: &mut [f64; 3], v: DVec3| *dst = (DVec3::from_array(*dst) + v).to_array();
                add3(&mut up.normal[p], gb.normal[p]);
                add3(&mut up.albedo[p], gb.albedo[p]);
                up.roughness[p] += gb.roughness[p];
                up.ior[p] += gb.ior[p];
            }
            env_grad = Some(env_g);
        }
    }

    let grads = inputs
        .backend
        .backward(surfels, camera, &inputs.settings, &raster, &up)?;
    let mut angle_grads = BTreeMap::new();
    if let Some(name) = plan.learned_angle {
        angle_grads.insert(name, angle_grad);
    }
    let total = losses.values().sum();
    Ok(StepResult {
        losses,
        total,
        surfels: grads.surfels,
        mean2d_grad_norm: grads.mean2d_grad_norm,
        env: env_grad,
        angles: angle_grads,
        width: w,
        height: h,
    })
}

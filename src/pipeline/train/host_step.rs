//! One optimization step's forward and backward pass on one view: rasterize, shade (PolarDR once
//! the geometry stage is over), evaluate the weighted losses of METHOD.md §6, and carry their
//! gradients back through shading and rasterization to the surfels, the environment map and the
//! learned polarizer angles.
//!
//! [`StepPlan`] (in [`crate::core::step`]) holds what a step computes for a view in a stage (shading, the polarizer angle,
//! which loss terms apply) and turns per-pixel loss sums into the named terms; [`run`] is the
//! host's step over a rasterizer [`Backend`], and the gpu backend's resident trainer
//! (`phygap::gpu::DeviceTrainer`) follows the same plan on the device.

use std::collections::BTreeMap;

use glam::DVec3;
use rayon::prelude::*;

use crate::core::brdf_lut::BrdfLut;
use crate::core::engine::Backend;
use crate::core::envmap::EnvGrad;
use crate::core::events::Stage;
use crate::core::filled::filled;
use crate::core::light::LightProbe;
use crate::core::loss::{self, sum_in_chunk_order, LossWeights, CHUNK};
use crate::core::raster::{GBufferGrads, GBuffers, RasterSettings};
use crate::core::render::ShadingInputs;
use crate::core::shading::{SavedShading, StokesImage, StokesImageGrad};
use crate::core::step::{widen, StepPlan, ViewTarget};
use crate::core::surfels::{SurfelGrads, Surfels};

use super::{colour, TrainError};

/// Gradients and loss values of one step.
pub struct StepResult {
    /// Named loss terms (weighted) and their sum under `total`.
    pub losses: BTreeMap<String, f64>,
    pub total: f64,
    pub surfels: SurfelGrads,
    /// Per-surfel screen-space gradient norm (pixels) for densification.
    pub mean2d_grad_norm: Vec<f64>,
    /// Gradient on the view's pose correction, where the engine computes it.
    pub pose: Option<crate::core::pose::PoseGrad>,
    /// How much brighter the view's fitted samples are than the prediction, per channel
    /// ([`colour::ratio`]).
    pub colour_ratio: [Option<f64>; 3],
    /// Gradient of the environment light (shading stages only).
    pub env: Option<EnvGrad>,
    /// Gradient of each learned polarizer angle.
    pub angles: BTreeMap<String, f64>,
    pub width: usize,
    pub height: usize,
}

/// Fixed inputs of every step.
pub struct StepInputs<'a> {
    pub backend: &'a dyn Backend,
    pub settings: RasterSettings,
    pub lut: &'a BrdfLut,
    pub weights: LossWeights,
}

fn add_into(dst: &mut [f64], src: &[f64], scale: f64) {
    dst.par_iter_mut()
        .zip(src)
        .with_min_len(CHUNK)
        .for_each(|(d, s)| *d += scale * s);
}

/// Runs forward and backward for `target` seen by `camera`, its samples divided by the view's
/// `colour` ([`colour`]), shading with `light` (the global environment, or GridMap over it; the
/// light gradient is shaped like the global environment).
#[allow(clippy::too_many_arguments)]
pub fn run(
    inputs: &StepInputs,
    surfels: &Surfels,
    light: &dyn LightProbe,
    angles: &BTreeMap<String, f64>,
    camera: &crate::core::camera::Camera,
    target: &ViewTarget,
    colour: [f64; 3],
    stage: Stage,
) -> Result<StepResult, TrainError> {
    let _span = tracing::debug_span!("step", ?stage).entered();
    let raster = inputs.backend.forward(surfels, camera, &inputs.settings)?;
    let g = &raster.gbuffers;
    let weights = &inputs.weights;
    let mut up = GBufferGrads::zeros(g.width, g.height);
    let mut losses = BTreeMap::new();
    let plan = StepPlan::new(target, stage, angles, weights);

    // Shading (not in the geometry stage, where colour = albedo).
    let shaded = if !plan.shaded {
        None
    } else {
        let shading = ShadingInputs::new(g, camera);
        let (image, saved) =
            inputs
                .backend
                .shade_saved(camera, &shading.buffers(g), light, inputs.lut)?;
        Some(Shaded {
            inputs: shading,
            image,
            saved,
        })
    };
    // The view's photometric target in f64, which both groups of losses read.
    let gains = target.channel_gains(colour);
    let photometric = target.fitted_in(&target.photometric, gains);
    let image_grads = {
        let _span = tracing::debug_span!("image_losses").entered();
        image_losses(
            g,
            shaded.as_ref(),
            &plan,
            target,
            &photometric,
            gains,
            inputs,
            &mut losses,
        )
    };
    {
        let _span = tracing::debug_span!("gbuffer_losses").entered();
        gbuffer_losses(
            g,
            camera,
            &plan,
            target,
            &photometric,
            weights,
            &mut up,
            &mut losses,
        );
    }

    // Chain the image gradients into the G-buffers.
    let (angle_grad, env_grad) = match &shaded {
        None => {
            let _span = tracing::debug_span!("chain_unshaded").entered();
            chain_unshaded(g, &image_grads, plan.unpolarized_scale, &mut up);
            (0.0, None)
        }
        Some(shaded) => {
            let (angle_grad, env_grad) = chain_shaded(
                inputs,
                g,
                camera,
                light,
                shaded,
                &image_grads,
                &plan,
                &mut up,
            )?;
            (angle_grad, Some(env_grad))
        }
    };

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
        pose: grads.pose,
        colour_ratio: image_grads.colour_ratio,
        env: env_grad,
        angles: angle_grads,
        width: g.width,
        height: g.height,
    })
}

/// A view shaded by PolarDR, with what its backward pass reuses.
struct Shaded {
    inputs: ShadingInputs,
    image: StokesImage,
    saved: Option<SavedShading>,
}

/// The gradients of the image losses: with respect to the photometric prediction, and to the
/// α-premultiplied S1 and S2 (the Stokes loss of full views).
struct ImageGrads {
    pred: Vec<f64>,
    s12: Option<(Vec<f64>, Vec<f64>)>,
    /// The fitted target over the prediction, per channel ([`colour::ratio`]).
    colour_ratio: [Option<f64>; 3],
}

/// The photometric prediction, α-premultiplied like the capture: the albedo (geometry stage),
/// S0, or the intensity behind the view's polarizer angle θ.
fn predict(g: &GBuffers, shaded: Option<&Shaded>, plan: &StepPlan) -> Vec<f64> {
    let pixels = g.width * g.height;
    let polarizer = plan.polarizer_cos_sin();
    let mut pred = filled(pixels * 3, 0.0);
    pred.par_chunks_mut(3).enumerate().for_each(|(p, out)| {
        let colour = match shaded {
            None => DVec3::from_array(g.albedo[p]) * plan.unpolarized_scale,
            Some(Shaded { image: s, .. }) => match polarizer {
                None => s.s0[p] * plan.unpolarized_scale,
                Some((c, sn)) => 0.5 * (s.s0[p] + s.s1[p] * c + s.s2[p] * sn),
            },
        };
        out.copy_from_slice(&(colour * g.alpha[p]).to_array());
    });
    pred
}

/// The photometric loss against `photometric_target` (the view's, widened; SSIM in the backend's
/// loss precision), and in the PolarDR stage the Stokes loss on S1/S2 (full views) or the extra
/// L1 on I(θ) (partial views).
#[allow(clippy::too_many_arguments)]
fn image_losses(
    g: &GBuffers,
    shaded: Option<&Shaded>,
    plan: &StepPlan,
    target: &ViewTarget,
    photometric_target: &[f64],
    gains: [f32; 3],
    inputs: &StepInputs,
    losses: &mut BTreeMap<String, f64>,
) -> ImageGrads {
    let weights = &inputs.weights;
    let (w, h) = (g.width, g.height);
    let pred = predict(g, shaded, plan);
    let colour_ratio = colour::ratio(&pred, photometric_target, &g.alpha, &target.mask);
    let photometric = loss::photometric(
        &pred,
        photometric_target,
        w,
        h,
        3,
        weights.lambda_ssim,
        inputs.backend.loss_precision(),
    );
    losses.insert("photometric".to_owned(), photometric.value);
    let mut grad_pred = photometric.grad;
    let mut grad_s12 = None;
    if plan.stokes_loss || plan.extra_l1 {
        if let (Some((t1, t2)), Some(Shaded { image: s, .. })) = (&target.stokes, shaded) {
            let mut stokes =
                loss::stokes_l1_premultiplied((&s.s1, &s.s2), &g.alpha, (t1, t2), gains);
            losses.insert("stokes".to_owned(), weights.lambda_stokes * stokes.value);
            for grad in [&mut stokes.grad_s1, &mut stokes.grad_s2] {
                grad.par_iter_mut()
                    .for_each(|x| *x *= weights.lambda_stokes);
            }
            grad_s12 = Some((stokes.grad_s1, stokes.grad_s2));
        } else {
            let extra = loss::l1(&pred, photometric_target, None);
            losses.insert("stokes".to_owned(), weights.lambda_stokes * extra.value);
            add_into(&mut grad_pred, &extra.grad, weights.lambda_stokes);
        }
    }
    ImageGrads {
        pred: grad_pred,
        s12: grad_s12,
        colour_ratio,
    }
}

/// Mask, normal smoothness, depth distortion, the AoLP prior and depth–normal consistency,
/// which act on the G-buffers directly.
#[allow(clippy::too_many_arguments)]
fn gbuffer_losses(
    g: &GBuffers,
    camera: &crate::core::camera::Camera,
    plan: &StepPlan,
    target: &ViewTarget,
    photometric_target: &[f64],
    weights: &LossWeights,
    up: &mut GBufferGrads,
    losses: &mut BTreeMap<String, f64>,
) {
    let mask = loss::mask_mse(
        &g.alpha,
        &widen(&target.mask),
        target.mask_weight.as_deref(),
    );
    losses.insert("mask".to_owned(), weights.lambda_mask * mask.value);
    add_into(&mut up.alpha, &mask.grad, weights.lambda_mask);
    if plan.normal_smooth {
        let smooth = loss::normal_smoothness(
            g.normal.as_flattened(),
            photometric_target,
            g.width,
            g.height,
        );
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
    if plan.distortion {
        let d = loss::depth_distortion(&g.alpha, &g.depth, &g.depth_sq, weights.distortion_scale);
        losses.insert("distortion".to_owned(), weights.lambda_distortion * d.value);
        add_into(&mut up.alpha, &d.grad_alpha, weights.lambda_distortion);
        add_into(&mut up.depth, &d.grad_depth, weights.lambda_distortion);
        add_into(
            &mut up.depth_sq,
            &d.grad_depth_sq,
            weights.lambda_distortion,
        );
    }
    if let (true, Some((s1, s2))) = (plan.aolp, &target.stokes) {
        let polarization = loss::measured_polarization(
            &target.photometric,
            s1,
            s2,
            &target.mask,
            target.gain,
            target.polarization_confidence.as_deref(),
        );
        let prior = loss::aolp_normal(g.normal.as_flattened(), camera, &polarization);
        losses.insert("aolp".to_owned(), weights.lambda_aolp * prior.value);
        add_into(
            up.normal.as_flattened_mut(),
            &prior.grad,
            weights.lambda_aolp,
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
}

/// The prediction's gradient into the albedo and opacity buffers (geometry stage: colour =
/// albedo × scale, premultiplied by α).
fn chain_unshaded(g: &GBuffers, image: &ImageGrads, scale: f64, up: &mut GBufferGrads) {
    (up.albedo.par_iter_mut(), up.alpha.par_iter_mut())
        .into_par_iter()
        .enumerate()
        .for_each(|(p, (albedo_grad, alpha_grad))| {
            let gp = DVec3::from_slice(&image.pred[p * 3..p * 3 + 3]);
            let albedo = DVec3::from_array(g.albedo[p]);
            *albedo_grad = (DVec3::from_array(*albedo_grad) + gp * (scale * g.alpha[p])).to_array();
            *alpha_grad += scale * albedo.dot(gp);
        });
}

/// The image gradients through the Stokes images into the opacity and, by PolarDR's backward
/// pass, the normal, albedo, roughness and IoR buffers; returns the polarizer angle's gradient and
/// the light's.
#[allow(clippy::too_many_arguments)]
fn chain_shaded(
    inputs: &StepInputs,
    g: &GBuffers,
    camera: &crate::core::camera::Camera,
    light: &dyn LightProbe,
    shaded: &Shaded,
    image: &ImageGrads,
    plan: &StepPlan,
    up: &mut GBufferGrads,
) -> Result<(f64, EnvGrad), TrainError> {
    let (pixels, s) = (g.width * g.height, &shaded.image);
    let polarizer = plan.polarizer_cos_sin();
    let mut d0 = filled(pixels, DVec3::ZERO);
    let mut d1 = filled(pixels, DVec3::ZERO);
    let mut d2 = filled(pixels, DVec3::ZERO);
    // Per pixel: the Stokes images' upstream and the opacity's; the angle's gradient is summed
    // in chunk order (the same whatever the thread count).
    let chunks = (
        d0.par_chunks_mut(CHUNK),
        d1.par_chunks_mut(CHUNK),
        d2.par_chunks_mut(CHUNK),
        up.alpha.par_chunks_mut(CHUNK),
    )
        .into_par_iter();
    let angle_grad = sum_in_chunk_order(chunks, |chunk, (d0, d1, d2, alpha_grad)| {
        let mut angle_grad = 0.0;
        for j in 0..d0.len() {
            let p = chunk * CHUNK + j;
            let a = g.alpha[p];
            let gp = DVec3::from_slice(&image.pred[p * 3..p * 3 + 3]);
            match polarizer {
                None => {
                    d0[j] = gp * (a * plan.unpolarized_scale);
                    alpha_grad[j] += plan.unpolarized_scale * s.s0[p].dot(gp);
                }
                Some((c, sn)) => {
                    d0[j] = gp * (0.5 * a);
                    d1[j] = gp * (0.5 * a * c);
                    d2[j] = gp * (0.5 * a * sn);
                    let intensity = 0.5 * (s.s0[p] + s.s1[p] * c + s.s2[p] * sn);
                    alpha_grad[j] += intensity.dot(gp);
                    angle_grad += a * (s.s2[p] * c - s.s1[p] * sn).dot(gp);
                }
            }
            if let Some((g1, g2)) = &image.s12 {
                let g1 = DVec3::from_slice(&g1[p * 3..p * 3 + 3]);
                let g2 = DVec3::from_slice(&g2[p * 3..p * 3 + 3]);
                d1[j] += g1 * a;
                d2[j] += g2 * a;
                alpha_grad[j] += s.s1[p].dot(g1) + s.s2[p].dot(g2);
            }
        }
        angle_grad
    });
    let (gb, env_grad) = inputs.backend.shade_backward_saved(
        camera,
        &shaded.inputs.buffers(g),
        light,
        inputs.lut,
        shaded.saved.as_ref(),
        &StokesImageGrad {
            s0: &d0,
            s1: &d1,
            s2: &d2,
        },
    )?;
    let add3 = |dst: &mut [f64; 3], v: DVec3| *dst = (DVec3::from_array(*dst) + v).to_array();
    (
        up.normal.par_iter_mut(),
        up.albedo.par_iter_mut(),
        up.roughness.par_iter_mut(),
        up.ior.par_iter_mut(),
    )
        .into_par_iter()
        .enumerate()
        .for_each(|(p, (normal, albedo, roughness, ior))| {
            add3(normal, gb.normal[p]);
            add3(albedo, gb.albedo[p]);
            *roughness += gb.roughness[p];
            *ior += gb.ior[p];
        });
    Ok((angle_grad, env_grad))
}

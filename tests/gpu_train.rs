//! Parity of the gpu backend's resident trainer (`DeviceTrainer`: whole steps on the device) with
//! the host's f64 step (`train::host_step::run` on the cpu backend): the named loss terms, every raw
//! gradient group, the screen-space gradient of densification, the light's gradient and the
//! polarizer angle's, for each stage and each kind of view (full Stokes, behind a learned
//! polarizer, plain RGB), under the global light and under GridMap; and the Adam update and the
//! densification statistics it applies. Skips like tests/gpu_parity.rs where no adapter exists.

use std::collections::BTreeMap;

use glam::DVec3;
use phygap::core::brdf_lut::BrdfLut;
use phygap::core::camera::Camera;
use phygap::core::config::TrainConfig;
use phygap::core::densify::DensifyStats;
use phygap::core::envmap::{EnvGrad, PreparedEnv};
use phygap::core::events::Stage;
use phygap::core::light::LightProbe;
use phygap::core::loss::LossWeights;
use phygap::core::mask_band::mask_loss_weights;
use phygap::core::optim::{Adam, AdamConfig};
use phygap::core::raster::cpu::CpuBackend;
use phygap::core::raster::RasterSettings;
use phygap::core::step::{Polarizer, StepPlan, ViewTarget};
use phygap::core::surfels::Surfels;
use phygap::gpu::{DeviceStep, DeviceTrainer, GpuBackend, GpuOptions};
use phygap::pipeline::train::host_step::{self, StepInputs};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

mod common;
use common::{gpu, random_cube, random_env, shell};

/// A target of `camera`'s size: the photometric image and S1/S2 smooth functions of the pixel
/// (so SSIM sees structure), the mask the disc the shell covers, a varying confidence of the
/// polarization, and the mask loss's band around the disc's edge.
fn target(camera: &Camera, kind: &str, rng: &mut ChaCha8Rng) -> ViewTarget<'static> {
    let (w, h) = (camera.width as usize, camera.height as usize);
    let phase: f64 = rng.random_range(0.0..6.0);
    let mut photometric = Vec::with_capacity(w * h * 3);
    let mut s1 = Vec::with_capacity(w * h * 3);
    let mut s2 = Vec::with_capacity(w * h * 3);
    let mut mask = Vec::with_capacity(w * h);
    for p in 0..w * h {
        let (x, y) = ((p % w) as f64 / w as f64, (p / w) as f64 / h as f64);
        let r2 = (x - 0.5).powi(2) + (y - 0.5).powi(2);
        let inside = f64::from(r2 < 0.12);
        mask.push(inside as f32);
        for c in 0..3 {
            let v = 0.5 + 0.4 * (7.0 * x + 5.0 * y + phase + c as f64).sin();
            photometric.push((inside * v) as f32);
            s1.push((inside * 0.1 * (9.0 * y + c as f64).cos()) as f32);
            s2.push((inside * 0.1 * (8.0 * x - c as f64).sin()) as f32);
        }
    }
    let (stokes, polarizer) = match kind {
        "full" => (Some((s1.into(), s2.into())), None),
        "partial" => (None, Some(Polarizer::Learned("cam0".into()))),
        _ => (None, None),
    };
    // The polarization's confidence varying across the view, the mask loss left out near the
    // disc's edge (both planes default to 1 on the device).
    let polarization_confidence = (kind == "full").then(|| {
        (0..w * h)
            .map(|p| (0.5 + 0.5 * (0.3 * (p % w) as f64 - 0.2 * (p / w) as f64).sin()) as f32)
            .collect()
    });
    let mask_weight = Some(mask_loss_weights(&mask, w, h, 2));
    ViewTarget {
        view: 0,
        photometric: photometric.into(),
        stokes,
        polarizer,
        mask: mask.into(),
        gain: 0.5,
        polarization_confidence,
        mask_weight,
    }
}

/// `|a − b| ≤ tolerance (|b| + floor · max |b|)` over two buffers; returns the worst ratio.
fn assert_close(a: &[f64], b: &[f64], tolerance: f64, floor: f64, what: &str) -> f64 {
    assert_eq!(a.len(), b.len(), "{what}: lengths");
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let (mut worst, mut at) = (0.0, 0);
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        let e = (x - y).abs() / (y.abs() + floor * scale + 1e-30);
        if e > worst {
            (worst, at) = (e, i);
        }
    }
    assert!(
        worst <= tolerance,
        "{what}: error {worst:.2e} at {at} (gpu {}, cpu {}, scale {scale:.3e})",
        a[at],
        b[at]
    );
    worst
}

/// ‖a − b‖ / ‖b‖ (0 when both vanish).
fn relative_l2_of(a: &[f64], b: &[f64]) -> f64 {
    let diff: f64 = a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum();
    let norm: f64 = b.iter().map(|y| y * y).sum();
    if norm == 0.0 {
        diff.sqrt()
    } else {
        (diff / norm).sqrt()
    }
}

/// [`relative_l2_of`] over every texel of two light gradients.
fn relative_l2(a: &EnvGrad, b: &EnvGrad) -> f64 {
    let flat = |g: &EnvGrad| -> Vec<f64> {
        g.levels
            .iter()
            .chain(&g.irradiance)
            .flatten()
            .copied()
            .collect()
    };
    relative_l2_of(&flat(a), &flat(b))
}

/// The raw gradients of project_backward's layout as the host's groups (position, scale,
/// rotation, opacity, albedo, roughness, IoR) and the screen-space norm.
fn device_groups(raw: &[f32]) -> (Vec<Vec<f64>>, Vec<f64>) {
    let slots: [&[usize]; 7] = [
        &[0, 1, 2],
        &[3, 4],
        &[5, 6, 7, 8],
        &[9],
        &[10, 11, 12],
        &[13],
        &[14],
    ];
    let groups = slots
        .iter()
        .map(|s| {
            raw.chunks_exact(16)
                .flat_map(|g| s.iter().map(|&k| f64::from(g[k])))
                .collect()
        })
        .collect();
    (
        groups,
        raw.chunks_exact(16).map(|g| f64::from(g[15])).collect(),
    )
}

struct Scene {
    surfels: Surfels,
    camera: Camera,
    env: PreparedEnv,
    lut: BrdfLut,
    weights: LossWeights,
}

/// One step on both sides; asserts that every quantity agrees and returns the worst element's
/// relative gradient error. Tolerances: loss terms 1e-4 relative (f32 sums over the pixels);
/// each raw gradient group 1e-3 in relative L2 norm and 5e-2 per element above a floor of 1% of
/// the group's largest value. The per-element bound is looser than the rasterizer's alone
/// (tests/gpu_parity.rs, 1e-3 on random upstream gradients) because a shaded step's positions and
/// opacities receive sums over pixels of the shader's normal gradients that largely cancel: the
/// f32 shader's ~1e-4 relative error per pixel (tests/gpu_shading.rs) becomes up to a few 1e-4
/// of the group's norm (measured 2–4e-4 in the shaded stages, 1e-5 in plain 2DGS).
fn compare(
    gpu: &GpuBackend,
    scene: &Scene,
    target: &ViewTarget,
    stage: Stage,
    light: &dyn LightProbe,
    grid: Option<&phygap::core::gridmap::GridMap>,
) -> f64 {
    let settings = RasterSettings::default();
    let angles: BTreeMap<String, f64> = [("cam0".to_owned(), 0.6)].into();
    let inputs = StepInputs {
        backend: &CpuBackend,
        settings,
        lut: &scene.lut,
        weights: scene.weights,
    };
    let host = host_step::run(
        &inputs,
        &scene.surfels,
        light,
        &angles,
        &scene.camera,
        target,
        [1.0; 3],
        stage,
    )
    .unwrap();
    let mut trainer = trainer(gpu, scene, target);
    trainer.set_light(&scene.env).unwrap();
    trainer.set_gridmap(grid).unwrap();
    let plan = StepPlan::new(target, stage, &angles, &scene.weights);
    let result = trainer
        .step(&DeviceStep {
            view: 0,
            camera: &scene.camera,
            plan: &plan,
            rates: [Some(1e-3); 7],
        })
        .unwrap();
    assert!(result.finite);
    let what = format!(
        "{stage:?}, {:?}",
        target
            .polarizer
            .as_ref()
            .map(|_| "partial")
            .or(target.stokes.as_ref().map(|_| "full"))
    );
    let losses = plan.losses(&result.sums, &scene.weights, scene.camera.num_pixels());
    assert_eq!(
        losses.keys().collect::<Vec<_>>(),
        host.losses.keys().collect::<Vec<_>>(),
        "{what}: loss terms"
    );
    for (name, &value) in &host.losses {
        let e = (losses[name] - value).abs() / value.abs().max(1e-6);
        assert!(
            e < 1e-4,
            "{what}: loss {name} gpu {} vs cpu {value}",
            losses[name]
        );
    }
    let raw = trainer.last_raw_gradients().unwrap();
    let (groups, mean2d) = device_groups(&raw);
    let mut worst = 0.0f64;
    for ((name, cpu), gpu) in host.surfels.groups().iter().zip(&groups) {
        let what = format!("{what}: dL/d{name}");
        let l2 = relative_l2_of(gpu, cpu);
        assert!(l2 < 1e-3, "{what}: relative L2 error {l2:.2e}");
        worst = worst.max(assert_close(gpu, cpu, 5e-2, 1e-2, &what));
    }
    // The densification statistic: per surfel the norm of a sum over its pixels whose terms
    // cancel, in f32 on the device (worst 0.8–1.1 % on these scenes).
    let screen = assert_close(
        &mean2d,
        &host.mean2d_grad_norm,
        2e-2,
        1e-2,
        &format!("{what}: screen-space gradient"),
    );
    println!("{what}: worst screen-space gradient error {screen:.2e}");
    if let Some(env) = &host.env {
        let light_error = relative_l2(&trainer.take_light_grad().unwrap(), env);
        assert!(
            light_error < 1e-3,
            "{what}: light gradient {light_error:.2e}"
        );
    }
    if let Some(&angle) = host.angles.get("cam0") {
        let e = (result.angle_grad - angle).abs() / angle.abs().max(1e-9);
        assert!(
            e < 1e-2,
            "{what}: angle gradient gpu {} vs cpu {angle}",
            result.angle_grad
        );
    }
    println!(
        "{what}: worst gradient error {worst:.2e}, {} tile entries",
        result.tile_entries
    );
    worst
}

/// A trainer of `target` seen by the scene's camera, holding the scene's surfels with fresh Adam
/// moments and statistics.
fn trainer<'g>(gpu: &'g GpuBackend, scene: &'g Scene, target: &ViewTarget) -> DeviceTrainer<'g> {
    let mut trainer = DeviceTrainer::new(
        gpu,
        RasterSettings::default(),
        scene.weights,
        AdamConfig::default(),
        &scene.lut,
        std::slice::from_ref(target),
        &[scene.camera],
    )
    .unwrap();
    let fresh = Adam::new(AdamConfig::default());
    let statistics = DensifyStats::new(scene.surfels.len());
    trainer.load(&scene.surfels, &fresh, &statistics).unwrap();
    trainer
}

/// The trainer uploads its views' targets one at a time: right after it is made, the device
/// holds the targets and not also wgpu's staging copies of them (which, left until the first
/// submission, doubled the upload's memory: host memory on a discrete GPU). The trainer's other
/// buffers cancel out between a trainer of 8 views and one of 1.
#[test]
fn view_targets_are_uploaded_without_holding_their_staging_copies() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(17);
    // 256×170 pixels of 48 bytes are just under 2 MiB, so an allocator that rounds a buffer up to
    // a power of two (lavapipe's does) adds 0.4%.
    let camera = Camera::look_at(
        256,
        170,
        0.9,
        DVec3::new(0.3, -3.2, 1.1),
        DVec3::ZERO,
        DVec3::Z,
    );
    let lut = BrdfLut::compute(16, 64);
    let mut held_with = |views: usize| {
        let targets: Vec<ViewTarget> = (0..views)
            .map(|_| target(&camera, "full", &mut rng))
            .collect();
        let before = gpu.buffer_memory().in_use_bytes;
        let trainer = DeviceTrainer::new(
            &gpu,
            RasterSettings::default(),
            LossWeights::from(&TrainConfig::default()),
            AdamConfig::default(),
            &lut,
            &targets,
            &vec![camera; views],
        )
        .unwrap();
        (gpu.buffer_memory().in_use_bytes - before, trainer)
    };
    // Both trainers live until the end, so neither's buffers are freed during the other's count.
    let (one, _first) = held_with(1);
    let (eight, _second) = held_with(8);
    // Photometric RGB, mask, S1 and S2 RGB, the polarization's confidence and the mask loss's
    // weight: 12 floats a pixel.
    let seven_targets = 7 * camera.num_pixels() as u64 * 12 * 4;
    let more = eight - one;
    assert!(
        more >= seven_targets && more < seven_targets + seven_targets / 10,
        "7 more views' targets ({seven_targets} bytes) took {more} bytes more"
    );
}

/// A capture rendered by `synth` into `dir/capture` and loaded.
fn synth_capture(
    dir: &std::path::Path,
    options: phygap::pipeline::synth::SynthOptions,
) -> phygap::io::capture::Capture {
    phygap::pipeline::synth::synth(&dir.join("capture"), &options).unwrap();
    phygap::io::capture::load(&dir.join("capture")).unwrap()
}

fn scene(seed: u64) -> Scene {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let camera = Camera::look_at(
        40,
        36,
        0.9,
        DVec3::new(0.3, -3.2, 1.1),
        DVec3::ZERO,
        DVec3::Z,
    );
    Scene {
        surfels: shell(&mut rng, 2500),
        camera,
        env: random_env(&mut rng, false, false),
        lut: BrdfLut::compute(16, 64),
        // Every term on, the depth distortion too (off by default).
        weights: LossWeights {
            lambda_distortion: 0.5,
            distortion_scale: 0.8,
            ..LossWeights::from(&TrainConfig::default())
        },
    }
}

#[test]
fn a_device_step_matches_the_host_step() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let scene = scene(1);
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    for kind in ["full", "partial", "rgb"] {
        let target = target(&scene.camera, kind, &mut rng);
        for stage in [Stage::Geometry, Stage::Material, Stage::Polar] {
            compare(&gpu, &scene, &target, stage, &scene.env, None);
        }
    }
}

/// The PolarDR stage under GridMap: two spheres' mesh (the shell's and one beside it, which
/// blocks part of the shell's mirror rays), the probes blended at the surface points the device
/// back-projects from its depth.
#[test]
fn a_device_step_under_gridmap_matches_the_host_step() {
    use phygap::core::gridmap::{AnchorPlacement, GridMap};
    use phygap::pipeline::reconstruction::prefilter_plan;
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let mut scene = scene(3);
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let cube = random_cube(&mut rng, 16);
    scene.env = PreparedEnv::new(&cube, prefilter_plan(16, false, 1).unwrap()).unwrap();
    scene.camera = Camera::look_at(
        40,
        36,
        0.9,
        DVec3::new(1.0, -3.0, 0.4),
        DVec3::ZERO,
        DVec3::Z,
    );
    let (mesh, _) = phygap::testing::two_spheres();
    let grid = GridMap::build(
        &mesh,
        &scene.surfels,
        &cube,
        scene.env.clone(),
        AnchorPlacement::Box,
    )
    .unwrap();
    for kind in ["full", "partial"] {
        let target = target(&scene.camera, kind, &mut rng);
        compare(&gpu, &scene, &target, Stage::Polar, &grid, Some(&grid));
    }
}

/// After a step the device's surfels are one Adam step (t = 1) on the device's own gradients
/// from where they started, in every trained group and in none of the frozen ones (roughness and
/// IoR in plain 2DGS), its moments are Adam's, and the densification statistics count the
/// surfels the view moved.
#[test]
fn the_update_is_adam_on_the_device_gradients() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let scene = scene(5);
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let target = target(&scene.camera, "full", &mut rng);
    let n = scene.surfels.len();
    let mut trainer = trainer(&gpu, &scene, &target);
    let adam = Adam::new(AdamConfig::default());
    let plan = StepPlan::new(&target, Stage::Geometry, &BTreeMap::new(), &scene.weights);
    let rates = [
        Some(2e-3),
        Some(5e-3),
        Some(1e-3),
        Some(5e-2),
        Some(7.5e-3),
        None,
        None,
    ];
    trainer
        .step(&DeviceStep {
            view: 0,
            camera: &scene.camera,
            plan: &plan,
            rates,
        })
        .unwrap();
    let raw = trainer.last_raw_gradients().unwrap();
    let (grads, mean2d) = device_groups(&raw);
    let (mut surfels, mut adam_after, mut densify) =
        (Surfels::default(), adam.clone(), DensifyStats::default());
    trainer
        .sync(&mut surfels, &mut adam_after, &mut densify)
        .unwrap();

    let mut expected = scene.surfels.clone();
    let mut reference = Adam::new(AdamConfig::default());
    for (((name, params), grad), rate) in expected.groups_mut().into_iter().zip(&grads).zip(rates) {
        if let Some(lr) = rate {
            reference.step(name, params, grad, lr).unwrap();
        }
    }
    for ((name, got), (_, want)) in surfels.groups().iter().zip(expected.groups()) {
        let start = scene
            .surfels
            .groups()
            .iter()
            .find(|g| g.0 == *name)
            .unwrap()
            .1
            .to_vec();
        for ((g, w), s) in got.iter().zip(want).zip(&start) {
            // f32 storage of the parameter, plus f32 rounding of the step.
            assert!(
                (g - w).abs() <= 1e-6 * (1.0 + w.abs()),
                "{name}: {g} vs {w} (from {s})"
            );
        }
        let moved = got
            .iter()
            .zip(&start)
            .any(|(g, s)| g != &(*s as f32 as f64));
        let trained = !matches!(*name, "roughness" | "ior");
        assert_eq!(moved, trained, "{name}: moved {moved}");
        match (adam_after.group(name), reference.group(name)) {
            (Some(a), Some(b)) => {
                assert_eq!(a.step, 1, "{name}");
                assert_close(&a.exp_avg, &b.exp_avg, 1e-5, 1e-6, &format!("{name} m"));
                // 1 − β2 = 0.001 is 1.3e-5 off in f32.
                assert_close(
                    &a.exp_avg_sq,
                    &b.exp_avg_sq,
                    3e-5,
                    1e-6,
                    &format!("{name} v"),
                );
            }
            (None, None) => {}
            (a, b) => panic!(
                "{name}: device state {} vs host {}",
                a.is_some(),
                b.is_some()
            ),
        }
    }
    let to_ndc = 0.5 * f64::from(scene.camera.width.max(scene.camera.height));
    let mut reference_stats = DensifyStats::new(n);
    reference_stats.add_view(
        &mean2d,
        scene.camera.width as usize,
        scene.camera.height as usize,
    );
    assert_eq!(densify.seen, reference_stats.seen);
    assert!(densify.seen.iter().filter(|&&s| s > 0).count() > n / 10);
    assert_close(
        &densify.grad_sum,
        &reference_stats.grad_sum,
        1e-6,
        1e-6,
        "densify sums",
    );
    assert!(to_ndc > 1.0);
}

/// A step whose tile entries overflow their buffer is not applied from the partial sort: it is
/// rerun with a larger buffer and gives what a trainer with room from the start gives.
#[test]
fn a_step_whose_entries_overflow_is_rerun_with_room() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let scene = scene(7);
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let target = target(&scene.camera, "full", &mut rng);
    let plan = StepPlan::new(&target, Stage::Geometry, &BTreeMap::new(), &scene.weights);
    let run = |capacity: Option<u64>| {
        let mut trainer = trainer(&gpu, &scene, &target);
        let adam = Adam::new(AdamConfig::default());
        if let Some(c) = capacity {
            trainer.set_entry_capacity(c).unwrap();
        }
        let result = trainer
            .step(&DeviceStep {
                view: 0,
                camera: &scene.camera,
                plan: &plan,
                rates: [Some(1e-3); 7],
            })
            .unwrap();
        let (mut surfels, mut adam, mut densify) =
            (Surfels::default(), adam, DensifyStats::default());
        trainer.sync(&mut surfels, &mut adam, &mut densify).unwrap();
        (result, surfels, trainer.entry_capacity())
    };
    let (roomy, roomy_surfels, _) = run(None);
    let (tight, tight_surfels, grown) = run(Some(100));
    assert!(roomy.tile_entries > 1000, "{} entries", roomy.tile_entries);
    assert_eq!(tight.tile_entries, roomy.tile_entries);
    assert!(
        grown >= tight.tile_entries,
        "capacity {grown} after the rerun"
    );
    let loss = |r: &phygap::gpu::DeviceStepResult| {
        plan.losses(&r.sums, &scene.weights, scene.camera.num_pixels())["photometric"]
    };
    assert!((loss(&tight) - loss(&roomy)).abs() <= 1e-6 * loss(&roomy));
    for ((name, a), (_, b)) in tight_surfels.groups().iter().zip(roomy_surfels.groups()) {
        // Float atomics sum in any order: the updates agree to f32 rounding.
        assert_close(a, b, 1e-5, 1e-3, name);
    }
}

/// Steps on the same buffers reuse the bind groups of the step before (none is created after the
/// first step), a step after `load` (new surfel buffers) makes new ones and the stale ones are
/// dropped, and a step through cached groups computes what one through fresh groups does.
#[test]
fn steps_reuse_their_bind_groups_and_drop_stale_ones() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let scene = scene(9);
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    let target = target(&scene.camera, "full", &mut rng);
    let plan = StepPlan::new(&target, Stage::Polar, &BTreeMap::new(), &scene.weights);
    let step = DeviceStep {
        view: 0,
        camera: &scene.camera,
        plan: &plan,
        rates: [Some(1e-3); 7],
    };
    let photometric = |r: &phygap::gpu::DeviceStepResult| {
        plan.losses(&r.sums, &scene.weights, scene.camera.num_pixels())["photometric"]
    };

    // Cached: three steps on the same buffers.
    let mut cached = trainer(&gpu, &scene, &target);
    cached.set_light(&scene.env).unwrap();
    cached.step(&step).unwrap();
    let first = cached.bind_counts();
    let per_step = cached.cached_bind_groups();
    assert!(first.created >= 20, "{first:?}");
    assert_eq!(per_step as u64, first.created);
    let second = cached.step(&step).unwrap();
    cached.step(&step).unwrap();
    let after = cached.bind_counts();
    assert_eq!(after.created, first.created, "{after:?}");
    assert_eq!(
        after.reused,
        first.reused + 2 * (first.created + first.reused)
    );

    // Fresh: the same first step, then the surfels loaded again (new buffers) before the second.
    let (mut surfels, mut adam, mut densify) = (
        Surfels::default(),
        Adam::new(AdamConfig::default()),
        DensifyStats::default(),
    );
    let mut fresh = trainer(&gpu, &scene, &target);
    fresh.set_light(&scene.env).unwrap();
    fresh.step(&step).unwrap();
    fresh.sync(&mut surfels, &mut adam, &mut densify).unwrap();
    fresh.load(&surfels, &adam, &densify).unwrap();
    let reloaded = fresh.step(&step).unwrap();
    let counts = fresh.bind_counts();
    assert!(
        counts.created > first.created && counts.created < 2 * first.created,
        "the reload remade only the groups of the surfel buffers: {counts:?} after {first:?}"
    );
    assert_eq!(
        fresh.cached_bind_groups(),
        per_step,
        "stale groups are dropped"
    );
    assert_eq!(reloaded.tile_entries, second.tile_entries);
    let (a, b) = (photometric(&reloaded), photometric(&second));
    // Float atomics sum in any order: the losses agree to f32 rounding.
    assert!((a - b).abs() <= 1e-5 * b, "{a} vs {b}");
}

/// When the device cannot hold a step's buffers (here: a binding limit below the SSIM planes of
/// a 112×112 view, above its target, the light and the BRDF table), training continues with the gpu
/// backend's host steps, which split images into bands and shade them in chunks, instead of
/// failing.
#[test]
fn training_falls_back_to_host_steps_when_buffers_exceed_the_device() {
    use phygap::core::config::TrainConfig;
    use phygap::core::events::TrainEvent;
    let limit = 700_000;
    let Some(gpu) = gpu(GpuOptions {
        max_binding_bytes: Some(limit),
        ..GpuOptions::default()
    }) else {
        return;
    };
    let gpu = phygap::pipeline::backend::Engine::Gpu(gpu);
    let dir = tempfile::tempdir().unwrap();
    let capture = synth_capture(
        dir.path(),
        phygap::pipeline::synth::SynthOptions {
            views: 6,
            size: 112,
            ..Default::default()
        },
    );
    // The device step needs 112 · 112 · 15 f32 for the SSIM planes: more than the limit; a
    // view's target, 112 · 112 · 12 f32, fits.
    assert!(112 * 112 * 15 * 4 > limit && 112 * 112 * 12 * 4 < limit);
    let config = TrainConfig {
        iterations: 12.into(),
        initial_surfels: 500,
        envmap_resolution: 16,
        checkpoint_interval: 0,
        eval_interval: 0,
        gridmap: false,
        ..TrainConfig::default()
    };
    let cancel = std::sync::atomic::AtomicBool::new(false);
    let mut steps = Vec::new();
    let mut description = String::new();
    let outcome = phygap::pipeline::train::train_on(
        &gpu,
        &capture,
        &dir.path().join("model"),
        &config,
        false,
        &cancel,
        &mut |e| match e {
            TrainEvent::Started { backend, .. } => description = backend.clone(),
            TrainEvent::Step {
                iteration, loss, ..
            } => steps.push((*iteration, *loss)),
            _ => {}
        },
    )
    .unwrap();
    assert_eq!(outcome, phygap::pipeline::train::TrainOutcome::Finished);
    assert!(
        description.ends_with("whole steps on the device"),
        "{description}"
    );
    assert_eq!(steps.last().map(|s| s.0), Some(12));
    assert!(steps.iter().all(|s| s.1.is_finite()));
}

/// The environment prefilter on the device (`set_envmap`: the raw cube map goes up and is
/// prefiltered there) lights a step as the host's `PreparedEnv` does, and its transpose
/// (`take_envmap_grad`) gives `PreparedEnv::backward` of the light's gradient, for the default
/// chain (D = 64) with Fresnel-weighted irradiance (five irradiance kernels), for a small one,
/// and for the small one with two roughness levels per size (three levels of one size in a row).
#[test]
fn the_device_prefilter_matches_the_host_prefilter() {
    use phygap::pipeline::reconstruction::prefilter_plan;
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let mut scene = scene(9);
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    let target = target(&scene.camera, "full", &mut rng);
    let angles = BTreeMap::new();
    let plan_of_step = StepPlan::new(&target, Stage::Polar, &angles, &scene.weights);
    for (size, fresnel, levels_per_size) in [(64, true, 1), (16, false, 1), (16, false, 2)] {
        let cube = random_cube(&mut rng, size);
        let plan = prefilter_plan(size, fresnel, levels_per_size).unwrap();
        scene.env = PreparedEnv::new(&cube, plan.clone()).unwrap();
        let lit_step = |device_prefilter: bool| {
            let mut t = trainer(&gpu, &scene, &target);
            if device_prefilter {
                t.set_envmap(&cube, &plan).unwrap();
            } else {
                t.set_light(&scene.env).unwrap();
            }
            let result = t
                .step(&DeviceStep {
                    view: 0,
                    camera: &scene.camera,
                    plan: &plan_of_step,
                    rates: [Some(1e-3); 7],
                })
                .unwrap();
            (
                t,
                plan_of_step.losses(&result.sums, &scene.weights, scene.camera.num_pixels()),
            )
        };
        let (mut host_lit, host_losses) = lit_step(false);
        let (mut device_lit, device_losses) = lit_step(true);
        let expected: Vec<f64> = scene
            .env
            .levels
            .iter()
            .chain(&scene.env.irradiance)
            .flatten()
            .copied()
            .collect();
        let got: Vec<f64> = device_lit
            .light_texels()
            .unwrap()
            .into_iter()
            .map(f64::from)
            .collect();
        let mut first = 0;
        for (k, part) in scene
            .env
            .levels
            .iter()
            .chain(&scene.env.irradiance)
            .enumerate()
        {
            let range = first..first + part.len();
            let what = format!("D = {size}: light part {k}");
            assert_close(&got[range.clone()], &expected[range], 1e-4, 1e-3, &what);
            first += part.len();
        }
        for (name, &value) in &host_losses {
            let e = (device_losses[name] - value).abs() / value.abs().max(1e-6);
            assert!(
                e < 1e-4,
                "D = {size}: loss {name} {} vs {value}",
                device_losses[name]
            );
        }
        let host_grad = scene.env.backward(&host_lit.take_light_grad().unwrap());
        let device_grad = device_lit.take_envmap_grad().unwrap();
        let l2 = relative_l2_of(&device_grad, &host_grad);
        println!("D = {size}, Fresnel {fresnel}: raw gradient relative L2 error {l2:.2e}");
        assert!(
            l2 < 1e-3,
            "D = {size}: raw gradient relative L2 error {l2:.2e}"
        );
        assert_close(
            &device_grad,
            &host_grad,
            1e-2,
            1e-2,
            &format!("D = {size}: raw gradient"),
        );
        // The sum starts again from zero.
        assert!(device_lit
            .take_envmap_grad()
            .unwrap()
            .iter()
            .all(|&g| g == 0.0));
    }
}

/// A run on the device interrupted at a checkpoint and resumed ends where the uninterrupted run
/// ends (to the f32 atomics' run-to-run spread: the final losses within 2%), and the checkpoint
/// holds the device's state (surfels, moments, densification statistics, the learned map).
#[test]
fn an_interrupted_device_run_resumes_from_its_checkpoint() {
    use phygap::core::config::{BackendChoice, TrainConfig};
    use phygap::core::events::TrainEvent;
    use phygap::pipeline::train::{train, TrainOutcome};
    if gpu(GpuOptions::default()).is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let capture = synth_capture(
        dir.path(),
        phygap::pipeline::synth::SynthOptions {
            views: 8,
            size: 40,
            ..Default::default()
        },
    );
    let config = TrainConfig {
        iterations: 60.into(),
        backend: BackendChoice::Gpu,
        initial_surfels: 1500,
        envmap_resolution: 16,
        geometry_stage_end: 0.2,
        material_stage_end: 0.3,
        checkpoint_interval: 30,
        eval_interval: 0,
        mesh_interval: 20,
        gridmap_interval: 10,
        ..TrainConfig::default()
    };
    let never = std::sync::atomic::AtomicBool::new(false);
    let last_loss = |events: &[TrainEvent]| {
        events
            .iter()
            .rev()
            .find_map(|e| match e {
                TrainEvent::Step { loss, .. } => Some(*loss),
                _ => None,
            })
            .unwrap()
    };
    let mut whole_events = Vec::new();
    let whole = dir.path().join("whole");
    train(&capture, &whole, &config, false, &never, &mut |e| {
        whole_events.push(e.clone())
    })
    .unwrap();
    let split = dir.path().join("split");
    let cancel = std::sync::atomic::AtomicBool::new(false);
    let outcome = train(&capture, &split, &config, false, &cancel, &mut |e| {
        if matches!(e, TrainEvent::Checkpoint { iteration: 30 }) {
            cancel.store(true, std::sync::atomic::Ordering::Relaxed);
        }
    })
    .unwrap();
    assert_eq!(outcome, TrainOutcome::Interrupted { iteration: 30 });
    let (state, _) = phygap::pipeline::train::state::TrainState::load(
        &split.join(phygap::pipeline::train::state::CHECKPOINT_FILE),
    )
    .unwrap();
    assert_eq!(state.iteration, 30);
    assert!(state.surfels.is_finite() && !state.surfels.is_empty());
    assert!(state.adam.group("position").is_some_and(|g| g.step == 30));
    assert!(state.adam.group("envmap").is_some_and(|g| g.step > 0));
    let mut split_events = Vec::new();
    let outcome = train(&capture, &split, &config, true, &never, &mut |e| {
        split_events.push(e.clone())
    })
    .unwrap();
    assert_eq!(outcome, TrainOutcome::Finished);
    assert!(matches!(
        split_events[0],
        TrainEvent::Started {
            resumed_from: Some(30),
            ..
        }
    ));
    let (a, b) = (last_loss(&whole_events), last_loss(&split_events));
    assert!(
        (a - b).abs() <= 0.02 * a,
        "final loss {b} after resuming vs {a}"
    );
}

/// GridMap's mesh on a device run (issue: "GridMap mesh extraction failed: the TSDF has no zero
/// crossing" during PolarDR on a GPU). The cause was the schedule, not the device: the remesh that
/// follows an opacity reset fuses nearly transparent surfels, whose rendered opacity never reaches
/// the TSDF's ½. A 200-step device run whose reset (after 110 steps) falls on a remesh shows the
/// failure without the wait and none with it; every remesh renders depth through the per-call
/// rasterizer while the trainer owns the device.
#[test]
fn a_device_run_remeshes_gridmap_without_failures() {
    use phygap::core::config::TrainConfig;
    use phygap::core::events::TrainEvent;
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let gpu = phygap::pipeline::backend::Engine::Gpu(gpu);
    let dir = tempfile::tempdir().unwrap();
    let capture = synth_capture(
        dir.path(),
        phygap::pipeline::synth::SynthOptions {
            shape: phygap::pipeline::synth::Shape::Torus,
            views: 9,
            size: 24,
            ..Default::default()
        },
    );
    let run = |recovery: u32| {
        let config = TrainConfig {
            iterations: 200.into(),
            initial_surfels: 1500,
            envmap_resolution: 16,
            geometry_stage_end: 0.2,
            material_stage_end: 0.3,
            checkpoint_interval: 0,
            eval_interval: 0,
            mesh_interval: 50,
            gridmap_interval: 25,
            opacity_reset_interval: 110,
            opacity_recovery_steps: recovery,
            ..TrainConfig::default()
        };
        let cancel = std::sync::atomic::AtomicBool::new(false);
        let mut warnings = Vec::new();
        let mut description = String::new();
        phygap::pipeline::train::train_on(
            &gpu,
            &capture,
            &dir.path().join(format!("model{recovery}")),
            &config,
            false,
            &cancel,
            &mut |e| match e {
                TrainEvent::Started { backend, .. } => description = backend.clone(),
                TrainEvent::Warning { iteration, message } => {
                    warnings.push((*iteration, message.clone()))
                }
                _ => {}
            },
        )
        .unwrap();
        assert!(
            description.ends_with("whole steps on the device"),
            "{description}"
        );
        warnings
    };
    let failed = run(0);
    assert_eq!(failed.len(), 1, "{failed:?}");
    assert_eq!(failed[0].0, 110);
    assert_eq!(run(80), []);
}

/// `bench_train` on the device engine reports the host's side of each step (encode, read-back,
/// finish, submit, wait: one of each per attempt), the device's peak buffer memory (at least the
/// views' targets it holds) and the process's peak resident memory.
#[test]
fn the_training_benchmark_reports_host_phases_and_memory() {
    use phygap::core::config::TrainConfig;
    use phygap::pipeline::bench::{bench_train, BenchStage};
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let engine = phygap::pipeline::backend::Engine::Gpu(gpu);
    let dir = tempfile::tempdir().unwrap();
    let capture = synth_capture(
        dir.path(),
        phygap::pipeline::synth::SynthOptions {
            views: 6,
            size: 32,
            ..Default::default()
        },
    );
    let config = TrainConfig {
        iterations: 10.into(),
        initial_surfels: 400,
        envmap_resolution: 8,
        gridmap: false,
        ..TrainConfig::default()
    };
    let timing = bench_train(&engine, &capture, &config, BenchStage::Geometry).unwrap();
    let names: Vec<&str> = timing.host_phases.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["encode", "read-back", "finish", "submit", "wait"]);
    for phase in &timing.host_phases {
        assert!(phase.calls >= 10, "{phase:?}");
        assert_eq!(phase.calls, timing.host_phases[0].calls, "{phase:?}");
        assert!(phase.total_ms > 0.0, "{phase:?}");
    }
    let train_views = capture
        .views
        .iter()
        .filter(|v| v.split == phygap::io::capture::Split::Train)
        .count() as u64;
    // Each training view's target: ten f32 per pixel.
    let targets = train_views * 32 * 32 * 10 * 4;
    let device = timing
        .memory
        .device_peak_bytes
        .expect("a device run measures its buffers");
    assert!(
        device >= targets && device < 1 << 30,
        "{device} bytes on the device, {targets} of them targets"
    );
    if cfg!(target_os = "linux") {
        let host = timing.memory.host_peak_rss_bytes.expect("VmHWM on Linux");
        assert!(host > 10 << 20, "{host} bytes resident");
    }
}

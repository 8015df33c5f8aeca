//! End-to-end training on captures the project makes itself (`phygap::pipeline::synth`): the loss falls and
//! the test PSNR rises over a short run; a run interrupted at a checkpoint and resumed ends
//! bit-identical to an uninterrupted one; equal seeds give equal runs; every mode trains; the
//! model folder renders, evaluates and exports.

use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

use phygap::core::config::{AutoSwitch, Mode, TrainConfig};
use phygap::core::events::{Stage, TrainEvent};
use phygap::io::capture::{self, Capture, Measurement};
use phygap::io::model::Model;
use phygap::pipeline::synth::{synth, SynthOptions};
use phygap::pipeline::train::state::{TrainState, CHECKPOINT_FILE};
use phygap::pipeline::train::{train, TrainError, TrainOutcome};

fn synthetic_capture(dir: &Path, views: usize, size: u32) -> Capture {
    let options = SynthOptions {
        views,
        size,
        ..SynthOptions::default()
    };
    synth(dir, &options).unwrap();
    capture::load(dir).unwrap()
}

fn small_config(iterations: u32) -> TrainConfig {
    TrainConfig {
        iterations: iterations.into(),
        initial_surfels: 1500,
        max_surfels: 6000,
        eval_interval: iterations / 4,
        checkpoint_interval: iterations / 2,
        ..TrainConfig::default()
    }
}

/// Runs training and returns every event.
fn run(
    capture: &Capture,
    model: &Path,
    config: &TrainConfig,
    resume: bool,
    cancel_at_checkpoint: Option<u32>,
) -> (TrainOutcome, Vec<TrainEvent>) {
    let cancel = AtomicBool::new(false);
    let mut events = Vec::new();
    let outcome = train(capture, model, config, resume, &cancel, &mut |e| {
        if let (TrainEvent::Checkpoint { iteration }, Some(at)) = (e, cancel_at_checkpoint) {
            if *iteration == at {
                cancel.store(true, Ordering::Relaxed);
            }
        }
        events.push(e.clone());
    })
    .unwrap();
    (outcome, events)
}

fn photometric_losses(events: &[TrainEvent], stage: Stage) -> Vec<f64> {
    events
        .iter()
        .filter_map(|e| match e {
            TrainEvent::Step {
                stage: s, losses, ..
            } if *s == stage => losses.get("photometric").copied(),
            _ => None,
        })
        .collect()
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}

#[test]
fn training_lowers_the_loss_and_raises_test_psnr() {
    let dir = tempfile::tempdir().unwrap();
    let capture = synthetic_capture(&dir.path().join("capture"), 16, 48);
    let model = dir.path().join("model");
    // The core loop alone (GridMap has its own tests; on a 48² sphere it changes little).
    let config = TrainConfig {
        gridmap: false,
        ..small_config(400)
    };
    let (outcome, events) = run(&capture, &model, &config, false, None);
    assert_eq!(outcome, TrainOutcome::Finished);

    // Within the geometry stage and within the PolarDR stage, the photometric loss falls.
    for (stage, factor) in [(Stage::Geometry, 0.8), (Stage::Polar, 0.9)] {
        let losses = photometric_losses(&events, stage);
        assert!(losses.len() >= 40, "{stage:?}: {} steps", losses.len());
        let (early, late) = (mean(&losses[..20]), mean(&losses[losses.len() - 20..]));
        assert!(
            late < factor * early,
            "{stage:?}: photometric {early} → {late}"
        );
    }
    let psnrs: Vec<f64> = events
        .iter()
        .filter_map(|e| match e {
            TrainEvent::Evaluated { test_psnr, .. } => Some(*test_psnr),
            _ => None,
        })
        .collect();
    assert!(psnrs.len() >= 4, "evaluated {} times", psnrs.len());
    let (first, last) = (psnrs[0], psnrs[psnrs.len() - 1]);
    assert!(last > first + 2.0, "test PSNR {first:.2} → {last:.2} dB");
    assert!(last > 20.0, "final test PSNR {last:.2} dB");

    // The model folder is complete and reloads; its metrics are real numbers.
    for file in [
        "model.json",
        "config.json",
        "surfels.ply",
        "envmap.exr",
        "envmap_cube.exr",
        "metrics.json",
        "progress.jsonl",
        "test_cameras.json",
        CHECKPOINT_FILE,
    ] {
        assert!(model.join(file).exists(), "{file} missing");
    }
    let metrics: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(model.join("metrics.json")).unwrap())
            .unwrap();
    assert!((metrics["psnr"].as_f64().unwrap() - last).abs() < 1e-9);
    let normal_mae = metrics["normal_mae_deg"].as_f64().unwrap();
    assert!(normal_mae > 0.0 && normal_mae < 45.0, "{metrics}");
    let reloaded = phygap::io::model::Model::load(&model).unwrap();
    assert_eq!(reloaded.info.mode, Mode::Full);
    let reconstruction = phygap::pipeline::reconstruction::Reconstruction::new(reloaded).unwrap();
    let report = reconstruction.evaluate(&capture).unwrap();
    assert!(
        (report.psnr.unwrap() - last).abs() < 0.5,
        "reloaded model (f32 PLY) evaluates like the trained one: {} vs {last}",
        report.psnr.unwrap()
    );
    // What the run reports as it trains is the evaluation's PSNR, without its other metrics.
    let psnr_only = phygap::pipeline::evaluate::test_psnr_scaled(
        &reconstruction.scene(),
        1.0,
        &capture,
        &Default::default(),
    )
    .unwrap();
    assert_eq!(psnr_only, report.psnr);
    let exported = phygap::pipeline::export::export(&model, &dir.path().join("export")).unwrap();
    assert!(exported.iter().any(|p| p.ends_with("renders/s0/000.png")));
}

#[test]
fn resumed_run_is_bit_identical_and_seeds_are_deterministic() {
    let dir = tempfile::tempdir().unwrap();
    let capture = synthetic_capture(&dir.path().join("capture"), 12, 32);
    let config = small_config(200);

    let straight = dir.path().join("straight");
    run(&capture, &straight, &config, false, None);

    let resumed = dir.path().join("resumed");
    let (outcome, _) = run(&capture, &resumed, &config, false, Some(100));
    assert_eq!(outcome, TrainOutcome::Interrupted { iteration: 100 });
    let (outcome, events) = run(&capture, &resumed, &config, true, None);
    assert_eq!(outcome, TrainOutcome::Finished);
    assert!(matches!(
        events[0],
        TrainEvent::Started {
            resumed_from: Some(100),
            ..
        }
    ));

    let again = dir.path().join("again");
    run(&capture, &again, &config, false, None);

    let load = |dir: &Path| TrainState::load(&dir.join(CHECKPOINT_FILE)).unwrap().0;
    let (a, b, c) = (load(&straight), load(&resumed), load(&again));
    let bits = |s: &TrainState| -> Vec<u64> {
        let mut v: Vec<u64> = s
            .surfels
            .groups()
            .iter()
            .flat_map(|(_, g)| g.iter().map(|x| x.to_bits()))
            .collect();
        v.extend(s.envmap.raw.iter().map(|x| x.to_bits()));
        v
    };
    assert_eq!(a.iteration, 200);
    assert_eq!(
        bits(&a),
        bits(&b),
        "resumed run differs from the straight one"
    );
    assert_eq!(bits(&a), bits(&c), "same seed, different result");

    // A different seed gives a different run.
    let other = dir.path().join("other");
    run(
        &capture,
        &other,
        &TrainConfig {
            seed: 1,
            ..config.clone()
        },
        false,
        None,
    );
    assert_ne!(bits(&a), bits(&load(&other)));

    // Resuming with another configuration is refused.
    let cancel = AtomicBool::new(false);
    let changed = TrainConfig {
        lambda_mask: 0.5,
        ..config
    };
    let err = train(&capture, &resumed, &changed, true, &cancel, &mut |_| {}).unwrap_err();
    assert!(err.to_string().contains("different configuration"), "{err}");
}

/// Surfels no training view sees (`prune_hidden`) are pruned at the opacity reset and only there:
/// runs with and without it report the same surfels up to the reset, and fewer after it.
#[test]
fn surfels_hidden_at_an_opacity_reset_are_pruned() {
    let dir = tempfile::tempdir().unwrap();
    let capture = synthetic_capture(&dir.path().join("capture"), 12, 32);
    let reset = 200;
    let base = TrainConfig {
        opacity_reset_interval: reset,
        gridmap: false,
        ..small_config(300)
    };
    let surfel_counts = |prune_hidden: bool, name: &str| -> Vec<(u32, usize)> {
        let config = TrainConfig {
            prune_hidden,
            ..base.clone()
        };
        let (outcome, events) = run(&capture, &dir.path().join(name), &config, false, None);
        assert_eq!(outcome, TrainOutcome::Finished);
        events
            .iter()
            .filter_map(|e| match e {
                TrainEvent::Step {
                    iteration,
                    num_surfels,
                    ..
                } => Some((*iteration, *num_surfels)),
                _ => None,
            })
            .collect()
    };
    let (kept, pruned) = (surfel_counts(false, "kept"), surfel_counts(true, "pruned"));
    let upto = |c: &[(u32, usize)]| -> Vec<(u32, usize)> {
        c.iter().copied().filter(|&(i, _)| i <= reset).collect()
    };
    assert_eq!(
        upto(&kept),
        upto(&pruned),
        "the runs differ before the reset"
    );
    let after = |c: &[(u32, usize)]| c.iter().find(|&&(i, _)| i == reset + 1).unwrap().1;
    let (n_kept, n_pruned) = (after(&kept), after(&pruned));
    println!("surfels after the reset: {n_kept} kept, {n_pruned} with the hidden ones pruned");
    assert!(n_pruned < n_kept, "{n_pruned} >= {n_kept}");
}

#[test]
fn a_darker_exposure_of_the_same_views_trains_to_the_same_surfels() {
    let dir = tempfile::tempdir().unwrap();
    let bright = synthetic_capture(&dir.path().join("capture"), 12, 32);
    // The same views a quarter as bright: dividing by a power of two is exact, so after the
    // run's exposure normalization both fit the same bits.
    let mut dark = bright.clone();
    for view in &mut dark.views {
        let Measurement::Stokes { s0, s1, s2 } = &mut view.measurement else {
            panic!("synth writes full Stokes");
        };
        for image in [s0, s1, s2] {
            image.data.iter_mut().for_each(|v| *v *= 0.25);
        }
    }
    let config = small_config(120);
    let (bright_dir, dark_dir) = (dir.path().join("bright"), dir.path().join("dark"));
    run(&bright, &bright_dir, &config, false, None);
    run(&dark, &dark_dir, &config, false, None);

    let load = |dir: &Path| TrainState::load(&dir.join(CHECKPOINT_FILE)).unwrap().0;
    let (a, b) = (load(&bright_dir), load(&dark_dir));
    assert_eq!(b.radiance_scale, 0.25 * a.radiance_scale);
    // (`assert!`, not `assert_eq!`: a failure would print thousands of surfels.)
    assert!(
        a.surfels == b.surfels,
        "the exposure changed what the views train to"
    );
    assert!(a.envmap == b.envmap, "the exposure changed the run's light");
    // The models' light is in their captures' units (stored as f32).
    let (a, b) = (
        Model::load(&bright_dir).unwrap().envmap.radiance(),
        Model::load(&dark_dir).unwrap().envmap.radiance(),
    );
    for (bright, dark) in a.iter().zip(&b) {
        assert!(
            (dark - 0.25 * bright).abs() <= 1e-6 * bright.max(1e-3),
            "{dark} {bright}"
        );
    }
    // A checkpoint resumed against views of another exposure is refused, not refitted.
    let cancel = AtomicBool::new(false);
    let err = train(&bright, &dark_dir, &config, true, &cancel, &mut |_| {}).unwrap_err();
    assert!(matches!(err, TrainError::ExposureChanged { .. }), "{err}");
}

#[test]
fn partial_and_rgb_modes_train_and_partial_recovers_polarizer_angles() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().join("capture");
    synthetic_capture(&root, 16, 48);
    // Derive a partial capture: even views behind a polarizer at 20°, odd at 110°, angles unknown.
    let transforms: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("transforms.json")).unwrap())
            .unwrap();
    let mut partial = transforms.clone();
    let truth = [20.0f64, 110.0];
    for (k, frame) in partial["frames"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .enumerate()
    {
        let theta = truth[k % 2].to_radians();
        let read = |key: &str| {
            phygap::formats::image_io::read_image(&root.join(frame[key].as_str().unwrap()))
                .unwrap()
                .0
        };
        let (s0, s1, s2) = (read("s0_path"), read("s1_path"), read("s2_path"));
        let mut image = s0.clone();
        for (i, v) in image.data.iter_mut().enumerate() {
            *v = 0.5
                * (s0.data[i]
                    + s1.data[i] * (2.0 * theta).cos() as f32
                    + s2.data[i] * (2.0 * theta).sin() as f32);
        }
        let name = format!("lp_{k:03}.exr");
        phygap::formats::image_io::write_exr(&root.join(&name), &image).unwrap();
        let object = frame.as_object_mut().unwrap();
        for key in ["s0_path", "s1_path", "s2_path"] {
            object.remove(key);
        }
        object.insert("file_path".into(), name.into());
        object.insert("polarizer_group".into(), format!("cam{}", k % 2).into());
    }
    std::fs::write(root.join("partial.json"), partial.to_string()).unwrap();
    let capture = capture::load(&root.join("partial.json")).unwrap();
    assert_eq!(capture.summary().kinds, ["partial"]);

    // The angles are estimated once PolarDR starts and then learned; a few hundred steps of
    // geometry are not enough to tell θ from θ + 90° reliably, so this run is longer.
    let model = dir.path().join("partial_model");
    let config = TrainConfig {
        initial_surfels: 3000,
        max_surfels: 8000,
        ..small_config(1200)
    };
    let (_, events) = run(&capture, &model, &config, false, None);
    assert!(matches!(&events[0], TrainEvent::Started { mode, .. } if mode == "partial"));
    let metrics: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(model.join("metrics.json")).unwrap())
            .unwrap();
    for (group, truth) in [("cam0", truth[0]), ("cam1", truth[1])] {
        let learned = metrics["polarizer_angles_deg"][group].as_f64().unwrap();
        let error = (learned - truth).rem_euclid(180.0);
        let error = error.min(180.0 - error);
        assert!(
            error < 10.0,
            "{group}: learned {learned:.1}°, truth {truth}°"
        );
    }

    let rgb = dir.path().join("rgb_model");
    let full = capture::load(&root).unwrap();
    let (_, events) = run(
        &full,
        &rgb,
        &TrainConfig {
            mode: Mode::Rgb,
            ..small_config(200)
        },
        false,
        None,
    );
    assert!(matches!(&events[0], TrainEvent::Started { mode, .. } if mode == "rgb"));
    assert!(
        !events
            .iter()
            .any(|e| matches!(e, TrainEvent::Step { losses, .. } if losses.contains_key("stokes"))),
        "rgb mode never uses the Stokes loss"
    );
}

/// A capture trained at a working resolution: the views are shrunk at load, the model records
/// the resolution, the run reports it, and the model evaluates at either resolution.
#[test]
fn a_capture_trains_at_its_working_resolution_and_evaluates_at_both() {
    use phygap::core::resolution::Resolution;
    use phygap::io::capture::{CaptureLimits, LoadOptions};
    use phygap::io::model::{Model, WorkingResolution};
    let dir = tempfile::tempdir().unwrap();
    let options = SynthOptions {
        views: 9,
        size: 48,
        height: Some(32),
        ..SynthOptions::default()
    };
    synth(dir.path(), &options).unwrap();
    let config = TrainConfig {
        resolution: Resolution::Downscale(2),
        backend: phygap::core::config::BackendChoice::Fast,
        gridmap: false,
        ..small_config(120)
    };
    let engine = phygap::pipeline::train::engine_for(&config).unwrap();
    let capture = phygap::pipeline::train::load_capture(
        dir.path(),
        &config,
        &engine,
        &CaptureLimits::DEFAULT,
    )
    .unwrap();
    assert_eq!(capture.views[0].camera.width, 24);
    let model_dir = dir.path().join("model");
    let (outcome, events) = run(&capture, &model_dir, &config, false, None);
    assert_eq!(outcome, TrainOutcome::Finished);
    let started = events
        .iter()
        .find_map(|e| match e {
            TrainEvent::Started { resolution, .. } => Some(resolution.clone()),
            _ => None,
        })
        .unwrap();
    assert_eq!(started, "24×16 (48×32 ÷ 2)");
    let model = Model::load(&model_dir).unwrap();
    assert_eq!(
        model.info.working_resolution,
        Some(WorkingResolution {
            downscale: 2,
            width: 24,
            height: 16,
            full_width: 48,
            full_height: 32
        })
    );
    let score = |resolution| {
        let options = LoadOptions {
            resolution,
            ..LoadOptions::default()
        };
        let capture = capture::load_with(dir.path(), &options).unwrap();
        let truth = phygap::pipeline::scorecard::GroundTruth::default();
        phygap::pipeline::scorecard::score(&model, &capture, &truth).unwrap()
    };
    let (working, full) = (score(Resolution::Downscale(2)), score(Resolution::Full));
    println!(
        "working: PSNR {:?}, normals {:?}; full: PSNR {:?}, normals {:?}",
        working.psnr, working.normal_mae_deg, full.psnr, full.normal_mae_deg
    );
    for report in [&working, &full] {
        assert!(report.psnr.unwrap() > 15.0, "{:?}", report.psnr);
        assert!(report.normal_mae_deg.unwrap().is_finite());
    }
    // The same model against the capture's own pixels: finer detail it never saw, but no
    // misregistration (a wrongly scaled camera would cost far more than a few dB).
    assert!(full.psnr.unwrap() > working.psnr.unwrap() - 3.0);
    assert_ne!(working.psnr, full.psnr, "two resolutions, two comparisons");

    // The same object rendered at twice the size (a raw capture's reference is the sensor's
    // size): `eval`'s working resolution brings it to the model's 24×16 by ÷ 4, not ÷ 2.
    let trained = model.info.working_resolution.unwrap();
    assert_eq!(trained.for_views(48, 32), Resolution::Downscale(2));
    let larger_dir = dir.path().join("larger");
    let larger = SynthOptions {
        size: 96,
        height: Some(64),
        ..options
    };
    synth(&larger_dir, &larger).unwrap();
    let resolution = trained.for_views(96, 64);
    assert_eq!(resolution, Resolution::LongestSide(24));
    let options = LoadOptions {
        resolution,
        ..LoadOptions::default()
    };
    let reference = capture::load_with(&larger_dir, &options).unwrap();
    assert_eq!(
        (
            reference.views[0].camera.width,
            reference.views[0].camera.height
        ),
        (24, 16)
    );
    let truth = phygap::pipeline::scorecard::GroundTruth::default();
    let shrunk = phygap::pipeline::scorecard::score(&model, &reference, &truth).unwrap();
    println!(
        "the larger render at the working size: PSNR {:?}",
        shrunk.psnr
    );
    assert!((shrunk.psnr.unwrap() - working.psnr.unwrap()).abs() < 1.5);
}

/// `phygap diagnose`'s budget on a trained synthetic capture: every variant is scored, the
/// ground truth of everything is the best of them, and the normals' tail is reported.
#[test]
fn the_loss_budget_scores_every_replacement() {
    use phygap::io::model::Model;
    use phygap::pipeline::diagnose::{diagnose, DiagnoseTruth};
    use phygap::pipeline::reconstruction::Reconstruction;
    let dir = tempfile::tempdir().unwrap();
    let capture = synthetic_capture(dir.path(), 9, 32);
    let model_dir = dir.path().join("model");
    let config = TrainConfig {
        gridmap: false,
        ..small_config(200)
    };
    run(&capture, &model_dir, &config, false, None);
    let reconstruction = Reconstruction::new(Model::load(&model_dir).unwrap()).unwrap();
    let truth = DiagnoseTruth::discover(dir.path());
    assert!(
        truth.light.is_some() && truth.relight.is_some(),
        "{truth:?}"
    );
    let report = diagnose(&reconstruction, &capture, &truth).unwrap();
    let names: Vec<&str> = report.variants.iter().map(|v| v.name).collect();
    assert_eq!(
        names,
        [
            "learned",
            "geometry",
            "albedo",
            "roughness",
            "ior",
            "light",
            "albedo+light",
            "materials+light",
            "all"
        ]
    );
    let psnr = |name: &str| {
        report
            .variants
            .iter()
            .find(|v| v.name == name)
            .unwrap()
            .s0_psnr
    };
    println!("{report:#?}");
    assert!(
        psnr("all") > psnr("learned"),
        "the truth of everything is the ceiling"
    );
    assert!(report.variants[0].relit_psnr.is_some());
    assert!(report
        .variants
        .iter()
        .find(|v| v.name == "light")
        .unwrap()
        .relit_psnr
        .is_none());
    let normals = &report.normals;
    assert!(normals.pixels > 100 && normals.p99_degrees >= normals.p90_degrees);
    assert!(normals.p90_degrees >= normals.median_degrees);
    let banded: usize = normals
        .by_silhouette_distance
        .iter()
        .map(|b| b.pixels)
        .sum();
    assert_eq!(banded, normals.pixels);
    // The contours split the cosine distance in two: theirs and the others'.
    let contours = &normals.contours;
    assert!(
        contours.pixel_share > 0.0 && contours.pixel_share < 1.0,
        "{contours:?}"
    );
    assert!((0.0..=1.0).contains(&contours.cosine_distance_share));
    let others = contours.cosine_distance_elsewhere * (1.0 - contours.pixel_share);
    let expected = normals.cosine_distance * (1.0 - contours.cosine_distance_share);
    assert!((others - expected).abs() < 1e-9, "{others} {expected}");
    // The per-view error images hold the same errors as the statistics: one image per test
    // view, defined on exactly the pixels counted, averaging to the MAE.
    assert_eq!(report.normal_error_maps.len(), report.test_views);
    let defined: Vec<f64> = report
        .normal_error_maps
        .iter()
        .inspect(|map| {
            assert_eq!((map.degrees.width, map.degrees.height), (32, 32));
            assert_eq!(map.degrees.channels, 1);
        })
        .flat_map(|map| map.degrees.data.iter().copied())
        .filter(|d| !d.is_nan())
        .map(f64::from)
        .collect();
    assert_eq!(defined.len(), normals.pixels);
    assert!(defined.iter().all(|d| (0.0..=90.0).contains(d)));
    let mean = defined.iter().sum::<f64>() / defined.len() as f64;
    assert!(
        (mean - normals.mae_degrees).abs() < 1e-3,
        "{mean} {normals:?}"
    );
    // The depths are measured on the covered pixels (200 steps leave the surfels a fuzzy volume,
    // so no bound on how far off they are).
    let depths = &report.depths;
    assert!(depths.pixels > 100, "{depths:?}");
    assert!(
        depths.median_abs_offset.is_finite()
            && depths.median_abs_offset >= depths.median_offset.abs(),
        "{depths:?}"
    );
    let shares = [depths.far_behind_share, depths.far_in_front_share];
    assert!(
        shares.iter().all(|s| (0.0..=1.0).contains(s)) && shares.iter().sum::<f64>() <= 1.0,
        "{depths:?}"
    );
}

/// `pose_refinement: auto` (the default) refines the poses of a capture whose cameras are off by
/// a degree or two and leaves exact ones alone; the run reports the decision once, where
/// refinement would start, and the model keeps what it measured.
#[test]
fn auto_refines_estimated_poses_and_leaves_exact_ones() {
    use phygap::io::capture::degrade::{degrade, DegradeOptions};
    let dir = tempfile::tempdir().unwrap();
    let exact = dir.path().join("exact");
    synth(
        &exact,
        &SynthOptions {
            views: 24,
            size: 96,
            ..SynthOptions::default()
        },
    )
    .unwrap();
    let estimated = dir.path().join("estimated");
    let noise = DegradeOptions {
        rotation_sigma_deg: 1.5,
        seed: 3,
        ..DegradeOptions::default()
    };
    degrade(&exact, &estimated, &noise).unwrap();
    let config = TrainConfig {
        refine_views_from: 0.5,
        checkpoint_interval: 0,
        eval_interval: 0,
        ..small_config(240)
    };
    assert_eq!(config.pose_refinement, AutoSwitch::Auto);
    for (capture_dir, refined) in [(&exact, false), (&estimated, true)] {
        let capture = capture::load(capture_dir).unwrap();
        let model_dir = dir.path().join(format!("model-{refined}"));
        let (_, events) = run(&capture, &model_dir, &config, false, None);
        let decisions: Vec<_> = events
            .iter()
            .filter_map(|e| match e {
                TrainEvent::Decided {
                    iteration,
                    setting,
                    on,
                    evidence,
                } => Some((*iteration, setting.as_str(), *on, evidence.clone())),
                _ => None,
            })
            .collect();
        assert_eq!(decisions.len(), 1, "{decisions:?}");
        let (iteration, setting, on, evidence) = &decisions[0];
        assert_eq!(
            (*iteration, *setting, *on),
            (120, "pose_refinement", refined)
        );
        assert!(evidence.contains("px RMS"), "{evidence}");
        let model = Model::load(&model_dir).unwrap();
        let offset = model.info.silhouette_offset_px.unwrap();
        println!("refined {refined}: the masks' own offset {offset:.2} px");
        assert_eq!(
            model.info.refined_poses,
            Some(refined),
            "offset {offset} px"
        );
        assert!(
            if refined { offset > 2.0 } else { offset < 0.5 },
            "offset {offset} px"
        );
        let moved = model
            .train_cameras
            .iter()
            .zip(
                capture
                    .views
                    .iter()
                    .filter(|v| v.split == capture::Split::Train),
            )
            .any(|((_, camera), view)| camera.c2w != view.camera.c2w);
        assert_eq!(moved, refined, "the cameras move only where refined");
    }
}

//! Parity of the fast host backend (f32 SIMD) with the f64 cpu reference, at the gpu backend's
//! tolerances (`common::parity`): forward G-buffers and every gradient group on random scenes,
//! opaque shells, deep stacks (transmittance early stop, `alpha_max` clamp, surfels larger than a
//! tile), sub-pixel surfels (the low-pass branch), images smaller than a tile or a lane group,
//! empty scenes and degenerate surfels; bit-identical results run to run, for any thread count and
//! on every SIMD path; and a short training run.

use glam::{DMat3, DQuat, DVec3};
use phygap::core::camera::Camera;
use phygap::core::config::BackendChoice;
use phygap::core::raster::cpu::CpuBackend;
use phygap::core::raster::fast::{FastBackend, SimdPath};
use phygap::core::raster::{GBuffers, RasterGrads, RasterSettings};
use phygap::core::surfels::{logit, SurfelGrads, Surfels};
use phygap::testing::random_upstream;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

mod common;
use common::parity::{
    assert_backward_parity_with_zero_groups, assert_forward_parity, check_scene, smooth_settings,
    train_with,
};
use common::{deep_stack, random_camera, random_surfels, shell};

fn fast() -> FastBackend {
    let backend = FastBackend::new();
    println!("{}", backend.description());
    backend
}

/// Forward parity, then backward parity at 1e-3 (1e-2 where a threshold pixel was found, as in
/// [`check_scene`]; the `zero` groups exactly zero in both), for one scene and settings; returns
/// both backends' forward buffers.
fn compare(
    surfels: &Surfels,
    camera: &Camera,
    settings: &RasterSettings,
    seed: u64,
    what: &str,
    zero: &[&str],
) -> (GBuffers, GBuffers) {
    let cpu_fwd = CpuBackend.forward(surfels, camera, settings).unwrap();
    let fast_fwd = fast().forward(surfels, camera, settings).unwrap();
    assert_eq!(
        fast_fwd.stats.visible_surfels, cpu_fwd.stats.visible_surfels,
        "{what}"
    );
    assert!(fast_fwd.gbuffers.is_finite(), "{what}: non-finite buffers");
    let outliers = assert_forward_parity(&fast_fwd.gbuffers, &cpu_fwd.gbuffers, what);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
    let upstream = random_upstream(&mut rng, camera.width as usize, camera.height as usize);
    let cpu_grad = CpuBackend
        .backward(surfels, camera, settings, &cpu_fwd, &upstream)
        .unwrap();
    let fast_grad = fast()
        .backward(surfels, camera, settings, &fast_fwd, &upstream)
        .unwrap();
    assert_finite_grads(&fast_grad, what);
    let tol = if outliers == 0 { 1e-3 } else { 1e-2 };
    assert_backward_parity_with_zero_groups(&fast_grad, &cpu_grad, tol, what, zero);
    (fast_fwd.gbuffers, cpu_fwd.gbuffers)
}

fn assert_finite_grads(g: &RasterGrads, what: &str) {
    let s = &g.surfels;
    let all = s
        .position
        .as_flattened()
        .iter()
        .chain(s.log_scale.as_flattened())
        .chain(s.rotation.as_flattened())
        .chain(&s.opacity)
        .chain(s.albedo.as_flattened())
        .chain(&s.roughness)
        .chain(&s.ior)
        .chain(&g.mean2d_grad_norm);
    assert!(
        all.into_iter().all(|v| v.is_finite()),
        "{what}: non-finite gradients"
    );
}

/// Image sizes not multiples of the 16-pixel tile or the 8-lane group: partial tiles on the
/// right and bottom, and groups that run past the tile's edge.
#[test]
fn forward_and_backward_match_cpu_on_random_scenes() {
    for seed in 0..4u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let camera = random_camera(&mut rng, 61, 45);
        let surfels = random_surfels(&mut rng, 300);
        check_scene(
            &fast(),
            &surfels,
            &camera,
            seed,
            &format!("random scene {seed}"),
        );
    }
}

#[test]
fn forward_and_backward_match_cpu_on_an_opaque_shell() {
    for seed in 10..12u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let camera = random_camera(&mut rng, 80, 64);
        let surfels = shell(&mut rng, 1500);
        check_scene(&fast(), &surfels, &camera, seed, &format!("shell {seed}"));
    }
}

/// 300 surfels each covering most of the view (larger than a tile): every pixel's list is
/// hundreds of surfels deep with opacities ≥ 0.2, so compositing stops at `transmittance_min`
/// (asserted: most pixels reach α ≥ 0.999); a third of them have opacity 0.999, so α hits the
/// `alpha_max` clamp (0.99) near their centres.
#[test]
fn deep_stacks_stop_early_and_clamp_alpha_like_cpu() {
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let camera = random_camera(&mut rng, 70, 52);
    let mut surfels = deep_stack(&mut rng, 300);
    for i in (0..surfels.len()).step_by(3) {
        surfels.opacity[i] = logit(0.999);
    }
    let (fast_gb, cpu_gb) = compare(
        &surfels,
        &camera,
        &RasterSettings::default(),
        31,
        "deep stack",
        &[],
    );
    let opaque = cpu_gb.alpha.iter().filter(|&&a| a >= 0.999).count();
    assert!(
        opaque * 2 > cpu_gb.alpha.len(),
        "only {opaque} pixels reach α ≥ 0.999: the early stop is not exercised"
    );
    let clamped_alpha = fast_gb.alpha.iter().filter(|&&a| a >= 0.99).count();
    assert!(clamped_alpha > 0);
}

/// Surfels of 1/50 pixel: the plane's ρ is huge at every pixel centre, so whatever they draw
/// comes from the screen-space low-pass filter (asserted: without the filter they cover less
/// than a tenth of what they cover with it), at their centre's depth.
#[test]
fn sub_pixel_surfels_take_the_low_pass_branch_like_cpu() {
    let mut rng = ChaCha8Rng::seed_from_u64(41);
    let camera = random_camera(&mut rng, 53, 37);
    let mut surfels = random_surfels(&mut rng, 1500);
    for s in &mut surfels.log_scale {
        *s = [0.001f64.ln(), 0.001f64.ln()];
    }
    let coverage = |settings: &RasterSettings| -> f64 {
        let fwd = CpuBackend.forward(&surfels, &camera, settings).unwrap();
        fwd.gbuffers.alpha.iter().sum()
    };
    let with_filter = coverage(&RasterSettings::default());
    let without = coverage(&RasterSettings {
        lowpass_sigma_px: 0.0,
        ..RasterSettings::default()
    });
    assert!(
        with_filter > 10.0 * without && with_filter > 100.0,
        "coverage with the filter {with_filter}, without {without}"
    );
    for (settings, label) in [
        (RasterSettings::default(), "default settings"),
        (smooth_settings(), "smooth settings"),
    ] {
        // The plane never wins: no gradient reaches the scales.
        let what = format!("sub-pixel surfels, {label}");
        compare(&surfels, &camera, &settings, 41, &what, &["log_scale"]);
    }
}

/// With the low-pass filter off every pair takes the plane branch.
#[test]
fn random_scenes_without_the_low_pass_filter_match_cpu() {
    let settings = RasterSettings {
        lowpass_sigma_px: 0.0,
        ..RasterSettings::default()
    };
    for seed in 50..52u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let camera = random_camera(&mut rng, 64, 48);
        let surfels = random_surfels(&mut rng, 300);
        let what = format!("no filter {seed}");
        compare(&surfels, &camera, &settings, seed, &what, &[]);
    }
}

/// Images smaller than one tile and narrower than one lane group.
#[test]
fn images_smaller_than_a_tile_match_cpu() {
    for (seed, (w, h)) in (60u64..).zip([(7, 5), (1, 1), (5, 3), (9, 11), (17, 2)]) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let camera = random_camera(&mut rng, w, h);
        let surfels = deep_stack(&mut rng, 40);
        let what = format!("{w}×{h}");
        let cpu = CpuBackend
            .forward(&surfels, &camera, &RasterSettings::default())
            .unwrap();
        let covered = cpu.gbuffers.alpha.iter().filter(|&&a| a > 0.1).count();
        assert!(covered * 2 >= (w * h) as usize, "{what}: not covered");
        // At 1×1 the pixel is wider than any surfel: the low-pass branch everywhere.
        let zero: &[&str] = if w == 1 { &["log_scale"] } else { &[] };
        compare(
            &surfels,
            &camera,
            &RasterSettings::default(),
            seed,
            &what,
            zero,
        );
    }
}

/// No surfels, and surfels that are all culled (behind the camera), give empty buffers and zero
/// gradients.
#[test]
fn empty_and_fully_culled_scenes() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let camera = random_camera(&mut rng, 20, 17);
    let settings = RasterSettings::default();
    let mut behind = random_surfels(&mut rng, 40);
    let back = -camera.origin();
    for p in &mut behind.position {
        *p = (DVec3::from_array(*p) * 0.1 + camera.origin() - back.normalize() * 0.5).to_array();
    }
    for surfels in [Surfels::zeros(0), behind] {
        let fwd = fast().forward(&surfels, &camera, &settings).unwrap();
        assert_eq!(fwd.stats.visible_surfels, 0);
        assert_eq!(fwd.stats.tile_entries, 0);
        assert_eq!(fwd.gbuffers, GBuffers::zeros(20, 17));
        let upstream = random_upstream(&mut rng, 20, 17);
        let grads = fast()
            .backward(&surfels, &camera, &settings, &fwd, &upstream)
            .unwrap();
        assert_eq!(grads.surfels, SurfelGrads::zeros(surfels.len()));
        assert!(grads.mean2d_grad_norm.iter().all(|&v| v == 0.0));
    }
}

/// Rotation (w, x, y, z) whose normal is `normal` (any tangent frame).
fn quaternion_facing(normal: DVec3) -> [f64; 4] {
    let n = normal.normalize();
    let helper = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let tu = n.cross(helper).normalize();
    let q = DQuat::from_mat3(&DMat3::from_cols(tu, n.cross(tu), n));
    [q.w, q.x, q.y, q.z]
}

/// Degenerate surfels among ordinary ones, handled like the reference: NaN position, scale or
/// opacity, a zero quaternion (culled); zero scale (a plane map of zeros: NaN ρ_3d everywhere,
/// drawn by the low-pass filter alone); one axis collapsed (a line); a surfel seen exactly edge-on
/// (its plane through the camera centre: every intersection at depth 0); and one of scale 1e25,
/// whose plane map (~1e53) overflows f32 unless scaled first.
#[test]
fn degenerate_surfels_are_handled_like_cpu() {
    let mut rng = ChaCha8Rng::seed_from_u64(71);
    let camera = random_camera(&mut rng, 48, 40);
    let mut s = random_surfels(&mut rng, 200);
    s.position[0] = [f64::NAN, 0.0, 0.0];
    s.log_scale[1] = [f64::NAN, 0.0];
    s.opacity[2] = f64::NAN;
    s.rotation[3] = [0.0; 4];
    s.log_scale[4] = [f64::NEG_INFINITY, f64::NEG_INFINITY];
    s.log_scale[5] = [1e-30f64.ln(), 0.1f64.ln()];
    let view = DVec3::from_array(s.position[6]) - camera.origin();
    s.rotation[6] = quaternion_facing(view.cross(DVec3::Z));
    s.log_scale[6] = [0.3f64.ln(), 0.3f64.ln()];
    // Far behind the others, so it is a backdrop rather than a wall in front of them.
    let far = camera.origin() + (-camera.origin()).normalize() * 30.0;
    s.position[7] = far.to_array();
    s.log_scale[7] = [1e25f64.ln(), 1e25f64.ln()];
    s.rotation[7] = quaternion_facing(far - camera.origin());
    let settings = RasterSettings::default();
    let cpu = CpuBackend.forward(&s, &camera, &settings).unwrap();
    assert_eq!(cpu.stats.visible_surfels, 196, "four are culled");
    for (settings, label) in [
        (RasterSettings::default(), "default settings"),
        (smooth_settings(), "smooth settings"),
    ] {
        compare(
            &s,
            &camera,
            &settings,
            71,
            &format!("degenerate, {label}"),
            &[],
        );
    }
}

/// One forward and backward pass; the results compared bit for bit.
fn run_once(backend: &FastBackend, seed: u64) -> (GBuffers, RasterGrads) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let camera = random_camera(&mut rng, 77, 59);
    let surfels = shell(&mut rng, 3000);
    let settings = RasterSettings::default();
    let fwd = backend.forward(&surfels, &camera, &settings).unwrap();
    let upstream = random_upstream(&mut rng, 77, 59);
    let grads = backend
        .backward(&surfels, &camera, &settings, &fwd, &upstream)
        .unwrap();
    (fwd.gbuffers, grads)
}

fn bits(gb: &GBuffers, g: &RasterGrads) -> Vec<u64> {
    let s = &g.surfels;
    gb.alpha
        .iter()
        .chain(&gb.depth)
        .chain(gb.normal.as_flattened())
        .chain(gb.albedo.as_flattened())
        .chain(&gb.roughness)
        .chain(&gb.ior)
        .chain(&gb.depth_sq)
        .chain(gb.depth_normal.as_flattened())
        .chain(s.position.as_flattened())
        .chain(s.log_scale.as_flattened())
        .chain(s.rotation.as_flattened())
        .chain(&s.opacity)
        .chain(s.albedo.as_flattened())
        .chain(&s.roughness)
        .chain(&s.ior)
        .chain(&g.mean2d_grad_norm)
        .map(|v| v.to_bits())
        .collect()
}

/// Twice in a row, in rayon pools of 1, 2 and 3 threads, and on every SIMD path this CPU has:
/// the same bits.
#[test]
fn results_are_bit_identical_across_runs_threads_and_simd_paths() {
    let backend = fast();
    let (gb, g) = run_once(&backend, 81);
    let reference = bits(&gb, &g);
    assert!(g.surfels.opacity.iter().any(|&v| v != 0.0));
    let again = run_once(&backend, 81);
    assert!(bits(&again.0, &again.1) == reference, "second run differs");
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let (gb, g) = pool.install(|| run_once(&backend, 81));
        assert!(bits(&gb, &g) == reference, "{threads} threads differ");
    }
    for path in [SimdPath::Portable, SimdPath::Avx2] {
        match FastBackend::with_path(path) {
            Some(b) => {
                let (gb, g) = run_once(&b, 81);
                assert!(bits(&gb, &g) == reference, "{path:?} differs");
                println!("{path:?}: identical");
            }
            None => {
                assert!(!path.is_available());
                println!("{path:?}: not on this CPU");
            }
        }
    }
}

/// `fast` is a backend choice of its own, and `auto` resolves to it where there is no hardware
/// gpu (checked where `auto` did not find one).
#[test]
fn fast_is_selectable_and_the_auto_fallback() {
    let b = phygap::pipeline::backend::select(BackendChoice::Fast).unwrap();
    assert_eq!(b.name(), "fast");
    assert!(b.description().starts_with("fast ("), "{}", b.description());
    let auto = phygap::pipeline::backend::select(BackendChoice::Auto).unwrap();
    assert!(["gpu", "fast"].contains(&auto.name()), "{}", auto.name());
    let parsed: BackendChoice = serde_json::from_str("\"fast\"").unwrap();
    assert_eq!(parsed, BackendChoice::Fast);
}

/// A 100-iteration training run (same seed: same views, same schedule) on a synthetic capture
/// with the fast backend follows the cpu run: every logged loss within 2% of the cpu run's at
/// the same iteration (f32 gradients perturb the trajectory slightly), the mean loss over
/// iterations 76–100 within 1%, and the final test PSNR within 0.2 dB (the gpu backend's bounds).
#[test]
fn short_training_run_matches_cpu() {
    let dir = tempfile::tempdir().unwrap();
    let options = phygap::pipeline::synth::SynthOptions {
        shape: phygap::pipeline::synth::Shape::Sphere,
        views: 8,
        size: 48,
        ..Default::default()
    };
    phygap::pipeline::synth::synth(dir.path(), &options).unwrap();
    let capture = phygap::io::capture::load(dir.path()).unwrap();
    let t0 = std::time::Instant::now();
    let (cpu, cpu_psnr) = train_with(BackendChoice::Cpu, &capture, false);
    let t1 = std::time::Instant::now();
    let (fast, fast_psnr) = train_with(BackendChoice::Fast, &capture, false);
    let t2 = std::time::Instant::now();
    assert_eq!(cpu.len(), fast.len(), "different numbers of logged steps");
    assert!(cpu.len() >= 20, "too few logged steps: {}", cpu.len());
    let mut worst = 0.0f64;
    for (&(it_c, l_c), &(it_f, l_f)) in cpu.iter().zip(&fast) {
        assert_eq!(it_c, it_f);
        let e = (l_f - l_c).abs() / l_c;
        worst = worst.max(e);
        assert!(e <= 0.02, "iteration {it_c}: loss fast {l_f} vs cpu {l_c}");
    }
    let late = |v: &[(u32, f64)]| {
        let l: Vec<f64> = v.iter().filter(|p| p.0 > 75).map(|p| p.1).collect();
        l.iter().sum::<f64>() / l.len() as f64
    };
    let (cpu_late, fast_late) = (late(&cpu), late(&fast));
    println!(
        "cpu: late loss {cpu_late:.5}, test PSNR {cpu_psnr:.3} dB, {:.1} s; fast: late loss \
         {fast_late:.5}, test PSNR {fast_psnr:.3} dB, {:.1} s; worst per-step loss difference \
         {worst:.2e}",
        (t1 - t0).as_secs_f64(),
        (t2 - t1).as_secs_f64()
    );
    assert!(
        (fast_late - cpu_late).abs() <= 0.01 * cpu_late,
        "late loss fast {fast_late} vs cpu {cpu_late}"
    );
    assert!(
        (fast_psnr - cpu_psnr).abs() <= 0.2,
        "test PSNR fast {fast_psnr} vs cpu {cpu_psnr}"
    );
}

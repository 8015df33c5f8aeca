//! Parity of the wgpu backend with the f64 cpu reference: forward G-buffers, every gradient group
//! of the backward pass (with float atomics and with the compare-and-swap path), and a short
//! training run.
//!
//! These run on whatever adapter `--backend gpu` would open (in CI: lavapipe). Where no adapter
//! can be created at all they print "skipping: no GPU adapter" and return, except under CI
//! (`CI=true`), where that is a failure. With `WGPU_BACKEND` set (CI sets `vulkan`) the adapter's
//! backend must be the one named, so a silent fallback to another API fails.

use glam::DVec3;
use phygap::core::engine::Backend;
use phygap::core::raster::cpu::CpuBackend;
use phygap::core::raster::{GBuffers, RasterSettings};
use phygap::core::surfels::{SurfelGrads, Surfels};
use phygap::gpu::{AtomicsMode, GpuOptions, Walk};
use phygap::testing::random_upstream;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

mod common;
use common::parity::{
    assert_backward_parity, assert_forward_parity, check_scene, smooth_settings, train_with,
};
use common::{deep_stack, gpu, random_camera, random_surfels, shell};

#[test]
fn adapter_matches_wgpu_backend_env() {
    let Some(backend) = gpu(GpuOptions::default()) else {
        return;
    };
    let info = backend.context().adapter_info();
    println!("adapter: {}", backend.context().adapter_summary());
    if let Ok(wanted) = std::env::var("WGPU_BACKEND") {
        let wanted = wgpu::Backends::from_comma_list(&wanted);
        assert!(
            wanted.contains(info.backend.into()),
            "WGPU_BACKEND asks for {wanted:?}, the adapter is {:?}",
            info.backend
        );
        if wanted == wgpu::Backends::VULKAN {
            assert_eq!(info.backend, wgpu::Backend::Vulkan);
        }
    }
}

#[test]
fn forward_and_backward_match_cpu_on_random_scenes() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    println!("{}", gpu.description());
    if gpu.context().has_subgroups() {
        assert_eq!(gpu.walk(), Walk::Subgroup);
    }
    for seed in 0..4u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        // Not multiples of 16: partial tiles on the right and bottom.
        let camera = random_camera(&mut rng, 61, 45);
        let surfels = random_surfels(&mut rng, 300);
        check_scene(
            &gpu,
            &surfels,
            &camera,
            seed,
            &format!("random scene {seed}"),
        );
    }
}

#[test]
fn forward_and_backward_match_cpu_on_an_opaque_shell() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    for seed in 10..12u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let camera = random_camera(&mut rng, 80, 64);
        let surfels = shell(&mut rng, 1500);
        check_scene(&gpu, &surfels, &camera, seed, &format!("shell {seed}"));
    }
}

/// Enough (tile, surfel) entries for the radix sort to span several workgroup blocks (2048
/// entries each) and the tile index two 4-bit digits. The scene is many layers deep, so the
/// depth-derived normals (a host-side f64 function of the f32 depth, which amplifies its rounding
/// by depth over pixel footprint) are left out; the depth itself is held to 1e-4.
#[test]
fn many_entries_sort_across_radix_blocks() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let camera = random_camera(&mut rng, 96, 72);
    let surfels = random_surfels(&mut rng, 3000);
    let settings = smooth_settings();
    let cpu_fwd = CpuBackend.forward(&surfels, &camera, &settings).unwrap();
    let mut gpu_fwd = gpu.forward(&surfels, &camera, &settings).unwrap();
    assert!(
        gpu_fwd.stats.tile_entries > 4 * 2048,
        "only {} entries",
        gpu_fwd.stats.tile_entries
    );
    gpu_fwd.gbuffers.depth_normal = cpu_fwd.gbuffers.depth_normal.clone();
    assert_forward_parity(&gpu_fwd.gbuffers, &cpu_fwd.gbuffers, "many entries");
    let upstream = random_upstream(&mut rng, 96, 72);
    let cpu_grad = CpuBackend
        .backward(&surfels, &camera, &settings, &cpu_fwd, &upstream)
        .unwrap();
    let gpu_grad = gpu
        .backward(&surfels, &camera, &settings, &gpu_fwd, &upstream)
        .unwrap();
    assert_backward_parity(&gpu_grad, &cpu_grad, 1e-3, "many entries");
}

/// The backend's fallback paths, forced on where the adapter has the faster ones: each matches
/// the cpu backend on its own random scene.
#[test]
fn fallback_paths_match_cpu() {
    let variants = [
        (
            GpuOptions {
                force_own_walk: true,
                ..GpuOptions::default()
            },
            "own walk",
        ),
        (
            GpuOptions {
                force_compare_exchange: true,
                ..GpuOptions::default()
            },
            "compare-exchange",
        ),
    ];
    for (seed, (options, what)) in (21u64..).zip(variants) {
        let Some(gpu) = gpu(options) else {
            return;
        };
        assert_eq!(
            gpu.walk() == Walk::OwnEntries,
            options.force_own_walk || !gpu.context().has_subgroups()
        );
        assert_eq!(
            gpu.atomics() == AtomicsMode::CompareExchange,
            options.force_compare_exchange || !gpu.context().has_float_atomics()
        );
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let camera = random_camera(&mut rng, 50, 38);
        let surfels = random_surfels(&mut rng, 250);
        check_scene(&gpu, &surfels, &camera, seed, what);
    }
}

/// A 100-iteration training run (same seed: same views, same schedule) on a synthetic capture
/// with the gpu backend (whole steps on the device) follows the cpu run: every logged loss within
/// 2% of the cpu run's at the same iteration (f32 gradients perturb the trajectory slightly), the
/// mean loss over iterations 76–100 within 1%, and the final test PSNR within 0.2 dB.
fn training_run_matches_cpu(shape: phygap::pipeline::synth::Shape, gridmap: bool) {
    if gpu(GpuOptions::default()).is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let options = phygap::pipeline::synth::SynthOptions {
        shape,
        views: 8,
        size: 48,
        ..Default::default()
    };
    phygap::pipeline::synth::synth(dir.path(), &options).unwrap();
    let capture = phygap::io::capture::load(dir.path()).unwrap();
    let t0 = std::time::Instant::now();
    let (cpu, cpu_psnr) = train_with(phygap::core::config::BackendChoice::Cpu, &capture, gridmap);
    let t1 = std::time::Instant::now();
    let (gpu, gpu_psnr) = train_with(phygap::core::config::BackendChoice::Gpu, &capture, gridmap);
    let t2 = std::time::Instant::now();
    assert_eq!(cpu.len(), gpu.len(), "different numbers of logged steps");
    assert!(cpu.len() >= 20, "too few logged steps: {}", cpu.len());
    let mut worst = 0.0f64;
    for (&(it_c, l_c), &(it_g, l_g)) in cpu.iter().zip(&gpu) {
        assert_eq!(it_c, it_g);
        let e = (l_g - l_c).abs() / l_c;
        worst = worst.max(e);
        assert!(e <= 0.02, "iteration {it_c}: loss gpu {l_g} vs cpu {l_c}");
    }
    let late = |v: &[(u32, f64)]| {
        let l: Vec<f64> = v.iter().filter(|p| p.0 > 75).map(|p| p.1).collect();
        l.iter().sum::<f64>() / l.len() as f64
    };
    let (cpu_late, gpu_late) = (late(&cpu), late(&gpu));
    println!(
        "{shape:?}, GridMap {gridmap}: cpu: late loss {cpu_late:.5}, test PSNR {cpu_psnr:.3} dB, \
         {:.1} s; gpu: late loss {gpu_late:.5}, test PSNR {gpu_psnr:.3} dB, {:.1} s; worst \
         per-step loss difference {worst:.2e}",
        (t1 - t0).as_secs_f64(),
        (t2 - t1).as_secs_f64()
    );
    assert!(
        (gpu_late - cpu_late).abs() <= 0.01 * cpu_late,
        "late loss gpu {gpu_late} vs cpu {cpu_late}"
    );
    assert!(
        (gpu_psnr - cpu_psnr).abs() <= 0.2,
        "test PSNR gpu {gpu_psnr} vs cpu {cpu_psnr}"
    );
}

/// Global light only.
#[test]
fn short_training_run_matches_cpu() {
    training_run_matches_cpu(phygap::pipeline::synth::Shape::Sphere, false);
}

/// A torus (it occludes parts of itself) under GridMap, rebuilt every 20 steps of the PolarDR
/// stage: the probes, the occlusion test and the blended light on the device.
#[test]
fn short_training_run_with_gridmap_matches_cpu() {
    training_run_matches_cpu(phygap::pipeline::synth::Shape::Torus, true);
}

/// No surfels, and surfels that are all culled (behind the camera), give empty buffers and zero
/// gradients without touching a zero-sized binding.
#[test]
fn empty_and_fully_culled_scenes() {
    let Some(gpu) = gpu(GpuOptions::default()) else {
        return;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let camera = random_camera(&mut rng, 20, 17);
    let settings = RasterSettings::default();
    let mut behind = random_surfels(&mut rng, 40);
    let back = -camera.origin();
    for p in &mut behind.position {
        *p = (DVec3::from_array(*p) * 0.1 + camera.origin() - back.normalize() * 0.5).to_array();
    }
    for surfels in [Surfels::zeros(0), behind] {
        let fwd = gpu.forward(&surfels, &camera, &settings).unwrap();
        assert_eq!(fwd.stats.visible_surfels, 0);
        assert_eq!(fwd.stats.tile_entries, 0);
        assert_eq!(fwd.gbuffers, GBuffers::zeros(20, 17));
        let upstream = random_upstream(&mut rng, 20, 17);
        let grads = gpu
            .backward(&surfels, &camera, &settings, &fwd, &upstream)
            .unwrap();
        assert_eq!(grads.surfels, SurfelGrads::zeros(surfels.len()));
        assert!(grads.mean2d_grad_norm.iter().all(|&v| v == 0.0));
    }
}

/// Renders whose buffers exceed the binding limit are split into bands of tile rows (by the
/// G-buffer size, then by the entries of each band) and still match the cpu backend.
#[test]
fn large_renders_are_split_into_bands() {
    let mut rng = ChaCha8Rng::seed_from_u64(41);
    let camera = random_camera(&mut rng, 61, 45);
    // 61 × 8 pixels × 10 f32 = 19,520 bytes of G-buffer per tile row.
    let shallow = random_surfels(&mut rng, 300);
    // ~300 entries per tile: ~40 kB of entries per tile row.
    let deep = deep_stack(&mut rng, 300);
    for (surfels, limit, what) in [
        (&shallow, 40_000, "3 bands of 2 tile rows (G-buffer)"),
        (&deep, 48_000, "bands split again by their entries"),
    ] {
        let Some(gpu) = gpu(GpuOptions {
            max_binding_bytes: Some(limit),
            ..GpuOptions::default()
        }) else {
            return;
        };
        // Every buffer is checked against the limit as it is created, so these renders
        // succeed only if they were split.
        let stats = gpu
            .forward(surfels, &camera, &RasterSettings::default())
            .unwrap()
            .stats;
        let gbuffer_bytes = 61 * 45 * 10 * 4;
        let entry_bytes = stats.tile_entries as u64 * 16;
        assert!(
            gbuffer_bytes > limit || entry_bytes > limit,
            "{what}: no split needed"
        );
        if surfels == &deep {
            // The G-buffer allows bands of 2 tile rows (3 bands); with more than 3 × limit of
            // entries at least one of them must be split again.
            assert!(
                entry_bytes > 3 * limit,
                "{what}: {entry_bytes} bytes of entries"
            );
        }
        check_scene(&gpu, surfels, &camera, 41, what);
    }
}

/// A render that cannot be split small enough (here: one tile row's entries exceed the limit)
/// fails with an error that names the buffer, instead of a device error or a crash.
#[test]
fn unsplittable_render_fails_with_a_clear_error() {
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    let camera = random_camera(&mut rng, 61, 45);
    let surfels = deep_stack(&mut rng, 300);
    // Room for the 300 projected surfels (112 bytes each), not for a tile row of entries.
    let Some(gpu) = gpu(GpuOptions {
        max_binding_bytes: Some(300 * 112 + 1000),
        ..GpuOptions::default()
    }) else {
        return;
    };
    let err = gpu
        .forward(&surfels, &camera, &RasterSettings::default())
        .err()
        .expect("a render beyond the binding limit must fail");
    let msg = err.to_string();
    assert!(
        msg.contains("tile entries") && msg.contains("max_storage_buffer_binding_size"),
        "{msg}"
    );
}

/// With `profile`, every compute pass of a forward and backward pass is timed (where the adapter
/// has timestamp queries); `take_stage_times` drains the totals; without `profile` nothing is timed.
#[test]
fn profiling_times_every_stage() {
    let Some(plain) = gpu(GpuOptions::default()) else {
        return;
    };
    let Some(profiled) = gpu(GpuOptions {
        profile: true,
        ..GpuOptions::default()
    }) else {
        return;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(51);
    let camera = random_camera(&mut rng, 40, 30);
    let surfels = random_surfels(&mut rng, 200);
    let settings = RasterSettings::default();
    let upstream = random_upstream(&mut rng, 40, 30);
    for backend in [&plain, &profiled] {
        let fwd = backend.forward(&surfels, &camera, &settings).unwrap();
        backend
            .backward(&surfels, &camera, &settings, &fwd, &upstream)
            .unwrap();
    }
    assert!(plain.take_stage_times().is_empty());
    let features = profiled.context().device.features();
    if !features.contains(wgpu::Features::TIMESTAMP_QUERY) {
        println!("skipping: the adapter has no timestamp queries");
        return;
    }
    let stages = profiled.take_stage_times();
    let names: Vec<&str> = stages.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "project",
            "emit",
            "radix sort",
            "tile_ranges",
            "rasterize",
            "rasterize_backward",
            "project_backward"
        ]
    );
    assert!(stages.iter().all(|s| s.calls == 1 && s.total_ms >= 0.0));
    assert!(stages.iter().any(|s| s.total_ms > 0.0));
    assert!(profiled.take_stage_times().is_empty());
}

/// `auto` takes the gpu backend only on a hardware adapter (else fast); `gpu` takes any adapter.
#[test]
fn auto_prefers_hardware_and_gpu_takes_any_adapter() {
    use phygap::core::config::BackendChoice;
    use phygap::pipeline::backend::select;
    if gpu(GpuOptions::default()).is_none() {
        return;
    }
    let adapters = phygap::gpu::list_adapters();
    assert!(!adapters.is_empty());
    let auto = select(BackendChoice::Auto).unwrap();
    let hardware = adapters.iter().any(|a| !a.software);
    assert_eq!(auto.name(), if hardware { "gpu" } else { "fast" });
    assert_eq!(select(BackendChoice::Gpu).unwrap().name(), "gpu");
    assert_eq!(select(BackendChoice::Cpu).unwrap().name(), "cpu");
    assert_eq!(select(BackendChoice::Fast).unwrap().name(), "fast");
}

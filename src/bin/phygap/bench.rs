//! `phygap bench ...`: timing of the compute backends on synthetic scenes, of GridMap's rebuild
//! on a trained model, of training steps on a capture, and of a whole run to its quality.

use anyhow::Result;
use clap::{Args, Subcommand};

use phygap::gpu::GpuOptions;
use phygap::pipeline::backend::{select_with, Engine};
use std::path::PathBuf;

use phygap::core::config::{BackendChoice, Iterations};
use phygap::io::model::Model;
use phygap::pipeline::bench::{
    bench_gridmap, bench_quality, bench_raster, bench_train, BenchStage, MemoryPeaks,
};

#[derive(Args)]
pub struct BenchArgs {
    #[command(subcommand)]
    what: BenchWhat,
}

#[derive(Subcommand)]
enum BenchWhat {
    /// Rasterizer forward and forward+backward on surfels covering a unit sphere.
    Raster(RasterBenchArgs),
    /// GridMap on a trained model: mesh extraction and the probes' rebuild.
    Gridmap(GridMapBenchArgs),
    /// Training steps per second on a capture, the run held in one stage.
    Train(TrainBenchArgs),
    /// Time to quality: a whole training run (default settings unless told), its wall time, the
    /// test PSNR along the way and every metric at the end.
    Quality(QualityBenchArgs),
}

#[derive(Args)]
struct QualityBenchArgs {
    /// Capture folder (`transforms.json`); its `scene.json` relight map and `mesh.ply`, where
    /// present, add the relit and Chamfer metrics.
    capture: PathBuf,
    #[arg(long, value_enum)]
    backend: Option<BackendChoice>,
    /// Optimization steps, or auto (default: the configuration's, auto unless it says).
    #[arg(long)]
    iterations: Option<Iterations>,
    /// Training settings (JSON, as `phygap train --config`).
    #[arg(long)]
    config: Option<PathBuf>,
    /// Keep the model in this folder (default: a scratch folder, removed afterwards).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Relighting map of the capture's `relight_s0` views (default: from `scene.json`).
    #[arg(long)]
    relight_envmap: Option<PathBuf>,
    /// Ground-truth mesh (default: the capture's `mesh.ply`).
    #[arg(long)]
    gt_mesh: Option<PathBuf>,
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct TrainBenchArgs {
    /// Capture folder (`transforms.json`).
    capture: PathBuf,
    /// As `phygap train`: `auto` is a real GPU when one is found, else `fast`; `gpu` trains whole
    /// steps on the device (any Vulkan/Metal/DX12 adapter, lavapipe included); `cpu` is the f64
    /// reference.
    #[arg(long, value_enum, default_value = "auto")]
    backend: BackendChoice,
    /// Steps of the run (the schedule's intervals scale with it).
    #[arg(long, default_value_t = 200)]
    iterations: u32,
    /// The stage the whole run is held in.
    #[arg(long, value_enum, default_value = "polar")]
    stage: StageArg,
    /// Training settings (JSON, as `phygap train --config`); the stage boundaries, evaluation and
    /// checkpoints are overridden.
    #[arg(long)]
    config: Option<PathBuf>,
    /// Also time each compute pass on the device (gpu backend with timestamp queries).
    #[arg(long)]
    stages: bool,
    #[arg(long)]
    json: bool,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum StageArg {
    Geometry,
    Polar,
}

#[derive(Args)]
struct GridMapBenchArgs {
    /// Model folder written by `phygap train`.
    model: PathBuf,
    /// Timed rebuilds (the median is reported).
    #[arg(long, default_value_t = 3)]
    repeats: usize,
    /// Print the timing as JSON.
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct RasterBenchArgs {
    /// As `phygap train`: `auto` is a real GPU when one is found, else `fast`; `gpu` runs on any
    /// Vulkan/Metal/DX12 adapter, lavapipe included.
    #[arg(long, value_enum, default_value = "auto")]
    backend: BackendChoice,
    /// Print a JSON array of {surfels, width, height, fwd_ms, fwd_bwd_ms}.
    #[arg(long)]
    json: bool,
    /// Surfel counts, comma separated.
    #[arg(long, value_delimiter = ',', default_values_t = [10_000usize, 50_000, 200_000])]
    surfels: Vec<usize>,
    #[arg(long, default_value_t = 256)]
    width: u32,
    #[arg(long, default_value_t = 256)]
    height: u32,
    /// Timed runs per count (the median is reported).
    #[arg(long, default_value_t = 7)]
    repeats: usize,
    /// Also time each compute pass on the device (gpu backend, where the adapter has timestamp
    /// queries): mean milliseconds per pass over the timed runs.
    #[arg(long)]
    stages: bool,
}

/// Mean device milliseconds per pass of each stage, one column per surfel count.
fn print_stages(rows: &[phygap::pipeline::bench::BenchRow]) {
    if rows.iter().all(|r| r.stages.is_empty()) {
        println!("no stage times: the backend does not measure them (gpu backend, adapter with timestamp queries)");
        return;
    }
    println!();
    print!("{:<20}", "device ms per pass");
    for r in rows {
        print!(" {:>10}", r.surfels);
    }
    println!();
    let mut names: Vec<&str> = Vec::new();
    for s in rows.iter().flat_map(|r| &r.stages) {
        if !names.contains(&s.name.as_str()) {
            names.push(&s.name);
        }
    }
    for name in names {
        print!("{name:<20}");
        for r in rows {
            match r.stages.iter().find(|s| s.name == name) {
                Some(s) => print!(" {:>10.2}", s.total_ms / s.calls.max(1) as f64),
                None => print!(" {:>10}", "-"),
            }
        }
        println!();
    }
}

/// Calls and mean device milliseconds of each pass of a training run.
fn print_passes(passes: &[phygap::core::raster::StageTime]) {
    if passes.is_empty() {
        println!("no pass times: the backend does not measure them (gpu backend, adapter with timestamp queries)");
        return;
    }
    let total: f64 = passes.iter().map(|p| p.total_ms).sum();
    println!(
        "\n{:<24} {:>8} {:>12} {:>8}",
        "pass", "calls", "ms per call", "share"
    );
    for p in passes {
        println!(
            "{:<24} {:>8} {:>12.3} {:>7.1}%",
            p.name,
            p.calls,
            p.total_ms / p.calls.max(1) as f64,
            100.0 * p.total_ms / total
        );
    }
}

/// Peak device buffer memory (gpu backend) and host resident memory of a benchmark's run.
fn print_memory(memory: &MemoryPeaks) {
    let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
    if let Some(bytes) = memory.device_peak_bytes {
        println!("device buffers  {:.1} MiB at the peak", mib(bytes));
    }
    if let Some(bytes) = memory.host_peak_rss_bytes {
        println!("host memory     {:.1} MiB resident at the peak", mib(bytes));
    }
}

/// Mean host milliseconds per device step of each phase (encode, finish, submit, wait).
fn print_host_phases(phases: &[phygap::core::raster::StageTime]) {
    if phases.is_empty() {
        return;
    }
    println!("\nhost per device step (ms; attempts = steps + reruns):");
    for p in phases {
        println!(
            "{:<8} {:>8} attempts {:>9.3}",
            p.name,
            p.calls,
            p.total_ms / p.calls.max(1) as f64
        );
    }
}

/// The backend `choice` resolves to, timing each device pass when `stages` is asked for.
fn bench_backend(choice: BackendChoice, stages: bool) -> Result<Engine> {
    let options = GpuOptions {
        profile: stages,
        ..GpuOptions::default()
    };
    Ok(select_with(choice, options)?)
}

pub fn run(args: &BenchArgs) -> Result<()> {
    match &args.what {
        BenchWhat::Raster(a) => {
            let backend = bench_backend(a.backend, a.stages)?;
            let rows = bench_raster(&*backend, &a.surfels, a.width, a.height, a.repeats)?;
            if a.json {
                println!("{}", serde_json::to_string_pretty(&rows)?);
            } else {
                println!("backend {}", backend.description());
                println!(
                    "{:>9} {:>9} {:>10} {:>13} {:>16}",
                    "surfels", "size", "fwd ms", "fwd+bwd ms", "fwd evals/s"
                );
                for r in &rows {
                    println!(
                        "{:>9} {:>9} {:>10.2} {:>13.2} {:>16.3e}",
                        r.surfels,
                        format!("{}x{}", r.width, r.height),
                        r.fwd_ms,
                        r.fwd_bwd_ms,
                        r.evaluations_per_s()
                    );
                }
                if a.stages {
                    print_stages(&rows);
                }
            }
        }
        BenchWhat::Train(a) => {
            let backend = bench_backend(a.backend, a.stages)?;
            let mut config = crate::train::read_config(a.config.as_deref())?;
            config.iterations = a.iterations.into();
            let stage = match a.stage {
                StageArg::Geometry => BenchStage::Geometry,
                StageArg::Polar => BenchStage::Polar,
            };
            let limits = phygap::io::capture::CaptureLimits::DEFAULT;
            let capture =
                phygap::pipeline::train::load_capture(&a.capture, &config, &backend, &limits)?;
            let t = bench_train(&backend, &capture, &config, stage)?;
            if a.json {
                println!("{}", serde_json::to_string_pretty(&t)?);
            } else {
                println!("backend {}", t.backend);
                println!(
                    "{:?} stage, {}x{}: {} steps in {:.2} s = {:.2} steps/s ({:.1} ms/step), \
                     {} -> {} surfels; {:.2} s before the first timed step",
                    t.stage,
                    t.width,
                    t.height,
                    t.steps,
                    t.seconds,
                    t.steps_per_second,
                    1e3 / t.steps_per_second,
                    t.surfels.0,
                    t.surfels.1,
                    t.startup_seconds
                );
                print_memory(&t.memory);
                print_host_phases(&t.host_phases);
                if a.stages {
                    print_passes(&t.passes);
                }
            }
        }
        BenchWhat::Quality(a) => run_quality(a)?,
        BenchWhat::Gridmap(a) => {
            let t = bench_gridmap(&Model::load(&a.model)?, a.repeats)?;
            if a.json {
                println!("{}", serde_json::to_string_pretty(&t)?);
            } else {
                println!(
                    "mesh    {:.2} s  ({} surfels -> {} triangles at resolution {})",
                    t.mesh_seconds, t.surfels, t.triangles, t.mesh_resolution
                );
                println!(
                    "rebuild {:.2} s  ({} anchors, median of {}, {} threads)",
                    t.rebuild_seconds,
                    t.anchors,
                    a.repeats.max(1),
                    rayon::current_num_threads()
                );
            }
        }
    }
    Ok(())
}

/// `phygap bench quality`: trains with a progress bar, then prints the timing and the scorecard.
fn run_quality(a: &QualityBenchArgs) -> Result<()> {
    let mut config = crate::train::read_config(a.config.as_deref())?;
    if let Some(v) = a.iterations {
        config.iterations = v;
    }
    if let Some(v) = a.backend {
        config.backend = v;
    }
    config.validate()?;
    let truth = phygap::pipeline::scorecard::GroundTruth::discover_or(
        &a.capture,
        a.relight_envmap.clone(),
        a.gt_mesh.clone(),
    );
    let scratch = std::env::temp_dir().join(format!("phygap-bench-quality-{}", std::process::id()));
    let model_dir = a.out.clone().unwrap_or_else(|| scratch.clone());
    let bar = crate::train::progress_bar(config.steps());
    let result = bench_quality(&a.capture, &model_dir, &config, &truth, &mut |e| {
        crate::train::show_event(&bar, e)
    });
    if a.out.is_none() {
        // A scratch folder: failing to remove it loses nothing.
        let _ = std::fs::remove_dir_all(&scratch);
    }
    let run = result?;
    if a.json {
        println!("{}", serde_json::to_string_pretty(&run)?);
        return Ok(());
    }
    println!("backend         {}", run.backend);
    println!(
        "wall time       {:.1} s training ({} steps), {:.1} s scoring",
        run.train_wall_seconds, run.iterations, run.score_wall_seconds
    );
    print_memory(&run.memory);
    println!("test PSNR along the run:");
    for r in &run.progress {
        println!(
            "  step {:>6}  {:>7.1} s  {:>6.2} dB",
            r.iteration, r.seconds, r.test_psnr
        );
    }
    for w in &run.warnings {
        println!("warning: {w}");
    }
    crate::eval::print_table(&run.metrics);
    Ok(())
}

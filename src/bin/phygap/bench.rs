//! `phygap bench ...`: timing of the compute backends on synthetic scenes, and of GridMap's
//! rebuild on a trained model.

use anyhow::Result;
use clap::{Args, Subcommand};

use phygap::backend::select_with;
use phygap::gpu::GpuOptions;
use std::path::PathBuf;

use phygap::bench::{bench_gridmap, bench_raster};
use phygap::config::BackendChoice;
use phygap::model::Model;

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
    /// `gpu` runs on any Vulkan/Metal/DX12 adapter, lavapipe included.
    #[arg(long, value_enum, default_value = "cpu")]
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
fn print_stages(rows: &[phygap::bench::BenchRow]) {
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

pub fn run(args: &BenchArgs) -> Result<()> {
    match &args.what {
        BenchWhat::Raster(a) => {
            let backend = select_with(
                a.backend,
                GpuOptions {
                    profile: a.stages,
                    ..GpuOptions::default()
                },
            )?;
            let rows = bench_raster(backend.as_ref(), &a.surfels, a.width, a.height, a.repeats)?;
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

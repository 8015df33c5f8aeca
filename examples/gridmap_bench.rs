//! Timings of GridMap on a trained model: mesh extraction (R = 256 and the training-time R = 128),
//! the GridMap rebuild, one PolarDR training step and a render of every test view with GridMap vs
//! the global map alone (runs interleaved, best of `--repeats`).
//!
//! `cargo run --release --example gridmap_bench -- MODEL CAPTURE [REPEATS]`

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{bail, Context};
use phygap::core::brdf_lut::BrdfLut;
use phygap::core::envmap::PreparedEnv;
use phygap::core::events::Stage;
use phygap::core::gridmap::GridMap;
use phygap::core::light::LightProbe;
use phygap::core::loss::LossWeights;
use phygap::core::raster::RasterSettings;
use phygap::core::step::ViewTarget;
use phygap::io::capture;
use phygap::io::model::Model;
use phygap::pipeline::mesh_extraction::{self, MeshResolution, GRIDMAP_MESH_RESOLUTION};
use phygap::pipeline::reconstruction::{run_prefilter_plan, Reconstruction};
use phygap::pipeline::train::host_step::{self, StepInputs};
use phygap::pipeline::train::targets::{resolve_mode, view_target};

/// CPU seconds (user + system) of this process so far, from /proc (Linux; 0 elsewhere). On a
/// shared machine CPU time / threads estimates the wall time an idle machine would take.
fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return 0.0;
    };
    // Fields after the parenthesized command name; utime and stime are the 12th and 13th.
    let after = stat.rsplit(')').next().unwrap_or("");
    let fields: Vec<&str> = after.split_whitespace().collect();
    let ticks = |i: usize| {
        fields
            .get(i)
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(0.0)
    };
    (ticks(11) + ticks(12)) / 100.0
}

fn best<T>(repeats: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..repeats {
        let start = Instant::now();
        let out = f();
        best = best.min(start.elapsed().as_secs_f64());
        last = Some(out);
    }
    (best, last.expect("at least one repeat"))
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 3 {
        bail!("usage: gridmap_bench MODEL CAPTURE [REPEATS]");
    }
    let model_dir = PathBuf::from(&args[1]);
    let capture = capture::load(&PathBuf::from(&args[2]))?;
    let repeats: usize = args
        .get(3)
        .map_or(Ok(3), |s| s.parse())
        .context("REPEATS")?;
    let model = Model::load(&model_dir)?;
    println!(
        "rayon threads {}, {} surfels, {} training cameras, env D = {}",
        rayon::current_num_threads(),
        model.surfels.len(),
        model.train_cameras.len(),
        model.envmap.size
    );

    for resolution in [256, GRIDMAP_MESH_RESOLUTION] {
        let (t, mesh) = best(repeats, || {
            mesh_extraction::extract_from_model(&model, MeshResolution::Voxels(resolution))
        });
        let mesh = mesh?;
        println!(
            "mesh R = {resolution}: {t:.2} s ({} triangles)",
            mesh.triangles.len()
        );
    }
    let mesh = mesh_extraction::extract_from_model(
        &model,
        MeshResolution::Voxels(GRIDMAP_MESH_RESOLUTION),
    )?;
    let plan = run_prefilter_plan(&model.config, model.envmap.size)?;
    let env = PreparedEnv::new(&model.envmap, plan)?;
    let cpu_before = cpu_seconds();
    let (t_build, grid) = best(repeats, || {
        GridMap::build(
            &mesh,
            &model.surfels,
            &model.envmap,
            env.clone(),
            model.config.gridmap_anchors,
        )
    });
    let cpu_build = (cpu_seconds() - cpu_before) / repeats as f64;
    let grid = grid?;
    println!(
        "GridMap rebuild ({} anchors, D = {}): {t_build:.2} s wall (best), {cpu_build:.2} CPU-s per build",
        grid.anchors().len(),
        model.envmap.size
    );

    // One PolarDR step per training view, with each light.
    let mode = resolve_mode(&capture, model.config.mode);
    let targets: Vec<ViewTarget> = capture
        .views
        .iter()
        .enumerate()
        .filter(|(_, v)| v.split == capture::Split::Train)
        .map(|(i, v)| view_target(i, v, mode, &model.config))
        .collect();
    let backend = phygap::pipeline::backend::select(model.config.backend)?;
    let inputs = StepInputs {
        backend: &*backend,
        settings: RasterSettings::default(),
        lut: BrdfLut::shared(),
        weights: LossWeights::from(&model.config),
    };
    let angles: BTreeMap<String, f64> = model.polarizer_angles();
    let steps = |light: &dyn LightProbe| -> anyhow::Result<()> {
        for target in &targets {
            let camera = &capture.views[target.view].camera;
            host_step::run(
                &inputs,
                &model.surfels,
                light,
                &angles,
                camera,
                target,
                [1.0; 3],
                Stage::Polar,
            )?;
        }
        Ok(())
    };
    let (mut t_env, mut t_grid) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..repeats {
        t_env = t_env.min(best(1, || steps(&env)).0);
        t_grid = t_grid.min(best(1, || steps(&grid)).0);
    }
    let per = targets.len() as f64;
    println!(
        "PolarDR step: global {:.1} ms, GridMap {:.1} ms (x{:.2})",
        1e3 * t_env / per,
        1e3 * t_grid / per,
        t_grid / t_env
    );
    let (interval, mesh_interval) = (model.config.gridmap_interval, model.config.mesh_interval);
    let (t_mesh128, _) = best(1, || {
        mesh_extraction::extract_from_model(&model, MeshResolution::Voxels(GRIDMAP_MESH_RESOLUTION))
    });
    let amortized = t_grid / per
        + t_build / f64::from(interval.max(1))
        + t_mesh128 / f64::from(mesh_interval.max(1));
    println!(
        "PolarDR stage with rebuilds every {interval} and meshes every {mesh_interval}: x{:.2} per step",
        amortized / (t_env / per)
    );

    // Rendering every test view (the load-time mesh + GridMap build counted separately).
    let cameras: Vec<_> = capture.test_views().map(|v| v.camera).collect();
    let mut plain_model = model.clone();
    plain_model.config.gridmap = false;
    let plain = Reconstruction::new(plain_model)?;
    let (t_load, with_grid) = best(1, || Reconstruction::new(model.clone()));
    let with_grid = with_grid?;
    if with_grid.gridmap().is_none() {
        bail!("the model was not trained with GridMap (or its build failed)");
    }
    let render_all = |r: &Reconstruction| -> anyhow::Result<()> {
        for camera in &cameras {
            r.scene().render(camera)?;
        }
        Ok(())
    };
    let (mut t_plain, mut t_with) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..repeats {
        t_plain = t_plain.min(best(1, || render_all(&plain)).0);
        t_with = t_with.min(best(1, || render_all(&with_grid)).0);
    }
    println!(
        "render {} test views: global {:.1} ms/view, GridMap {:.1} ms/view (x{:.2}); load with GridMap {t_load:.2} s",
        cameras.len(),
        1e3 * t_plain / cameras.len() as f64,
        1e3 * t_with / cameras.len() as f64,
        t_with / t_plain
    );
    Ok(())
}

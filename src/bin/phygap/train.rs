//! `phygap train CAPTURE --out MODEL [...]`: train a reconstruction with a progress bar; Ctrl-C
//! writes a checkpoint and stops (continue with `--resume`).

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use anyhow::{Context, Result};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};

use phygap::core::config::TrainConfig;
use phygap::core::events::TrainEvent;
use phygap::io::capture::CaptureLimits;
use phygap::io::model::ModelInfo;
use phygap::pipeline::scorecard::GroundTruth;
use phygap::pipeline::train::{self, TrainOutcome};

#[derive(Args, Debug)]
pub struct TrainArgs {
    /// Capture folder (with transforms.json) or a transforms JSON file.
    pub capture: PathBuf,
    /// Model folder to write.
    #[arg(long)]
    pub out: PathBuf,
    /// JSON file with any training settings (keys: the long flag names in snake_case; see
    /// `phygap config`). Flags given on the command line override it.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Continue from the model folder's last checkpoint.
    #[arg(long)]
    pub resume: bool,
    /// Every training setting, as a flag.
    #[command(flatten)]
    pub settings: TrainConfig,
}

/// The defaults, overridden by the config file at `path` when given.
pub fn read_config(path: Option<&std::path::Path>) -> Result<TrainConfig> {
    Ok(match path {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("cannot read config {}", path.display()))?;
            TrainConfig::from_json(&text).with_context(|| format!("{}", path.display()))?
        }
        None => TrainConfig::default(),
    })
}

impl TrainArgs {
    /// Defaults, then the config file, then the flags given on the command line (`matches`).
    pub fn config(&self, matches: &clap::ArgMatches) -> Result<TrainConfig> {
        let config = read_config(self.config.as_deref())?.overridden_by(&self.settings, matches);
        config.validate()?;
        Ok(config)
    }
}

pub fn run(args: &TrainArgs, matches: &clap::ArgMatches) -> Result<()> {
    let config = args.config(matches)?;
    let engine = train::engine_for(&config)?;
    let capture = train::load_capture(&args.capture, &config, &engine, &CaptureLimits::DEFAULT)?;
    // The capture's warnings are already on stderr: loading logs each one.
    let cancel = Arc::new(AtomicBool::new(false));
    {
        let cancel = cancel.clone();
        ctrlc::set_handler(move || cancel.store(true, Ordering::Relaxed))
            .context("cannot install the Ctrl-C handler")?;
    }
    let bar = progress_bar(config.steps());
    let mut on_event = |event: &TrainEvent| show_event(&bar, event);
    let outcome = train::train_on(
        &engine,
        &capture,
        &args.out,
        &config,
        args.resume,
        &cancel,
        &mut on_event,
    )?;
    match outcome {
        TrainOutcome::Finished => {
            println!("model written to {}", args.out.display());
            let info = std::fs::read_to_string(args.out.join("model.json")).ok();
            if let Some(r) = info
                .and_then(|json| serde_json::from_str::<ModelInfo>(&json).ok())
                .and_then(|info| info.frame_registration)
            {
                println!(
                    "refined poses: cameras and surfels moved back into the capture's frame \
                     (turned {:.3}°, scaled by {:.4}, shifted {:.2} % of the object's radius)",
                    r.angle_deg,
                    r.scale,
                    100.0 * r.shift_radius
                );
            }
            if let Ok(metrics) = std::fs::read_to_string(args.out.join("metrics.json")) {
                println!("test metrics: {metrics}");
            }
            let truth = GroundTruth::discover(&args.capture);
            if truth.relight_envmap.is_some() || truth.mesh.is_some() {
                println!(
                    "relit PSNR and Chamfer-L1 against the capture's relighting map and mesh: phygap eval {} {}",
                    args.out.display(),
                    args.capture.display()
                );
            }
        }
        TrainOutcome::Interrupted { iteration } => {
            bar.abandon();
            println!(
                "interrupted at iteration {iteration}; continue with: phygap train {} --out {} --resume",
                args.capture.display(),
                args.out.display()
            );
        }
    }
    Ok(())
}

/// The training progress bar: iteration, stage, loss, surfels, test PSNR and the run's own ETA
/// (which knows that PolarDR steps cost more than geometry steps).
pub fn progress_bar(iterations: u32) -> ProgressBar {
    let bar = ProgressBar::new(u64::from(iterations));
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:30} {pos}/{len} {msg}")
            .expect("valid template"),
    );
    bar
}

/// Shows one training event on `bar`.
pub fn show_event(bar: &ProgressBar, event: &TrainEvent) {
    match event {
        TrainEvent::Started {
            iterations,
            mode,
            backend,
            train_views,
            resumed_from,
            resolution,
            radiance_scale,
            ..
        } => {
            bar.println(format!(
                "training: {iterations} steps, mode {mode}, backend {backend}, {train_views} \
                 training views of {resolution} (exposure normalized: ÷ {radiance_scale:.3}){}",
                resumed_from.map_or(String::new(), |it| format!(", resumed at {it}"))
            ));
            bar.set_length(u64::from(*iterations));
            bar.set_position(u64::from(resumed_from.unwrap_or(0)));
        }
        TrainEvent::Step {
            iteration,
            stage,
            loss,
            num_surfels,
            eta_seconds,
            ..
        } => {
            bar.set_position(u64::from(*iteration));
            let eta = eta_seconds.max(0.0).round() as u64;
            bar.set_message(format!(
                "{stage:?} loss {loss:.4} surfels {num_surfels} (eta {}:{:02})",
                eta / 60,
                eta % 60
            ));
        }
        TrainEvent::Evaluated {
            iteration,
            test_psnr,
        } => bar.println(format!("step {iteration}: test PSNR {test_psnr:.2} dB")),
        TrainEvent::Warning { iteration, message } => {
            bar.println(format!("warning at step {iteration}: {message}"));
        }
        TrainEvent::Decided {
            iteration,
            setting,
            on,
            evidence,
        } => {
            let switch = if *on { "on" } else { "off" };
            bar.println(format!("step {iteration}: {setting} {switch}: {evidence}"));
        }
        TrainEvent::Checkpoint { .. } => {}
        TrainEvent::Finished {
            seconds,
            peak_rss_bytes,
            ..
        } => {
            let memory = peak_rss_bytes.map_or(String::new(), |bytes| {
                format!(
                    ", {:.1} MiB resident at the peak",
                    bytes as f64 / (1024.0 * 1024.0)
                )
            });
            bar.finish_with_message(format!("done in {seconds:.1} s{memory}"));
        }
    }
}

//! The `phygap` command line: a thin shell over the library; each subcommand lives in its own module.

mod bench;
mod check_shading;
mod degrade;
mod diagnose;
mod eval;
mod export;
mod import;
mod info;
mod inspect;
mod mesh;
mod relight;
mod render;
mod synth;
mod train;

use clap::{CommandFactory, FromArgMatches, Subcommand};

#[derive(clap::Parser)]
#[command(
    name = "phygap",
    version,
    about = "Relightable reconstruction of glossy objects from polarization captures"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Load and validate a capture; print its views, kinds, resolution, split, bounds and warnings.
    Inspect(inspect::InspectArgs),
    /// Read a dataset in the IDR/NeuS or LLFF layout (per-angle image folders, Stokes .npy,
    /// masks by number): write its transforms.json and print what was decided.
    Import(import::ImportArgs),
    /// Train a reconstruction of a capture into a model folder.
    // Boxed: every training setting makes it several times the other commands' size.
    Train(Box<train::TrainArgs>),
    /// Render novel views of a model (Stokes, DoLP, AoLP, G-buffers, diffuse/specular).
    Render(render::RenderArgs),
    /// Evaluate a model on a capture's test views (JSON metrics).
    Eval(eval::EvalArgs),
    /// The loss budget of a model: its test views with each learned component (geometry,
    /// albedo, roughness, IoR, light) replaced by the capture's ground truth, and its normal
    /// errors' distribution.
    Diagnose(diagnose::DiagnoseArgs),
    /// Render a model under another environment map (relighting).
    Relight(relight::RelightArgs),
    /// Extract a model's surface as a triangle mesh (PLY or OBJ).
    Mesh(mesh::MeshArgs),
    /// Write a model's deliverables (surfels, mesh, glTF with materials, environment map as
    /// EXR/HDR/PNG, config, metrics, renders).
    Export(export::ExportArgs),
    /// Render a small synthetic full-Stokes capture (sample data for a fresh machine).
    Synth(synth::SynthArgs),
    /// Make a realistic capture from a clean one: sensor bit depth and noise, JPEG, per-view
    /// exposure and white balance, vignetting, pose noise, mask erosion/dilation, polarizer
    /// offset (`--preset machine-vision`); true poses and settings go to degrade.json.
    Degrade(degrade::DegradeArgs),
    /// Check PolarDR against a capture's ground truth (GT G-buffers and light, no rasterizer).
    CheckShading(check_shading::CheckShadingArgs),
    /// Time the compute backends on synthetic scenes.
    Bench(bench::BenchArgs),
    /// Print the default training configuration as JSON (a template for --config).
    Config,
    /// List the gpu adapters found and which backend each `--backend` choice would use.
    Info,
}

/// An on/off flag value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Switch {
    On,
    Off,
}

/// Help text of the `--gridmap` override of the commands that render a trained model.
const GRIDMAP_OVERRIDE_HELP: &str = "Render with GridMap on or off regardless of how the model \
was trained (the ablation of METHOD.md §5); default: as trained";

/// Applies a `--gridmap` override to a loaded model before it is rendered.
fn override_gridmap(model: &mut phygap::io::model::Model, switch: Option<Switch>) {
    if let Some(switch) = switch {
        model.config.gridmap = switch == Switch::On;
    }
}

/// The resolution that shows `capture`'s views at the size `model` was trained at
/// ([`WorkingResolution::for_views`](phygap::io::model::WorkingResolution::for_views) of the
/// capture's first camera, read without its images). A model that records no working resolution
/// was trained at the capture's own.
fn working_resolution(
    model: &phygap::io::model::Model,
    capture: &std::path::Path,
) -> anyhow::Result<phygap::core::resolution::Resolution> {
    use phygap::core::resolution::Resolution;
    let Some(trained) = model.info.working_resolution else {
        return Ok(Resolution::Full);
    };
    let cameras = phygap::io::capture::load_cameras(capture)?;
    Ok(cameras
        .first()
        .map_or(Resolution::Downscale(trained.downscale), |(_, camera)| {
            trained.for_views(camera.width, camera.height)
        }))
}

/// Runs `command`; `matches` are the command line's (the training settings need to know which
/// flags were given, to override a config file with those only).
fn run(command: Command, matches: &clap::ArgMatches) -> anyhow::Result<()> {
    match command {
        Command::Inspect(args) => inspect::run(&args),
        Command::Import(args) => import::run(&args),
        Command::Train(args) => {
            let train_matches = matches
                .subcommand_matches("train")
                .expect("the train subcommand's matches");
            train::run(&args, train_matches)
        }
        Command::Render(args) => render::run(&args),
        Command::Eval(args) => eval::run(&args),
        Command::Degrade(args) => degrade::run(&args),
        Command::Diagnose(args) => diagnose::run(&args),
        Command::Relight(args) => relight::run(&args),
        Command::Mesh(args) => mesh::run(&args),
        Command::Export(args) => export::run(&args),
        Command::Synth(args) => synth::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::CheckShading(args) => check_shading::run(&args),
        Command::Info => info::run(),
        Command::Config => {
            let config = phygap::core::config::TrainConfig::default();
            println!("{}", serde_json::to_string_pretty(&config)?);
            Ok(())
        }
    }
}

/// Mesa's device-select Vulkan layer looks for a display server through `XDG_RUNTIME_DIR` and
/// prints `error: XDG_RUNTIME_DIR is invalid or not set` at every adapter probe without one (a
/// server, a container, an ssh session); phygap shows nothing on a display, so there it switches
/// the layer off. Called first, while the process has one thread.
fn quiet_device_select() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none()
        && std::env::var_os("NODEVICE_SELECT").is_none()
    {
        std::env::set_var("NODEVICE_SELECT", "1");
    }
}

/// Colours in the log only on a terminal and never with `NO_COLOR` set.
fn colour_log() -> bool {
    use std::io::IsTerminal;
    std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

fn main() {
    quiet_device_select();
    phygap::pipeline::allocator::keep_large_buffers();
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| "warn,wgpu_hal=error,wgpu_core=error".into()),
        )
        .with_ansi(colour_log())
        .with_writer(std::io::stderr)
        // With RUST_LOG=phygap=debug every pipeline span reports its busy time when it closes.
        .with_span_events(tracing_subscriber::fmt::format::FmtSpan::CLOSE)
        .init();
    // Errors are printed as one line (with their causes), never as a debug dump or backtrace.
    let matches = Cli::command().get_matches();
    let cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit());
    if let Err(e) = run(cli.command, &matches) {
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}

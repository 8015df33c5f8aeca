//! The `phygap` command line: a thin shell over the library; each subcommand lives in its own module.

mod bench;

use anyhow::Result;
use clap::{Parser, Subcommand};

#[derive(Parser)]
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
    /// Print the default training configuration as JSON (a template for --config).
    Config,
    /// Time the compute backends on synthetic scenes.
    Bench(bench::BenchArgs),
}

fn main() -> Result<()> {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env().unwrap_or_else(|_| "warn".into()),
        )
        .with_writer(std::io::stderr)
        .init();
    match Cli::parse().command {
        Command::Config => {
            println!(
                "{}",
                serde_json::to_string_pretty(&phygap::config::TrainConfig::default())?
            );
        }
        Command::Bench(args) => bench::run(args)?,
    }
    Ok(())
}

//! `phygap-api serve` (API and workers) or `phygap-api worker` (workers alone): runs the
//! reconstruction service until SIGTERM or Ctrl-C, then checkpoints and requeues running jobs
//! before exiting. `phygap-api openapi` prints the API's OpenAPI document. `phygap-api stage`
//! is one stage of a job, in the process of its own the service starts for it.

use anyhow::Context;
use clap::Parser;
use phygap_api::cli::{Cli, Command};

fn main() -> anyhow::Result<()> {
    let config = match Cli::parse().command {
        Command::Serve(args) => args.to_config(),
        Command::Worker(args) => args.to_worker_config(),
        Command::Openapi(args) => return args.run(),
        Command::Stage(args) => return stage(&args),
    }
    .context("reading the configuration")?;
    tokio::runtime::Runtime::new()
        .context("starting the async runtime")?
        .block_on(serve(config))
}

/// Colours in the log only on a terminal (a log file or a collector gets plain text) and never
/// with `NO_COLOR` set.
fn colour_log() -> bool {
    use std::io::IsTerminal;
    std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// One stage of a job, in its own process: the memory cap comes first, before anything is read.
fn stage(args: &phygap_api::cli::StageArgs) -> anyhow::Result<()> {
    if let Some(bytes) = args.memory_bytes {
        phygap_api::jobs::child_process_runner::child::limit_memory(bytes)?;
    }
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| "info,wgpu_hal=error,wgpu_core=error".into()),
        )
        .with_ansi(false)
        .with_writer(std::io::stderr)
        .init();
    phygap::pipeline::allocator::keep_large_buffers();
    let pipeline = phygap_api::jobs::in_process_runner::CorePipeline {
        capture_limits: args.capture_limits(),
    };
    Ok(phygap_api::jobs::child_process_runner::child::run(
        &pipeline,
    )?)
}

async fn serve(config: phygap_api::ServiceConfig) -> anyhow::Result<()> {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| "info,wgpu_hal=error,wgpu_core=error".into()),
        )
        .with_ansi(colour_log())
        .with_writer(std::io::stderr)
        .init();
    let executable = std::env::current_exe().context("finding the service's own executable")?;
    let pipeline = std::sync::Arc::new(
        phygap_api::jobs::child_process_runner::ProcessPipeline::for_service(
            executable,
            &config.limits,
        ),
    );
    let server = phygap_api::Server::start(config, pipeline)
        .await
        .context("starting the service")?;
    wait_for_signal().await?;
    server.shutdown().await;
    Ok(())
}

async fn wait_for_signal() -> anyhow::Result<()> {
    let mut terminate = tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate())
        .context("installing the SIGTERM handler")?;
    tokio::select! {
        result = tokio::signal::ctrl_c() => result.context("waiting for Ctrl-C")?,
        _ = terminate.recv() => {}
    }
    Ok(())
}

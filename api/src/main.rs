//! `phygap-api serve` (API and workers) or `phygap-api worker` (workers alone): runs the
//! reconstruction service until SIGTERM or Ctrl-C, then checkpoints and requeues running jobs
//! before exiting. `phygap-api openapi` prints the API's OpenAPI document.

use anyhow::Context;
use clap::Parser;
use phygap_api::cli::{Cli, Command};

fn main() -> anyhow::Result<()> {
    let config = match Cli::parse().command {
        Command::Serve(args) => args.to_config(),
        Command::Worker(args) => args.to_worker_config(),
        Command::Openapi(args) => return args.run(),
    }
    .context("reading the configuration")?;
    phygap::pipeline::allocator::keep_large_buffers();
    tokio::runtime::Runtime::new()
        .context("starting the async runtime")?
        .block_on(serve(config))
}

async fn serve(config: phygap_api::ServiceConfig) -> anyhow::Result<()> {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| "info,wgpu_hal=error,wgpu_core=error".into()),
        )
        .with_writer(std::io::stderr)
        .init();
    let pipeline = phygap_api::pipeline::production_pipeline();
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

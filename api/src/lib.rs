//! The phygap reconstruction service: a JSON HTTP API (axum) over a durable job queue (SQLite),
//! local artifact storage and a pool of workers that run the reconstruction core through the
//! [`pipeline::Pipeline`] trait. HTTP handlers only validate, store and enqueue; all heavy work
//! (archive extraction, capture loading, training, export, relighting) runs on tokio's blocking
//! pool, one blocking thread per running job.
//!
//! Layout of `--data-dir`: `phygap.sqlite3` (captures, jobs, queue, progress), `captures/ID/`
//! (extracted captures), `jobs/ID/model/` (checkpoints), `jobs/ID/input/` (relight inputs),
//! `artifacts/ID/` (downloadable results), `tmp/` (uploads in progress; emptied at start).

pub mod archive;
pub mod artifacts;
pub mod auth;
pub mod cli;
pub mod core_pipeline;
pub mod error;
pub mod material_mesh;
pub mod metrics;
pub mod openapi;
pub mod pipeline;
pub mod queue;
pub mod routes;
pub mod store;
pub mod web;

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use thiserror::Error;
use tokio::task::JoinHandle;
use tokio_util::sync::CancellationToken;

use crate::archive::ExtractLimits;
use crate::artifacts::{ArtifactError, ArtifactStore, FsArtifacts};
use crate::metrics::Metrics;
use crate::pipeline::Pipeline;
use crate::queue::{CancelReason, Runtime};
use crate::store::{SqliteStore, Store, StoreError};

/// Settings of one service instance.
#[derive(Clone, Debug)]
pub struct ServiceConfig {
    pub bind: SocketAddr,
    pub data_dir: PathBuf,
    /// Worker tasks running jobs (0: accept and queue jobs but run none).
    pub workers: usize,
    /// When set, every `/v1` route requires `Authorization: Bearer <token>`.
    pub token: Option<String>,
    /// Largest accepted request body (capture archive, environment map), bytes.
    pub max_upload_bytes: u64,
    pub extract_limits: ExtractLimits,
    /// How long a claimed job stays owned without a heartbeat; a job whose worker died is
    /// requeued this long after its last heartbeat.
    pub lease: Duration,
    /// Claims after which a job whose worker keeps dying is failed instead of requeued.
    pub max_attempts: u32,
    /// How often idle workers look for jobs queued by other processes.
    pub poll_interval: Duration,
}

impl ServiceConfig {
    /// Defaults: loopback port 8080, one worker, no token, 1 GiB uploads, 30 s leases.
    pub fn new(data_dir: impl Into<PathBuf>) -> Self {
        ServiceConfig {
            bind: SocketAddr::from(([127, 0, 0, 1], 8080)),
            data_dir: data_dir.into(),
            workers: 1,
            token: None,
            max_upload_bytes: 1024 << 20,
            extract_limits: ExtractLimits::default(),
            lease: Duration::from_secs(30),
            max_attempts: 5,
            poll_interval: Duration::from_secs(1),
        }
    }
}

/// Folders under the data dir.
#[derive(Clone, Debug)]
pub struct Paths {
    pub root: PathBuf,
    pub database: PathBuf,
    pub tmp: PathBuf,
    pub captures: PathBuf,
    pub jobs: PathBuf,
    pub artifacts: PathBuf,
}

impl Paths {
    pub fn new(root: &Path) -> Self {
        Paths {
            root: root.to_owned(),
            database: root.join("phygap.sqlite3"),
            tmp: root.join("tmp"),
            captures: root.join("captures"),
            jobs: root.join("jobs"),
            artifacts: root.join("artifacts"),
        }
    }

    pub fn capture_dir(&self, capture_id: &str) -> PathBuf {
        self.captures.join(capture_id)
    }

    pub fn model_dir(&self, job_id: &str) -> PathBuf {
        self.jobs.join(job_id).join("model")
    }

    pub fn input_dir(&self, job_id: &str) -> PathBuf {
        self.jobs.join(job_id).join("input")
    }

    pub fn staging_dir(&self, job_id: &str) -> PathBuf {
        self.jobs.join(job_id).join("staging")
    }
}

/// Everything a handler or worker needs; cheap to clone.
#[derive(Clone)]
pub struct AppState {
    pub config: Arc<ServiceConfig>,
    pub paths: Arc<Paths>,
    pub store: Arc<dyn Store>,
    pub artifacts: Arc<dyn ArtifactStore>,
    pub pipeline: Arc<dyn Pipeline>,
    pub metrics: Arc<Metrics>,
    pub runtime: Arc<Runtime>,
    /// Cancelled when the server shuts down (stops workers claiming and ends event streams).
    pub shutdown: CancellationToken,
}

/// Why the service could not start.
#[derive(Debug, Error)]
pub enum StartError {
    #[error("cannot prepare `{path}`: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot open the job store: {0}")]
    Store(#[from] StoreError),
    #[error("cannot open artifact storage: {0}")]
    Artifacts(#[from] ArtifactError),
}

/// A running service: HTTP listener, workers and the lease reaper.
pub struct Server {
    addr: SocketAddr,
    state: AppState,
    http: JoinHandle<std::io::Result<()>>,
    tasks: Vec<JoinHandle<()>>,
}

fn prepare_dir(path: &Path) -> Result<(), StartError> {
    std::fs::create_dir_all(path).map_err(|source| StartError::Io {
        path: path.to_owned(),
        source,
    })
}

/// Removes what a crash can leave behind: partial uploads, and capture folders whose database row
/// was never written (or was deleted).
fn sweep_leftovers(paths: &Paths, store: &dyn Store) -> Result<(), StartError> {
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| StartError::Io { path, source }
    };
    if paths.tmp.exists() {
        std::fs::remove_dir_all(&paths.tmp).map_err(io(&paths.tmp))?;
    }
    prepare_dir(&paths.tmp)?;
    let known: std::collections::HashSet<String> = store.capture_ids()?.into_iter().collect();
    for entry in std::fs::read_dir(&paths.captures).map_err(io(&paths.captures))? {
        let entry = entry.map_err(io(&paths.captures))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if !known.contains(&name) {
            tracing::warn!(
                capture_id = name,
                "removing a capture folder without a record"
            );
            std::fs::remove_dir_all(entry.path()).map_err(io(&entry.path()))?;
        }
    }
    Ok(())
}

impl Server {
    /// Opens the data dir, binds the listener and starts workers; returns once it accepts requests.
    pub async fn start(
        config: ServiceConfig,
        pipeline: Arc<dyn Pipeline>,
    ) -> Result<Server, StartError> {
        let paths = Paths::new(&config.data_dir);
        for dir in [&paths.root, &paths.captures, &paths.jobs, &paths.artifacts] {
            prepare_dir(dir)?;
        }
        let store: Arc<dyn Store> = Arc::new(SqliteStore::open(&paths.database)?);
        sweep_leftovers(&paths, store.as_ref())?;
        let artifacts: Arc<dyn ArtifactStore> =
            Arc::new(FsArtifacts::new(paths.artifacts.clone())?);
        let listener = tokio::net::TcpListener::bind(config.bind)
            .await
            .map_err(|source| StartError::Io {
                path: PathBuf::from(config.bind.to_string()),
                source,
            })?;
        let addr = listener.local_addr().map_err(|source| StartError::Io {
            path: PathBuf::from(config.bind.to_string()),
            source,
        })?;
        let state = AppState {
            config: Arc::new(config),
            paths: Arc::new(paths),
            store,
            artifacts,
            pipeline,
            metrics: Arc::new(Metrics::default()),
            runtime: Arc::new(Runtime::new()),
            shutdown: CancellationToken::new(),
        };
        let router = routes::router(state.clone());
        let stop = state.shutdown.clone();
        let http = tokio::spawn(async move {
            axum::serve(listener, router)
                .with_graceful_shutdown(stop.cancelled_owned())
                .await
        });
        let tasks = queue::worker::spawn(&state);
        tracing::info!(%addr, owner = state.runtime.owner(), "phygap-api listening");
        Ok(Server {
            addr,
            state,
            http,
            tasks,
        })
    }

    /// The bound address (the real port when started on port 0).
    pub fn local_addr(&self) -> SocketAddr {
        self.addr
    }

    pub fn state(&self) -> &AppState {
        &self.state
    }

    /// Graceful stop: no new claims, running jobs are told to checkpoint and go back to the queue
    /// (unlike a user cancel), then workers and HTTP connections are awaited.
    pub async fn shutdown(self) {
        tracing::info!("shutting down: checkpointing running jobs");
        self.state.shutdown.cancel();
        self.state.runtime.cancel_all(CancelReason::Shutdown);
        for task in self.tasks {
            if let Err(e) = task.await {
                tracing::error!(error = %e, "worker task ended abnormally");
            }
        }
        match tokio::time::timeout(Duration::from_secs(10), self.http).await {
            Ok(Ok(Ok(()))) => {}
            Ok(Ok(Err(e))) => tracing::error!(error = %e, "HTTP server error"),
            Ok(Err(e)) => tracing::error!(error = %e, "HTTP task ended abnormally"),
            Err(_) => tracing::warn!("HTTP connections still open after 10 s; leaving them"),
        }
    }
}

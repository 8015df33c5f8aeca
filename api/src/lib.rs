//! The phygap reconstruction service: a JSON HTTP API (axum) over a durable job queue (SQLite, or
//! PostgreSQL shared by several processes), artifact storage (the data dir, or an object store
//! shared by processes on other machines: [`storage::bucket`]) and a pool of workers that run the
//! reconstruction core through the [`jobs::pipeline_seam::Pipeline`] trait. HTTP handlers only
//! validate, store and enqueue; all heavy work (archive extraction, capture loading, training,
//! export, relighting) runs on tokio's blocking pool, one blocking thread per running job. A
//! process serves the API, runs jobs, or both ([`ServiceConfig::api`], [`ServiceConfig::workers`]).
//!
//! The crate is in layers, each module using only its own layer and those below it (lowest
//! first; `api/tests/module_layers.rs` checks it):
//!
//! - [`domain`]: plain values every layer shares (identifiers, quoting inputs in messages);
//! - [`storage`]: the job store (SQLite, PostgreSQL), the object store, artifacts, the keys of
//!   objects, the parts of resumable uploads, archive extraction;
//! - [`accounts`]: who a token belongs to, accounts' limits and quotas, admission of a job's
//!   capture against the job memory limit;
//! - [`jobs`]: the service's settings and shared state, the queue and its workers, the pipeline
//!   seam and its two runners (in this process, in a child process per job), webhooks, purges
//!   and the retention sweeper, metrics;
//! - [`http`]: the router and its routes, the listener's limits and middleware, the one error
//!   type that becomes a JSON error answer, the OpenAPI document, the embedded web page;
//! - this root ([`Server`]) and [`cli`]: the binary's edge, which opens everything and starts
//!   the listener and the workers.
//!
//! Lower layers answer their own errors (`thiserror`); only [`http`] turns them into status codes
//! and JSON error bodies.
//!
//! Layout of `--data-dir`: `phygap.sqlite3` (captures, jobs, queue, progress; unless a PostgreSQL
//! `--database-url` holds them), `captures/ID/` (extracted captures), `jobs/ID/model/`
//! (checkpoints), `jobs/ID/input/` (relight inputs), `artifacts/ID/` (downloadable results, unless
//! an `--artifact-url` holds them), `uploads/ID/` (parts of resumable uploads, unless the object
//! store holds them), `tmp/` (uploads in progress; leftovers removed at start). With an object
//! store, the folders other than `tmp/` are working copies of its objects.

pub mod accounts;
pub mod cli;
pub mod domain;
pub mod http;
pub mod jobs;
pub mod storage;

pub use jobs::settings::{Paths, ServiceConfig, ServiceLimits};
pub use jobs::state::AppState;

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use thiserror::Error;
use tokio::task::JoinHandle;
use tokio_util::sync::CancellationToken;

use crate::jobs::metrics::Metrics;
use crate::jobs::pipeline_seam::Pipeline;
use crate::jobs::queue::{CancelReason, Runtime};
use crate::jobs::{purge, webhooks, worker};
use crate::storage::artifacts::{ArtifactError, ArtifactStore, BucketArtifacts, FsArtifacts};
use crate::storage::bucket::{Bucket, BucketError};
use crate::storage::store::{PostgresStore, SqliteStore, Store, StoreError};

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
    #[error("cannot open the object store: {0}")]
    Bucket(#[from] BucketError),
}

/// A running service: HTTP listener, workers and the lease reaper.
pub struct Server {
    addr: SocketAddr,
    state: AppState,
    http: JoinHandle<()>,
    tasks: Vec<JoinHandle<()>>,
}

fn prepare_dir(path: &Path) -> Result<(), StartError> {
    std::fs::create_dir_all(path).map_err(|source| StartError::Io {
        path: path.to_owned(),
        source,
    })
}

/// How old a leftover must be before a process sharing its database and data dir with others
/// removes it at start: older than any upload still in flight in another process.
const SHARED_LEFTOVER_AGE: Duration = Duration::from_secs(3600);

/// Whether `path` was last modified at least `min_age` ago (always, for a zero age).
fn older_than(path: &Path, min_age: Duration) -> bool {
    min_age.is_zero()
        || std::fs::metadata(path)
            .and_then(|m| m.modified())
            .is_ok_and(|modified| modified.elapsed().is_ok_and(|age| age >= min_age))
}

/// Removes what a crash can leave behind: partial uploads, and capture folders whose database row
/// was never written (or was deleted). Only leftovers older than `min_age` go (a shared data dir
/// may hold another process's uploads in progress).
async fn sweep_leftovers(
    paths: &Paths,
    store: &dyn Store,
    min_age: Duration,
) -> Result<(), StartError> {
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| StartError::Io { path, source }
    };
    prepare_dir(&paths.tmp)?;
    for entry in std::fs::read_dir(&paths.tmp).map_err(io(&paths.tmp))? {
        let path = entry.map_err(io(&paths.tmp))?.path();
        if older_than(&path, min_age) {
            let removed = if path.is_dir() {
                std::fs::remove_dir_all(&path)
            } else {
                std::fs::remove_file(&path)
            };
            removed.map_err(io(&path))?;
        }
    }
    let known: std::collections::HashSet<String> = store.capture_ids().await?.into_iter().collect();
    for entry in std::fs::read_dir(&paths.captures).map_err(io(&paths.captures))? {
        let entry = entry.map_err(io(&paths.captures))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if !known.contains(&name) && older_than(&entry.path(), min_age) {
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
        let (store, leftover_age): (Arc<dyn Store>, _) = match &config.database_url {
            None => (
                Arc::new(SqliteStore::open(&paths.database)?),
                Duration::ZERO,
            ),
            Some(url) => (
                Arc::new(PostgresStore::connect(url).await?),
                SHARED_LEFTOVER_AGE,
            ),
        };
        sweep_leftovers(&paths, store.as_ref(), leftover_age).await?;
        let bucket = match &config.artifact_url {
            Some(url) => Some(Arc::new(Bucket::open(url, &config.artifact_options)?)),
            None => None,
        };
        let artifacts: Arc<dyn ArtifactStore> = match &bucket {
            Some(bucket) => Arc::new(BucketArtifacts::new(bucket.clone())),
            None => Arc::new(FsArtifacts::new(paths.artifacts.clone())?),
        };
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
            bucket,
            pipeline,
            metrics: Arc::new(Metrics::default()),
            runtime: Arc::new(Runtime::new()),
            engines: Arc::default(),
            shutdown: CancellationToken::new(),
        };
        let router = http::router(state.clone());
        let stop = state.shutdown.clone();
        let http_limits = state.config.http;
        let http = tokio::spawn(http::connections::serve(
            listener,
            router,
            http_limits,
            stop,
        ));
        let mut tasks = worker::spawn(&state);
        tasks.extend(purge::spawn_sweeper(&state));
        tasks.push(webhooks::spawn_sender(
            &state,
            http::routes::jobs::webhook_body,
        ));
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
            Ok(Ok(())) => {}
            Ok(Err(e)) => tracing::error!(error = %e, "HTTP task ended abnormally"),
            Err(_) => tracing::warn!("HTTP connections still open after 10 s; leaving them"),
        }
    }
}

//! The phygap reconstruction service: a JSON HTTP API (axum) over a durable job queue (SQLite, or
//! PostgreSQL shared by several processes), artifact storage (the data dir, or an object store
//! shared by processes on other machines: [`bucket`]) and a pool of workers that run the
//! reconstruction core through the [`pipeline::Pipeline`] trait. HTTP handlers only validate,
//! store and enqueue; all heavy work (archive extraction, capture loading, training, export,
//! relighting) runs on tokio's blocking pool, one blocking thread per running job. A process
//! serves the API, runs jobs, or both ([`ServiceConfig::api`], [`ServiceConfig::workers`]).
//!
//! Layout of `--data-dir`: `phygap.sqlite3` (captures, jobs, queue, progress; unless a PostgreSQL
//! `--database-url` holds them), `captures/ID/` (extracted captures), `jobs/ID/model/`
//! (checkpoints), `jobs/ID/input/` (relight inputs), `artifacts/ID/` (downloadable results, unless
//! an `--artifact-url` holds them), `uploads/ID/` (parts of resumable uploads, unless the object
//! store holds them), `tmp/` (uploads in progress; leftovers removed at start). With an object
//! store, the folders other than `tmp/` are working copies of its objects.

pub mod admission;
pub mod archive;
pub mod artifacts;
pub mod auth;
pub mod bucket;
pub mod cli;
pub mod connections;
pub mod core_pipeline;
pub mod error;
pub mod intake;
pub mod job_process;
pub mod metrics;
pub mod object_keys;
pub mod openapi;
pub mod outbound;
pub mod pipeline;
pub mod purge;
pub mod queue;
pub mod quotas;
pub mod routes;
pub mod security_headers;
pub mod slow_body;
pub mod store;
pub mod uploads;
pub mod web;
pub mod webhooks;

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use thiserror::Error;
use tokio::task::JoinHandle;
use tokio_util::sync::CancellationToken;

use crate::archive::ExtractLimits;
use crate::artifacts::{ArtifactError, ArtifactStore, BucketArtifacts, FsArtifacts};
use crate::bucket::{Bucket, BucketError};
use crate::metrics::Metrics;
use crate::pipeline::Pipeline;
use crate::queue::{CancelReason, Runtime};
use crate::store::{PostgresStore, SqliteStore, Store, StoreError};

/// Settings of one service instance.
#[derive(Clone, Debug)]
pub struct ServiceConfig {
    pub bind: SocketAddr,
    pub data_dir: PathBuf,
    /// Worker tasks running jobs (0: accept and queue jobs but run none).
    pub workers: usize,
    /// The admin token: when set (or with account tokens), every `/v1` route and `/metrics`
    /// require `Authorization: Bearer <token>`; this one sees every record.
    pub token: Option<String>,
    /// Account tokens: each sees only its own account's captures and jobs ([`auth`]).
    pub account_tokens: Vec<auth::AccountToken>,
    /// Limits of accounts whose tokens set none of their own ([`quotas`]).
    pub account_defaults: quotas::AccountLimits,
    /// Jobs that ended, and unused captures uploaded, longer ago than this are removed.
    pub retention: Option<Duration>,
    /// How often the sweeper runs (retention, idle uploads).
    pub retention_sweep: Duration,
    /// Resumable uploads untouched for this long are removed with their parts.
    pub upload_expiry: Duration,
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
    /// A PostgreSQL database shared with other processes (`postgres://…`); without one, the
    /// embedded SQLite file in the data dir.
    pub database_url: Option<String>,
    /// The object store shared with other processes (`s3://bucket/prefix`, `file:///folder`) for
    /// captures, relight inputs, checkpoints and artifacts; without one, the data dir alone.
    pub artifact_url: Option<String>,
    /// Settings of that store that win over the AWS environment variables (`aws_endpoint`, …).
    pub artifact_options: Vec<(String, String)>,
    /// Serve the `/v1` API (a worker process serves only `/healthz` and `/metrics`).
    pub api: bool,
    /// What inputs may declare and what a job's process may use.
    pub limits: ServiceLimits,
    /// Connections, timeouts and request sizes of the HTTP listener.
    pub http: connections::HttpLimits,
    /// Artifact downloads answer 307 to a bucket URL presigned for this long (an S3
    /// `--artifact-url` only); `None`: every byte streams through the API.
    pub presigned_downloads: Option<Duration>,
    /// Where jobs' ends are reported, how they are signed, which hosts may be called.
    pub webhooks: webhooks::WebhookSettings,
}

/// The bounds every input and every job is held to (docs/service.md, "Limits").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ServiceLimits {
    /// Views, pixels per view and decoded bytes of a capture (also a relight's cameras' views
    /// and pixels).
    pub capture: phygap::io::capture::CaptureLimits,
    /// Most pixels of an uploaded environment map.
    pub max_envmap_pixels: u64,
    /// Memory, threads and run time of each job's process.
    pub job: job_process::JobLimits,
}

impl ServiceLimits {
    /// 64 megapixels: a 16384 × 4096 map (an 8K HDRI is 33.5).
    pub const DEFAULT_ENVMAP_PIXELS: u64 = 64_000_000;
}

impl Default for ServiceLimits {
    /// The core's capture limits, 64-megapixel maps, and jobs without memory or time caps (the
    /// command line sets those from the machine: [`cli::ServeArgs::to_config`]).
    fn default() -> Self {
        ServiceLimits {
            capture: phygap::io::capture::CaptureLimits::DEFAULT,
            max_envmap_pixels: Self::DEFAULT_ENVMAP_PIXELS,
            job: job_process::JobLimits::NONE,
        }
    }
}

impl ServiceConfig {
    /// Defaults: loopback port 8080, one worker, no token, 1 GiB uploads, 30 s leases.
    pub fn new(data_dir: impl Into<PathBuf>) -> Self {
        ServiceConfig {
            bind: SocketAddr::from(([127, 0, 0, 1], 8080)),
            data_dir: data_dir.into(),
            workers: 1,
            token: None,
            account_tokens: Vec::new(),
            account_defaults: quotas::AccountLimits::default(),
            retention: None,
            retention_sweep: Duration::from_secs(3600),
            upload_expiry: Duration::from_secs(24 * 3600),
            max_upload_bytes: 1024 << 20,
            extract_limits: ExtractLimits::default(),
            lease: Duration::from_secs(30),
            max_attempts: 5,
            poll_interval: Duration::from_secs(1),
            database_url: None,
            artifact_url: None,
            artifact_options: Vec::new(),
            api: true,
            limits: ServiceLimits::default(),
            http: connections::HttpLimits::DEFAULT,
            webhooks: webhooks::WebhookSettings::default(),
            presigned_downloads: None,
        }
    }
}

impl ServiceConfig {
    /// Every account's limits: the tokens file's over the defaults.
    pub fn quotas(&self) -> quotas::Quotas {
        quotas::Quotas {
            defaults: self.account_defaults,
            accounts: self
                .account_tokens
                .iter()
                .map(|t| (t.account.clone(), t.limits))
                .collect(),
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
    /// The shared object store, where the deployment has one ([`bucket`]).
    pub bucket: Option<Arc<Bucket>>,
    pub pipeline: Arc<dyn Pipeline>,
    pub metrics: Arc<Metrics>,
    pub runtime: Arc<Runtime>,
    /// This machine's engines, probed once in a job's process on the first `GET /v1/info`.
    pub engines: Arc<tokio::sync::OnceCell<pipeline::Engines>>,
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
        let router = routes::router(state.clone());
        let stop = state.shutdown.clone();
        let http_limits = state.config.http;
        let http = tokio::spawn(connections::serve(listener, router, http_limits, stop));
        let mut tasks = queue::worker::spawn(&state);
        tasks.extend(purge::spawn_sweeper(&state));
        tasks.push(webhooks::spawn_sender(&state));
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

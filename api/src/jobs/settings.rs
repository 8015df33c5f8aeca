//! The service's settings: what one instance serves and runs ([`ServiceConfig`]), the bounds it
//! holds inputs and jobs to ([`ServiceLimits`], [`JobLimits`]), the HTTP listener's limits
//! ([`HttpLimits`], enforced by [`crate::http::connections`] and [`crate::http::slow_body`]) and
//! the folders of its data dir ([`Paths`]). Plain values: the command line builds them
//! ([`crate::cli`]), [`crate::Server::start`] opens what they name.

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::accounts::auth;
use crate::accounts::limits::{AccountLimits, Quotas};
use crate::jobs::webhook_targets::WebhookSettings;
use crate::storage::archive::ExtractLimits;

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
    pub account_defaults: AccountLimits,
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
    pub http: HttpLimits,
    /// Artifact downloads answer 307 to a bucket URL presigned for this long (an S3
    /// `--artifact-url` only); `None`: every byte streams through the API.
    pub presigned_downloads: Option<Duration>,
    /// Where jobs' ends are reported, how they are signed, which hosts may be called.
    pub webhooks: WebhookSettings,
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
    pub job: JobLimits,
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
            job: JobLimits::NONE,
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
            account_defaults: AccountLimits::default(),
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
            http: HttpLimits::DEFAULT,
            webhooks: WebhookSettings::default(),
            presigned_downloads: None,
        }
    }
}

impl ServiceConfig {
    /// Every account's limits: the tokens file's over the defaults.
    pub fn quotas(&self) -> Quotas {
        Quotas {
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

/// What a job's process may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JobLimits {
    /// Its heap and other private writable memory (`RLIMIT_DATA`), bytes; `None`: unlimited.
    pub memory_bytes: Option<u64>,
    /// The worker threads of its compute pool (`RAYON_NUM_THREADS`); `None`: one per core.
    pub threads: Option<usize>,
    /// Longest one stage may run (wall clock) before it is stopped as `time_limit`.
    pub max_runtime: Option<Duration>,
}

impl JobLimits {
    /// No memory cap, every core, no time limit.
    pub const NONE: JobLimits = JobLimits {
        memory_bytes: None,
        threads: None,
        max_runtime: None,
    };
}

/// The memory a job's process gets by default: three quarters of the machine's memory
/// (`MemTotal`, taken as 32 GiB where it cannot be read) shared among the `workers` jobs that
/// run at once, at least 1 GiB.
pub fn default_job_memory(workers: usize) -> u64 {
    let total = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
            let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
            Some(kib * 1024)
        })
        .unwrap_or(32 << 30);
    (total / 4 * 3 / workers.max(1) as u64).max(1 << 30)
}

/// Bounds on connections and requests (`--max-connections`, `--header-timeout-seconds`, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HttpLimits {
    /// Connections served at once.
    pub max_connections: usize,
    /// Connections served at once from one client address (behind a reverse proxy every client
    /// has the proxy's address: raise it to `max_connections` there).
    pub max_connections_per_client: usize,
    /// Longest wait for a complete request head, also between requests of a kept-alive
    /// connection.
    pub header_timeout: Duration,
    /// A request body must bring at least this many bytes in every `body_window`.
    pub min_body_bytes: u64,
    /// See `min_body_bytes`.
    pub body_window: Duration,
    /// Longest request target (path and query), bytes (414 above).
    pub max_uri_bytes: usize,
    /// Most bytes of header names and values together (431 above).
    pub max_header_bytes: usize,
    /// Most header fields (431 above).
    pub max_headers: usize,
}

impl HttpLimits {
    /// 512 connections, 128 of one client; 15 s for a request head; bodies at 8 KiB per 10 s at least; 8 KiB
    /// targets; 32 KiB and 100 header fields.
    pub const DEFAULT: HttpLimits = HttpLimits {
        max_connections: 512,
        max_connections_per_client: 128,
        header_timeout: Duration::from_secs(15),
        min_body_bytes: 8 << 10,
        body_window: Duration::from_secs(10),
        max_uri_bytes: 8 << 10,
        max_header_bytes: 32 << 10,
        max_headers: 100,
    };
}

impl Default for HttpLimits {
    fn default() -> Self {
        HttpLimits::DEFAULT
    }
}

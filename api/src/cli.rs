//! The `phygap-api` command line (also read by the deploy test to check the flags the Dockerfile
//! and the systemd unit use).

use std::net::SocketAddr;
use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use phygap::io::capture::CaptureLimits;

use crate::accounts::auth::{read_tokens_file, TokensFileError, MIN_TOKEN_CHARS};
use crate::accounts::limits::AccountLimits;
use crate::jobs::outbound::AddressPolicy;
use crate::jobs::settings::HttpLimits;
use crate::jobs::settings::JobLimits;
use crate::jobs::webhook_targets::WebhookSettings;
use crate::{ServiceConfig, ServiceLimits};

/// The longest `--max-runtime-minutes`: ten years (a longer one would overflow the clock's
/// deadline arithmetic).
const MAX_RUNTIME_MINUTES: u64 = 10 * 366 * 24 * 60;

#[derive(Debug, Parser)]
#[command(
    name = "phygap-api",
    version,
    about = "The phygap reconstruction service (HTTP API, job queue, workers)"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Serve the HTTP API and run queued jobs (`--workers`; 0: the API alone) until SIGTERM or
    /// Ctrl-C.
    Serve(ServeArgs),
    /// Run queued jobs of a shared database and object store, without the API (its listener
    /// answers only /healthz and /metrics), until SIGTERM or Ctrl-C.
    Worker(ServeArgs),
    /// Print the OpenAPI document of the HTTP API (YAML, derived from the code), or write it to
    /// `--out` (`--out api/openapi.yaml` regenerates the committed copy).
    Openapi(OpenapiArgs),
    /// Run one stage of a job (the service starts this in a child process of its own and talks
    /// to it on standard input and output; not for people).
    #[command(hide = true)]
    Stage(StageArgs),
}

/// The limits a job's process runs under (set by the service from its own flags).
#[derive(Debug, Args)]
pub struct StageArgs {
    /// Cap on the process's heap and private writable memory, bytes.
    #[arg(long)]
    pub memory_bytes: Option<u64>,
    #[arg(long, default_value_t = CaptureLimits::DEFAULT.max_views)]
    pub max_views: usize,
    #[arg(long, default_value_t = CaptureLimits::DEFAULT.max_pixels_per_view)]
    pub max_pixels_per_view: u64,
    #[arg(long, default_value_t = CaptureLimits::DEFAULT.max_decoded_bytes)]
    pub max_decoded_bytes: u64,
}

impl StageArgs {
    pub fn capture_limits(&self) -> CaptureLimits {
        CaptureLimits {
            max_views: self.max_views,
            max_pixels_per_view: self.max_pixels_per_view,
            max_decoded_bytes: self.max_decoded_bytes,
        }
    }
}

#[derive(Debug, Args)]
pub struct OpenapiArgs {
    /// File to write (default: standard output).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

impl OpenapiArgs {
    /// Writes the document where the flags say.
    pub fn run(&self) -> anyhow::Result<()> {
        use anyhow::Context;
        let yaml = crate::http::openapi::spec_yaml().context("rendering the OpenAPI document")?;
        match &self.out {
            Some(path) => {
                std::fs::write(path, yaml).with_context(|| format!("writing {}", path.display()))?
            }
            None => {
                use std::io::Write;
                std::io::stdout()
                    .write_all(yaml.as_bytes())
                    .context("writing the OpenAPI document")?;
            }
        }
        Ok(())
    }
}

/// Flags that cannot make a service.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    #[error(transparent)]
    TokensFile(#[from] TokensFileError),
    #[error(
        "the admin token has {0} characters; it needs at least {MIN_TOKEN_CHARS} (and is best \
         given as PHYGAP_TOKEN, which `ps` does not show, rather than --token)"
    )]
    WeakToken(usize),
    #[error("--webhook: {0}")]
    Webhook(String),
    #[error("--webhook-allow-cidr: {0}")]
    WebhookAllowCidr(String),
}

#[derive(Debug, Args)]
pub struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1:8080", env = "PHYGAP_BIND")]
    pub bind: SocketAddr,
    /// Folder of the database, captures, checkpoints and artifacts.
    #[arg(long, default_value = "phygap-data", env = "PHYGAP_DATA_DIR")]
    pub data_dir: PathBuf,
    /// Jobs run at once (0: queue jobs without running any).
    #[arg(long, default_value_t = 1, env = "PHYGAP_WORKERS")]
    pub workers: usize,
    /// Require `Authorization: Bearer TOKEN` on every /v1 route (at least 16 characters; prefer
    /// the PHYGAP_TOKEN variable: a flag shows in `ps`).
    #[arg(long, env = "PHYGAP_TOKEN", hide_env_values = true)]
    pub token: Option<String>,
    /// Account tokens, one `ACCOUNT TOKEN` pair a line: each token sees only its account's
    /// captures and jobs (the --token one sees all).
    #[arg(long, env = "PHYGAP_TOKENS_FILE")]
    pub tokens_file: Option<PathBuf>,
    /// Remove jobs that ended, and unused captures uploaded, more than this many days ago
    /// (with their artifacts and checkpoints); default: keep everything.
    #[arg(long, env = "PHYGAP_RETENTION_DAYS",
          value_parser = clap::value_parser!(u32).range(1..=36_500))]
    pub retention_days: Option<u32>,
    /// Remove resumable uploads (and their parts) untouched for this many hours.
    #[arg(long, default_value_t = 24, env = "PHYGAP_UPLOAD_EXPIRY_HOURS",
          value_parser = clap::value_parser!(u64).range(1..=8_760))]
    pub upload_expiry_hours: u64,
    /// Largest upload (capture archive, environment map) in MiB; larger ones get 413.
    #[arg(long, default_value_t = 1024, env = "PHYGAP_MAX_UPLOAD_MB",
          value_parser = clap::value_parser!(u64).range(1..=1_048_576))]
    pub max_upload_mb: u64,
    /// PostgreSQL database for captures, jobs and the queue, shared by every process serving
    /// the same data dir (`postgres://user:password@host:5432/phygap`); default: the embedded
    /// SQLite file in the data dir.
    #[arg(long, env = "PHYGAP_DATABASE_URL", hide_env_values = true)]
    pub database_url: Option<String>,
    /// Object store for captures, checkpoints and artifacts, shared by processes on other
    /// machines: `s3://bucket/prefix` (endpoint and credentials from the usual AWS variables:
    /// AWS_ENDPOINT_URL, AWS_ACCESS_KEY_ID, AWS_SECRET_ACCESS_KEY, AWS_REGION, AWS_ALLOW_HTTP)
    /// or `file:///shared/folder`; default: the data dir alone.
    #[arg(long, env = "PHYGAP_ARTIFACT_URL")]
    pub artifact_url: Option<String>,
    /// Seconds a worker owns a job without a heartbeat; a job whose worker died is taken over
    /// by another after this.
    #[arg(long, default_value_t = 30, env = "PHYGAP_LEASE_SECONDS",
          value_parser = clap::value_parser!(u64).range(2..=3600))]
    pub lease_seconds: u64,
    /// Memory of each job's process in MiB (its heap; a job over it fails `out_of_memory`);
    /// default: three quarters of this machine's memory divided among the workers.
    #[arg(long, env = "PHYGAP_JOB_MEMORY_MB",
          value_parser = clap::value_parser!(u64).range(64..=16_777_216))]
    pub job_memory_mb: Option<u64>,
    /// Compute threads of each job's process; default: one per core.
    #[arg(long, env = "PHYGAP_JOB_THREADS",
          value_parser = clap::value_parser!(u64).range(1..=4096))]
    pub job_threads: Option<u64>,
    /// Longest a job's stage (training, export, relighting) may run, in minutes; a job over it
    /// fails `time_limit`; 0: no limit (at most ten years).
    #[arg(long, default_value_t = 1440, env = "PHYGAP_MAX_RUNTIME_MINUTES",
          value_parser = clap::value_parser!(u64).range(0..=MAX_RUNTIME_MINUTES))]
    pub max_runtime_minutes: u64,
    /// Most views (frames) a capture may have.
    #[arg(long, default_value_t = CaptureLimits::DEFAULT.max_views, env = "PHYGAP_MAX_VIEWS",
          value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(2..=1_000_000))]
    pub max_views: usize,
    /// Most megapixels one view of a capture (or one relight camera) may have.
    #[arg(long, default_value_t = CaptureLimits::DEFAULT.max_pixels_per_view / 1_000_000,
          env = "PHYGAP_MAX_MEGAPIXELS",
          value_parser = clap::value_parser!(u64).range(1..=4096))]
    pub max_megapixels: u64,
    /// Most MiB a capture's views may hold once decoded (40 bytes a pixel of every view).
    #[arg(long, default_value_t = CaptureLimits::DEFAULT.max_decoded_bytes >> 20,
          env = "PHYGAP_MAX_CAPTURE_MB",
          value_parser = clap::value_parser!(u64).range(1..=16_777_216))]
    pub max_capture_mb: u64,
    /// Most megapixels of an uploaded environment map (relighting).
    #[arg(long, default_value_t = ServiceLimits::DEFAULT_ENVMAP_PIXELS / 1_000_000,
          env = "PHYGAP_MAX_ENVMAP_MEGAPIXELS",
          value_parser = clap::value_parser!(u64).range(1..=1024))]
    pub max_envmap_megapixels: u64,
    /// HTTP connections served at once (more wait until one closes).
    #[arg(long, default_value_t = HttpLimits::DEFAULT.max_connections,
          env = "PHYGAP_MAX_CONNECTIONS",
          value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=1_000_000))]
    pub max_connections: usize,
    /// Seconds a connection may take to send a request's head, or sit idle between requests.
    #[arg(long, default_value_t = HttpLimits::DEFAULT.header_timeout.as_secs(),
          env = "PHYGAP_HEADER_TIMEOUT_SECONDS",
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    pub header_timeout_seconds: u64,
    /// A request body must bring 8 KiB in every window of this many seconds, or is cut off
    /// (408).
    #[arg(long, default_value_t = HttpLimits::DEFAULT.body_window.as_secs(),
          env = "PHYGAP_UPLOAD_WINDOW_SECONDS",
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    pub upload_window_seconds: u64,
    /// Jobs an account runs at once unless its line in the tokens file says `max_running=N`;
    /// more wait in the queue. Default: no limit.
    #[arg(long, env = "PHYGAP_ACCOUNT_MAX_RUNNING",
          value_parser = clap::value_parser!(u32).range(1..))]
    pub account_max_running: Option<u32>,
    /// Jobs an account may have queued unless its line says `max_queued=N`; a submit beyond
    /// answers 429. Default: no limit.
    #[arg(long, env = "PHYGAP_ACCOUNT_MAX_QUEUED")]
    pub account_max_queued: Option<u32>,
    /// MiB of captures and open uploads an account may store unless its line says
    /// `max_storage_mb=N`. Default: no limit.
    #[arg(long, env = "PHYGAP_ACCOUNT_MAX_STORAGE_MB",
          value_parser = clap::value_parser!(u64).range(1..=1 << 40))]
    pub account_max_storage_mb: Option<u64>,
    /// Highest job priority an account may ask for unless its line says `max_priority=N`
    /// (-100 to 100; the admin may use up to 100).
    #[arg(long, default_value_t = 0, env = "PHYGAP_ACCOUNT_MAX_PRIORITY",
          value_parser = clap::value_parser!(i32).range(-100..=100))]
    pub account_max_priority: i32,
    /// Artifact downloads answer 307 to a bucket URL valid for this many seconds (with an S3
    /// --artifact-url), so the bytes come from the bucket, not through the API. Default: off.
    #[arg(long, env = "PHYGAP_PRESIGNED_DOWNLOADS_SECONDS",
          value_parser = clap::value_parser!(u64).range(1..=604_800))]
    pub presigned_downloads_seconds: Option<u64>,
    /// URL every job's end is POSTed to when the job names none of its own.
    #[arg(long, env = "PHYGAP_WEBHOOK")]
    pub webhook: Option<String>,
    /// Key of the webhooks' HMAC-SHA256 signatures (header Phygap-Signature).
    #[arg(long, env = "PHYGAP_WEBHOOK_SECRET", hide_env_values = true)]
    pub webhook_secret: Option<String>,
    /// Hosts webhooks may call, comma separated (default: any public host; the service calls
    /// out from inside its network, so list them).
    #[arg(long, env = "PHYGAP_WEBHOOK_HOSTS", value_delimiter = ',')]
    pub webhook_hosts: Vec<String>,
    /// Internal address ranges webhooks may reach, comma separated CIDR (`127.0.0.0/8`,
    /// `10.1.0.0/16`, `::1/128`). Default: none (loopback, private, link-local, unique-local,
    /// CGNAT, multicast and unspecified addresses are refused, however a URL names them).
    #[arg(long, env = "PHYGAP_WEBHOOK_ALLOW_CIDR", value_delimiter = ',')]
    pub webhook_allow_cidr: Vec<String>,
    /// Connections one client address may hold open at once (past it, its new connections are
    /// closed at once), so one client cannot take every slot of --max-connections.
    #[arg(long, default_value_t = HttpLimits::DEFAULT.max_connections_per_client,
          env = "PHYGAP_MAX_CONNECTIONS_PER_CLIENT",
          value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=1_000_000))]
    pub max_connections_per_client: usize,
}

impl ServeArgs {
    /// The service configuration these flags describe (reads the tokens file).
    pub fn to_config(&self) -> Result<ServiceConfig, ConfigError> {
        let mut config = ServiceConfig::new(self.data_dir.clone());
        if let Some(token) = self.token.as_deref().filter(|t| !t.is_empty()) {
            let chars = token.chars().count();
            if chars < MIN_TOKEN_CHARS {
                return Err(ConfigError::WeakToken(chars));
            }
        }
        if let Some(path) = &self.tokens_file {
            config.account_tokens = read_tokens_file(path)?;
        }
        config.account_defaults = AccountLimits {
            max_running: self.account_max_running,
            max_queued: self.account_max_queued,
            max_storage_bytes: self.account_max_storage_mb.map(|mb| mb << 20),
            max_priority: Some(self.account_max_priority),
        };
        config.presigned_downloads = self
            .presigned_downloads_seconds
            .map(std::time::Duration::from_secs);
        config.retention = self
            .retention_days
            .map(|days| std::time::Duration::from_secs(u64::from(days) * 86_400));
        config.bind = self.bind;
        config.workers = self.workers;
        config.token = self.token.clone().filter(|t| !t.is_empty());
        config.max_upload_bytes = self.max_upload_mb << 20;
        config.upload_expiry = std::time::Duration::from_secs(self.upload_expiry_hours * 3600);
        config.database_url = self.database_url.clone().filter(|url| !url.is_empty());
        config.artifact_url = self.artifact_url.clone().filter(|url| !url.is_empty());
        config.lease = std::time::Duration::from_secs(self.lease_seconds);
        config.http = HttpLimits {
            max_connections: self.max_connections,
            max_connections_per_client: self.max_connections_per_client,
            header_timeout: std::time::Duration::from_secs(self.header_timeout_seconds),
            body_window: std::time::Duration::from_secs(self.upload_window_seconds),
            ..HttpLimits::DEFAULT
        };
        config.webhooks = WebhookSettings {
            default_url: self.webhook.clone().filter(|u| !u.is_empty()),
            secret: self.webhook_secret.clone().unwrap_or_default(),
            allowed_hosts: self
                .webhook_hosts
                .iter()
                .map(|h| h.trim().to_owned())
                .filter(|h| !h.is_empty())
                .collect(),
            addresses: AddressPolicy::allowing(
                self.webhook_allow_cidr
                    .iter()
                    .filter(|r| !r.trim().is_empty()),
            )
            .map_err(ConfigError::WebhookAllowCidr)?,
        };
        if let Some(url) = &config.webhooks.default_url {
            config
                .webhooks
                .parse(url)
                .map_err(|e| ConfigError::Webhook(e.message))?;
        }
        config.limits = ServiceLimits {
            capture: CaptureLimits {
                max_views: self.max_views,
                max_pixels_per_view: self.max_megapixels * 1_000_000,
                max_decoded_bytes: self.max_capture_mb << 20,
            },
            max_envmap_pixels: self.max_envmap_megapixels * 1_000_000,
            job: JobLimits {
                memory_bytes: Some(match self.job_memory_mb {
                    Some(mb) => mb << 20,
                    None => crate::jobs::settings::default_job_memory(self.workers),
                }),
                threads: self.job_threads.map(|t| t as usize),
                max_runtime: (self.max_runtime_minutes > 0)
                    .then(|| std::time::Duration::from_secs(self.max_runtime_minutes * 60)),
            },
        };
        Ok(config)
    }

    /// The configuration of a worker process: jobs only, no `/v1` API.
    pub fn to_worker_config(&self) -> Result<ServiceConfig, ConfigError> {
        Ok(ServiceConfig {
            api: false,
            ..self.to_config()?
        })
    }
}

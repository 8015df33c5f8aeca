//! `GET /v1/info`: what this deployment offers, for operators and client programs deciding how
//! to use it: the version, the engines of the machine answering, every limit an input or a job
//! is held to, and the queue (the caller's account's jobs; the admin's: all).

use axum::extract::State;
use axum::{Extension, Json};
use serde::Serialize;
use utoipa::ToSchema;

use crate::accounts::auth::Caller;
use crate::accounts::limits::AccountLimits;
use crate::http::error::{ApiError, ErrorBody};
use crate::jobs::pipeline_seam::Engines;
use crate::jobs::state::AppState;
use crate::storage::store::AccountUsage;

/// What the deployment offers.
#[derive(Serialize, ToSchema)]
pub struct Info {
    /// The service's version.
    version: &'static str,
    /// The engines of the machine answering (its jobs' processes probe them): the adapters and
    /// what each `backend` choice trains on. Workers on other machines may differ; a job's
    /// `backend` says what its run trains on.
    engines: Engines,
    limits: Limits,
    /// Jobs queued and running: the token's account's (the admin token: every account's).
    queue: Queue,
    /// Jobs this process runs at once (`--workers`; 0: an API without workers).
    workers: usize,
    /// The token's account: what it may hold and ask for, and what it holds; null for the
    /// admin token (held only to the limits above).
    #[schema(required = true)]
    account: Option<AccountInfo>,
}

/// An account's share of the deployment.
#[derive(Serialize, ToSchema)]
pub struct AccountInfo {
    name: String,
    /// Its limits (null: none).
    limits: AccountLimits,
    usage: AccountUsage,
}

/// Every limit an input or a job is held to (README, "Jobs in their own processes, and
/// limits").
#[derive(Serialize, ToSchema)]
pub struct Limits {
    /// Largest capture archive or relight upload, bytes.
    max_upload_bytes: u64,
    /// Largest `POST /v1/jobs` body, bytes.
    max_job_request_bytes: usize,
    max_views: usize,
    max_pixels_per_view: u64,
    /// Bytes a capture's views may hold once decoded at the working resolution.
    max_decoded_bytes: u64,
    max_envmap_pixels: u64,
    /// Memory of a job's process, bytes; null: no cap.
    #[schema(required = true)]
    job_memory_bytes: Option<u64>,
    /// Compute threads of a job's process; null: one per core.
    #[schema(required = true)]
    job_threads: Option<usize>,
    /// Longest one stage of a job may run, seconds; null: no limit.
    #[schema(required = true)]
    max_runtime_seconds: Option<u64>,
    max_connections: usize,
    /// Seconds a connection may take to send a request head or sit idle.
    header_timeout_seconds: u64,
    /// A request body must bring `upload_window_min_bytes` in every window of this many
    /// seconds.
    upload_window_seconds: u64,
    upload_window_min_bytes: u64,
}

/// Jobs waiting and running.
#[derive(Serialize, ToSchema)]
pub struct Queue {
    queued: u64,
    running: u64,
}

/// `GET /v1/info`.
#[utoipa::path(
    get,
    path = "/v1/info",
    tag = "service",
    operation_id = "info",
    summary = "What this deployment offers",
    description = "The version, the engines of the machine answering, every limit, and the \
        queue (the token's account's jobs; the admin token: every job).",
    responses(
        (status = OK, description = "The deployment", body = Info),
        (status = SERVICE_UNAVAILABLE, description = "The job store is not answering \
            (store_unavailable)", body = ErrorBody),
    )
)]
pub async fn info(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
) -> Result<Json<Info>, ApiError> {
    let counts = state.store.counts(caller.account()).await?;
    let account = match caller.account() {
        Some(name) => Some(AccountInfo {
            name: name.to_owned(),
            limits: state.config.quotas().of(name),
            usage: state.store.account_usage(name).await?,
        }),
        None => None,
    };
    let engines = state
        .engines
        .get_or_try_init(|| async {
            let pipeline = state.pipeline.clone();
            tokio::task::spawn_blocking(move || pipeline.engines())
                .await
                .map_err(|e| ApiError::internal("describing the engines", e))?
                .map_err(|e| ApiError::internal("describing the engines", e))
        })
        .await?
        .clone();
    let (config, limits, http) = (&state.config, &state.config.limits, &state.config.http);
    Ok(Json(Info {
        version: env!("CARGO_PKG_VERSION"),
        engines,
        limits: Limits {
            max_upload_bytes: config.max_upload_bytes,
            max_job_request_bytes: crate::http::routes::jobs::MAX_SUBMIT_BYTES,
            max_views: limits.capture.max_views,
            max_pixels_per_view: limits.capture.max_pixels_per_view,
            max_decoded_bytes: limits.capture.max_decoded_bytes,
            max_envmap_pixels: limits.max_envmap_pixels,
            job_memory_bytes: limits.job.memory_bytes,
            job_threads: limits.job.threads,
            max_runtime_seconds: limits.job.max_runtime.map(|d| d.as_secs()),
            max_connections: http.max_connections,
            header_timeout_seconds: http.header_timeout.as_secs(),
            upload_window_seconds: http.body_window.as_secs(),
            upload_window_min_bytes: http.min_body_bytes,
        },
        queue: Queue {
            queued: counts.queued,
            running: counts.running,
        },
        workers: config.workers,
        account,
    }))
}

//! Jobs: submit (idempotent with `Idempotency-Key`), list, show, progress events (SSE), cancel,
//! and relighting a trained job under an uploaded environment map.

use std::collections::BTreeMap;
use std::convert::Infallible;
use std::time::Duration;

use axum::body::Bytes;
use axum::extract::rejection::BytesRejection;
use axum::extract::{Multipart, Path, Query, State};
use axum::http::{HeaderMap, StatusCode};
use axum::response::sse::{Event, KeepAlive, Sse};
use axum::{Extension, Json};
use futures_util::Stream;
use phygap::core::config::TrainConfig;
use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use crate::accounts::auth::Caller;
use crate::accounts::quotas::JobRequestLimits;
use crate::domain::ids::new_id;
use crate::http::bodies::TempDir;
use crate::http::error::{ApiError, ErrorBody};
use crate::http::intake::RelightInputs;
use crate::jobs::queue::CancelReason;
use crate::jobs::state::AppState;
use crate::storage::store::{
    now_ms, rfc3339, DeleteOutcome, JobRecord, JobSpec, JobState, NewJob, StoreError, WebhookRecord,
};

/// A job and its progress, as answered (and as each event of its event stream carries it).
#[derive(Clone, Debug, PartialEq, Serialize, ToSchema)]
#[schema(as = Job)]
pub struct JobView {
    /// `job_…`.
    id: String,
    kind: JobKind,
    /// The capture it trains on (a relight job: its model's).
    capture_id: String,
    /// Relight jobs only: the training job whose model it relights.
    #[serde(skip_serializing_if = "Option::is_none")]
    parent_job_id: Option<String>,
    state: JobState,
    /// Stage of the run: starting, geometry, material, polar, exporting, relighting, done.
    #[schema(required = true)]
    stage: Option<String>,
    /// Steps done.
    iteration: u32,
    /// Steps of the whole run (0 for relight jobs); for `auto` its least (6,000) until training
    /// starts and sizes it to the capture.
    iterations: u32,
    /// The latest loss terms by name (`total` among them).
    losses: BTreeMap<String, f64>,
    /// PSNR of the latest test-view evaluation, dB.
    #[schema(required = true)]
    test_psnr: Option<f64>,
    /// Estimated seconds until the run ends.
    #[schema(required = true)]
    eta_seconds: Option<f64>,
    /// Why it failed, for people.
    #[schema(required = true)]
    error: Option<String>,
    /// Why it failed, as a stable name: `out_of_memory`, `time_limit`, `killed` or `crashed`
    /// (its process died the same way twice), `training_failed`, `export_failed`,
    /// `relighting_failed`, `invalid_capture`, `capture_too_large`, `invalid_input`,
    /// `capture_missing`, `abandoned` (its workers kept dying), `internal`; null unless failed.
    #[schema(required = true)]
    error_code: Option<String>,
    #[schema(format = DateTime)]
    created_at: String,
    #[schema(format = DateTime, required = true)]
    started_at: Option<String>,
    #[schema(format = DateTime, required = true)]
    finished_at: Option<String>,
    /// Times a worker started it (more than 1: it was resumed).
    attempts: u32,
    /// The iteration the latest run resumed from after a restart.
    #[schema(required = true)]
    resumed_from: Option<u32>,
    /// Compute backend of the latest run, what it runs on and how its steps run, e.g.
    /// "fast (16 threads, f32 AVX2); steps on the host" or "gpu on NVIDIA H100 …; whole steps on
    /// the device"; null before training starts.
    #[schema(required = true)]
    backend: Option<String>,
    /// The latest problem the run worked around, with its iteration (e.g. a GridMap mesh that
    /// could not be extracted, the previous one kept); null if none.
    #[schema(required = true)]
    warning: Option<String>,
    /// The size of the views the latest run trains on, and how it came about (the config's
    /// `resolution`), e.g. "306×256 (1224×1024 ÷ 4)"; null before training starts.
    #[schema(required = true)]
    resolution: Option<String>,
    /// The most memory the latest run's training process has held so far (its peak resident
    /// set, bytes); null before training starts or where the worker's system does not say.
    #[schema(required = true)]
    peak_rss_bytes: Option<u64>,
    /// A cancel was asked for and the running job has not stopped yet.
    cancel_requested: bool,
    /// Training jobs only: the training configuration, defaults filled in.
    #[serde(skip_serializing_if = "Option::is_none")]
    config: Option<TrainConfig>,
    /// Where the job's end is reported, and how that goes; null without a webhook.
    #[schema(required = true)]
    webhook: Option<WebhookRecord>,
    /// Queued jobs of higher priority start first, then the oldest.
    priority: i32,
    /// The job's own time limit per attempt, seconds; null: the server's
    /// (`GET /v1/info`).
    #[schema(required = true)]
    max_runtime_seconds: Option<u64>,
}

/// What a job does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum JobKind {
    /// Trains a model of a capture.
    Train,
    /// Renders a trained model under an uploaded environment map.
    Relight,
}

/// The job a route is about.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Path)]
pub struct JobPath {
    /// The job's id (`job_…`).
    pub id: String,
}

/// A webhook delivery's body: the job as `GET /v1/jobs/{id}` answers it
/// ([`crate::jobs::webhooks::JobBody`]).
pub fn webhook_body(job: JobRecord) -> serde_json::Result<Vec<u8>> {
    serde_json::to_vec(&JobView::from(job))
}

impl From<JobRecord> for JobView {
    fn from(job: JobRecord) -> Self {
        let (kind, parent_job_id, config) = match job.spec {
            JobSpec::Train { config } => (JobKind::Train, None, Some(config)),
            JobSpec::Relight { parent_job_id, .. } => (JobKind::Relight, Some(parent_job_id), None),
        };
        JobView {
            id: job.id,
            kind,
            capture_id: job.capture_id,
            parent_job_id,
            state: job.state,
            stage: job.progress.stage,
            iteration: job.progress.iteration,
            iterations: job.progress.iterations,
            losses: job.progress.losses,
            test_psnr: job.progress.test_psnr,
            eta_seconds: job.progress.eta_seconds,
            error: job.error,
            error_code: job.error_code,
            created_at: rfc3339(job.created_at),
            started_at: job.started_at.map(rfc3339),
            finished_at: job.finished_at.map(rfc3339),
            attempts: job.attempts,
            resumed_from: job.progress.resumed_from,
            backend: job.progress.backend,
            warning: job.progress.warning,
            resolution: job.progress.resolution,
            peak_rss_bytes: job.progress.peak_rss_bytes,
            cancel_requested: job.cancel_requested,
            config,
            webhook: job.webhook,
            priority: job.priority,
            max_runtime_seconds: job.max_runtime_seconds,
        }
    }
}

/// The body of `POST /v1/jobs`.
#[derive(Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SubmitRequest {
    /// The capture to train on.
    capture_id: String,
    /// The training configuration (`phygap config` prints the defaults; keys are the `phygap
    /// train` flag names in snake_case; unknown keys are errors); missing keys take their
    /// defaults.
    #[serde(default)]
    config: TrainConfig,
    /// An http(s) URL the job's end is POSTed to (the job as `GET /v1/jobs/{id}` answers it,
    /// signed: `Phygap-Signature`); default: the server's `--webhook`, if any.
    #[serde(default)]
    webhook: Option<String>,
    /// Queued jobs of higher priority start first (-100 to the token's `max_priority`, 0 by
    /// default for accounts; the admin may use up to 100).
    #[serde(default)]
    #[schema(minimum = -100, maximum = 100)]
    priority: i32,
    /// Longest one attempt of the job may run, seconds (at most the server's limit): past it the
    /// job checkpoints and fails `time_limit`.
    #[serde(default)]
    #[schema(minimum = 1)]
    max_runtime_seconds: Option<u64>,
}

/// Largest `POST /v1/jobs` body (axum's default body limit; a config is about 2 KB).
pub const MAX_SUBMIT_BYTES: usize = 2 << 20;

/// Longest `Idempotency-Key` (utoipa takes the document's `maxLength` as a literal only, on
/// [`SubmitHeaders`]; `api/tests/openapi.rs` sends a key of that length and one longer).
const MAX_IDEMPOTENCY_KEY: usize = 255;

/// The headers `POST /v1/jobs` reads (by hand, from the request's header map).
#[derive(IntoParams)]
#[into_params(parameter_in = Header)]
#[allow(dead_code)] // Only its parameters' schemas are used.
pub struct SubmitHeaders {
    /// A retried submit with the same key and body returns the same job (200); with another
    /// body, 422 idempotency_key_reused. Keys are scoped to the token's account.
    #[param(rename = "Idempotency-Key", value_type = String, required = false, max_length = 255)]
    idempotency_key: Option<String>,
}

fn idempotency_key(headers: &HeaderMap) -> Result<Option<String>, ApiError> {
    let Some(value) = headers.get("idempotency-key") else {
        return Ok(None);
    };
    let key = value
        .to_str()
        .ok()
        .filter(|k| !k.is_empty() && k.len() <= MAX_IDEMPOTENCY_KEY)
        .ok_or_else(|| {
            ApiError::bad_request(
                "invalid_idempotency_key",
                "Idempotency-Key must be 1 to 255 visible ASCII characters",
            )
        })?;
    Ok(Some(key.to_owned()))
}

/// The job `id` where `caller` may see it (404 otherwise: another account's records are not
/// confirmed to exist).
pub async fn load_job(state: &AppState, caller: &Caller, id: &str) -> Result<JobRecord, ApiError> {
    state
        .store
        .job(id)
        .await?
        .filter(|job| caller.may_see(job.account.as_deref()))
        .ok_or_else(|| ApiError::not_found("job", id))
}

/// `POST /v1/jobs` with `{capture_id, config}`: 201 with the new job, or 200 with the job an
/// earlier request with the same `Idempotency-Key` created.
#[utoipa::path(
    post,
    path = "/v1/jobs",
    tag = "jobs",
    operation_id = "submit_job",
    summary = "Queue a training job",
    params(SubmitHeaders),
    request_body = SubmitRequest,
    responses(
        (status = CREATED, description = "Queued", body = JobView),
        (status = OK, description = "The job an earlier request with this Idempotency-Key \
            created", body = JobView),
        (status = BAD_REQUEST, description = "A body that is not JSON (invalid_json) or cannot \
            be read (invalid_body), or an Idempotency-Key that is not 1 to 255 visible ASCII \
            characters (invalid_idempotency_key)", body = ErrorBody),
        (status = PAYLOAD_TOO_LARGE, description = "A body over 2 MiB (payload_too_large)",
            body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "Unknown or missing request fields \
            (invalid_request), an invalid config, e.g. a size over its bound (invalid_config), \
            a webhook that is not an http(s) URL of an allowed host (invalid_webhook), \
            an unknown capture (unknown_capture), a job whose estimated memory at its working \
            resolution exceeds the job memory limit (capture_too_large, naming a resolution that \
            fits), a reused idempotency key (idempotency_key_reused), a priority above the \
            token's (priority_not_allowed), a time limit of 0 or over the server's \
            (invalid_max_runtime)", body = ErrorBody),
        (status = TOO_MANY_REQUESTS, description = "The account has as many jobs queued as its \
            limit allows (queued_job_limit)", body = ErrorBody),
    )
)]
pub async fn submit(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Result<(StatusCode, Json<JobView>), ApiError> {
    let body = body.map_err(|e| match e.status() {
        StatusCode::PAYLOAD_TOO_LARGE => ApiError::too_large(format!(
            "a job request is at most {} KiB: {}",
            MAX_SUBMIT_BYTES >> 10,
            e.body_text()
        )),
        _ if crate::http::slow_body::is_too_slow(&e) => crate::http::bodies::body_error(&e),
        status => ApiError::new(status, "invalid_body", e.body_text()),
    })?;
    let value: serde_json::Value = serde_json::from_slice(&body)
        .map_err(|e| ApiError::bad_request("invalid_json", format!("request body: {e}")))?;
    let request: SubmitRequest = super::from_json_value(value)
        .map_err(|message| ApiError::unprocessable("invalid_request", message))?;
    request
        .config
        .validate()
        .map_err(|e| ApiError::unprocessable("invalid_config", e.to_string()))?;
    let capture = state
        .store
        .capture(&request.capture_id)
        .await?
        .filter(|c| caller.may_see(c.account.as_deref()))
        .ok_or_else(|| {
            ApiError::unprocessable(
                "unknown_capture",
                format!("capture `{}` does not exist", request.capture_id),
            )
        })?;
    crate::accounts::admission::check(
        &capture,
        &request.config,
        state.config.limits.job.memory_bytes,
    )?;
    // The store keeps keys per account (the job's), so one account cannot reach another's
    // jobs through them.
    let key = idempotency_key(&headers)?;
    // Requests without a priority or time limit hash as they did before those existed, so a
    // retry across an upgrade still finds its job.
    let base = (&request.capture_id, &request.config, &request.webhook);
    let hash = if request.priority == 0 && request.max_runtime_seconds.is_none() {
        serde_json::to_string(&base)
    } else {
        serde_json::to_string(&(
            base.0,
            base.1,
            base.2,
            request.priority,
            request.max_runtime_seconds,
        ))
    }
    .map_err(|e| ApiError::internal("hashing the request", e))?;
    let webhook_url = state
        .config
        .webhooks
        .target(request.webhook.as_deref())
        .await?;
    let asks = JobRequestLimits {
        priority: request.priority,
        max_runtime_seconds: request.max_runtime_seconds,
    };
    // A retry of a submit that was accepted answers its job, even with the queue full now.
    let replay = match key.as_deref() {
        Some(key) => state.store.has_request_key(caller.account(), key).await?,
        None => false,
    };
    let job_id = new_id("job");
    // A place in the account's queue is held for the job until it is submitted.
    let _place = if replay {
        None
    } else {
        crate::accounts::quotas::admit_job(&state.ledger(), &caller, asks, &job_id).await?
    };
    let job = NewJob {
        id: job_id,
        capture_id: request.capture_id,
        webhook_url,
        priority: asks.priority,
        max_runtime_seconds: asks.max_runtime_seconds,
        iterations: request.config.steps(),
        spec: JobSpec::Train {
            config: request.config,
        },
        created_at: now_ms(),
        account: caller.account().map(str::to_owned),
    };
    let (record, created) = state
        .store
        .submit(&job, key.as_deref().map(|k| (k, hash.as_str())))
        .await
        .map_err(|e| match e {
            StoreError::IdempotencyConflict(_) => {
                ApiError::unprocessable("idempotency_key_reused", e.to_string())
            }
            other => other.into(),
        })?;
    if created {
        tracing::info!(job_id = %record.id, capture_id = %record.capture_id, "job queued");
        state.runtime.wake_workers();
    }
    let status = if created {
        StatusCode::CREATED
    } else {
        StatusCode::OK
    };
    Ok((status, Json(record.into())))
}

/// Jobs answered by default.
const DEFAULT_LIST_LIMIT: usize = 100;
/// Most jobs answered.
const MAX_LIST_LIMIT: usize = 1000;

/// The query of `GET /v1/jobs`.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Query)]
pub struct ListQuery {
    /// Most jobs to answer, newest first: 100 when absent, 1 to 1000 (others are clamped).
    #[param(default = json!(DEFAULT_LIST_LIMIT))]
    limit: Option<usize>,
}

/// Jobs, newest first.
#[derive(Serialize, ToSchema)]
pub struct JobList {
    jobs: Vec<JobView>,
}

/// `GET /v1/jobs?limit=N`: newest first (default 100, at most 1000).
#[utoipa::path(
    get,
    path = "/v1/jobs",
    tag = "jobs",
    operation_id = "list_jobs",
    summary = "Jobs, newest first",
    description = "The token's account's jobs (the admin token: every job).",
    params(ListQuery),
    responses(
        (status = OK, description = "Jobs", body = JobList),
        (status = BAD_REQUEST, description = "A query that does not parse (invalid_query)", body = ErrorBody),
    )
)]
pub async fn list(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    query: Result<Query<ListQuery>, axum::extract::rejection::QueryRejection>,
) -> Result<Json<JobList>, ApiError> {
    let Query(query) = query.map_err(|e| ApiError::bad_request("invalid_query", e.body_text()))?;
    let limit = query
        .limit
        .unwrap_or(DEFAULT_LIST_LIMIT)
        .clamp(1, MAX_LIST_LIMIT);
    let jobs = state.store.list_jobs(limit, caller.account()).await?;
    Ok(Json(JobList {
        jobs: jobs.into_iter().map(JobView::from).collect(),
    }))
}

/// `GET /v1/jobs/{id}`.
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}",
    tag = "jobs",
    operation_id = "get_job",
    summary = "A job and its progress",
    params(JobPath),
    responses(
        (status = OK, description = "The job", body = JobView),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
    )
)]
pub async fn show(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
) -> Result<Json<JobView>, ApiError> {
    Ok(Json(load_job(&state, &caller, &id).await?.into()))
}

/// `POST /v1/jobs/{id}/cancel`: a queued job is cancelled at once; a running one checkpoints and
/// ends `cancelled` shortly after (its `cancel_requested` is true meanwhile). Finished jobs are
/// left as they are (409).
#[utoipa::path(
    post,
    path = "/v1/jobs/{id}/cancel",
    tag = "jobs",
    operation_id = "cancel_job",
    summary = "Cancel a job",
    description = "A queued job is cancelled at once; a running one checkpoints and ends \
        `cancelled` shortly after (`cancel_requested` is true meanwhile).",
    params(JobPath),
    responses(
        (status = OK, description = "The job after the request", body = JobView),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "The job already ended (job_finished)", body = ErrorBody),
    )
)]
pub async fn cancel(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
) -> Result<Json<JobView>, ApiError> {
    let before = load_job(&state, &caller, &id).await?;
    if before.state.is_terminal() {
        return Err(ApiError::conflict(
            "job_finished",
            format!("job `{id}` already ended ({})", before.state.as_str()),
        ));
    }
    let job = state
        .store
        .request_cancel(&id, now_ms())
        .await?
        .ok_or_else(|| ApiError::not_found("job", &id))?;
    state.runtime.cancel(&id, CancelReason::User);
    state.runtime.changed(&id);
    tracing::info!(job_id = %id, "cancel requested");
    Ok(Json(job.into()))
}

struct EventsCursor {
    state: AppState,
    id: String,
    changes: tokio::sync::broadcast::Receiver<String>,
    last: Option<JobView>,
    first: bool,
    finished: bool,
}

/// Waits until the job may have changed: a change notice for it, a 1 s tick, or shutdown.
async fn wait_for_change(cursor: &mut EventsCursor) -> bool {
    let deadline = tokio::time::sleep(Duration::from_secs(1));
    tokio::pin!(deadline);
    loop {
        tokio::select! {
            _ = cursor.state.shutdown.cancelled() => return false,
            _ = &mut deadline => return true,
            message = cursor.changes.recv() => match message {
                Ok(id) if id == cursor.id => return true,
                Ok(_) => continue,
                Err(tokio::sync::broadcast::error::RecvError::Lagged(_)) => return true,
                Err(tokio::sync::broadcast::error::RecvError::Closed) => return false,
            },
        }
    }
}

/// The next event of a job's stream; `None` ends the stream.
async fn next_event(mut cursor: EventsCursor) -> Option<(Result<Event, Infallible>, EventsCursor)> {
    loop {
        if cursor.finished {
            return None;
        }
        if !cursor.first && !wait_for_change(&mut cursor).await {
            return None;
        }
        cursor.first = false;
        let job = match cursor.state.store.job(&cursor.id).await {
            Ok(Some(job)) => job,
            Ok(None) => return None,
            Err(e) => {
                tracing::error!(error = %e, "event stream: reading the job failed");
                continue;
            }
        };
        let terminal = job.state.is_terminal();
        let view = JobView::from(job);
        if cursor.last.as_ref() == Some(&view) {
            continue;
        }
        let event = Event::default()
            .event(if terminal { "end" } else { "progress" })
            .json_data(&view)
            .unwrap_or_else(|_| Event::default().comment("unserializable job"));
        cursor.last = Some(view);
        cursor.finished = terminal;
        return Some((Ok(event), cursor));
    }
}

/// `GET /v1/jobs/{id}/events`: server-sent events, each `data` a job object as in
/// `GET /v1/jobs/{id}`; event `progress` while it runs, `end` once it finished (then the stream
/// closes).
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}/events",
    tag = "jobs",
    operation_id = "job_events",
    summary = "Progress as server-sent events",
    description = "Each event's data is a Job object (the `Job` schema). Event `progress` while \
        the job is queued or running, `end` once it has ended; the stream then closes.",
    params(JobPath),
    responses(
        (status = OK, description = "Event stream", body = String, content_type = "text/event-stream"),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
    )
)]
pub async fn events(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
) -> Result<Sse<impl Stream<Item = Result<Event, Infallible>>>, ApiError> {
    load_job(&state, &caller, &id).await?;
    let cursor = EventsCursor {
        changes: state.runtime.subscribe(),
        state,
        id,
        last: None,
        first: true,
        finished: false,
    };
    let stream = futures_util::stream::unfold(cursor, next_event);
    Ok(Sse::new(stream).keep_alive(KeepAlive::default()))
}

/// The form of `POST /v1/jobs/{id}/relight` (the handler reads it field by field).
#[derive(ToSchema)]
#[allow(dead_code)] // Read by hand from the multipart stream; this is its schema.
pub struct RelightForm {
    /// A lat-long environment map, OpenEXR or Radiance HDR.
    #[schema(value_type = String, format = Binary)]
    envmap: Vec<u8>,
    /// transforms.json-style cameras to render from (default: the capture's test views).
    #[schema(value_type = Option<String>, format = Binary)]
    cameras: Option<Vec<u8>>,
    /// Rotation of the map about the world up axis, in degrees (default 0).
    rotate_deg: Option<f64>,
    /// An http(s) URL the relight job's end is POSTed to (default: the server's --webhook).
    webhook: Option<String>,
}

/// `POST /v1/jobs/{id}/relight`: multipart form with `envmap` (an `.exr` or `.hdr` file),
/// optional `cameras` (a transforms.json-style file) and optional `rotate_deg`. Queues a relight
/// job of its own (201).
#[utoipa::path(
    post,
    path = "/v1/jobs/{id}/relight",
    tag = "jobs",
    operation_id = "relight_job",
    summary = "Relight a trained model",
    description = "Queues a relight job of the succeeded training job `id`; its artifacts are \
        the renders under the uploaded environment map.",
    params(JobPath),
    request_body(content = RelightForm, content_type = "multipart/form-data"),
    responses(
        (status = CREATED, description = "The relight job, queued", body = JobView),
        (status = BAD_REQUEST, description = "A malformed form (invalid_multipart) or a field \
            other than envmap, cameras, rotate_deg (unknown_field)", body = ErrorBody),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "The job is not a succeeded training job \
            (model_not_ready)", body = ErrorBody),
        (status = PAYLOAD_TOO_LARGE, description = "An upload over --max-upload-mb \
            (payload_too_large)", body = ErrorBody),
        (status = UNSUPPORTED_MEDIA_TYPE, description = "Not multipart (invalid_multipart), or \
            a map that is neither OpenEXR nor Radiance HDR (unsupported_envmap)",
            body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "No envmap field (missing_envmap), a map \
            whose header cannot be read (invalid_envmap) or that declares more pixels than \
            --max-envmap-megapixels (envmap_too_large), cameras that are not valid cameras \
            (invalid_cameras) or more views or pixels than the capture limits allow \
            (cameras_too_large), a rotate_deg that is not a finite number (invalid_rotate_deg)",
            body = ErrorBody),
        (status = TOO_MANY_REQUESTS, description = "The account has as many jobs queued as its \
            limit allows (queued_job_limit)", body = ErrorBody),
    )
)]
pub async fn relight(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id: parent_id }): Path<JobPath>,
    headers: HeaderMap,
    multipart: Result<Multipart, axum::extract::multipart::MultipartRejection>,
) -> Result<(StatusCode, Json<JobView>), ApiError> {
    crate::http::bodies::check_content_length(&headers, state.config.max_upload_bytes)?;
    let parent = load_job(&state, &caller, &parent_id).await?;
    if !matches!(parent.spec, JobSpec::Train { .. }) || parent.state != JobState::Succeeded {
        return Err(ApiError::conflict(
            "model_not_ready",
            format!(
                "job `{parent_id}` is not a succeeded training job (it is a {} job, {})",
                parent.spec.kind(),
                parent.state.as_str()
            ),
        ));
    }
    // A relight runs at its model's priority, under the server's time limit.
    let asks = JobRequestLimits {
        priority: parent.priority,
        max_runtime_seconds: None,
    };
    let id = new_id("job");
    // A place in the account's queue is held for the job until it is submitted.
    let _place = crate::accounts::quotas::admit_job(&state.ledger(), &caller, asks, &id).await?;
    let multipart = multipart.map_err(|e| {
        ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "invalid_multipart",
            e.body_text(),
        )
    })?;
    let staging = TempDir::create(state.paths.tmp.join(&id))?;
    let RelightInputs {
        envmap_file,
        cameras_file,
        rotate_deg,
        webhook,
    } = crate::http::intake::read_relight_form(multipart, staging.path()).await?;
    let webhook_url = state.config.webhooks.target(webhook.as_deref()).await?;
    let (envmap_path, cameras_path, limits) = (
        staging.path().join(&envmap_file),
        cameras_file.as_ref().map(|name| staging.path().join(name)),
        state.config.limits,
    );
    tokio::task::spawn_blocking(move || {
        crate::http::intake::check_relight_inputs(&envmap_path, cameras_path.as_deref(), &limits)
    })
    .await
    .map_err(|e| ApiError::internal("checking the relight inputs", e))??;
    let input_dir = state.paths.input_dir(&id);
    if let Some(parent_dir) = input_dir.parent() {
        std::fs::create_dir_all(parent_dir)
            .map_err(|e| ApiError::internal("filing the relight inputs", e))?;
    }
    std::fs::rename(staging.path(), &input_dir)
        .map_err(|e| ApiError::internal("filing the relight inputs", e))?;
    let job = NewJob {
        id: id.clone(),
        capture_id: parent.capture_id.clone(),
        spec: JobSpec::Relight {
            parent_job_id: parent_id,
            envmap_file,
            cameras_file,
            rotate_deg,
        },
        iterations: 0,
        created_at: now_ms(),
        account: caller.account().map(str::to_owned),
        webhook_url,
        priority: asks.priority,
        max_runtime_seconds: asks.max_runtime_seconds,
    };
    let filed = crate::http::intake::Filed {
        dir: &input_dir,
        key: crate::storage::object_keys::job_input(&id),
        remove: state.paths.jobs.join(&id),
    };
    let (record, _) = crate::http::intake::publish_then_record(&state, filed, || async {
        state.store.submit(&job, None).await
    })
    .await?;
    tracing::info!(job_id = %id, parent = %record.capture_id, "relight job queued");
    state.runtime.wake_workers();
    Ok((StatusCode::CREATED, Json(record.into())))
}

/// The largest event number the stores can hold (a signed 64-bit column): a larger `from` is
/// refused rather than wrapped.
const MAX_EVENT_NUMBER: u64 = i64::MAX as u64;

/// Most events `GET /v1/jobs/{id}/progress` answers at once.
const MAX_PROGRESS_EVENTS: usize = 1000;

/// The query of `GET /v1/jobs/{id}/progress`.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Query)]
pub struct ProgressQuery {
    /// The number of the first event to answer (0: from the start; the previous answer's
    /// `next` to continue).
    #[param(default = 0)]
    from: Option<u64>,
    /// Most events to answer, 1 to 1000 (default 1000).
    #[param(default = 1000)]
    limit: Option<usize>,
}

/// One recorded event of a run.
#[derive(Serialize, ToSchema)]
pub struct ProgressEvent {
    /// Its number in the job's history (counted across the job's runs).
    seq: u64,
    /// The event as the run reported it: `type` started, step (iteration, stage, loss, losses,
    /// num_surfels, elapsed_seconds, eta_seconds), evaluated (test_psnr), checkpoint, warning
    /// or finished.
    #[schema(value_type = Object)]
    event: serde_json::Value,
}

/// A page of a job's history.
#[derive(Serialize, ToSchema)]
pub struct ProgressPage {
    job_id: String,
    events: Vec<ProgressEvent>,
    /// The `from` that continues after this page (equal to the request's when it had none).
    next: u64,
}

/// `GET /v1/jobs/{id}/progress?from=N`: the events the job's runs reported, from number `N`.
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}/progress",
    tag = "jobs",
    operation_id = "job_progress",
    summary = "A job's progress history",
    description = "Every event its runs reported (steps with their losses, evaluations, \
        checkpoints, warnings), numbered across runs, from number `from`; a client polls with \
        the previous answer's `next` (the event stream carries the latest state only).",
    params(JobPath, ProgressQuery),
    responses(
        (status = OK, description = "Events from `from`", body = ProgressPage),
        (status = BAD_REQUEST, description = "A query that does not parse (invalid_query)", body = ErrorBody),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
    )
)]
pub async fn progress(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
    query: Result<Query<ProgressQuery>, axum::extract::rejection::QueryRejection>,
) -> Result<Json<ProgressPage>, ApiError> {
    let Query(query) = query.map_err(|e| ApiError::bad_request("invalid_query", e.body_text()))?;
    load_job(&state, &caller, &id).await?;
    let from = query.from.unwrap_or(0);
    if from > MAX_EVENT_NUMBER {
        return Err(ApiError::bad_request(
            "invalid_query",
            format!("`from` is at most {MAX_EVENT_NUMBER}"),
        ));
    }
    let limit = query
        .limit
        .unwrap_or(MAX_PROGRESS_EVENTS)
        .clamp(1, MAX_PROGRESS_EVENTS);
    let rows = state.store.events(&id, from, limit).await?;
    let next = rows.last().map_or(from, |(seq, _)| seq + 1);
    let events = rows
        .into_iter()
        .map(|(seq, text)| ProgressEvent {
            seq,
            event: serde_json::from_str(&text).unwrap_or(serde_json::Value::Null),
        })
        .collect();
    Ok(Json(ProgressPage {
        job_id: id,
        events,
        next,
    }))
}

/// The body of `POST /v1/jobs/{id}/restart` (optional: without one, the job runs again as it
/// was).
#[derive(Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RestartRequest {
    /// Training jobs: settings to change, keys of the job's `config` (the others keep their
    /// values). A changed config starts the run over; an unchanged one resumes from the last
    /// checkpoint.
    #[serde(default)]
    #[schema(value_type = Option<Object>)]
    config: Option<serde_json::Map<String, serde_json::Value>>,
}

/// `POST /v1/jobs/{id}/restart`: a failed or cancelled job runs again, resuming from its last
/// checkpoint, or over from the start with changed settings.
#[utoipa::path(
    post,
    path = "/v1/jobs/{id}/restart",
    tag = "jobs",
    operation_id = "restart_job",
    summary = "Run a failed or cancelled job again",
    description = "The job goes back to the queue under its id: its error cleared, resuming from \
        its last checkpoint, or, when `config` changes a setting, starting over with the changed \
        config (`attempts` counts from 0 again). A training job's capture must still exist, a \
        relight job's model too.",
    params(JobPath),
    request_body(content = Option<RestartRequest>, content_type = "application/json"),
    responses(
        (status = OK, description = "The job, queued again", body = JobView),
        (status = BAD_REQUEST, description = "A body that is not JSON (invalid_json)",
            body = ErrorBody),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)",
            body = ErrorBody),
        (status = CONFLICT, description = "The job is queued, running or succeeded \
            (job_not_restartable), or its capture (capture_missing) or model \
            (model_not_ready) is gone", body = ErrorBody),
        (status = PAYLOAD_TOO_LARGE, description = "A body over 2 MiB (payload_too_large)",
            body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "Unknown request fields \
            (invalid_request), an invalid config (invalid_config), settings for a relight job \
            (invalid_request), a capture that cannot fit at the new resolution \
            (capture_too_large)", body = ErrorBody),
        (status = TOO_MANY_REQUESTS, description = "The account has as many jobs queued as its \
            limit allows (queued_job_limit)", body = ErrorBody),
    )
)]
pub async fn restart(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Json<JobView>, ApiError> {
    let request: RestartRequest = match body {
        Ok(bytes) if bytes.iter().all(u8::is_ascii_whitespace) => RestartRequest::default(),
        body => crate::http::routes::json_request(body)?,
    };
    let job = load_job(&state, &caller, &id).await?;
    if !matches!(job.state, JobState::Failed | JobState::Cancelled) {
        return Err(ApiError::conflict(
            "job_not_restartable",
            format!(
                "job `{id}` is {}; only failed or cancelled jobs restart",
                job.state.as_str()
            ),
        ));
    }
    let asks = JobRequestLimits {
        priority: job.priority,
        max_runtime_seconds: job.max_runtime_seconds,
    };
    // A place in the account's queue is held for the job until it is back in the queue.
    let _place = crate::accounts::quotas::admit_job(&state.ledger(), &caller, asks, &id).await?;
    let (spec, fresh) = match &job.spec {
        JobSpec::Train { config } => {
            let changed = match &request.config {
                Some(changes) => Some(changed_config(config, changes)?),
                None => None,
            };
            let new_config = changed.as_ref().unwrap_or(config);
            let capture = state.store.capture(&job.capture_id).await?.ok_or_else(|| {
                ApiError::conflict(
                    "capture_missing",
                    format!("capture `{}` of job `{id}` was deleted", job.capture_id),
                )
            })?;
            crate::accounts::admission::check(
                &capture,
                new_config,
                state.config.limits.job.memory_bytes,
            )?;
            match changed.filter(|c| c != config) {
                Some(changed) => {
                    let fresh = crate::storage::store::Progress {
                        iterations: changed.steps(),
                        ..Default::default()
                    };
                    (Some(JobSpec::Train { config: changed }), Some(fresh))
                }
                None => (None, None),
            }
        }
        JobSpec::Relight { parent_job_id, .. } => {
            if request.config.is_some() {
                return Err(ApiError::unprocessable(
                    "invalid_request",
                    "a relight job has no config to change; upload a new relight instead",
                ));
            }
            let parent = state.store.job(parent_job_id).await?;
            if !parent.is_some_and(|p| p.state == JobState::Succeeded) {
                return Err(ApiError::conflict(
                    "model_not_ready",
                    format!("the model of job `{parent_job_id}` is gone"),
                ));
            }
            (None, None)
        }
    };
    let job = state
        .store
        .restart(&id, spec.as_ref(), fresh.as_ref())
        .await?
        .ok_or_else(|| ApiError::not_found("job", &id))?;
    if job.state != JobState::Queued {
        return Err(ApiError::conflict(
            "job_not_restartable",
            format!("job `{id}` is {} now", job.state.as_str()),
        ));
    }
    tracing::info!(job_id = %id, fresh = fresh.is_some(), "job restarted");
    state.runtime.wake_workers();
    state.runtime.changed(&id);
    Ok(Json(job.into()))
}

/// `config` with the keys of `changes` replaced (every value checked as a training config is).
fn changed_config(
    config: &TrainConfig,
    changes: &serde_json::Map<String, serde_json::Value>,
) -> Result<TrainConfig, ApiError> {
    let invalid =
        |e: &dyn std::fmt::Display| ApiError::unprocessable("invalid_config", e.to_string());
    let mut merged = serde_json::to_value(config).map_err(|e| invalid(&e))?;
    if let Some(object) = merged.as_object_mut() {
        object.extend(changes.clone());
    }
    let changed: TrainConfig = super::from_json_value(merged).map_err(|e| invalid(&e))?;
    changed.validate().map_err(|e| invalid(&e))?;
    Ok(changed)
}

/// How long `DELETE` of a running job waits for it to stop (it checkpoints first).
const DELETE_WAIT: Duration = Duration::from_secs(60);

/// `DELETE /v1/jobs/{id}`: 204 once the job and everything stored for it (checkpoints, inputs,
/// artifacts) are gone. A queued job is cancelled first, a running one is cancelled and awaited
/// (409 `job_stopping` if it has not stopped within a minute); 409 `job_in_use` while a queued or
/// running relight job uses its model.
#[utoipa::path(
    delete,
    path = "/v1/jobs/{id}",
    tag = "jobs",
    operation_id = "delete_job",
    summary = "Delete a job and everything stored for it",
    description = "Removes the job's record, checkpoints, inputs and artifacts. A queued job is \
        cancelled first; a running one is cancelled and awaited for up to a minute.",
    params(JobPath),
    responses(
        (status = NO_CONTENT, description = "Deleted"),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "A queued or running relight job uses its model \
            (job_in_use), or it was cancelled and is still stopping (job_stopping)",
            body = ErrorBody),
    )
)]
pub async fn remove(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
) -> Result<StatusCode, ApiError> {
    let job = load_job(&state, &caller, &id).await?;
    if !job.state.is_terminal() {
        state.store.request_cancel(&id, now_ms()).await?;
        state.runtime.cancel(&id, CancelReason::User);
        state.runtime.changed(&id);
        let deadline = tokio::time::Instant::now() + DELETE_WAIT;
        loop {
            match state.store.job(&id).await? {
                None => return Ok(StatusCode::NO_CONTENT),
                Some(job) if job.state.is_terminal() => break,
                Some(_) if tokio::time::Instant::now() >= deadline => {
                    return Err(ApiError::conflict(
                        "job_stopping",
                        format!("job `{id}` was cancelled but is still stopping; try again"),
                    ))
                }
                Some(_) => tokio::time::sleep(Duration::from_millis(100)).await,
            }
        }
    }
    match crate::jobs::purge::delete_job(&state, &id).await? {
        DeleteOutcome::Deleted => Ok(StatusCode::NO_CONTENT),
        DeleteOutcome::NotFound => Err(ApiError::not_found("job", &id)),
        DeleteOutcome::InUse => Err(ApiError::conflict(
            "job_in_use",
            format!("a queued or running relight job uses the model of job `{id}`"),
        )),
    }
}

//! Jobs: submit (idempotent with `Idempotency-Key`), list, show, progress events (SSE), cancel,
//! and relighting a trained job under an uploaded environment map.

use std::collections::BTreeMap;
use std::convert::Infallible;
use std::time::Duration;

use axum::body::Bytes;
use axum::extract::multipart::{Field, MultipartError};
use axum::extract::rejection::BytesRejection;
use axum::extract::{Multipart, Path, Query, State};
use axum::http::{HeaderMap, StatusCode};
use axum::response::sse::{Event, KeepAlive, Sse};
use axum::{Extension, Json};
use futures_util::Stream;
use phygap::core::config::TrainConfig;
use serde::{Deserialize, Serialize};
use tokio::io::AsyncWriteExt;

use crate::auth::Caller;
use crate::error::ApiError;
use crate::queue::{new_id, CancelReason};
use crate::routes::captures::TempDir;
use crate::store::{
    now_ms, rfc3339, DeleteOutcome, JobRecord, JobSpec, JobState, NewJob, StoreError,
};
use crate::AppState;

/// A job as answered (and as sent on its event stream).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JobView {
    id: String,
    kind: &'static str,
    capture_id: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    parent_job_id: Option<String>,
    state: JobState,
    stage: Option<String>,
    iteration: u32,
    iterations: u32,
    losses: BTreeMap<String, f64>,
    test_psnr: Option<f64>,
    eta_seconds: Option<f64>,
    error: Option<String>,
    created_at: String,
    started_at: Option<String>,
    finished_at: Option<String>,
    attempts: u32,
    resumed_from: Option<u32>,
    backend: Option<String>,
    warning: Option<String>,
    cancel_requested: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    config: Option<TrainConfig>,
}

impl From<JobRecord> for JobView {
    fn from(job: JobRecord) -> Self {
        let kind = job.spec.kind();
        let (parent_job_id, config) = match job.spec {
            JobSpec::Train { config } => (None, Some(config)),
            JobSpec::Relight { parent_job_id, .. } => (Some(parent_job_id), None),
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
            created_at: rfc3339(job.created_at),
            started_at: job.started_at.map(rfc3339),
            finished_at: job.finished_at.map(rfc3339),
            attempts: job.attempts,
            resumed_from: job.progress.resumed_from,
            backend: job.progress.backend,
            warning: job.progress.warning,
            cancel_requested: job.cancel_requested,
            config,
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SubmitRequest {
    capture_id: String,
    #[serde(default)]
    config: TrainConfig,
}

fn idempotency_key(headers: &HeaderMap) -> Result<Option<String>, ApiError> {
    let Some(value) = headers.get("idempotency-key") else {
        return Ok(None);
    };
    let key = value
        .to_str()
        .ok()
        .filter(|k| !k.is_empty() && k.len() <= 255)
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
pub async fn submit(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Result<(StatusCode, Json<JobView>), ApiError> {
    let body = body.map_err(|e| ApiError::new(e.status(), "invalid_body", e.body_text()))?;
    let value: serde_json::Value = serde_json::from_slice(&body)
        .map_err(|e| ApiError::bad_request("invalid_json", format!("request body: {e}")))?;
    let request: SubmitRequest = serde_json::from_value(value)
        .map_err(|e| ApiError::unprocessable("invalid_request", e.to_string()))?;
    request
        .config
        .validate()
        .map_err(|e| ApiError::unprocessable("invalid_config", e.to_string()))?;
    let visible = state
        .store
        .capture(&request.capture_id)
        .await?
        .is_some_and(|c| caller.may_see(c.account.as_deref()));
    if !visible {
        return Err(ApiError::unprocessable(
            "unknown_capture",
            format!("capture `{}` does not exist", request.capture_id),
        ));
    }
    // Keys are scoped to the account, so one account cannot reach another's jobs through them.
    let key = idempotency_key(&headers)?.map(|key| match caller.account() {
        Some(account) => format!("{account}/{key}"),
        None => key,
    });
    let hash = serde_json::to_string(&(&request.capture_id, &request.config))
        .map_err(|e| ApiError::internal("hashing the request", e))?;
    let job = NewJob {
        id: new_id("job"),
        capture_id: request.capture_id,
        iterations: request.config.iterations,
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

#[derive(Deserialize)]
pub struct ListQuery {
    limit: Option<usize>,
}

#[derive(Serialize)]
pub struct JobList {
    jobs: Vec<JobView>,
}

/// `GET /v1/jobs?limit=N`: newest first (default 100, at most 1000).
pub async fn list(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    query: Result<Query<ListQuery>, axum::extract::rejection::QueryRejection>,
) -> Result<Json<JobList>, ApiError> {
    let Query(query) = query.map_err(|e| ApiError::bad_request("invalid_query", e.body_text()))?;
    let limit = query.limit.unwrap_or(100).clamp(1, 1000);
    let jobs = state.store.list_jobs(limit, caller.account()).await?;
    Ok(Json(JobList {
        jobs: jobs.into_iter().map(JobView::from).collect(),
    }))
}

/// `GET /v1/jobs/{id}`.
pub async fn show(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(id): Path<String>,
) -> Result<Json<JobView>, ApiError> {
    Ok(Json(load_job(&state, &caller, &id).await?.into()))
}

/// `POST /v1/jobs/{id}/cancel`: a queued job is cancelled at once; a running one checkpoints and
/// ends `cancelled` shortly after (its `cancel_requested` is true meanwhile). Finished jobs are
/// left as they are (409).
pub async fn cancel(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(id): Path<String>,
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
pub async fn events(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(id): Path<String>,
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

fn multipart_error(e: MultipartError) -> ApiError {
    if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
        ApiError::too_large(e.body_text())
    } else {
        ApiError::bad_request("invalid_multipart", e.body_text())
    }
}

/// Streams one multipart field into `target`; returns its first bytes (for format sniffing).
async fn save_field(mut field: Field<'_>, target: &std::path::Path) -> Result<Vec<u8>, ApiError> {
    let mut file = tokio::fs::File::create(target)
        .await
        .map_err(|e| ApiError::internal("saving an upload", e))?;
    let mut head = Vec::new();
    while let Some(chunk) = field.chunk().await.map_err(multipart_error)? {
        if head.len() < 16 {
            head.extend_from_slice(&chunk[..chunk.len().min(16 - head.len())]);
        }
        file.write_all(&chunk)
            .await
            .map_err(|e| ApiError::internal("saving an upload", e))?;
    }
    file.flush()
        .await
        .map_err(|e| ApiError::internal("saving an upload", e))?;
    Ok(head)
}

/// The environment-map format from its magic bytes.
fn envmap_extension(head: &[u8]) -> Option<&'static str> {
    if head.starts_with(&[0x76, 0x2f, 0x31, 0x01]) {
        Some("exr")
    } else if head.starts_with(b"#?RADIANCE") || head.starts_with(b"#?RGBE") {
        Some("hdr")
    } else {
        None
    }
}

/// `POST /v1/jobs/{id}/relight`: multipart form with `envmap` (an `.exr` or `.hdr` file),
/// optional `cameras` (a transforms.json-style file) and optional `rotate_deg`. Queues a relight
/// job of its own (201).
pub async fn relight(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(parent_id): Path<String>,
    headers: HeaderMap,
    multipart: Result<Multipart, axum::extract::multipart::MultipartRejection>,
) -> Result<(StatusCode, Json<JobView>), ApiError> {
    crate::routes::captures::check_content_length(&headers, state.config.max_upload_bytes)?;
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
    let mut multipart = multipart.map_err(|e| {
        ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "invalid_multipart",
            e.body_text(),
        )
    })?;
    let id = new_id("job");
    let staging = TempDir::create(state.paths.tmp.join(&id))?;
    let mut envmap_file = None;
    let mut cameras_file = None;
    let mut rotate_deg = 0.0f64;
    while let Some(field) = multipart.next_field().await.map_err(multipart_error)? {
        match field.name().unwrap_or("") {
            "envmap" => {
                let upload = staging.path().join("envmap.upload");
                let head = save_field(field, &upload).await?;
                let ext = envmap_extension(&head).ok_or_else(|| {
                    ApiError::new(
                        StatusCode::UNSUPPORTED_MEDIA_TYPE,
                        "unsupported_envmap",
                        "the environment map must be an OpenEXR (.exr) or Radiance (.hdr) file",
                    )
                })?;
                let name = format!("envmap.{ext}");
                std::fs::rename(&upload, staging.path().join(&name))
                    .map_err(|e| ApiError::internal("saving the environment map", e))?;
                envmap_file = Some(name);
            }
            "cameras" => {
                let path = staging.path().join("cameras.json");
                save_field(field, &path).await?;
                let text = tokio::fs::read(&path)
                    .await
                    .map_err(|e| ApiError::internal("reading the cameras", e))?;
                serde_json::from_slice::<serde_json::Value>(&text).map_err(|e| {
                    ApiError::unprocessable("invalid_cameras", format!("cameras: {e}"))
                })?;
                cameras_file = Some("cameras.json".to_owned());
            }
            "rotate_deg" => {
                let text = field.text().await.map_err(multipart_error)?;
                rotate_deg = text
                    .trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| {
                        ApiError::unprocessable(
                            "invalid_rotate_deg",
                            format!("rotate_deg must be a finite number, got {text:?}"),
                        )
                    })?;
            }
            other => {
                return Err(ApiError::bad_request(
                    "unknown_field",
                    format!("unknown form field `{other}` (expected envmap, cameras, rotate_deg)"),
                ))
            }
        }
    }
    let envmap_file = envmap_file.ok_or_else(|| {
        ApiError::unprocessable("missing_envmap", "the form has no `envmap` file field")
    })?;
    let input_dir = state.paths.input_dir(&id);
    if let Some(parent_dir) = input_dir.parent() {
        std::fs::create_dir_all(parent_dir)
            .map_err(|e| ApiError::internal("filing the relight inputs", e))?;
    }
    std::fs::rename(staging.path(), &input_dir)
        .map_err(|e| ApiError::internal("filing the relight inputs", e))?;
    let input_key = format!("jobs/{id}/input");
    if let Some(bucket) = &state.bucket {
        if let Err(e) = bucket.upload_dir(&input_key, &input_dir).await {
            let _ = std::fs::remove_dir_all(state.paths.jobs.join(&id));
            let _ = bucket.delete_folder(&input_key).await;
            return Err(e.into());
        }
    }
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
    };
    let record = match state.store.submit(&job, None).await {
        Ok((record, _)) => record,
        Err(e) => {
            let _ = std::fs::remove_dir_all(state.paths.jobs.join(&id));
            if let Some(bucket) = &state.bucket {
                let _ = bucket.delete_folder(&input_key).await;
            }
            return Err(e.into());
        }
    };
    tracing::info!(job_id = %id, parent = %record.capture_id, "relight job queued");
    state.runtime.wake_workers();
    Ok((StatusCode::CREATED, Json(record.into())))
}

/// How long `DELETE` of a running job waits for it to stop (it checkpoints first).
const DELETE_WAIT: Duration = Duration::from_secs(60);

/// `DELETE /v1/jobs/{id}`: 204 once the job and everything stored for it (checkpoints, inputs,
/// artifacts) are gone. A queued job is cancelled first, a running one is cancelled and awaited
/// (409 `job_stopping` if it has not stopped within a minute); 409 `job_in_use` while a queued or
/// running relight job uses its model.
pub async fn remove(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(id): Path<String>,
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
    match crate::purge::delete_job(&state, &id).await? {
        DeleteOutcome::Deleted => Ok(StatusCode::NO_CONTENT),
        DeleteOutcome::NotFound => Err(ApiError::not_found("job", &id)),
        DeleteOutcome::InUse => Err(ApiError::conflict(
            "job_in_use",
            format!("a queued or running relight job uses the model of job `{id}`"),
        )),
    }
}

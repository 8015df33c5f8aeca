//! Capture upload (streamed to disk, extracted safely, validated by the pipeline), lookup and
//! deletion. A rejected upload leaves nothing behind: its temporary folder is removed and no record
//! is written. An account's storage quota is reserved before a byte is kept
//! ([`crate::accounts::quotas::Reservation`]): the declared length at once, a body without one as
//! it arrives, cut off where it crosses the quota.

use std::path::{Path as FsPath, PathBuf};

use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{HeaderMap, StatusCode};
use axum::Extension;
use axum::Json;
use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use super::Binary;
use crate::accounts::auth::Caller;
use crate::accounts::quotas::Reservation;
use crate::domain::ids::new_id;
use crate::http::bodies::{
    check_content_length, content_length, refuse_unread, stream_to_file_within, too_large, TempDir,
};
use crate::http::error::{ApiError, ErrorBody, ProblemBody};
use crate::jobs::pipeline_seam::{DeathReason, PipelineError};
use crate::jobs::state::AppState;
use crate::storage::archive::ArchiveError;
use crate::storage::store::{now_ms, rfc3339, CaptureRecord, DeleteOutcome};

/// An accepted capture.
#[derive(Serialize, ToSchema)]
#[schema(as = Capture)]
pub struct CaptureView {
    /// `cap_…`; what a job's `capture_id` names.
    id: String,
    /// Views in transforms.json.
    views: usize,
    /// The size of its views, pixels (0 for captures uploaded before it was recorded).
    width: u32,
    height: u32,
    /// The kinds of measurement its views hold: `stokes`, `polarizer4`, `partial`, `rgb`.
    kinds: Vec<String>,
    /// What the loader noticed but accepted (e.g. views without masks).
    warnings: Vec<String>,
    /// Size of the uploaded archive.
    size_bytes: u64,
    #[schema(format = DateTime)]
    created_at: String,
}

/// The capture a route is about.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Path)]
pub struct CapturePath {
    /// The capture's id (`cap_…`).
    id: String,
}

impl CaptureView {
    pub fn id(&self) -> &str {
        &self.id
    }
}

impl From<CaptureRecord> for CaptureView {
    fn from(c: CaptureRecord) -> Self {
        CaptureView {
            id: c.id,
            views: c.views,
            width: c.width,
            height: c.height,
            kinds: c.kinds,
            warnings: c.warnings,
            size_bytes: c.size_bytes,
            created_at: rfc3339(c.created_at),
        }
    }
}

fn archive_error(e: ArchiveError) -> ApiError {
    match e {
        ArchiveError::UnknownFormat(m) => ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "unsupported_archive",
            format!("unsupported archive format: {m}"),
        ),
        ArchiveError::Corrupt(m) => {
            ApiError::bad_request("invalid_archive", format!("corrupt archive: {m}"))
        }
        e @ ArchiveError::Unsafe { .. } => ApiError::bad_request("unsafe_archive", e.to_string()),
        e @ ArchiveError::TooLarge(_) => ApiError::too_large(e.to_string()),
        e @ ArchiveError::Io { .. } => ApiError::internal("extracting the archive", e),
    }
}

/// A capture extracted, validated and moved to its folder, before its record is written.
struct Filed {
    record: CaptureRecord,
    dir: PathBuf,
    /// The upload's temporary folder, removed once the capture is recorded (or rejected).
    staging: TempDir,
}

/// Names the files of a validation message relative to the archive (the server's own folders
/// are no business of the client's).
fn relative_to_archive(message: &str, extracted: &FsPath) -> String {
    let prefix = format!("{}{}", extracted.display(), std::path::MAIN_SEPARATOR);
    message.replace(&prefix, "")
}

/// The answer to a capture the validator refused (or could not finish validating).
fn rejected_capture(error: PipelineError, extracted: &FsPath) -> ApiError {
    let relative = |text: &str| relative_to_archive(text, extracted);
    match error {
        PipelineError::InvalidCapture { message, problems } => {
            let problems = problems
                .into_iter()
                .map(|p| ProblemBody {
                    frame: relative(&p.frame),
                    key: p.key,
                    message: relative(&p.message),
                })
                .collect();
            ApiError::unprocessable("invalid_capture", relative(&message)).with_problems(problems)
        }
        PipelineError::CaptureTooLarge { message, .. } => {
            ApiError::unprocessable("capture_too_large", relative(&message))
        }
        PipelineError::Died {
            reason: reason @ (DeathReason::OutOfMemory | DeathReason::TimeLimit),
            detail,
        } => ApiError::unprocessable(
            "capture_too_large",
            format!(
                "validating the capture {} ({detail}); it is too large for this service",
                if reason == DeathReason::OutOfMemory {
                    "ran out of memory"
                } else {
                    "ran past the time limit"
                }
            ),
        ),
        PipelineError::Died { detail, .. } => ApiError::unprocessable(
            "invalid_capture",
            format!("the capture could not be validated: the validating process died ({detail})"),
        ),
        other => ApiError::internal("validating the capture", other),
    }
}

/// Extracts, validates and files an uploaded archive (blocking).
fn extract_and_file(
    state: &AppState,
    staging: TempDir,
    id: &str,
    archive: &FsPath,
    size_bytes: u64,
    account: Option<String>,
) -> Result<Filed, ApiError> {
    let extracted = staging.path().join("capture");
    let root = crate::storage::archive::extract(archive, &extracted, &state.config.extract_limits)
        .map_err(archive_error)?;
    let info = state
        .pipeline
        .inspect(&root)
        .map_err(|e| rejected_capture(e, &extracted))?;
    let dir = state.paths.capture_dir(id);
    std::fs::rename(&root, &dir).map_err(|e| ApiError::internal("filing the capture", e))?;
    let record = CaptureRecord {
        id: id.to_owned(),
        views: info.views,
        width: info.width,
        height: info.height,
        kinds: info.kinds,
        warnings: info.warnings,
        size_bytes,
        created_at: now_ms(),
        account,
    };
    Ok(Filed {
        record,
        dir,
        staging,
    })
}

/// Extracts and validates an upload on the blocking pool, copies it to the deployment's object
/// store where there is one (so workers elsewhere can fetch it), then records it; a capture
/// that cannot be stored or recorded is removed again.
pub(crate) async fn ingest(
    state: AppState,
    staging: TempDir,
    id: String,
    archive: PathBuf,
    size_bytes: u64,
    account: Option<String>,
) -> Result<CaptureRecord, ApiError> {
    let blocking_state = state.clone();
    let filed = tokio::task::spawn_blocking(move || {
        let span = tracing::info_span!("capture_upload", capture_id = %id);
        let _entered = span.enter();
        extract_and_file(&blocking_state, staging, &id, &archive, size_bytes, account)
    })
    .await
    .map_err(|e| ApiError::internal("processing the upload", e))??;
    let published = crate::http::intake::Filed {
        dir: &filed.dir,
        key: crate::storage::object_keys::capture(&filed.record.id),
        remove: filed.dir.clone(),
    };
    crate::http::intake::publish_then_record(&state, published, || {
        state.store.insert_capture(&filed.record)
    })
    .await?;
    drop(filed.staging);
    Ok(filed.record)
}

/// `POST /v1/captures`: body is a `.zip` or `.tar` archive.
#[utoipa::path(
    post,
    path = "/v1/captures",
    tag = "captures",
    operation_id = "upload_capture",
    summary = "Upload a capture archive",
    description = "The body, a .zip or .tar holding transforms.json (or a COLMAP model in \
        sparse/0/) and its images or raw mosaic frames, is streamed to disk, extracted safely and validated by the capture loader. A rejected upload leaves \
        nothing behind.",
    request_body(content(
        (Binary = "application/zip"),
        (Binary = "application/x-tar"),
        (Binary = "application/octet-stream"),
    )),
    responses(
        (status = CREATED, description = "The accepted capture", body = CaptureView),
        (status = BAD_REQUEST, description = "An empty body (empty_upload), a corrupt archive \
            (invalid_archive), an unsafe entry: traversal, absolute path, link, a name over 255 \
            bytes (unsafe_archive), or an interrupted upload (upload_interrupted)", body = ErrorBody),
        (status = REQUEST_TIMEOUT, description = "The body arrived slower than the service's \
            minimum rate (request_timeout)", body = ErrorBody),
        (status = PAYLOAD_TOO_LARGE, description = "An upload over --max-upload-mb, or an \
            archive expanding past the limits: decompression bomb, too many entries \
            (payload_too_large)", body = ErrorBody),
        (status = FORBIDDEN, description = "The account's stored bytes would pass its quota \
            (storage_quota_exceeded)", body = ErrorBody),
        (status = UNSUPPORTED_MEDIA_TYPE, description = "Not a .zip or .tar archive \
            (unsupported_archive)", body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "The capture breaks the capture format \
            (invalid_capture), or declares more views, pixels a view or decoded bytes than the \
            service's limits allow (capture_too_large, naming the limit)", body = ErrorBody),
    )
)]
pub async fn upload(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    headers: HeaderMap,
    body: Body,
) -> Result<(StatusCode, Json<CaptureView>), ApiError> {
    let limit = state.config.max_upload_bytes;
    if let Err(too_large) = check_content_length(&headers, limit) {
        return Err(refuse_unread(body, too_large).await);
    }
    let id = new_id("cap");
    // The account's storage is reserved before a byte is kept: the declared length, or a body
    // without one as it arrives.
    let reserved = match content_length(&headers) {
        Some(declared) => Reservation::exactly(&state.ledger(), &caller, &id, declared).await,
        None => Reservation::growing(&state.ledger(), &caller, &id).await,
    };
    let mut reservation = match reserved {
        Ok(reservation) => reservation,
        Err(over_quota) => return Err(refuse_unread(body, over_quota.into()).await),
    };
    let staging = TempDir::create(state.paths.tmp.join(&id))?;
    let archive = staging.path().join("upload");
    let size = stream_to_file_within(
        body,
        &archive,
        limit,
        || too_large(limit),
        |_| {},
        reservation.as_mut(),
    )
    .await?;
    if size == 0 {
        return Err(ApiError::bad_request(
            "empty_upload",
            "the request body is empty; send a .zip or .tar archive",
        ));
    }
    // The rest runs to completion in its own task even if the client disconnects, so the
    // capture is either recorded or removed, and the temporary folder always cleaned up; the
    // reservation is held until the capture's record counts in its place.
    let account = caller.account().map(str::to_owned);
    let record = tokio::spawn(async move {
        let recorded = ingest(state.clone(), staging, id, archive, size, account).await;
        drop(reservation);
        recorded
    })
    .await
    .map_err(|e| ApiError::internal("processing the upload", e))??;
    tracing::info!(capture_id = %record.id, views = record.views, "capture accepted");
    Ok((StatusCode::CREATED, Json(record.into())))
}

/// The capture `id` where `caller` may see it (404 otherwise: another account's records are
/// not confirmed to exist).
pub async fn visible_capture(
    state: &AppState,
    caller: &Caller,
    id: &str,
) -> Result<CaptureRecord, ApiError> {
    state
        .store
        .capture(id)
        .await?
        .filter(|c| caller.may_see(c.account.as_deref()))
        .ok_or_else(|| ApiError::not_found("capture", id))
}

/// `GET /v1/captures/{id}`.
#[utoipa::path(
    get,
    path = "/v1/captures/{id}",
    tag = "captures",
    operation_id = "get_capture",
    summary = "A capture",
    params(CapturePath),
    responses(
        (status = OK, description = "The capture", body = CaptureView),
        (status = NOT_FOUND, description = "No such capture the token may see (not_found)", body = ErrorBody),
    )
)]
pub async fn show(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(CapturePath { id }): Path<CapturePath>,
) -> Result<Json<CaptureView>, ApiError> {
    Ok(Json(visible_capture(&state, &caller, &id).await?.into()))
}

/// `DELETE /v1/captures/{id}`: 204 once its record and files are gone; 409 while a queued or
/// running job uses it.
#[utoipa::path(
    delete,
    path = "/v1/captures/{id}",
    tag = "captures",
    operation_id = "delete_capture",
    summary = "Delete a capture and its files",
    params(CapturePath),
    responses(
        (status = NO_CONTENT, description = "Deleted"),
        (status = NOT_FOUND, description = "No such capture the token may see (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "A queued or running job uses it (capture_in_use)", body = ErrorBody),
    )
)]
pub async fn remove(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(CapturePath { id }): Path<CapturePath>,
) -> Result<StatusCode, ApiError> {
    visible_capture(&state, &caller, &id).await?;
    match crate::jobs::purge::delete_capture(&state, &id).await? {
        DeleteOutcome::NotFound => Err(ApiError::not_found("capture", &id)),
        DeleteOutcome::InUse => Err(ApiError::conflict(
            "capture_in_use",
            format!("capture `{id}` is used by a queued or running job; cancel it first"),
        )),
        DeleteOutcome::Deleted => Ok(StatusCode::NO_CONTENT),
    }
}

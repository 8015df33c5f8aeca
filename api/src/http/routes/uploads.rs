//! Resumable capture uploads ([`crate::http::upload_sessions`]): create one, send its parts in any
//! order, ask which arrived, commit it into a capture, or abandon it.

use axum::body::{Body, Bytes};
use axum::extract::rejection::BytesRejection;
use axum::extract::{Path, State};
use axum::http::{HeaderMap, StatusCode};
use axum::Extension;
use axum::Json;
use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use super::captures::{ingest, visible_capture, CaptureView};
use super::Binary;
use crate::accounts::auth::Caller;
use crate::accounts::quotas::Reservation;
use crate::domain::ids::new_id;
use crate::http::bodies::{content_length, refuse_unread, TempDir};
use crate::http::error::{ApiError, ErrorBody};
use crate::http::upload_sessions::{
    self, AssembleError, DEFAULT_PART_BYTES, MAX_PARTS, MAX_PART_BYTES, MIN_PART_BYTES,
};
use crate::jobs::state::AppState;
use crate::storage::store::{now_ms, rfc3339, PartOutcome, UploadEnd, UploadRecord, UploadState};

/// How long a commit holds an upload before another request may commit it again (a process
/// that died while committing leaves its upload in `committing` until then).
const COMMIT_LEASE_MS: i64 = 30 * 60 * 1000;

/// A new resumable upload.
#[derive(Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct NewUpload {
    /// The archive's size, bytes (at most the service's upload limit).
    size: u64,
    /// Bytes a part (65,536 to 134,217,728; default 67,108,864): every part but the last has
    /// exactly this length.
    #[serde(default)]
    part_size: Option<u64>,
    /// The whole archive's SHA-256 in hexadecimal, checked at commit.
    #[serde(default)]
    sha256: Option<String>,
}

/// Where an upload stands.
#[derive(Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum UploadStateView {
    /// Receiving parts.
    Open,
    /// Its parts are being joined and validated.
    Committing,
    /// It became the capture `capture_id`.
    Committed,
    /// Its archive was refused (`error`); its parts are gone.
    Failed,
}

/// A resumable upload.
#[derive(Serialize, ToSchema)]
#[schema(as = Upload)]
pub struct UploadView {
    /// `upl_…`.
    id: String,
    state: UploadStateView,
    /// The archive's size, bytes.
    size: u64,
    /// Bytes a part; part `i` holds bytes `i·part_size` up to the next part's start.
    part_size: u64,
    /// How many parts the archive has.
    parts: u64,
    /// Parts received so far, by number (from 0), ascending.
    received: Vec<u32>,
    /// Bytes received so far.
    received_bytes: u64,
    /// The declared SHA-256 of the whole archive, if any.
    #[schema(required = true)]
    sha256: Option<String>,
    /// The capture it became (`committed`).
    #[schema(required = true)]
    capture_id: Option<String>,
    /// Why it was refused (`failed`): the code and message its commit answered.
    #[schema(required = true)]
    error: Option<UploadErrorView>,
    #[schema(format = DateTime)]
    created_at: String,
    /// When it is removed with its parts unless a part or commit arrives before.
    #[schema(format = DateTime)]
    expires_at: String,
}

/// Why an upload's commit was refused.
#[derive(Serialize, ToSchema)]
pub struct UploadErrorView {
    code: String,
    message: String,
}

/// A part as stored.
#[derive(Serialize, ToSchema)]
#[schema(as = UploadPart)]
pub struct PartView {
    /// The part's number, from 0.
    index: u32,
    /// Its length, bytes.
    size: u64,
    /// Its SHA-256, hexadecimal.
    sha256: String,
}

impl UploadView {
    fn new(state: &AppState, upload: UploadRecord) -> Self {
        let (state_view, capture_id, error) = match upload.state {
            UploadState::Open => (UploadStateView::Open, None, None),
            UploadState::Committing { .. } => (UploadStateView::Committing, None, None),
            UploadState::Committed { capture_id } => {
                (UploadStateView::Committed, Some(capture_id), None)
            }
            UploadState::Failed { code, message } => (
                UploadStateView::Failed,
                None,
                Some(UploadErrorView { code, message }),
            ),
        };
        UploadView {
            state: state_view,
            size: upload.size,
            part_size: upload.part_size,
            parts: upload_sessions::part_count(upload.size, upload.part_size),
            received: upload.parts.iter().map(|p| p.index).collect(),
            received_bytes: upload.parts.iter().map(|p| p.size).sum(),
            sha256: upload.sha256,
            capture_id,
            error,
            created_at: rfc3339(upload.created_at),
            expires_at: rfc3339(upload_sessions::expires_at(state, upload.updated_at)),
            id: upload.id,
        }
    }
}

/// The upload a route is about.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Path)]
pub struct UploadPath {
    /// The upload's id (`upl_…`).
    id: String,
}

/// One part of an upload.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Path)]
pub struct PartPath {
    /// The upload's id (`upl_…`).
    id: String,
    /// The part's number, from 0, in decimal digits without a sign or leading zeros.
    #[param(value_type = u32)]
    index: String,
}

/// The upload `id` where `caller` may see it (404 otherwise).
async fn visible_upload(
    state: &AppState,
    caller: &Caller,
    id: &str,
) -> Result<UploadRecord, ApiError> {
    state
        .store
        .upload(id)
        .await?
        .filter(|u| caller.may_see(u.account.as_deref()))
        .ok_or_else(|| ApiError::not_found("upload", id))
}

fn invalid_upload(message: impl Into<String>) -> ApiError {
    ApiError::unprocessable("invalid_upload", message)
}

/// `POST /v1/uploads`.
#[utoipa::path(
    post,
    path = "/v1/uploads",
    tag = "captures",
    operation_id = "create_upload",
    summary = "Start a resumable capture upload",
    description = "Declares an archive's size (and optionally its part size and SHA-256). Send \
        its parts with PUT /v1/uploads/{id}/parts/{index} in any order, ask which arrived with \
        GET /v1/uploads/{id}, then POST /v1/uploads/{id}/commit. An upload untouched for \
        --upload-expiry-hours is removed with its parts.",
    request_body = NewUpload,
    responses(
        (status = CREATED, description = "The new upload", body = UploadView),
        (status = BAD_REQUEST, description = "A body that is not JSON (invalid_json)", body = ErrorBody),
        (status = PAYLOAD_TOO_LARGE, description = "A size over --max-upload-mb \
            (payload_too_large)", body = ErrorBody),
        (status = FORBIDDEN, description = "The account's stored bytes would pass its quota \
            (storage_quota_exceeded)", body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "A size of 0, a part size out of range, \
            more than 10,000 parts, or a SHA-256 that is not 64 hexadecimal digits \
            (invalid_upload); a field of the wrong type or unknown (invalid_request)", body = ErrorBody),
    )
)]
pub async fn create(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    body: Result<Bytes, BytesRejection>,
) -> Result<(StatusCode, Json<UploadView>), ApiError> {
    let request: NewUpload = super::json_request(body)?;
    let limit = state.config.max_upload_bytes;
    if request.size == 0 {
        return Err(invalid_upload("an upload needs a size of at least 1 byte"));
    }
    if request.size > limit {
        return Err(ApiError::too_large(format!(
            "an upload of {} bytes exceeds the limit of {} MiB",
            request.size,
            limit >> 20
        )));
    }
    let part_size = request
        .part_size
        .unwrap_or(DEFAULT_PART_BYTES.min(request.size).max(MIN_PART_BYTES));
    if !(MIN_PART_BYTES..=MAX_PART_BYTES).contains(&part_size) {
        return Err(invalid_upload(format!(
            "part_size must be {MIN_PART_BYTES} to {MAX_PART_BYTES} bytes"
        )));
    }
    if upload_sessions::part_count(request.size, part_size) > MAX_PARTS {
        return Err(invalid_upload(format!(
            "an upload has at most {MAX_PARTS} parts: choose a part size of at least {} bytes",
            request.size.div_ceil(MAX_PARTS)
        )));
    }
    if let Some(sha) = &request.sha256 {
        if !upload_sessions::is_sha256_hex(sha) {
            return Err(invalid_upload("sha256 must be 64 hexadecimal digits"));
        }
    }
    let id = new_id("upl");
    // Held until the upload's record counts its size in the reservation's place.
    let reservation = Reservation::exactly(&state.ledger(), &caller, &id, request.size).await?;
    let now = now_ms();
    let record = UploadRecord {
        id,
        account: caller.account().map(str::to_owned),
        size: request.size,
        part_size,
        sha256: request.sha256.map(|s| s.to_ascii_lowercase()),
        state: UploadState::Open,
        parts: Vec::new(),
        created_at: now,
        updated_at: now,
    };
    state.store.create_upload(&record).await?;
    drop(reservation);
    tracing::info!(upload_id = %record.id, size = record.size, part_size, "upload created");
    Ok((StatusCode::CREATED, Json(UploadView::new(&state, record))))
}

/// `GET /v1/uploads/{id}`.
#[utoipa::path(
    get,
    path = "/v1/uploads/{id}",
    tag = "captures",
    operation_id = "get_upload",
    summary = "A resumable upload: which parts arrived",
    params(UploadPath),
    responses(
        (status = OK, description = "The upload", body = UploadView),
        (status = NOT_FOUND, description = "No such upload the token may see, or it expired \
            (not_found)", body = ErrorBody),
    )
)]
pub async fn show(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(UploadPath { id }): Path<UploadPath>,
) -> Result<Json<UploadView>, ApiError> {
    let upload = visible_upload(&state, &caller, &id).await?;
    Ok(Json(UploadView::new(&state, upload)))
}

fn not_open(upload: &UploadRecord) -> ApiError {
    let state = match upload.state {
        UploadState::Open => "open",
        UploadState::Committing { .. } => "being committed",
        UploadState::Committed { .. } => "committed",
        UploadState::Failed { .. } => "failed",
    };
    ApiError::conflict(
        "upload_closed",
        format!("upload `{}` is {state}: it takes no more parts", upload.id),
    )
}

/// What a part request's path and headers decide before its body is read: the open upload (not
/// expired), the part's number and length, and its declared SHA-256.
async fn check_part_request(
    state: &AppState,
    caller: &Caller,
    id: &str,
    index: &str,
    headers: &HeaderMap,
) -> Result<(UploadRecord, u32, u64, [u8; 32]), ApiError> {
    let upload = visible_upload(state, caller, id).await?;
    if !matches!(upload.state, UploadState::Open) {
        return Err(not_open(&upload));
    }
    upload_sessions::refuse_expired(state, &upload, now_ms())?;
    let digest = upload_sessions::content_digest(headers)?;
    let no_such_part = || {
        ApiError::bad_request(
            "no_such_part",
            format!(
                "this upload has parts 0 to {}, numbered in decimal digits without a sign or \
                 leading zeros",
                upload_sessions::part_count(upload.size, upload.part_size).saturating_sub(1)
            ),
        )
    };
    let index = upload_sessions::part_number(index).ok_or_else(no_such_part)?;
    let expected = upload_sessions::part_length(&upload, index).ok_or_else(no_such_part)?;
    if let Some(declared) = content_length(headers).filter(|&declared| declared != expected) {
        return Err(ApiError::bad_request(
            "part_size_mismatch",
            format!("part {index} must be {expected} bytes long, not {declared}"),
        ));
    }
    Ok((upload, index, expected, digest))
}

/// `PUT /v1/uploads/{id}/parts/{index}`.
#[utoipa::path(
    put,
    path = "/v1/uploads/{id}/parts/{index}",
    tag = "captures",
    operation_id = "upload_part",
    summary = "Send one part of a resumable upload",
    description = "The body is the part's bytes: exactly part_size of them (the last part: the \
        rest of the archive). Content-Digest: sha-256=:<base64>: (RFC 9530) is required; a part \
        is kept only when its length and digest match, and a part sent again replaces the one \
        before. A body that breaks off leaves nothing behind: send the part again. Part numbers \
        are decimal digits without a sign or leading zeros.",
    params(PartPath),
    request_body(content((Binary = "application/octet-stream"))),
    responses(
        (status = OK, description = "The part as stored", body = PartView),
        (status = BAD_REQUEST, description = "No Content-Digest (digest_required), a malformed \
            one (invalid_digest), bytes that do not match it (digest_mismatch), a length other \
            than the part's (part_size_mismatch), a number past the last part (no_such_part), \
            or a body that broke off (upload_interrupted)", body = ErrorBody),
        (status = NOT_FOUND, description = "No such upload the token may see (not_found)", body = ErrorBody),
        (status = GONE, description = "The upload expired: idle past --upload-expiry-hours \
            (upload_expired)", body = ErrorBody),
        (status = REQUEST_TIMEOUT, description = "The body arrived slower than the service's \
            minimum rate (request_timeout)", body = ErrorBody),
        (status = CONFLICT, description = "The upload is being committed, committed or failed \
            (upload_closed)", body = ErrorBody),
    )
)]
pub async fn put_part(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(PartPath { id, index }): Path<PartPath>,
    headers: HeaderMap,
    body: Body,
) -> Result<Json<PartView>, ApiError> {
    let (upload, index, expected, digest) =
        match check_part_request(&state, &caller, &id, &index, &headers).await {
            Ok(checked) => checked,
            Err(refused) => return Err(refuse_unread(body, refused).await),
        };
    let part =
        upload_sessions::receive_part(&state, &upload, index, expected, body, digest).await?;
    upload_sessions::pause::at(&id, upload_sessions::pause::PART_STORED).await;
    // The copy is this request's alone: whatever the store answers, no other request's copy
    // is touched.
    let recorded = match state.store.record_part(&id, &part, now_ms()).await {
        Ok(recorded) => recorded,
        Err(e) => {
            upload_sessions::discard_part(&state, &id, &part).await;
            return Err(e.into());
        }
    };
    match recorded {
        PartOutcome::Recorded { replaced } => {
            if let Some(old) = replaced {
                upload_sessions::discard_part(&state, &id, &old).await;
            }
        }
        PartOutcome::Closed => {
            upload_sessions::discard_part(&state, &id, &part).await;
            let upload = visible_upload(&state, &caller, &id).await?;
            return Err(not_open(&upload));
        }
        PartOutcome::NotFound => {
            // Deleted meanwhile: its folder, which this request may have made again, goes too.
            upload_sessions::discard_parts(&state, &id).await;
            return Err(ApiError::not_found("upload", &id));
        }
    }
    Ok(Json(PartView {
        index: part.index,
        size: part.size,
        sha256: part.sha256,
    }))
}

/// The answer a failed upload's commit gave, given again.
fn stored_failure(code: &str, message: &str) -> ApiError {
    let (status, code) = match code {
        "invalid_archive" => (StatusCode::BAD_REQUEST, "invalid_archive"),
        "unsafe_archive" => (StatusCode::BAD_REQUEST, "unsafe_archive"),
        "payload_too_large" => (StatusCode::PAYLOAD_TOO_LARGE, "payload_too_large"),
        "unsupported_archive" => (StatusCode::UNSUPPORTED_MEDIA_TYPE, "unsupported_archive"),
        "capture_too_large" => (StatusCode::UNPROCESSABLE_ENTITY, "capture_too_large"),
        "digest_mismatch" => (StatusCode::UNPROCESSABLE_ENTITY, "digest_mismatch"),
        _ => (StatusCode::UNPROCESSABLE_ENTITY, "invalid_capture"),
    };
    ApiError::new(status, code, message)
}

/// Joins, validates and records a committed upload's archive as a new capture.
async fn commit_parts(
    state: AppState,
    upload: UploadRecord,
) -> Result<CaptureView, upload_sessions::AssembleError> {
    let capture_id = new_id("cap");
    let staging = TempDir::create(state.paths.tmp.join(&capture_id))
        .map_err(upload_sessions::AssembleError::Refused)?;
    let archive = staging.path().join("upload");
    upload_sessions::assemble(&state, &upload, &archive).await?;
    let record = ingest(
        state.clone(),
        staging,
        capture_id,
        archive,
        upload.size,
        upload.account.clone(),
    )
    .await
    .map_err(upload_sessions::AssembleError::Refused)?;
    tracing::info!(upload_id = %upload.id, capture_id = %record.id, views = record.views, "upload committed");
    Ok(record.into())
}

/// `POST /v1/uploads/{id}/commit`.
#[utoipa::path(
    post,
    path = "/v1/uploads/{id}/commit",
    tag = "captures",
    operation_id = "commit_upload",
    summary = "Turn a complete resumable upload into a capture",
    description = "Joins the parts in order, checks the declared SHA-256, then extracts and \
        validates the archive as POST /v1/captures does. Committing again answers the same \
        capture (200) or the same refusal; a refused upload's parts are removed. A part whose \
        stored copy cannot be read back is named (409 part_unreadable) and dropped from the \
        received parts: send it again, then commit. A failure of the service's own (500) \
        leaves the upload open: commit again.",
    params(UploadPath),
    responses(
        (status = CREATED, description = "The capture it became", body = CaptureView),
        (status = OK, description = "It was committed before: its capture", body = CaptureView),
        (status = BAD_REQUEST, description = "A corrupt or unsafe archive (invalid_archive, \
            unsafe_archive)", body = ErrorBody),
        (status = NOT_FOUND, description = "No such upload the token may see, or its capture \
            was deleted since (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "Parts are missing (upload_incomplete, naming them), \
            a commit is under way (upload_committing), or a stored part could not be read back \
            (part_unreadable, naming it: it is no longer listed as received, send it again)", body = ErrorBody),
        (status = GONE, description = "The upload expired: idle past --upload-expiry-hours \
            (upload_expired)", body = ErrorBody),
        (status = PAYLOAD_TOO_LARGE, description = "An archive expanding past the limits \
            (payload_too_large)", body = ErrorBody),
        (status = UNSUPPORTED_MEDIA_TYPE, description = "Not a .zip or .tar archive \
            (unsupported_archive)", body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "The joined archive's SHA-256 differs \
            from the declared one (digest_mismatch), or the capture is refused \
            (invalid_capture, capture_too_large)", body = ErrorBody),
    )
)]
pub async fn commit(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(UploadPath { id }): Path<UploadPath>,
) -> Result<(StatusCode, Json<CaptureView>), ApiError> {
    let upload = visible_upload(&state, &caller, &id).await?;
    match &upload.state {
        UploadState::Committed { capture_id } => {
            let capture = visible_capture(&state, &caller, capture_id).await?;
            return Ok((StatusCode::OK, Json(capture.into())));
        }
        UploadState::Failed { code, message } => return Err(stored_failure(code, message)),
        UploadState::Open | UploadState::Committing { .. } => {}
    }
    upload_sessions::refuse_expired(&state, &upload, now_ms())?;
    let count = upload_sessions::part_count(upload.size, upload.part_size);
    let missing: Vec<u64> = (0..count)
        .filter(|&i| !upload.parts.iter().any(|p| u64::from(p.index) == i))
        .collect();
    if !missing.is_empty() {
        let shown: Vec<String> = missing.iter().take(20).map(u64::to_string).collect();
        return Err(ApiError::conflict(
            "upload_incomplete",
            format!(
                "{} of {count} parts are missing: {}{}",
                missing.len(),
                shown.join(", "),
                if missing.len() > shown.len() {
                    ", …"
                } else {
                    ""
                }
            ),
        ));
    }
    let now = now_ms();
    let Some(upload) = state
        .store
        .begin_commit(&id, now, now + COMMIT_LEASE_MS)
        .await?
    else {
        return Err(ApiError::conflict(
            "upload_committing",
            format!("upload `{id}` is being committed by another request"),
        ));
    };
    // Runs to the end in its own task even if the client goes away, so the upload is always
    // settled: committed, failed, or open again.
    let task_state = state.clone();
    let outcome = tokio::spawn(async move {
        upload_sessions::pause::at(&id, upload_sessions::pause::COMMIT_TAKEN).await;
        let parts = upload.parts.clone();
        let result = commit_parts(task_state.clone(), upload).await;
        let end = match &result {
            Ok(capture) => UploadEnd::Committed {
                capture_id: capture.id().to_owned(),
            },
            Err(AssembleError::PartUnreadable { index }) => UploadEnd::PartsLost {
                indexes: vec![*index],
            },
            Err(AssembleError::Refused(e)) if e.status.is_client_error() => UploadEnd::Failed {
                code: e.code.to_owned(),
                message: e.message.clone(),
            },
            Err(AssembleError::Refused(_)) => UploadEnd::Reopened,
        };
        task_state.store.end_commit(&id, &end, now_ms()).await?;
        match &end {
            UploadEnd::Reopened => {}
            UploadEnd::PartsLost { indexes } => {
                // What is left of the unreadable copies (one that changed) goes with them.
                for part in parts.iter().filter(|p| indexes.contains(&p.index)) {
                    upload_sessions::discard_part(&task_state, &id, part).await;
                }
            }
            UploadEnd::Committed { .. } | UploadEnd::Failed { .. } => {
                upload_sessions::discard_parts(&task_state, &id).await;
            }
        }
        result.map_err(|e| match e {
            AssembleError::PartUnreadable { index } => upload_sessions::part_unreadable(&id, index),
            AssembleError::Refused(e) => e,
        })
    })
    .await
    .map_err(|e| ApiError::internal("committing the upload", e))?;
    Ok((StatusCode::CREATED, Json(outcome?)))
}

/// `DELETE /v1/uploads/{id}`.
#[utoipa::path(
    delete,
    path = "/v1/uploads/{id}",
    tag = "captures",
    operation_id = "delete_upload",
    summary = "Abandon a resumable upload and its parts",
    params(UploadPath),
    responses(
        (status = NO_CONTENT, description = "Removed (a committed upload's capture stays)"),
        (status = NOT_FOUND, description = "No such upload the token may see (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "It is being committed (upload_committing)", body = ErrorBody),
    )
)]
pub async fn remove(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(UploadPath { id }): Path<UploadPath>,
) -> Result<StatusCode, ApiError> {
    let upload = visible_upload(&state, &caller, &id).await?;
    if matches!(upload.state, UploadState::Committing { until } if until > now_ms()) {
        return Err(ApiError::conflict(
            "upload_committing",
            format!("upload `{id}` is being committed; delete its capture afterwards instead"),
        ));
    }
    if state.store.delete_upload(&id).await? {
        upload_sessions::discard_parts(&state, &id).await;
    }
    Ok(StatusCode::NO_CONTENT)
}

#[cfg(test)]
mod tests {
    //! Interleavings of part, commit and delete requests, forced with [`upload_sessions::pause`]: a
    //! request is held at a chosen point while another runs, then let go.

    use std::sync::Arc;
    use std::time::Duration;

    use base64::Engine as _;
    use sha2::{Digest as _, Sha256};

    use crate::http::upload_sessions::pause;
    use crate::{Server, ServiceConfig};

    /// A server on loopback over a fresh data dir, no workers, the core validating in process.
    async fn server() -> (tempfile::TempDir, Server, reqwest::Client, String) {
        let dir = tempfile::tempdir().unwrap();
        let mut config = ServiceConfig::new(dir.path());
        config.bind = "127.0.0.1:0".parse().unwrap();
        config.workers = 0;
        let server = Server::start(
            config,
            Arc::new(crate::jobs::in_process_runner::CorePipeline::default()),
        )
        .await
        .unwrap();
        let base = format!("http://{}", server.local_addr());
        (dir, server, reqwest::Client::new(), base)
    }

    /// A small valid capture as a tar.
    fn capture_tar() -> Vec<u8> {
        let dir = tempfile::tempdir().unwrap();
        let options = phygap::pipeline::synth::SynthOptions {
            views: 10,
            size: 24,
            ..Default::default()
        };
        phygap::pipeline::synth::synth(dir.path(), &options).unwrap();
        let mut builder = tar::Builder::new(Vec::new());
        builder.append_dir_all(".", dir.path()).unwrap();
        builder.into_inner().unwrap()
    }

    const PART: usize = 64 << 10;

    async fn create(client: &reqwest::Client, base: &str, size: usize) -> String {
        let response = client
            .post(format!("{base}/v1/uploads"))
            .json(&serde_json::json!({ "size": size, "part_size": PART }))
            .send()
            .await
            .unwrap();
        assert_eq!(response.status(), 201);
        let body: serde_json::Value = response.json().await.unwrap();
        body["id"].as_str().unwrap().to_owned()
    }

    async fn put(
        client: &reqwest::Client,
        base: &str,
        id: &str,
        index: usize,
        bytes: &[u8],
    ) -> u16 {
        let digest = base64::engine::general_purpose::STANDARD.encode(Sha256::digest(bytes));
        client
            .put(format!("{base}/v1/uploads/{id}/parts/{index}"))
            .header("content-digest", format!("sha-256=:{digest}:"))
            .body(bytes.to_vec())
            .send()
            .await
            .unwrap()
            .status()
            .as_u16()
    }

    async fn commit(client: &reqwest::Client, base: &str, id: &str) -> (u16, serde_json::Value) {
        let response = client
            .post(format!("{base}/v1/uploads/{id}/commit"))
            .send()
            .await
            .unwrap();
        let status = response.status().as_u16();
        (status, response.json().await.unwrap_or_default())
    }

    async fn reached(pause: &pause::Pause) {
        tokio::time::timeout(Duration::from_secs(30), pause.reached.notified())
            .await
            .expect("the request reached its pause point");
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 4)]
    async fn a_part_sent_again_while_a_commit_runs_leaves_the_commit_its_parts() {
        let (_dir, server, client, base) = server().await;
        let archive = capture_tar();
        let id = create(&client, &base, archive.len()).await;
        for (index, part) in archive.chunks(PART).enumerate() {
            assert_eq!(put(&client, &base, &id, index, part).await, 200);
        }

        // Part 0 again, the same bytes: held once stored, before the store records it.
        let stored = pause::arm(&id, pause::PART_STORED);
        let again = tokio::spawn({
            let (client, base, id) = (client.clone(), base.clone(), id.clone());
            let part = archive[..PART].to_vec();
            async move { put(&client, &base, &id, 0, &part).await }
        });
        reached(&stored).await;
        // A commit takes the upload and is held before it reads a part.
        let taken = pause::arm(&id, pause::COMMIT_TAKEN);
        let committing = tokio::spawn({
            let (client, base, id) = (client.clone(), base.clone(), id.clone());
            async move { commit(&client, &base, &id).await }
        });
        reached(&taken).await;
        // The part request is refused (the upload is being committed) and cleans up after
        // itself; then the commit reads its parts.
        stored.release.notify_one();
        assert_eq!(again.await.unwrap(), 409);
        taken.release.notify_one();
        let (status, body) = committing.await.unwrap();
        assert_eq!(status, 201, "{body}");
        assert!(body["id"].as_str().unwrap().starts_with("cap_"), "{body}");
        server.shutdown().await;
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 4)]
    async fn a_delete_during_a_part_leaves_no_folder_behind() {
        let (dir, server, client, base) = server().await;
        let id = create(&client, &base, 3 * PART).await;
        let part = vec![7u8; PART];
        // Held before it stores its copy, while the upload and its folder are removed.
        let stored = pause::arm(&id, pause::PART_RECEIVED);
        let sending = tokio::spawn({
            let (client, base, id, part) = (client.clone(), base.clone(), id.clone(), part.clone());
            async move { put(&client, &base, &id, 1, &part).await }
        });
        reached(&stored).await;
        let deleted = client
            .delete(format!("{base}/v1/uploads/{id}"))
            .send()
            .await
            .unwrap();
        assert_eq!(deleted.status(), 204);
        stored.release.notify_one();
        assert_eq!(sending.await.unwrap(), 404);
        let folder = dir.path().join("uploads").join(&id);
        assert!(!folder.exists(), "{} is left", folder.display());
        server.shutdown().await;
    }
}

//! Artifact listing and download with single-range `Range` support.

use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::{Extension, Json};
use serde::{Deserialize, Serialize};
use tokio_util::io::ReaderStream;
use utoipa::{IntoParams, ToSchema};

use super::Binary;
use crate::accounts::auth::Caller;
use crate::http::conditional::Validators;
use crate::http::error::{ApiError, ErrorBody};
use crate::http::routes::jobs::{load_job, JobPath};
use crate::jobs::state::AppState;
use crate::storage::artifacts::ArtifactInfo;

/// A job's artifacts.
#[derive(Serialize, ToSchema)]
pub struct ArtifactList {
    job_id: String,
    /// Sorted by name; empty until the job has succeeded.
    artifacts: Vec<ArtifactInfo>,
}

/// One artifact of a job.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Path)]
pub struct ArtifactPath {
    /// The job's id (`job_…`).
    id: String,
    /// Artifact name as listed, e.g. surfels.ply, envmap.exr, metrics.json, mesh.ply,
    /// renders/s0/000.png (may contain /).
    name: String,
}

/// The headers a download reads (by hand, from the request's header map).
#[derive(IntoParams)]
#[into_params(parameter_in = Header)]
#[allow(dead_code)] // Only its parameters' schemas are used.
pub struct DownloadHeaders {
    /// One byte range: bytes=A-B, bytes=A-, bytes=-N (others are ignored: the whole file is
    /// sent).
    #[param(rename = "Range", value_type = String, required = false)]
    range: Option<String>,
    /// Send the range only if the file is still this one (its ETag, or its Last-Modified
    /// date); otherwise the whole file (200).
    #[param(rename = "If-Range", value_type = String, required = false)]
    if_range: Option<String>,
    /// ETags of copies the client holds (or `*`): 304 when one is this file.
    #[param(rename = "If-None-Match", value_type = String, required = false)]
    if_none_match: Option<String>,
    /// Without If-None-Match: 304 when the file is not newer than this HTTP date.
    #[param(rename = "If-Modified-Since", value_type = String, required = false)]
    if_modified_since: Option<String>,
}

/// `GET /v1/jobs/{id}/artifacts`.
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}/artifacts",
    tag = "artifacts",
    operation_id = "list_artifacts",
    summary = "A job's artifacts",
    params(JobPath),
    responses(
        (status = OK, description = "Its artifacts (none until it has succeeded)", body = ArtifactList),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
    )
)]
pub async fn list(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
) -> Result<Json<ArtifactList>, ApiError> {
    load_job(&state, &caller, &id).await?;
    let artifacts = state.artifacts.list(&id).await?;
    Ok(Json(ArtifactList {
        job_id: id,
        artifacts,
    }))
}

/// A parsed `Range` header against a resource of known size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ByteRange {
    /// No (usable) range: the whole body.
    Full,
    /// Inclusive byte positions.
    Partial {
        start: u64,
        end: u64,
    },
    Unsatisfiable,
}

/// Parses `bytes=A-B`, `bytes=A-`, `bytes=-N`. Malformed or multi-range headers are ignored (the
/// whole body is sent), as RFC 9110 allows.
pub fn parse_range(header: Option<&str>, size: u64) -> ByteRange {
    let Some(spec) = header.and_then(|h| h.trim().strip_prefix("bytes=")) else {
        return ByteRange::Full;
    };
    if spec.contains(',') {
        return ByteRange::Full;
    }
    let Some((first, last)) = spec.trim().split_once('-') else {
        return ByteRange::Full;
    };
    let (first, last) = (first.trim(), last.trim());
    let parsed = match (first.is_empty(), last.is_empty()) {
        (true, true) => return ByteRange::Full,
        (true, false) => match last.parse::<u64>() {
            Ok(0) => return ByteRange::Unsatisfiable,
            Ok(n) => Some((size.saturating_sub(n), size.saturating_sub(1))),
            Err(_) => None,
        },
        (false, _) => match (first.parse::<u64>(), last.parse::<u64>()) {
            (Ok(a), Err(_)) if last.is_empty() => Some((a, size.saturating_sub(1))),
            (Ok(a), Ok(b)) if b >= a => Some((a, b.min(size.saturating_sub(1)))),
            _ => None,
        },
    };
    match parsed {
        None => ByteRange::Full,
        Some((start, _)) if size == 0 || start >= size => ByteRange::Unsatisfiable,
        Some((start, end)) => ByteRange::Partial { start, end },
    }
}

fn header_value(text: &str) -> Result<HeaderValue, ApiError> {
    HeaderValue::from_str(text).map_err(|e| ApiError::internal("building a response header", e))
}

/// `GET /v1/jobs/{id}/artifacts/{name}`.
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}/artifacts/{name}",
    tag = "artifacts",
    operation_id = "download_artifact",
    summary = "Download an artifact",
    description = "The file with its own content type (the `content_type` of its listing), \
        whole or one byte range, with a strong ETag, Last-Modified and `Cache-Control: private, \
        no-cache`; a client's current copy gets 304.",
    params(ArtifactPath, DownloadHeaders),
    responses(
        (status = OK, description = "The file", body = Binary, content_type = "*/*"),
        (status = PARTIAL_CONTENT, description = "The requested range", body = Binary, content_type = "*/*"),
        (status = NOT_MODIFIED, description = "The client's copy (If-None-Match, \
            If-Modified-Since) is this file"),
        (status = TEMPORARY_REDIRECT, description = "With --presigned-downloads-seconds and an \
            S3 bucket: the file's presigned bucket URL (Location), valid that long; a client \
            sends its Range header there"),
        (status = NOT_FOUND, description = "No such job the token may see, or no such artifact \
            (not_found)", body = ErrorBody),
        (status = RANGE_NOT_SATISFIABLE, description = "The range starts past the end \
            (range_not_satisfiable)", body = ErrorBody),
    )
)]
pub async fn download(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(ArtifactPath { id, name }): Path<ArtifactPath>,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    load_job(&state, &caller, &id).await?;
    let stat = state
        .artifacts
        .stat(&id, &name)
        .await?
        .ok_or_else(|| ApiError::not_found("artifact", &name))?;
    let info = &stat.info;
    let validators = Validators {
        etag: stat.etag.clone(),
        modified: stat.modified,
    };
    if validators.not_modified(&headers) {
        let mut response = StatusCode::NOT_MODIFIED.into_response();
        caching_headers(response.headers_mut(), &validators)?;
        return Ok(response);
    }
    if let Some(expires) = state.config.presigned_downloads {
        if let Some(url) = state.artifacts.download_url(&id, info, expires).await? {
            // The client asks the bucket itself, its Range header with it.
            let mut response = StatusCode::TEMPORARY_REDIRECT.into_response();
            let h = response.headers_mut();
            h.insert(header::LOCATION, header_value(&url)?);
            h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
            return Ok(response);
        }
    }
    let range = match validators.range_applies(&headers) {
        true => parse_range(
            headers.get(header::RANGE).and_then(|v| v.to_str().ok()),
            info.size,
        ),
        // The client's partial copy is of another file: it gets this one whole.
        false => ByteRange::Full,
    };
    let (status, start, len) = match range {
        ByteRange::Full => (StatusCode::OK, 0, info.size),
        ByteRange::Partial { start, end } => (StatusCode::PARTIAL_CONTENT, start, end - start + 1),
        ByteRange::Unsatisfiable => {
            let mut response: Response = ApiError::new(
                StatusCode::RANGE_NOT_SATISFIABLE,
                "range_not_satisfiable",
                format!("`{name}` has {} bytes", info.size),
            )
            .into_response();
            response.headers_mut().insert(
                header::CONTENT_RANGE,
                header_value(&format!("bytes */{}", info.size))?,
            );
            return Ok(response);
        }
    };
    let reader = state.artifacts.open_range(&id, &name, start, len).await?;
    let mut response = Response::new(Body::from_stream(ReaderStream::new(reader)));
    *response.status_mut() = status;
    let h = response.headers_mut();
    h.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static(info.content_type),
    );
    h.insert(header::CONTENT_LENGTH, HeaderValue::from(len));
    h.insert(header::ACCEPT_RANGES, HeaderValue::from_static("bytes"));
    let file_name = name.rsplit('/').next().unwrap_or(&name);
    h.insert(
        header::CONTENT_DISPOSITION,
        header_value(&format!("attachment; filename=\"{file_name}\""))?,
    );
    caching_headers(h, &validators)?;
    if status == StatusCode::PARTIAL_CONTENT {
        h.insert(
            header::CONTENT_RANGE,
            header_value(&format!("bytes {start}-{}/{}", start + len - 1, info.size))?,
        );
    }
    Ok(response)
}

/// `ETag`, `Last-Modified`, and a `Cache-Control` that lets a browser keep the file but ask
/// again each time (the answer is a 304 while it is the same file; it needs the token, so only
/// the client's own cache may hold it).
fn caching_headers(h: &mut HeaderMap, validators: &Validators) -> Result<(), ApiError> {
    h.insert(header::ETAG, header_value(&validators.etag)?);
    h.insert(
        header::LAST_MODIFIED,
        header_value(&validators.last_modified())?,
    );
    h.insert(
        header::CACHE_CONTROL,
        HeaderValue::from_static("private, no-cache"),
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges() {
        use ByteRange::*;
        assert_eq!(parse_range(None, 10), Full);
        assert_eq!(
            parse_range(Some("bytes=0-3"), 10),
            Partial { start: 0, end: 3 }
        );
        assert_eq!(
            parse_range(Some("bytes=4-"), 10),
            Partial { start: 4, end: 9 }
        );
        assert_eq!(
            parse_range(Some("bytes=-3"), 10),
            Partial { start: 7, end: 9 }
        );
        assert_eq!(
            parse_range(Some("bytes=-30"), 10),
            Partial { start: 0, end: 9 }
        );
        assert_eq!(
            parse_range(Some("bytes=5-100"), 10),
            Partial { start: 5, end: 9 }
        );
        assert_eq!(parse_range(Some("bytes=10-"), 10), Unsatisfiable);
        assert_eq!(parse_range(Some("bytes=-0"), 10), Unsatisfiable);
        assert_eq!(parse_range(Some("bytes=3-1"), 10), Full);
        assert_eq!(parse_range(Some("bytes=0-1,4-5"), 10), Full);
        assert_eq!(parse_range(Some("items=0-1"), 10), Full);
        assert_eq!(parse_range(Some("bytes=x-"), 10), Full);
    }
}

//! Artifact listing and download with single-range `Range` support.

use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::{Extension, Json};
use serde::{Deserialize, Serialize};
use tokio_util::io::ReaderStream;
use utoipa::{IntoParams, ToSchema};

use crate::artifacts::ArtifactInfo;
use crate::auth::Caller;
use crate::error::{ApiError, ErrorBody};
use crate::openapi::Binary;
use crate::routes::jobs::{load_job, JobPath};
use crate::AppState;

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

/// The header a download reads (by hand, from the request's header map).
#[derive(IntoParams)]
#[into_params(parameter_in = Header)]
#[allow(dead_code)] // Only its parameter's schema is used.
pub struct RangeHeader {
    /// One byte range: bytes=A-B, bytes=A-, bytes=-N (others are ignored: the whole file is
    /// sent).
    #[param(rename = "Range", value_type = String, required = false)]
    range: Option<String>,
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
        whole or one byte range.",
    params(ArtifactPath, RangeHeader),
    responses(
        (status = OK, description = "The file", body = Binary, content_type = "*/*"),
        (status = PARTIAL_CONTENT, description = "The requested range", body = Binary, content_type = "*/*"),
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
    let info = state
        .artifacts
        .stat(&id, &name)
        .await?
        .ok_or_else(|| ApiError::not_found("artifact", &name))?;
    let range = parse_range(
        headers.get(header::RANGE).and_then(|v| v.to_str().ok()),
        info.size,
    );
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
    if status == StatusCode::PARTIAL_CONTENT {
        h.insert(
            header::CONTENT_RANGE,
            header_value(&format!("bytes {start}-{}/{}", start + len - 1, info.size))?,
        );
    }
    Ok(response)
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

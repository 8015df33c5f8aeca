//! Request bodies of the routes that take files: streamed to disk within a size limit (and an
//! account's storage quota), the answers to a body that breaks off, is too slow or declares too
//! much, what is read of a refused body before answering, and temporary folders that are removed
//! unless kept.

use std::path::{Path as FsPath, PathBuf};

use axum::body::Body;
use axum::http::{header, HeaderMap, StatusCode};
use futures_util::StreamExt;
use tokio::io::AsyncWriteExt;

use crate::accounts::quotas::Reservation;
use crate::http::error::ApiError;

/// A folder removed when dropped unless [`TempDir::keep`] was called.
pub struct TempDir {
    path: PathBuf,
    armed: bool,
}

impl TempDir {
    pub fn create(path: PathBuf) -> Result<Self, ApiError> {
        std::fs::create_dir_all(&path)
            .map_err(|e| ApiError::internal("creating an upload folder", e))?;
        Ok(TempDir { path, armed: true })
    }

    pub fn path(&self) -> &FsPath {
        &self.path
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        if self.armed {
            if let Err(e) = std::fs::remove_dir_all(&self.path) {
                if e.kind() != std::io::ErrorKind::NotFound {
                    tracing::error!(path = %self.path.display(), error = %e, "removing a temporary folder failed");
                }
            }
        }
    }
}

pub(crate) fn too_large(limit: u64) -> ApiError {
    ApiError::too_large(format!("upload exceeds the limit of {} MiB", limit >> 20))
}

/// Streams a request body into `target`, answering `over_limit()` past `limit` bytes and
/// showing every chunk to `inspect` as it is written (a digest, for instance); returns the size.
pub async fn stream_to_file_with(
    body: Body,
    target: &FsPath,
    limit: u64,
    over_limit: impl Fn() -> ApiError,
    inspect: impl FnMut(&[u8]),
) -> Result<u64, ApiError> {
    stream_to_file_within(body, target, limit, over_limit, inspect, None).await
}

/// [`stream_to_file_with`] that also keeps the bytes received covered by `quota`, before
/// each chunk is written: a body that crosses it is answered with the quota's refusal.
pub(crate) async fn stream_to_file_within(
    body: Body,
    target: &FsPath,
    limit: u64,
    over_limit: impl Fn() -> ApiError,
    mut inspect: impl FnMut(&[u8]),
    mut quota: Option<&mut Reservation>,
) -> Result<u64, ApiError> {
    let mut file = tokio::fs::File::create(target)
        .await
        .map_err(|e| ApiError::internal("creating the upload file", e))?;
    let mut stream = body.into_data_stream();
    let mut total = 0u64;
    while let Some(chunk) = stream.next().await {
        let chunk = chunk.map_err(|e| body_error(&e))?;
        total += chunk.len() as u64;
        if total > limit {
            drain_stream(&mut stream).await;
            return Err(over_limit());
        }
        if let Some(quota) = quota.as_deref_mut() {
            if let Err(over_quota) = quota.cover(total).await {
                drain_stream(&mut stream).await;
                return Err(over_quota.into());
            }
        }
        inspect(&chunk);
        file.write_all(&chunk)
            .await
            .map_err(|e| ApiError::internal("writing the upload", e))?;
    }
    file.flush()
        .await
        .map_err(|e| ApiError::internal("writing the upload", e))?;
    Ok(total)
}

/// The answer to a request body that broke off: 408 when it was too slow
/// ([`crate::http::slow_body`]), else 400 `upload_interrupted`.
pub fn body_error(e: &(dyn std::error::Error + 'static)) -> ApiError {
    if crate::http::slow_body::is_too_slow(e) {
        ApiError::new(
            StatusCode::REQUEST_TIMEOUT,
            "request_timeout",
            e.to_string(),
        )
    } else {
        ApiError::bad_request(
            "upload_interrupted",
            format!("reading the upload failed: {e}"),
        )
    }
}

/// Bytes of a refused request's body read (and dropped) before answering.
const DRAIN_BEFORE_REJECT: u64 = 8 << 20;

/// Reads and drops up to [`DRAIN_BEFORE_REJECT`] more bytes of a body the service refuses, so a
/// client still sending it reads the answer instead of a reset connection. Past the bound, or
/// when the body breaks off, the connection just closes.
async fn drain_stream(
    stream: &mut (impl futures_util::Stream<Item = Result<axum::body::Bytes, axum::Error>> + Unpin),
) {
    let mut drained = 0u64;
    while drained <= DRAIN_BEFORE_REJECT {
        match stream.next().await {
            Some(Ok(chunk)) => drained += chunk.len() as u64,
            _ => return,
        }
    }
}

/// `error`, answered after draining what [`drain_stream`] allows of the unread `body`.
pub async fn refuse_unread(body: Body, error: ApiError) -> ApiError {
    drain_stream(&mut body.into_data_stream()).await;
    error
}

/// The request's declared `Content-Length`, when it has a valid one.
pub(crate) fn content_length(headers: &HeaderMap) -> Option<u64> {
    headers
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok())
}

/// Rejects early when the declared length is already over the limit.
pub fn check_content_length(headers: &HeaderMap, limit: u64) -> Result<(), ApiError> {
    match content_length(headers) {
        Some(len) if len > limit => Err(too_large(limit)),
        _ => Ok(()),
    }
}

//! The one error type of the HTTP layer: every failure becomes a JSON body
//! `{"error": {"code", "message"}}` with a fitting status, so clients never parse HTML or plain text.
//! The errors of the layers below (refusals, store, object store, artifact and purge errors)
//! become an [`ApiError`] here, and only here.
//! The handlers answer [`ApiError`]s; [`json_errors`] turns what axum answers by itself (a path
//! that does not decode, a body over its limit, a wrong content type) into the same shape, and
//! [`oversized_requests`] answers request lines and headers over the service's limits (414, 431).

use axum::extract::Request;
use axum::http::{header, HeaderValue, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use utoipa::ToSchema;

use crate::accounts::quotas::QuotaError;
use crate::domain::refusal::{Refusal, RefusalKind};

/// An error answered to a client: HTTP status, stable machine-readable code, human message, and
/// for a rejected capture each problem found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ApiError {
    pub status: StatusCode,
    pub code: &'static str,
    pub message: String,
    pub problems: Vec<ProblemBody>,
}

/// One problem of a rejected capture: where (frame and key) and what.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, ToSchema)]
pub struct ProblemBody {
    /// `top level`, or the frame's index and main file, e.g. `frame 3 (raw/003.png)`.
    pub frame: String,
    /// The key in `transforms.json` (or `capture.json`, or the COLMAP record) at fault.
    pub key: String,
    /// What is wrong.
    pub message: String,
}

/// Every error the service answers: `{"error": {"code", "message"}}`.
#[derive(Serialize, ToSchema)]
#[schema(as = Error)]
pub struct ErrorBody<'a> {
    error: ErrorDetail<'a>,
}

/// What went wrong.
#[derive(Serialize, ToSchema)]
pub struct ErrorDetail<'a> {
    /// Stable machine-readable code, e.g. `not_found`, `invalid_config`.
    code: &'a str,
    /// For people; may change between versions.
    message: &'a str,
    /// Every problem of a rejected capture (`invalid_capture` only; absent otherwise).
    #[serde(skip_serializing_if = "<[ProblemBody]>::is_empty")]
    #[schema(required = false)]
    problems: &'a [ProblemBody],
}

impl ApiError {
    pub fn new(status: StatusCode, code: &'static str, message: impl Into<String>) -> Self {
        ApiError {
            status,
            code,
            message: message.into(),
            problems: Vec::new(),
        }
    }

    /// This error with the problems of a rejected capture.
    pub fn with_problems(self, problems: Vec<ProblemBody>) -> Self {
        ApiError { problems, ..self }
    }

    pub fn bad_request(code: &'static str, message: impl Into<String>) -> Self {
        Self::new(StatusCode::BAD_REQUEST, code, message)
    }

    pub fn not_found(what: &str, id: &str) -> Self {
        Self::new(
            StatusCode::NOT_FOUND,
            "not_found",
            format!("{what} `{id}` not found"),
        )
    }

    pub fn conflict(code: &'static str, message: impl Into<String>) -> Self {
        Self::new(StatusCode::CONFLICT, code, message)
    }

    pub fn unprocessable(code: &'static str, message: impl Into<String>) -> Self {
        Self::new(StatusCode::UNPROCESSABLE_ENTITY, code, message)
    }

    pub fn too_large(message: impl Into<String>) -> Self {
        Self::new(StatusCode::PAYLOAD_TOO_LARGE, "payload_too_large", message)
    }

    /// A server-side failure; the detail is logged, the client gets a generic message plus `what`.
    pub fn internal(what: &str, detail: impl std::fmt::Display) -> Self {
        tracing::error!(%detail, "{what}");
        Self::new(
            StatusCode::INTERNAL_SERVER_ERROR,
            "internal",
            format!("internal error while {what}"),
        )
    }
}

impl std::fmt::Display for ApiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} {}: {}",
            self.status.as_u16(),
            self.code,
            self.message
        )
    }
}

impl std::error::Error for ApiError {}

/// The JSON error body as bytes (also used by the panic handler and the auth layer).
pub fn error_body(code: &str, message: &str) -> String {
    detailed_error_body(code, message, &[])
}

fn detailed_error_body(code: &str, message: &str, problems: &[ProblemBody]) -> String {
    serde_json::to_string(&ErrorBody {
        error: ErrorDetail {
            code,
            message,
            problems,
        },
    })
    .unwrap_or_else(|_| r#"{"error":{"code":"internal","message":"unserializable error"}}"#.into())
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let body = detailed_error_body(self.code, &self.message, &self.problems);
        let mut response = (self.status, body).into_response();
        response.headers_mut().insert(
            header::CONTENT_TYPE,
            HeaderValue::from_static("application/json"),
        );
        if self.status == StatusCode::UNAUTHORIZED {
            response
                .headers_mut()
                .insert(header::WWW_AUTHENTICATE, HeaderValue::from_static("Bearer"));
        }
        response
    }
}

impl From<crate::storage::bucket::BucketError> for ApiError {
    fn from(e: crate::storage::bucket::BucketError) -> Self {
        match e {
            crate::storage::bucket::BucketError::Unavailable(detail) => {
                tracing::error!(%detail, "the object store is unavailable");
                ApiError::new(
                    StatusCode::SERVICE_UNAVAILABLE,
                    "storage_unavailable",
                    "the object store is unavailable; nothing was changed, try again shortly",
                )
            }
            other => ApiError::internal("accessing the object store", other),
        }
    }
}

impl From<crate::storage::store::StoreError> for ApiError {
    fn from(e: crate::storage::store::StoreError) -> Self {
        match e {
            crate::storage::store::StoreError::Unavailable(detail) => {
                tracing::error!(%detail, "the job store is unavailable");
                ApiError::new(
                    StatusCode::SERVICE_UNAVAILABLE,
                    "store_unavailable",
                    "the job database is unavailable; nothing was changed, try again shortly",
                )
            }
            other => ApiError::internal("accessing the job store", other),
        }
    }
}

impl From<crate::jobs::purge::PurgeError> for ApiError {
    fn from(e: crate::jobs::purge::PurgeError) -> Self {
        match e {
            crate::jobs::purge::PurgeError::Store(e) => e.into(),
            crate::jobs::purge::PurgeError::Artifacts(e) => e.into(),
            crate::jobs::purge::PurgeError::Bucket(e) => e.into(),
            other => ApiError::internal("deleting", other),
        }
    }
}

impl From<crate::storage::artifacts::ArtifactError> for ApiError {
    fn from(e: crate::storage::artifacts::ArtifactError) -> Self {
        match e {
            crate::storage::artifacts::ArtifactError::Bucket(e) => e.into(),
            other => ApiError::internal("accessing artifact storage", other),
        }
    }
}

impl From<Refusal> for ApiError {
    /// The status of each kind of refusal; the code and message are the refusal's.
    fn from(refusal: Refusal) -> Self {
        let status = match refusal.kind {
            RefusalKind::Invalid => StatusCode::BAD_REQUEST,
            RefusalKind::Forbidden => StatusCode::FORBIDDEN,
            RefusalKind::Conflict => StatusCode::CONFLICT,
            RefusalKind::Gone => StatusCode::GONE,
            RefusalKind::Unprocessable => StatusCode::UNPROCESSABLE_ENTITY,
            RefusalKind::TooMany => StatusCode::TOO_MANY_REQUESTS,
        };
        ApiError::new(status, refusal.code, refusal.message)
    }
}

impl From<QuotaError> for ApiError {
    fn from(e: QuotaError) -> Self {
        match e {
            QuotaError::Refused(refusal) => refusal.into(),
            QuotaError::Store(e) => e.into(),
        }
    }
}

/// The stable code of an error status that axum or hyper produced, not a handler.
pub fn status_code_name(status: StatusCode) -> &'static str {
    match status {
        StatusCode::BAD_REQUEST => "bad_request",
        StatusCode::UNAUTHORIZED => "unauthorized",
        StatusCode::FORBIDDEN => "forbidden",
        StatusCode::NOT_FOUND => "not_found",
        StatusCode::METHOD_NOT_ALLOWED => "method_not_allowed",
        StatusCode::REQUEST_TIMEOUT => "request_timeout",
        StatusCode::LENGTH_REQUIRED => "length_required",
        StatusCode::PAYLOAD_TOO_LARGE => "payload_too_large",
        StatusCode::URI_TOO_LONG => "uri_too_long",
        StatusCode::UNSUPPORTED_MEDIA_TYPE => "unsupported_media_type",
        StatusCode::UNPROCESSABLE_ENTITY => "unprocessable",
        StatusCode::REQUEST_HEADER_FIELDS_TOO_LARGE => "headers_too_large",
        StatusCode::SERVICE_UNAVAILABLE => "unavailable",
        s if s.is_client_error() => "bad_request",
        _ => "internal",
    }
}

/// Longest text of an axum rejection kept as the message.
const MAX_REJECTION_TEXT: usize = 1000;

/// Middleware: an error answer that is not JSON (axum's own rejections are plain text) is
/// rewritten as `{"error": {"code", "message"}}`, its text as the message. A 413 also says
/// `Connection: close`: the rest of its request's body was never read, so the connection cannot
/// carry another request, and a client that reused it would see it closed under its next one.
pub async fn json_errors(request: Request, next: Next) -> Response {
    let mut response = next.run(request).await;
    let status = response.status();
    if status == StatusCode::PAYLOAD_TOO_LARGE {
        response
            .headers_mut()
            .insert(header::CONNECTION, HeaderValue::from_static("close"));
    }
    let is_json = response
        .headers()
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.starts_with("application/json"));
    if !(status.is_client_error() || status.is_server_error()) || is_json {
        return response;
    }
    let (parts, body) = response.into_parts();
    let text = axum::body::to_bytes(body, MAX_REJECTION_TEXT * 4)
        .await
        .map(|bytes| String::from_utf8_lossy(&bytes).trim().to_owned())
        .unwrap_or_default();
    let message = match text.is_empty() {
        true => status.canonical_reason().unwrap_or("error").to_owned(),
        false => text.chars().take(MAX_REJECTION_TEXT).collect(),
    };
    let mut rewritten = ApiError::new(status, status_code_name(status), message).into_response();
    for (name, value) in &parts.headers {
        if name != header::CONTENT_TYPE && name != header::CONTENT_LENGTH {
            rewritten.headers_mut().insert(name, value.clone());
        }
    }
    rewritten
}

/// Middleware: a request target longer than `max_uri_bytes` is 414 `uri_too_long`, headers over
/// `max_header_bytes` or `max_headers` fields 431 `headers_too_large`, before any handler runs.
pub async fn oversized_requests(
    limits: crate::jobs::settings::HttpLimits,
    request: Request,
    next: Next,
) -> Response {
    let target = request
        .uri()
        .path_and_query()
        .map_or(0, |p| p.as_str().len());
    if target > limits.max_uri_bytes {
        return ApiError::new(
            StatusCode::URI_TOO_LONG,
            "uri_too_long",
            format!(
                "the request target has {target} bytes (at most {})",
                limits.max_uri_bytes
            ),
        )
        .into_response();
    }
    let headers = request.headers();
    let header_bytes: usize = headers
        .iter()
        .map(|(name, value)| name.as_str().len() + value.len())
        .sum();
    if headers.len() > limits.max_headers || header_bytes > limits.max_header_bytes {
        return ApiError::new(
            StatusCode::REQUEST_HEADER_FIELDS_TOO_LARGE,
            "headers_too_large",
            format!(
                "{} header fields of {header_bytes} bytes (at most {} fields and {} bytes)",
                headers.len(),
                limits.max_headers,
                limits.max_header_bytes
            ),
        )
        .into_response();
    }
    next.run(request).await
}

/// Answer for a path no route matches.
pub async fn not_found_fallback(uri: axum::http::Uri) -> ApiError {
    ApiError::new(
        StatusCode::NOT_FOUND,
        "not_found",
        format!("no route for `{}`", uri.path()),
    )
}

/// Answer for a known path with the wrong method.
pub async fn method_not_allowed_fallback(method: axum::http::Method) -> ApiError {
    ApiError::new(
        StatusCode::METHOD_NOT_ALLOWED,
        "method_not_allowed",
        format!("method {method} is not allowed on this route"),
    )
}

/// Last-resort answer when a handler panicked (the panic is logged, the server keeps serving).
pub fn panic_response(panic: Box<dyn std::any::Any + Send + 'static>) -> Response {
    let detail = panic
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| panic.downcast_ref::<&str>().copied())
        .unwrap_or("non-string panic payload");
    tracing::error!(detail, "handler panicked");
    ApiError::new(
        StatusCode::INTERNAL_SERVER_ERROR,
        "internal",
        "internal error (handler panicked)",
    )
    .into_response()
}

//! The one error type of the HTTP layer: every failure becomes a JSON body
//! `{"error": {"code", "message"}}` with a fitting status, so clients never parse HTML or plain text.

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use utoipa::ToSchema;

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

impl From<crate::bucket::BucketError> for ApiError {
    fn from(e: crate::bucket::BucketError) -> Self {
        match e {
            crate::bucket::BucketError::Unavailable(detail) => {
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

impl From<crate::store::StoreError> for ApiError {
    fn from(e: crate::store::StoreError) -> Self {
        match e {
            crate::store::StoreError::Unavailable(detail) => {
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

impl From<crate::purge::PurgeError> for ApiError {
    fn from(e: crate::purge::PurgeError) -> Self {
        match e {
            crate::purge::PurgeError::Store(e) => e.into(),
            crate::purge::PurgeError::Artifacts(e) => e.into(),
            crate::purge::PurgeError::Bucket(e) => e.into(),
            other => ApiError::internal("deleting", other),
        }
    }
}

impl From<crate::artifacts::ArtifactError> for ApiError {
    fn from(e: crate::artifacts::ArtifactError) -> Self {
        match e {
            crate::artifacts::ArtifactError::Bucket(e) => e.into(),
            other => ApiError::internal("accessing artifact storage", other),
        }
    }
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

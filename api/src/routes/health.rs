//! Liveness, Prometheus metrics and the OpenAPI document.

use axum::extract::State;
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::{Extension, Json};

use crate::auth::Caller;
use crate::error::ApiError;
use crate::AppState;

/// `GET /healthz`: 200 while the store answers.
pub async fn healthz(State(state): State<AppState>) -> Result<Json<serde_json::Value>, ApiError> {
    state.store.ping().await.map_err(|e| {
        tracing::error!(error = %e, "health check: store unavailable");
        ApiError::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "unavailable",
            "the job store is not answering",
        )
    })?;
    Ok(Json(serde_json::json!({ "status": "ok" })))
}

/// `GET /metrics`: Prometheus text format; with tokens, for the admin token only (the counts
/// span every account).
pub async fn metrics(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
) -> Result<Response, ApiError> {
    if caller != Caller::Admin {
        return Err(ApiError::new(
            StatusCode::FORBIDDEN,
            "forbidden",
            "the metrics need the admin token",
        ));
    }
    let counts = state.store.counts().await?;
    let body = state.metrics.render(counts, state.config.workers);
    Ok((
        [(
            header::CONTENT_TYPE,
            "text/plain; version=0.0.4; charset=utf-8",
        )],
        body,
    )
        .into_response())
}

/// `GET /v1/openapi.json`.
pub async fn openapi() -> Result<Json<serde_json::Value>, ApiError> {
    crate::openapi::spec_json()
        .map(Json)
        .map_err(|e| ApiError::internal("rendering the OpenAPI document", e))
}

//! Liveness, Prometheus metrics and the OpenAPI document.

use axum::extract::State;
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::{Extension, Json};

use serde::Serialize;
use utoipa::ToSchema;

use crate::accounts::auth::Caller;
use crate::http::error::{ApiError, ErrorBody};
use crate::jobs::state::AppState;

/// The answer of `GET /healthz`.
#[derive(Serialize, ToSchema)]
pub struct Health {
    status: HealthStatus,
}

/// Always `ok` (a service that is not answers 503 with an error body).
#[derive(Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum HealthStatus {
    Ok,
}

/// `GET /healthz`: 200 while the store answers.
#[utoipa::path(
    get,
    path = "/healthz",
    tag = "service",
    operation_id = "healthz",
    summary = "Liveness",
    description = "200 while the job store answers; no token needed.",
    responses(
        (status = OK, description = "Up", body = Health),
        (status = SERVICE_UNAVAILABLE, description = "The job store is not answering (unavailable)", body = ErrorBody),
    )
)]
pub async fn healthz(State(state): State<AppState>) -> Result<Json<Health>, ApiError> {
    state.store.ping().await.map_err(|e| {
        tracing::error!(error = %e, "health check: store unavailable");
        ApiError::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "unavailable",
            "the job store is not answering",
        )
    })?;
    Ok(Json(Health {
        status: HealthStatus::Ok,
    }))
}

/// `GET /metrics`: Prometheus text format; with tokens, for the admin token only (the counts
/// span every account).
#[utoipa::path(
    get,
    path = "/metrics",
    tag = "service",
    operation_id = "metrics",
    summary = "Prometheus metrics",
    description = "Prometheus text format. When the service has tokens, the admin token only: the counts span every account.",
    responses(
        (status = OK, description = "Prometheus text format 0.0.4", body = String, content_type = "text/plain"),
        (status = FORBIDDEN, description = "An account token (forbidden): the metrics span every account", body = ErrorBody),
    )
)]
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
    let counts = state.store.counts(None).await?;
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

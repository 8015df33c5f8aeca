//! The middleware that times every request for the metrics ([`crate::jobs::metrics`]), under its
//! route template.

use std::time::Instant;

use axum::extract::{MatchedPath, Request, State};
use axum::middleware::Next;
use axum::response::Response;

use crate::jobs::state::AppState;

/// Middleware timing every request under its route template (not its raw path, which would give
/// one series per job id).
pub async fn track_http(State(state): State<AppState>, request: Request, next: Next) -> Response {
    let start = Instant::now();
    let method = request.method().as_str().to_owned();
    let route = request
        .extensions()
        .get::<MatchedPath>()
        .map(|p| p.as_str().to_owned())
        .unwrap_or_else(|| "unmatched".to_owned());
    let response = next.run(request).await;
    state
        .metrics
        .observe_http(&method, &route, response.status().as_u16(), start.elapsed());
    response
}

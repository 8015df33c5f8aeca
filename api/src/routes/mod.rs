//! The HTTP surface. [`route_table`] is the single list of routes: the router is built from it,
//! the OpenAPI document ([`crate::openapi`]) takes from it which routes need the token, and a test
//! compares it with the document's operations, so the two cannot drift apart.

pub(crate) mod artifacts;
pub(crate) mod captures;
pub(crate) mod conditional;
pub(crate) mod health;
pub(crate) mod info;
pub(crate) mod jobs;
pub(crate) mod uploads;
pub(crate) mod viewer;

use axum::extract::DefaultBodyLimit;
use axum::http::Method;
use axum::routing::{delete, get, post, put, MethodRouter};
use axum::Router;
use tower_http::catch_panic::CatchPanicLayer;

use crate::error::{
    json_errors, method_not_allowed_fallback, not_found_fallback, oversized_requests,
    panic_response,
};
use crate::AppState;

/// A small JSON request body, read whole: 413 past the route's body limit, 408 when too slow,
/// 400 `invalid_json` when it does not parse, 422 `invalid_request` when it is not a `T` (an
/// unknown field included).
pub(crate) fn json_request<T: serde::de::DeserializeOwned>(
    body: Result<axum::body::Bytes, axum::extract::rejection::BytesRejection>,
) -> Result<T, crate::error::ApiError> {
    use crate::error::ApiError;
    let body = body.map_err(|e| match e.status() {
        axum::http::StatusCode::PAYLOAD_TOO_LARGE => ApiError::too_large(e.body_text()),
        _ if crate::slow_body::is_too_slow(&e) => captures::body_error(&e),
        status => ApiError::new(status, "invalid_body", e.body_text()),
    })?;
    let value: serde_json::Value = serde_json::from_slice(&body)
        .map_err(|e| ApiError::bad_request("invalid_json", format!("request body: {e}")))?;
    from_json_value(value).map_err(|message| ApiError::unprocessable("invalid_request", message))
}

/// `value` as a `T`; an error names the field it is about by its path (`config.iterations:
/// invalid value: integer `-5`, expected u32`), so a client knows which key to fix.
pub(crate) fn from_json_value<T: serde::de::DeserializeOwned>(
    value: serde_json::Value,
) -> Result<T, String> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        match path.as_str() {
            "" | "." => e.inner().to_string(),
            _ => format!("`{path}`: {}", e.inner()),
        }
    })
}

/// One route: method, path template (axum syntax), and whether the bearer token guards it.
pub struct RouteEntry {
    pub method: Method,
    pub path: &'static str,
    pub protected: bool,
    handler: MethodRouter<AppState>,
}

fn entry(
    method: Method,
    path: &'static str,
    protected: bool,
    handler: MethodRouter<AppState>,
) -> RouteEntry {
    RouteEntry {
        method,
        path,
        protected,
        handler,
    }
}

/// Every route of the service.
pub fn route_table(max_upload_bytes: u64) -> Vec<RouteEntry> {
    let upload_limit = usize::try_from(max_upload_bytes).unwrap_or(usize::MAX);
    vec![
        entry(Method::GET, "/healthz", false, get(health::healthz)),
        entry(Method::GET, "/metrics", true, get(health::metrics)),
        entry(Method::GET, "/v1/openapi.json", true, get(health::openapi)),
        entry(Method::GET, "/v1/info", true, get(info::info)),
        entry(
            Method::POST,
            "/v1/captures",
            true,
            post(captures::upload).layer(DefaultBodyLimit::disable()),
        ),
        entry(Method::GET, "/v1/captures/{id}", true, get(captures::show)),
        entry(
            Method::POST,
            "/v1/uploads",
            true,
            post(uploads::create).layer(DefaultBodyLimit::max(jobs::MAX_SUBMIT_BYTES)),
        ),
        entry(Method::GET, "/v1/uploads/{id}", true, get(uploads::show)),
        entry(
            Method::DELETE,
            "/v1/uploads/{id}",
            true,
            delete(uploads::remove),
        ),
        entry(
            Method::PUT,
            "/v1/uploads/{id}/parts/{index}",
            true,
            put(uploads::put_part).layer(DefaultBodyLimit::disable()),
        ),
        entry(
            Method::POST,
            "/v1/uploads/{id}/commit",
            true,
            post(uploads::commit),
        ),
        entry(
            Method::DELETE,
            "/v1/captures/{id}",
            true,
            delete(captures::remove),
        ),
        entry(
            Method::POST,
            "/v1/jobs",
            true,
            post(jobs::submit).layer(DefaultBodyLimit::max(jobs::MAX_SUBMIT_BYTES)),
        ),
        entry(Method::GET, "/v1/jobs", true, get(jobs::list)),
        entry(Method::GET, "/v1/jobs/{id}", true, get(jobs::show)),
        entry(Method::DELETE, "/v1/jobs/{id}", true, delete(jobs::remove)),
        entry(Method::GET, "/v1/jobs/{id}/events", true, get(jobs::events)),
        entry(
            Method::GET,
            "/v1/jobs/{id}/progress",
            true,
            get(jobs::progress),
        ),
        entry(
            Method::POST,
            "/v1/jobs/{id}/cancel",
            true,
            post(jobs::cancel),
        ),
        entry(
            Method::POST,
            "/v1/jobs/{id}/restart",
            true,
            post(jobs::restart).layer(DefaultBodyLimit::max(jobs::MAX_SUBMIT_BYTES)),
        ),
        entry(
            Method::POST,
            "/v1/jobs/{id}/relight",
            true,
            post(jobs::relight).layer(DefaultBodyLimit::max(upload_limit)),
        ),
        entry(
            Method::GET,
            "/v1/jobs/{id}/artifacts",
            true,
            get(artifacts::list),
        ),
        entry(
            Method::GET,
            "/v1/jobs/{id}/artifacts/{*name}",
            true,
            get(artifacts::download),
        ),
        entry(
            Method::GET,
            "/v1/jobs/{id}/material-mesh",
            true,
            get(viewer::material_mesh),
        ),
        entry(
            Method::GET,
            "/v1/jobs/{id}/ground-truth/{kind}/{view}",
            true,
            get(viewer::ground_truth),
        ),
    ]
}

/// The complete application: routes, auth on `/v1` and `/metrics`, JSON fallbacks and errors,
/// HTTP metrics, request-size and body-rate limits, security headers, panic guard, and the web
/// page at `/`. A worker process (`config.api` false) serves
/// only `/healthz` and `/metrics`.
pub fn router(state: AppState) -> Router {
    let mut open = Router::new();
    let mut protected = Router::new();
    let routes = route_table(state.config.max_upload_bytes);
    for route in routes
        .into_iter()
        .filter(|r| state.config.api || !r.path.starts_with("/v1/"))
    {
        if route.protected {
            protected = protected.route(route.path, route.handler);
        } else {
            open = open.route(route.path, route.handler);
        }
    }
    open = open.merge(protected.route_layer(axum::middleware::from_fn_with_state(
        state.clone(),
        crate::auth::require_token,
    )));
    if state.config.api {
        // The web page, for people (a worker process serves health and metrics only).
        open = open.merge(crate::web::router());
    }
    let limits = state.config.http;
    let app = open
        .fallback(not_found_fallback)
        .method_not_allowed_fallback(method_not_allowed_fallback)
        .layer(axum::middleware::from_fn(move |request, next| {
            crate::slow_body::enforce_min_rate(limits, request, next)
        }))
        .layer(axum::middleware::from_fn_with_state(
            state.clone(),
            crate::metrics::track_http,
        ))
        .layer(axum::middleware::from_fn(json_errors))
        .with_state(state);
    // Outermost: size checks before anything else reads the request; headers on every answer,
    // the panic guard's included.
    crate::security_headers::apply(app.layer(axum::middleware::from_fn(move |request, next| {
        oversized_requests(limits, request, next)
    })))
    .layer(CatchPanicLayer::custom(panic_response))
}

#[cfg(test)]
mod tests {
    use super::from_json_value;
    use phygap::core::config::TrainConfig;
    use serde_json::json;

    #[test]
    fn a_value_that_is_not_its_type_is_named_by_its_path() {
        let message =
            from_json_value::<TrainConfig>(json!({"checkpoint_interval": -5})).unwrap_err();
        assert!(
            message.starts_with("`checkpoint_interval`: invalid value: integer `-5`"),
            "{message}"
        );
        #[derive(Debug, serde::Deserialize)]
        #[allow(dead_code)]
        struct Request {
            config: TrainConfig,
        }
        let nested =
            from_json_value::<Request>(json!({"config": {"max_surfels": "many"}})).unwrap_err();
        assert!(nested.starts_with("`config.max_surfels`: "), "{nested}");
        let config = from_json_value::<TrainConfig>(json!({"checkpoint_interval": 50})).unwrap();
        assert_eq!(config.checkpoint_interval, 50);
    }
}

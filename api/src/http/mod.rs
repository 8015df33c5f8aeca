//! The top layer: HTTP. [`route_table`] is the single list of routes: the router is built from
//! it, the OpenAPI document ([`openapi`]) takes from it which routes need the token, and a test
//! compares it with the document's operations, so the two cannot drift apart.
//!
//! - [`routes`]: the handlers, one file per resource;
//! - [`error`]: [`error::ApiError`], the one error type that becomes an answer (status, JSON
//!   body); the errors of the layers below become one here and nowhere else;
//! - [`connections`] (the listener and its connection limits), [`slow_body`] (the minimum body
//!   rate), [`token_guard`] (the bearer token), [`request_metrics`], [`security_headers`] and
//!   [`conditional`] (validators of downloads): what wraps the handlers;
//! - [`bodies`] (request bodies streamed to files), [`intake`] (forms and what an uploaded input
//!   must be) and [`upload_sessions`] (parts, digests and commits of resumable uploads): what
//!   the handlers share;
//! - [`openapi`]: the OpenAPI document derived from the handlers; [`web_page`]: the embedded web
//!   page served at `/`.

pub mod bodies;
pub mod conditional;
pub mod connections;
pub mod error;
pub mod intake;
pub mod openapi;
pub mod request_metrics;
pub mod routes;
pub mod security_headers;
pub mod slow_body;
pub mod token_guard;
pub mod upload_sessions;
pub mod web_page;

use axum::extract::DefaultBodyLimit;
use axum::http::Method;
use axum::routing::{delete, get, post, put, MethodRouter};
use axum::Router;
use tower_http::catch_panic::CatchPanicLayer;

use crate::http::error::{
    json_errors, method_not_allowed_fallback, not_found_fallback, oversized_requests,
    panic_response,
};
use crate::http::routes::{artifacts, captures, health, info, jobs, uploads, viewer_data};
use crate::jobs::state::AppState;

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
        entry(Method::GET, "/v1/openapi.json", true, get(openapi::openapi)),
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
            get(viewer_data::material_mesh),
        ),
        entry(
            Method::GET,
            "/v1/jobs/{id}/ground-truth/{kind}/{view}",
            true,
            get(viewer_data::ground_truth),
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
        token_guard::require_token,
    )));
    if state.config.api {
        // The web page, for people (a worker process serves health and metrics only).
        open = open.merge(web_page::router());
    }
    let limits = state.config.http;
    let app = open
        .fallback(not_found_fallback)
        .method_not_allowed_fallback(method_not_allowed_fallback)
        .layer(axum::middleware::from_fn(move |request, next| {
            slow_body::enforce_min_rate(limits, request, next)
        }))
        .layer(axum::middleware::from_fn_with_state(
            state.clone(),
            request_metrics::track_http,
        ))
        .layer(axum::middleware::from_fn(json_errors))
        .with_state(state);
    // Outermost: size checks before anything else reads the request; headers on every answer,
    // the panic guard's included.
    security_headers::apply(app.layer(axum::middleware::from_fn(move |request, next| {
        oversized_requests(limits, request, next)
    })))
    .layer(CatchPanicLayer::custom(panic_response))
}

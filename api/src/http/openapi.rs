//! The OpenAPI 3.1 description of the service, derived from the code: each handler's
//! `#[utoipa::path]` (its responses and their bodies) and the `ToSchema` derives on the serde
//! types it answers with, so a schema cannot drift from what is sent. Which operations need the
//! bearer token comes from [`crate::http::route_table`], the table the router is built from.
//! Served at `/v1/openapi.json`; `phygap-api openapi --out api/openapi.yaml` writes the
//! committed copy (a test keeps the two equal).

use axum::http::Method;
use utoipa::openapi::path::Operation;
use utoipa::openapi::security::{HttpAuthScheme, HttpBuilder, SecurityRequirement, SecurityScheme};
use utoipa::openapi::{ContentBuilder, Ref, ResponseBuilder};
use utoipa::{Modify, OpenApi, ToSchema};

use axum::Json;

use crate::http::error::{ApiError, ErrorBody};
use crate::http::routes::{artifacts, captures, health, info, jobs, uploads, viewer_data};

/// The command that rewrites the committed document.
pub const REGENERATE: &str = "cargo run --release -p phygap-api -- openapi --out api/openapi.yaml";

/// The document.
#[derive(OpenApi)]
#[openapi(
    info(
        title = "phygap reconstruction service",
        description = "Upload a polarization capture (.zip or .tar holding transforms.json or a \
            COLMAP model, and its images or raw mosaic frames), train a relightable model of it as a queued job, follow its progress, \
            download its artifacts, and relight it under new environment maps. Every error is \
            `{\"error\": {\"code\", \"message\"}}`, those of the HTTP layer too: 404 \
            `not_found` for a path no route matches, 405 `method_not_allowed` for a wrong \
            method, and on every operation 414 `uri_too_long`, 431 `headers_too_large` and 500 \
            `internal`.\n\nWhen the server runs with tokens, every \
            /v1 route and /metrics need `Authorization: Bearer <token>`: the admin token \
            (--token) sees every capture and job, an account token (--tokens-file) only its own \
            account's (others' answer 404)."
    ),
    servers((url = "http://127.0.0.1:8080", description = "`phygap-api serve` on its default --bind")),
    paths(
        health::healthz,
        health::metrics,
        openapi,
        info::info,
        captures::upload,
        captures::show,
        captures::remove,
        uploads::create,
        uploads::show,
        uploads::put_part,
        uploads::commit,
        uploads::remove,
        jobs::submit,
        jobs::list,
        jobs::show,
        jobs::remove,
        jobs::events,
        jobs::progress,
        jobs::cancel,
        jobs::restart,
        jobs::relight,
        artifacts::list,
        artifacts::download,
        viewer_data::material_mesh,
        viewer_data::ground_truth,
    ),
    modifiers(&Access, &CommonErrors),
    tags(
        (name = "service", description = "Health, metrics and this document"),
        (name = "captures", description = "Capture archives: upload, look up, delete"),
        (name = "jobs", description = "Training and relight jobs: queue, follow, cancel, delete"),
        (name = "artifacts", description = "What a job produced"),
        (name = "viewer", description = "What the web viewer shows beside the artifacts"),
    )
)]
pub struct ApiDoc;

/// The name of the bearer-token security scheme.
const BEARER: &str = "bearer";

/// Adds the bearer scheme and, from the route table, each operation's security: the bearer
/// token (and its 401) where the router guards the route, none where it does not.
struct Access;

impl Modify for Access {
    fn modify(&self, openapi: &mut utoipa::openapi::OpenApi) {
        openapi
            .components
            .get_or_insert_with(Default::default)
            .add_security_scheme(
                BEARER,
                SecurityScheme::Http(HttpBuilder::new().scheme(HttpAuthScheme::Bearer).build()),
            );
        let unauthorized = ResponseBuilder::new()
            .description(
                "The service has tokens and the request has none or an unknown one \
                 (unauthorized)",
            )
            .content(
                "application/json",
                ContentBuilder::new()
                    .schema(Some(Ref::from_schema_name(ErrorBody::name())))
                    .build(),
            )
            .build();
        for route in crate::http::route_table(1) {
            let path = openapi_path(route.path);
            let Some(item) = openapi.paths.paths.get_mut(&path) else {
                continue;
            };
            let Some(operation) = operation_mut(item, &route.method) else {
                continue;
            };
            if route.protected {
                operation.security =
                    Some(vec![SecurityRequirement::new(BEARER, Vec::<String>::new())]);
                operation
                    .responses
                    .responses
                    .insert("401".into(), unauthorized.clone().into());
            } else {
                operation.security = Some(Vec::new());
            }
        }
    }
}

/// The errors any operation can answer from the HTTP layer, before or around its handler:
/// a request target or headers over the limits, a path parameter that does not decode, an
/// internal error; declared on every operation that does not declare them itself.
struct CommonErrors;

impl Modify for CommonErrors {
    fn modify(&self, openapi: &mut utoipa::openapi::OpenApi) {
        let error = |description: &str| {
            ResponseBuilder::new()
                .description(description)
                .content(
                    "application/json",
                    ContentBuilder::new()
                        .schema(Some(Ref::from_schema_name(ErrorBody::name())))
                        .build(),
                )
                .build()
        };
        let common = [
            (
                "414",
                error("A request target over the service's limit (uri_too_long)"),
            ),
            (
                "431",
                error("Headers over the service's limit in bytes or fields (headers_too_large)"),
            ),
            ("500", error("An internal error (internal)")),
        ];
        let bad_path = error("A path parameter that does not decode (bad_request)");
        for (path, item) in openapi.paths.paths.iter_mut() {
            for method in [Method::GET, Method::POST, Method::DELETE] {
                let Some(operation) = operation_mut(item, &method) else {
                    continue;
                };
                let responses = &mut operation.responses.responses;
                for (status, response) in &common {
                    responses
                        .entry((*status).to_owned())
                        .or_insert_with(|| response.clone().into());
                }
                if path.contains('{') {
                    responses
                        .entry("400".to_owned())
                        .or_insert_with(|| bad_path.clone().into());
                }
            }
        }
    }
}

fn operation_mut<'a>(
    item: &'a mut utoipa::openapi::PathItem,
    method: &Method,
) -> Option<&'a mut Operation> {
    match *method {
        Method::GET => item.get.as_mut(),
        Method::PUT => item.put.as_mut(),
        Method::POST => item.post.as_mut(),
        Method::DELETE => item.delete.as_mut(),
        Method::PATCH => item.patch.as_mut(),
        Method::HEAD => item.head.as_mut(),
        Method::OPTIONS => item.options.as_mut(),
        _ => None,
    }
}

/// The document as JSON (what `/v1/openapi.json` answers).
pub fn spec_json() -> Result<serde_json::Value, serde_json::Error> {
    serde_json::to_value(ApiDoc::openapi())
}

/// The document as YAML, as committed in `api/openapi.yaml`.
pub fn spec_yaml() -> Result<String, serde_yaml::Error> {
    let body = serde_yaml::to_string(&ApiDoc::openapi())?;
    Ok(format!(
        "# Generated from the code by `{REGENERATE}`; do not edit.\n{body}"
    ))
}

/// `(METHOD, path)` pairs the spec declares, path templates as written (`{id}`).
pub fn spec_operations(spec: &serde_json::Value) -> Vec<(String, String)> {
    const METHODS: [&str; 7] = ["get", "put", "post", "delete", "patch", "head", "options"];
    let mut operations = Vec::new();
    if let Some(paths) = spec.get("paths").and_then(|p| p.as_object()) {
        for (path, item) in paths {
            for method in METHODS {
                if item.get(method).is_some() {
                    operations.push((method.to_ascii_uppercase(), path.clone()));
                }
            }
        }
    }
    operations.sort();
    operations
}

/// An axum path template in OpenAPI form (`{*name}` → `{name}`).
pub fn openapi_path(axum_path: &str) -> String {
    axum_path.replace("{*", "{")
}

/// `GET /v1/openapi.json`: the document [`ApiDoc`] derives from the handlers.
#[utoipa::path(
    get,
    path = "/v1/openapi.json",
    tag = "service",
    operation_id = "openapi",
    summary = "This document, as JSON",
    responses(
        (status = OK, description = "The OpenAPI 3.1 document (api/openapi.yaml as JSON)", body = Object),
    )
)]
pub async fn openapi() -> Result<Json<serde_json::Value>, ApiError> {
    spec_json()
        .map(Json)
        .map_err(|e| ApiError::internal("rendering the OpenAPI document", e))
}

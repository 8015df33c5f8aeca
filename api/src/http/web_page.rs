//! The web page, served by the service itself: `web/dist` (built by `web/build.sh`, committed)
//! is embedded in the binary at compile time, so no separate server or Node.js is needed at run
//! time. `/` answers `index.html`; `/assets/…` the rest of `dist` (scripts, styles, the bundled
//! environment maps). The page only calls the public `/v1` API (its viewer's data included:
//! [`crate::http::routes::viewer_data`]).

use axum::extract::Path;
use axum::http::{header, HeaderValue};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;
use include_dir::{include_dir, Dir};

use crate::http::error::ApiError;
use crate::jobs::state::AppState;

/// `web/dist`, compiled in.
static DIST: Dir<'_> = include_dir!("$CARGO_MANIFEST_DIR/../web/dist");

/// Content type of a page file by extension.
fn content_type(name: &str) -> &'static str {
    match name.rsplit_once('.').map(|(_, e)| e) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") => "text/javascript; charset=utf-8",
        Some("css") => "text/css; charset=utf-8",
        Some("svg") => "image/svg+xml",
        Some("png") => "image/png",
        Some("hdr") => "image/vnd.radiance",
        Some("json") => "application/json",
        _ => "application/octet-stream",
    }
}

/// One embedded file, or the API's JSON 404.
fn asset(name: &str) -> Response {
    match DIST.get_file(name) {
        Some(file) => (
            [
                (
                    header::CONTENT_TYPE,
                    HeaderValue::from_static(content_type(name)),
                ),
                // The files change with the binary, not their names: revalidate every time.
                (header::CACHE_CONTROL, HeaderValue::from_static("no-cache")),
            ],
            file.contents(),
        )
            .into_response(),
        None => ApiError::not_found("page file", name).into_response(),
    }
}

async fn index() -> Response {
    asset("index.html")
}

async fn assets(Path(name): Path<String>) -> Response {
    asset(&format!("assets/{name}"))
}

/// The page's routes (open: the page itself holds no data; its API calls carry the token).
pub fn router() -> Router<AppState> {
    Router::new()
        .route("/", get(index))
        .route("/assets/{*name}", get(assets))
}

/// Every file of the embedded page, for tests.
pub fn files() -> Vec<&'static str> {
    fn walk(dir: &'static Dir<'static>, out: &mut Vec<&'static str>) {
        for file in dir.files() {
            if let Some(path) = file.path().to_str() {
                out.push(path);
            }
        }
        for sub in dir.dirs() {
            walk(sub, out);
        }
    }
    let mut out = Vec::new();
    walk(&DIST, &mut out);
    out.sort();
    out
}

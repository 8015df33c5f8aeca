//! The headers every answer carries, page and API alike (tower-http's `SetResponseHeader`, only
//! where a handler set none): a Content-Security-Policy that admits the web page's own scripts,
//! styles and the blob URLs it loads renders and models from, and nothing else (no inline
//! script, no other origin, no framing); `nosniff`; no `Referer` leaving the page; no caching of
//! API answers (downloads set their own validators).

use axum::http::{header, HeaderName, HeaderValue};
use axum::Router;
use tower_http::set_header::SetResponseHeaderLayer;

/// The page's policy: its scripts and styles from itself; images and fetches also from the blob
/// URLs it makes of downloaded renders and the glTF model; the favicon as a `data:` URL.
pub const CONTENT_SECURITY_POLICY: &str = "default-src 'self'; script-src 'self'; \
    style-src 'self'; img-src 'self' data: blob:; connect-src 'self' blob:; \
    object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'";

/// Every header set, with its value.
pub const HEADERS: [(HeaderName, &str); 6] = [
    (header::CONTENT_SECURITY_POLICY, CONTENT_SECURITY_POLICY),
    (header::X_CONTENT_TYPE_OPTIONS, "nosniff"),
    (header::X_FRAME_OPTIONS, "DENY"),
    (header::REFERRER_POLICY, "no-referrer"),
    (
        HeaderName::from_static("cross-origin-opener-policy"),
        "same-origin",
    ),
    (header::CACHE_CONTROL, "no-store"),
];

/// `router` with every answer carrying [`HEADERS`] (those a handler set are kept).
pub fn apply(router: Router) -> Router {
    HEADERS.into_iter().fold(router, |router, (name, value)| {
        router.layer(SetResponseHeaderLayer::if_not_present(
            name,
            HeaderValue::from_static(value),
        ))
    })
}

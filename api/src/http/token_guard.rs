//! Optional bearer-token authentication of the `/v1` routes and `/metrics`: the middleware that
//! resolves a request's `Authorization: Bearer` token to a [`Caller`] ([`accounts::auth`]) or
//! answers 401.
//!
//! [`accounts::auth`]: crate::accounts::auth

use axum::extract::{Request, State};
use axum::http::{header, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use crate::accounts::auth::{caller_of, Caller};
use crate::http::error::ApiError;
use crate::jobs::state::AppState;

/// The token of an `Authorization` value using the Bearer scheme, whose name is
/// case-insensitive (RFC 9110 §11.1).
fn bearer_token(value: &str) -> Option<&str> {
    let (scheme, token) = value.trim().split_once([' ', '\t'])?;
    scheme
        .eq_ignore_ascii_case("bearer")
        .then(|| token.trim())
        .filter(|t| !t.is_empty())
}

/// Resolves the request's bearer token to a [`Caller`] (stored as a request extension); 401 when
/// the service has tokens and the request carries none of them.
pub async fn require_token(
    State(state): State<AppState>,
    mut request: Request,
    next: Next,
) -> Response {
    let (admin, accounts) = (state.config.token.as_deref(), &state.config.account_tokens);
    if admin.is_none() && accounts.is_empty() {
        request.extensions_mut().insert(Caller::Admin);
        return next.run(request).await;
    }
    let given = request
        .headers()
        .get(header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(bearer_token);
    match given.map(|token| caller_of(token, admin, accounts)) {
        Some(Some(caller)) => {
            request.extensions_mut().insert(caller);
            next.run(request).await
        }
        Some(None) => ApiError::new(
            StatusCode::UNAUTHORIZED,
            "unauthorized",
            "invalid bearer token",
        )
        .into_response(),
        None => ApiError::new(
            StatusCode::UNAUTHORIZED,
            "unauthorized",
            "missing `Authorization: Bearer <token>` header",
        )
        .into_response(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bearer_scheme_is_case_insensitive() {
        for value in ["Bearer t0k", "bearer t0k", "BEARER  t0k ", "Bearer\tt0k"] {
            assert_eq!(bearer_token(value), Some("t0k"), "{value:?}");
        }
        for value in ["Basic dXNlcjpwYXNz", "Bearer", "Bearer   ", "Bearert0k"] {
            assert_eq!(bearer_token(value), None, "{value:?}");
        }
    }
}

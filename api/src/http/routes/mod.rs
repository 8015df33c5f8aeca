//! The route handlers, one file per resource: [`health`] (health, metrics), [`info`],
//! [`captures`], [`uploads`] (the routes of resumable uploads), [`jobs`], [`artifacts`] and
//! [`viewer_data`] (what the web viewer shows beside the artifacts). The table they are routed
//! by is [`crate::http::route_table`].

pub(crate) mod artifacts;
pub(crate) mod captures;
pub(crate) mod health;
pub(crate) mod info;
pub(crate) mod jobs;
pub(crate) mod uploads;
pub(crate) mod viewer_data;

use utoipa::ToSchema;

use crate::http::bodies;
use crate::http::error::ApiError;

/// Raw bytes (a file), as a request or response body.
#[derive(ToSchema)]
#[allow(dead_code)] // Only its schema is used.
#[schema(value_type = String, format = Binary)]
pub struct Binary(Vec<u8>);

/// A small JSON request body, read whole: 413 past the route's body limit, 408 when too slow,
/// 400 `invalid_json` when it does not parse, 422 `invalid_request` when it is not a `T` (an
/// unknown field included).
pub(crate) fn json_request<T: serde::de::DeserializeOwned>(
    body: Result<axum::body::Bytes, axum::extract::rejection::BytesRejection>,
) -> Result<T, ApiError> {
    let body = body.map_err(|e| match e.status() {
        axum::http::StatusCode::PAYLOAD_TOO_LARGE => ApiError::too_large(e.body_text()),
        _ if crate::http::slow_body::is_too_slow(&e) => bodies::body_error(&e),
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

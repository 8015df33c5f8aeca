//! Taking inputs in, shared by the routes that accept uploads: reading a relight form into a
//! staging folder, checking what an uploaded input must be before anything is filed or queued for
//! it (from headers and JSON alone in the API process; the decoding happens in a job's own
//! process), and publishing a filed folder to the bucket then recording it, rolled back whole when
//! either fails.

use std::path::Path;

use axum::extract::multipart::{Field, MultipartError};
use axum::extract::Multipart;
use axum::http::StatusCode;
use tokio::io::AsyncWriteExt;

use crate::http::error::ApiError;
use crate::jobs::state::AppState;
use crate::storage::store::StoreError;

/// Checks what a relight job will read before it is queued, from headers and JSON alone: the
/// map's size against the service's limit, the cameras as cameras (count and pixels within the
/// capture limits). Nothing is decoded here; the job's process renders.
pub fn check_relight_inputs(
    envmap: &std::path::Path,
    cameras: Option<&std::path::Path>,
    limits: &crate::jobs::settings::ServiceLimits,
) -> Result<(), ApiError> {
    let header = phygap::formats::image_io::read_header(envmap).map_err(|e| {
        ApiError::unprocessable(
            "invalid_envmap",
            format!(
                "the environment map cannot be read: {}",
                without_folder(&e.to_string(), envmap)
            ),
        )
    })?;
    let pixels = header.width as u64 * header.height as u64;
    if pixels > limits.max_envmap_pixels {
        return Err(ApiError::unprocessable(
            "envmap_too_large",
            format!(
                "the environment map declares {}×{} pixels, over the limit of {} megapixels \
                 (--max-envmap-megapixels)",
                header.width,
                header.height,
                limits.max_envmap_pixels / 1_000_000
            ),
        ));
    }
    if let Some(cameras) = cameras {
        use phygap::io::capture::CaptureError;
        phygap::io::capture::load_cameras_within(cameras, &limits.capture).map_err(|e| {
            let message = without_folder(&e.to_string(), cameras);
            match e {
                CaptureError::TooLarge { .. } => {
                    ApiError::unprocessable("cameras_too_large", message)
                }
                _ => ApiError::unprocessable("invalid_cameras", message),
            }
        })?;
    }
    Ok(())
}

/// `message` naming `file` by its name alone (the service's folders are not the client's).
fn without_folder(message: &str, file: &std::path::Path) -> String {
    match file.parent() {
        Some(folder) => message.replace(&format!("{}/", folder.display()), ""),
        None => message.to_owned(),
    }
}

/// A relight form's fields, its files saved in the staging folder.
pub struct RelightInputs {
    /// `envmap.exr` or `envmap.hdr`, as its magic bytes say.
    pub envmap_file: String,
    /// `cameras.json`, when the form has cameras.
    pub cameras_file: Option<String>,
    pub rotate_deg: f64,
    pub webhook: Option<String>,
}

/// Reads a relight form (`envmap`, optional `cameras`, `rotate_deg`, `webhook`) field by field,
/// saving its files into `staging`; refuses unknown fields, a map that is neither OpenEXR nor
/// Radiance HDR, cameras that are not JSON, a rotation that is not a finite number.
pub async fn read_relight_form(
    mut multipart: Multipart,
    staging: &Path,
) -> Result<RelightInputs, ApiError> {
    let mut envmap_file = None;
    let mut cameras_file = None;
    let mut rotate_deg = 0.0f64;
    let mut webhook = None;
    while let Some(field) = multipart.next_field().await.map_err(multipart_error)? {
        match field.name().unwrap_or("") {
            "webhook" => webhook = Some(read_text_field(field, "webhook").await?),
            "envmap" => {
                let upload = staging.join("envmap.upload");
                let head = save_field(field, &upload).await?;
                let ext = envmap_extension(&head).ok_or_else(|| {
                    ApiError::new(
                        StatusCode::UNSUPPORTED_MEDIA_TYPE,
                        "unsupported_envmap",
                        "the environment map must be an OpenEXR (.exr) or Radiance (.hdr) file",
                    )
                })?;
                let name = format!("envmap.{ext}");
                std::fs::rename(&upload, staging.join(&name))
                    .map_err(|e| ApiError::internal("saving the environment map", e))?;
                envmap_file = Some(name);
            }
            "cameras" => {
                let path = staging.join("cameras.json");
                save_field_within(field, &path, MAX_CAMERAS_BYTES, "cameras").await?;
                let text = tokio::fs::read(&path)
                    .await
                    .map_err(|e| ApiError::internal("reading the cameras", e))?;
                serde_json::from_slice::<serde_json::Value>(&text).map_err(|e| {
                    ApiError::unprocessable("invalid_cameras", format!("cameras: {e}"))
                })?;
                cameras_file = Some("cameras.json".to_owned());
            }
            "rotate_deg" => {
                let text = read_text_field(field, "rotate_deg").await?;
                rotate_deg = text
                    .trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| {
                        ApiError::unprocessable(
                            "invalid_rotate_deg",
                            format!(
                                "rotate_deg must be a finite number, got {:?}",
                                crate::domain::text::quoted_prefix(&text, QUOTED_CHARS)
                            ),
                        )
                    })?;
            }
            other => {
                return Err(ApiError::bad_request(
                    "unknown_field",
                    format!(
                        "unknown form field `{other}` (expected envmap, cameras, rotate_deg, \
                         webhook)"
                    ),
                ))
            }
        }
    }
    let envmap_file = envmap_file.ok_or_else(|| {
        ApiError::unprocessable("missing_envmap", "the form has no `envmap` file field")
    })?;
    Ok(RelightInputs {
        envmap_file,
        cameras_file,
        rotate_deg,
        webhook,
    })
}

pub(crate) fn multipart_error(e: MultipartError) -> ApiError {
    if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
        ApiError::too_large(e.body_text())
    } else if crate::http::slow_body::is_too_slow(&e) {
        crate::http::bodies::body_error(&e)
    } else {
        ApiError::bad_request("invalid_multipart", e.body_text())
    }
}

/// Most bytes of a form's text field (`rotate_deg`, `webhook`): a number or a URL.
pub const MAX_TEXT_FIELD_BYTES: usize = 4 << 10;

/// Most bytes of a relight form's `cameras` (JSON, read whole to be checked).
pub const MAX_CAMERAS_BYTES: u64 = 16 << 20;

/// Characters of an input quoted back in an error message.
const QUOTED_CHARS: usize = 64;

/// Reads a text field of a form, refusing it (413) as soon as it passes
/// [`MAX_TEXT_FIELD_BYTES`], before the rest is read.
async fn read_text_field(mut field: Field<'_>, name: &str) -> Result<String, ApiError> {
    let mut bytes = Vec::new();
    while let Some(chunk) = field.chunk().await.map_err(multipart_error)? {
        if bytes.len() + chunk.len() > MAX_TEXT_FIELD_BYTES {
            return Err(ApiError::too_large(format!(
                "the form field `{name}` is over {MAX_TEXT_FIELD_BYTES} bytes"
            )));
        }
        bytes.extend_from_slice(&chunk);
    }
    String::from_utf8(bytes).map_err(|_| {
        ApiError::bad_request(
            "invalid_multipart",
            format!("the form field `{name}` is not UTF-8 text"),
        )
    })
}

/// Streams one multipart field into `target`; returns its first bytes (for format sniffing).
async fn save_field(field: Field<'_>, target: &std::path::Path) -> Result<Vec<u8>, ApiError> {
    save_field_within(field, target, u64::MAX, "").await
}

/// [`save_field`], refusing (413) a field `name` once it passes `max_bytes`.
async fn save_field_within(
    mut field: Field<'_>,
    target: &std::path::Path,
    max_bytes: u64,
    name: &str,
) -> Result<Vec<u8>, ApiError> {
    let mut file = tokio::fs::File::create(target)
        .await
        .map_err(|e| ApiError::internal("saving an upload", e))?;
    let mut head = Vec::new();
    let mut written = 0u64;
    while let Some(chunk) = field.chunk().await.map_err(multipart_error)? {
        written += chunk.len() as u64;
        if written > max_bytes {
            return Err(ApiError::too_large(format!(
                "the form field `{name}` is over {max_bytes} bytes"
            )));
        }
        if head.len() < 16 {
            head.extend_from_slice(&chunk[..chunk.len().min(16 - head.len())]);
        }
        file.write_all(&chunk)
            .await
            .map_err(|e| ApiError::internal("saving an upload", e))?;
    }
    file.flush()
        .await
        .map_err(|e| ApiError::internal("saving an upload", e))?;
    Ok(head)
}

/// The environment-map format from its magic bytes.
fn envmap_extension(head: &[u8]) -> Option<&'static str> {
    if head.starts_with(&[0x76, 0x2f, 0x31, 0x01]) {
        Some("exr")
    } else if head.starts_with(b"#?RADIANCE") || head.starts_with(b"#?RGBE") {
        Some("hdr")
    } else {
        None
    }
}

/// A folder filed under the data dir, to publish to the bucket under `key`; `remove` is what a
/// failure removes locally (the folder, or the record's whole folder).
pub struct Filed<'a> {
    pub dir: &'a Path,
    pub key: String,
    pub remove: std::path::PathBuf,
}

/// Uploads `filed` to the deployment's bucket (when it has one), then records it (`record`, the
/// store write); when either fails, removes the local folder and the objects, so a failed intake
/// leaves nothing behind.
pub async fn publish_then_record<T, F, Fut>(
    state: &AppState,
    filed: Filed<'_>,
    record: F,
) -> Result<T, ApiError>
where
    F: FnOnce() -> Fut,
    Fut: std::future::Future<Output = Result<T, StoreError>>,
{
    let roll_back = || async {
        let _ = tokio::fs::remove_dir_all(&filed.remove).await;
        if let Some(bucket) = &state.bucket {
            let _ = bucket.delete_folder(&filed.key).await;
        }
    };
    if let Some(bucket) = &state.bucket {
        if let Err(e) = bucket.upload_dir(&filed.key, filed.dir).await {
            roll_back().await;
            return Err(e.into());
        }
    }
    match record().await {
        Ok(recorded) => Ok(recorded),
        Err(e) => {
            roll_back().await;
            Err(e.into())
        }
    }
}

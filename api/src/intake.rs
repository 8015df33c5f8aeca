//! What an uploaded input must be before anything is filed or queued for it, checked from
//! headers and JSON alone in the API process (the decoding happens in a job's own process): a
//! relight's environment map and cameras.

use crate::error::ApiError;

/// Checks what a relight job will read before it is queued, from headers and JSON alone: the
/// map's size against the service's limit, the cameras as cameras (count and pixels within the
/// capture limits). Nothing is decoded here; the job's process renders.
pub fn check_relight_inputs(
    envmap: &std::path::Path,
    cameras: Option<&std::path::Path>,
    limits: &crate::ServiceLimits,
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

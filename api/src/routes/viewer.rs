//! What a viewer needs beyond the artifacts as stored: the extracted mesh with the learned
//! materials on its vertices ([`crate::material_mesh`]), and the captured images of the test
//! views in the same 8-bit form as the job's renders (`renders/{kind}/NNN.png`), so the two can be
//! shown side by side.

use std::path::Path as FsPath;

use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::Response;
use axum::Extension;
use phygap::formats::image_io::Image;
use phygap::io::capture::{Measurement, View};
use serde::Deserialize;
use tokio::io::AsyncReadExt;
use utoipa::IntoParams;

use crate::auth::Caller;
use crate::error::{ApiError, ErrorBody};
use crate::material_mesh::{material_mesh_ply, MaterialMeshError};
use crate::openapi::Binary;
use crate::queue::new_id;
use crate::routes::jobs::JobPath;
use crate::store::{JobRecord, JobSpec, JobState};
use crate::AppState;

/// A succeeded training job the caller may see, or the error that says why it has no model to
/// view.
async fn trained_job(state: &AppState, caller: &Caller, id: &str) -> Result<JobRecord, ApiError> {
    let job = crate::routes::jobs::load_job(state, caller, id).await?;
    if !matches!(job.spec, JobSpec::Train { .. }) || job.state != JobState::Succeeded {
        return Err(ApiError::conflict(
            "model_not_ready",
            format!(
                "job `{id}` is not a succeeded training job (it is a {} job, {})",
                job.spec.kind(),
                job.state.as_str()
            ),
        ));
    }
    Ok(job)
}

/// The whole of one artifact.
async fn artifact_bytes(state: &AppState, id: &str, name: &str) -> Result<Vec<u8>, ApiError> {
    let info = state
        .artifacts
        .stat(id, name)
        .await?
        .ok_or_else(|| ApiError::not_found("artifact", name))?;
    let mut reader = state.artifacts.open_range(id, name, 0, info.size).await?;
    let mut bytes = Vec::with_capacity(info.size as usize);
    reader
        .read_to_end(&mut bytes)
        .await
        .map_err(|e| ApiError::internal("reading an artifact", e))?;
    Ok(bytes)
}

fn file_response(bytes: Vec<u8>, content_type: &'static str) -> Response {
    let mut response = Response::new(Body::from(bytes));
    response
        .headers_mut()
        .insert(header::CONTENT_TYPE, HeaderValue::from_static(content_type));
    response
}

/// `GET /v1/jobs/{id}/material-mesh`: `mesh.ply` with each vertex's albedo (sRGB colour),
/// roughness and IoR taken from the surfels around it.
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}/material-mesh",
    tag = "viewer",
    operation_id = "material_mesh",
    summary = "The extracted mesh with the learned materials on its vertices",
    description = "mesh.ply with, per vertex, the opacity- and distance-weighted mean of the \
        albedo, roughness and IoR of its 8 nearest opaque surfels: a binary little-endian PLY \
        with vertex x y z (nx ny nz), red green blue (albedo, sRGB 8-bit), roughness \
        (perceptual, as three.js and glTF) and ior (float32), and the mesh's faces.",
    params(JobPath),
    responses(
        (status = OK, description = "The mesh", body = Binary, content_type = "application/x-ply"),
        (status = NOT_FOUND, description = "No such job the token may see (not_found)", body = ErrorBody),
        (status = CONFLICT, description = "The job is not a succeeded training job \
            (model_not_ready)", body = ErrorBody),
        (status = UNPROCESSABLE_ENTITY, description = "Its mesh or surfels cannot be read \
            (invalid_model)", body = ErrorBody),
    )
)]
pub async fn material_mesh(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(JobPath { id }): Path<JobPath>,
) -> Result<Response, ApiError> {
    trained_job(&state, &caller, &id).await?;
    let mesh = artifact_bytes(&state, &id, "mesh.ply").await?;
    let surfels = artifact_bytes(&state, &id, "surfels.ply").await?;
    let ply = tokio::task::spawn_blocking(move || material_mesh_ply(&mesh, &surfels))
        .await
        .map_err(|e| ApiError::internal("building the material mesh", e))?
        .map_err(|e| match e {
            MaterialMeshError::Write(_) => ApiError::internal("writing the material mesh", e),
            other => ApiError::unprocessable("invalid_model", other.to_string()),
        })?;
    Ok(file_response(ply, "application/x-ply"))
}

/// The kinds of captured image [`ground_truth`] answers.
const GROUND_TRUTH_KINDS: [&str; 3] = ["s0", "dolp", "aolp"];

/// A captured test view.
#[derive(Deserialize, IntoParams)]
#[into_params(parameter_in = Path)]
pub struct GroundTruthPath {
    /// A succeeded training job's id (`job_…`).
    id: String,
    /// Which image: S0, DoLP or AoLP.
    #[param(value_type = GroundTruthKind, inline)]
    kind: String,
    /// The test view as NNN.png, the same name as the job's renders/{kind}/NNN.png.
    view: String,
}

/// The schema of [`GroundTruthPath::kind`]: one of [`GROUND_TRUTH_KINDS`].
struct GroundTruthKind;

impl utoipa::PartialSchema for GroundTruthKind {
    fn schema() -> utoipa::openapi::RefOr<utoipa::openapi::Schema> {
        utoipa::openapi::ObjectBuilder::new()
            .schema_type(utoipa::openapi::Type::String)
            .enum_values(Some(GROUND_TRUTH_KINDS))
            .into()
    }
}

impl utoipa::ToSchema for GroundTruthKind {}

/// The 8-bit preview of one captured view, as `renders/{kind}` shows the model's: S0 with the
/// mask applied (sRGB), DoLP in [0, 1], AoLP mapped from [0, π) to [0, 1], both masked.
fn captured_preview(view: &View, kind: &str) -> Result<(Image, bool), String> {
    let mask = &view.mask;
    let masked = |image: &Image| Image {
        data: image
            .data
            .iter()
            .enumerate()
            .map(|(i, &v)| v * mask.data.get(i / image.channels).copied().unwrap_or(1.0))
            .collect(),
        ..image.clone()
    };
    let summed = |image: &Image, p: usize| -> f64 {
        image.data[p * image.channels..(p + 1) * image.channels]
            .iter()
            .map(|&v| f64::from(v))
            .sum()
    };
    match (&view.measurement, kind) {
        (Measurement::Stokes { s0, .. }, "s0") => Ok((masked(s0), true)),
        (Measurement::Rgb { image } | Measurement::Polarizer { image, .. }, "s0") => {
            Ok((masked(image), true))
        }
        (Measurement::Stokes { s0, s1, s2 }, "dolp" | "aolp") => {
            let values: Vec<f32> = (0..s0.num_pixels())
                .map(|p| {
                    let (a, b, c) = (summed(s0, p), summed(s1, p), summed(s2, p));
                    let value = if kind == "dolp" {
                        phygap::core::shading::dolp(a, b, c)
                    } else {
                        phygap::core::shading::aolp(b, c).rem_euclid(std::f64::consts::PI)
                            / std::f64::consts::PI
                    };
                    value as f32
                })
                .collect();
            let grey = Image {
                width: s0.width,
                height: s0.height,
                channels: 1,
                data: values,
            };
            Ok((masked(&grey), false))
        }
        _ => Err(format!(
            "{} has no full Stokes measurement, so no {kind}",
            view.name
        )),
    }
}

/// `GET /v1/jobs/{id}/ground-truth/{kind}/{view}`: the captured image of test view `NNN.png`
/// (the one `renders/{kind}/NNN.png` renders), `kind` one of s0, dolp, aolp.
#[utoipa::path(
    get,
    path = "/v1/jobs/{id}/ground-truth/{kind}/{view}",
    tag = "viewer",
    operation_id = "ground_truth",
    summary = "A captured test view as the renders show it (8-bit PNG)",
    description = "The capture's image of the test view the render renders, in the same 8-bit \
        form so the two compare side by side: S0 with the mask applied (sRGB), DoLP in [0, 1], \
        AoLP from [0, π) mapped to [0, 1]. DoLP and AoLP need a full Stokes view.",
    params(GroundTruthPath),
    responses(
        (status = OK, description = "The image", body = Binary, content_type = "image/png"),
        (status = NOT_FOUND, description = "No such job the token may see, an unknown kind or \
            view, a deleted capture, or a view without full Stokes for dolp or aolp (not_found)",
            body = ErrorBody),
        (status = CONFLICT, description = "The job is not a succeeded training job \
            (model_not_ready)", body = ErrorBody),
    )
)]
pub async fn ground_truth(
    State(state): State<AppState>,
    Extension(caller): Extension<Caller>,
    Path(GroundTruthPath { id, kind, view }): Path<GroundTruthPath>,
) -> Result<Response, ApiError> {
    let job = trained_job(&state, &caller, &id).await?;
    if !GROUND_TRUTH_KINDS.contains(&kind.as_str()) {
        return Err(ApiError::not_found("ground-truth kind", &kind));
    }
    let index: usize = view
        .strip_suffix(".png")
        .and_then(|n| n.parse().ok())
        .ok_or_else(|| ApiError::not_found("test view", &view))?;
    let capture_dir = state.paths.capture_dir(&job.capture_id);
    if let (Some(bucket), false) = (&state.bucket, capture_dir.is_dir()) {
        // Another API replica took the upload: the bucket has the capture.
        let folder = format!("captures/{}", job.capture_id);
        bucket.download_dir(&folder, &capture_dir).await?;
    }
    let tmp = state.paths.tmp.join(format!("{}.png", new_id("gt")));
    let png = tokio::task::spawn_blocking(move || -> Result<Vec<u8>, ApiError> {
        if !capture_dir.is_dir() {
            return Err(ApiError::not_found("capture", &job.capture_id));
        }
        let capture = phygap::io::capture::load(&capture_dir)
            .map_err(|e| ApiError::internal("loading the capture", e))?;
        let view = capture
            .test_views()
            .nth(index)
            .ok_or_else(|| ApiError::not_found("test view", &index.to_string()))?;
        let (image, srgb) = captured_preview(view, &kind)
            .map_err(|m| ApiError::new(StatusCode::NOT_FOUND, "not_found", m))?;
        encode_png(&tmp, &image, srgb)
    })
    .await
    .map_err(|e| ApiError::internal("rendering the captured view", e))??;
    Ok(file_response(png, "image/png"))
}

/// The PNG bytes of an image (written through a temporary file, which is removed).
fn encode_png(tmp: &FsPath, image: &Image, srgb: bool) -> Result<Vec<u8>, ApiError> {
    let written = phygap::formats::image_io::write_png(tmp, image, srgb)
        .map_err(|e| ApiError::internal("encoding a PNG", e))
        .and_then(|()| std::fs::read(tmp).map_err(|e| ApiError::internal("encoding a PNG", e)));
    let _ = std::fs::remove_file(tmp);
    written
}

//! The viewer's data routes: what the web page's viewer needs beyond the artifacts as stored, the
//! extracted mesh with the learned materials on its vertices ([`material_mesh`]), and the
//! captured images of the test views in the same 8-bit form as the job's renders
//! (`renders/{kind}/NNN.png`), so the two can be shown side by side (the training job's process
//! writes them as `captured/{kind}/NNN.png`). The page itself is [`crate::http::web_page`].

use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::Response;
use axum::Extension;
use phygap::pipeline::previews::{CAPTURED_DIR, CAPTURED_KINDS};
use serde::Deserialize;
use tokio::io::AsyncReadExt;
use utoipa::IntoParams;

use super::Binary;
use crate::accounts::auth::Caller;
use crate::http::error::{ApiError, ErrorBody};
use crate::http::routes::jobs::JobPath;
use crate::jobs::state::AppState;
use crate::storage::store::{JobRecord, JobSpec, JobState};
use phygap::pipeline::export::material_mesh::{material_mesh_ply, MaterialMeshError};

/// A succeeded training job the caller may see, or the error that says why it has no model to
/// view.
async fn trained_job(state: &AppState, caller: &Caller, id: &str) -> Result<JobRecord, ApiError> {
    let job = crate::http::routes::jobs::load_job(state, caller, id).await?;
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
    let size = state
        .artifacts
        .stat(id, name)
        .await?
        .ok_or_else(|| ApiError::not_found("artifact", name))?
        .info
        .size;
    let mut reader = state.artifacts.open_range(id, name, 0, size).await?;
    let mut bytes = Vec::with_capacity(size as usize);
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

/// The schema of [`GroundTruthPath::kind`]: one of [`CAPTURED_KINDS`].
struct GroundTruthKind;

impl utoipa::PartialSchema for GroundTruthKind {
    fn schema() -> utoipa::openapi::RefOr<utoipa::openapi::Schema> {
        utoipa::openapi::ObjectBuilder::new()
            .schema_type(utoipa::openapi::Type::String)
            .enum_values(Some(CAPTURED_KINDS))
            .into()
    }
}

impl utoipa::ToSchema for GroundTruthKind {}

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
        AoLP from [0, π) mapped to [0, 1]. DoLP and AoLP need a full Stokes view. The training \
        job wrote them (the artifacts `captured/{kind}/NNN.png`).",
    params(GroundTruthPath),
    responses(
        (status = OK, description = "The image", body = Binary, content_type = "image/png"),
        (status = NOT_FOUND, description = "No such job the token may see, an unknown kind or \
            view, or a view without full Stokes for dolp or aolp (not_found)",
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
    trained_job(&state, &caller, &id).await?;
    if !CAPTURED_KINDS.contains(&kind.as_str()) {
        return Err(ApiError::not_found("ground-truth kind", &kind));
    }
    let index: usize = view
        .strip_suffix(".png")
        .and_then(|n| n.parse().ok())
        .ok_or_else(|| ApiError::not_found("test view", &view))?;
    // The training job wrote the previews in its own process; nothing is decoded here.
    let name = format!("{CAPTURED_DIR}/{kind}/{index:03}.png");
    if state.artifacts.stat(&id, &name).await?.is_none() {
        return Err(ApiError::new(
            StatusCode::NOT_FOUND,
            "not_found",
            format!(
                "job `{id}` has no captured {kind} image of test view {index} (DoLP and AoLP need \
                 a full Stokes view)"
            ),
        ));
    }
    let png = artifact_bytes(&state, &id, &name).await?;
    Ok(file_response(png, "image/png"))
}

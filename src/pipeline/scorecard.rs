//! The complete evaluation of a trained model against a capture: the test-view metrics of
//! [`crate::pipeline::evaluate`], plus, where ground truth for them is at hand, the relit S0 under the
//! capture's relighting map and the Chamfer-L1 of the model's mesh to the ground-truth mesh.
//! `phygap eval` and `phygap bench quality` both print this report.
//!
//! [`GroundTruth::discover`] finds the extras of a capture folder laid out as
//! `shared/data/DATA_FORMAT.md` describes (`scene.json` → `env_map.relight`, `mesh.ply`).

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

use crate::core::surfels::sigmoid;
use crate::io::capture::{Capture, SceneMaps};
use crate::io::model::Model;
use crate::pipeline::evaluate::{self, EvalError, EvalReport};
use crate::pipeline::mesh_extraction::{self, MeshingError, DEFAULT_MESH_RESOLUTION};
use crate::pipeline::reconstruction::{Reconstruction, ReconstructionError};
use crate::pipeline::relight::{self, RelightError};

/// Ground truth beyond the capture's own test views.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GroundTruth {
    /// Lat-long map (.exr/.hdr) that lights the test views' `relight_s0` images.
    pub relight_envmap: Option<PathBuf>,
    /// The object's mesh (PLY), for the Chamfer-L1.
    pub mesh: Option<PathBuf>,
}

impl GroundTruth {
    /// The relighting map named by `capture_dir/scene.json` (`env_map.relight`) and
    /// `capture_dir/mesh.ply`, where they exist; neither is required.
    pub fn discover(capture_dir: &Path) -> GroundTruth {
        GroundTruth {
            relight_envmap: SceneMaps::read(capture_dir).relight,
            mesh: Some(capture_dir.join("mesh.ply")).filter(|path| path.is_file()),
        }
    }

    /// What [`Self::discover`] finds in `capture_dir`, with each path given in place of the one
    /// found (the flags of `phygap eval` and `phygap bench quality`).
    pub fn discover_or(
        capture_dir: &Path,
        relight_envmap: Option<PathBuf>,
        mesh: Option<PathBuf>,
    ) -> GroundTruth {
        let found = GroundTruth::discover(capture_dir);
        GroundTruth {
            relight_envmap: relight_envmap.or(found.relight_envmap),
            mesh: mesh.or(found.mesh),
        }
    }
}

#[derive(Debug, Error)]
pub enum ScorecardError {
    #[error(transparent)]
    Reconstruction(#[from] ReconstructionError),
    #[error(transparent)]
    Relight(#[from] RelightError),
    #[error(transparent)]
    Eval(#[from] EvalError),
    #[error(transparent)]
    Meshing(#[from] MeshingError),
}

/// Every metric of `model` on `capture`'s test views, with the relit and mesh metrics where
/// `truth` has what they need.
pub fn score(
    model: &Model,
    capture: &Capture,
    truth: &GroundTruth,
) -> Result<EvalReport, ScorecardError> {
    let _span = tracing::info_span!("scorecard").entered();
    let reconstruction = Reconstruction::new(model.clone())?;
    let mut report = reconstruction.evaluate(capture)?;
    report.train_seconds = Some(model.info.train_seconds);
    if let Some(errors) =
        evaluate::pose_errors(&model.train_cameras, capture, &opaque_points(model))
    {
        report.pose_error_deg = Some(errors.angle_deg);
        report.pose_error_radius = Some(errors.distance_radius);
        report.pose_error_px = errors.image_px;
    }
    if let Some(envmap) = &truth.relight_envmap {
        // GridMap's mesh depends on the surfels alone: the relit copy reuses it.
        let relit = reconstruction.relit(relight::relight_cube(model, envmap, 0.0)?)?;
        (report.relight_psnr, report.relight_ssim) =
            evaluate::relight_metrics(&relit.scene(), capture)?;
    }
    if let Some(gt) = &truth.mesh {
        let mesh = mesh_extraction::extract_from_model(model, DEFAULT_MESH_RESOLUTION)?;
        report.chamfer = Some(evaluate::chamfer_to_gt(&mesh, gt)?);
    }
    Ok(report)
}

/// At most this many surfels stand for the object where the pose errors are seen in the images.
const POSE_POINTS: usize = 4096;

/// The centres of the model's opaque surfels (opacity above ½), evenly thinned to
/// [`POSE_POINTS`].
fn opaque_points(model: &Model) -> Vec<DVec3> {
    let surfels = &model.surfels;
    let opaque: Vec<DVec3> = (0..surfels.len())
        .filter(|&i| sigmoid(surfels.opacity[i]) > 0.5)
        .map(|i| DVec3::from_array(surfels.position[i]))
        .collect();
    let stride = opaque.len().div_ceil(POSE_POINTS).max(1);
    opaque.into_iter().step_by(stride).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn discovers_the_relight_map_and_mesh_of_a_capture_folder() {
        let dir = tempfile::tempdir().unwrap();
        assert_eq!(GroundTruth::discover(dir.path()), GroundTruth::default());
        std::fs::create_dir(dir.path().join("env")).unwrap();
        std::fs::write(dir.path().join("env/studio.exr"), b"x").unwrap();
        std::fs::write(dir.path().join("mesh.ply"), b"x").unwrap();
        std::fs::write(
            dir.path().join("scene.json"),
            r#"{"env_map": {"relight": "env/studio.exr"}}"#,
        )
        .unwrap();
        let truth = GroundTruth::discover(dir.path());
        assert_eq!(
            truth.relight_envmap,
            Some(dir.path().join("env/studio.exr"))
        );
        assert_eq!(truth.mesh, Some(dir.path().join("mesh.ply")));
        // A map that scene.json names but the folder lacks is not used.
        std::fs::remove_file(dir.path().join("env/studio.exr")).unwrap();
        assert_eq!(GroundTruth::discover(dir.path()).relight_envmap, None);
    }

    #[test]
    fn paths_given_replace_the_ones_found() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("mesh.ply"), b"x").unwrap();
        let found = GroundTruth::discover_or(dir.path(), None, None);
        assert_eq!(found, GroundTruth::discover(dir.path()));
        assert_eq!(found.mesh, Some(dir.path().join("mesh.ply")));
        let given = GroundTruth::discover_or(
            dir.path(),
            Some(PathBuf::from("other/map.exr")),
            Some(PathBuf::from("other/mesh.ply")),
        );
        assert_eq!(
            given,
            GroundTruth {
                relight_envmap: Some(PathBuf::from("other/map.exr")),
                mesh: Some(PathBuf::from("other/mesh.ply")),
            }
        );
    }
}

//! The complete evaluation of a trained model against a capture: the test-view metrics of
//! [`crate::pipeline::evaluate`], plus, where ground truth for them is at hand, the relit S0 under the
//! capture's relighting map and the Chamfer-L1 of the model's mesh to the ground-truth mesh.
//! `phygap eval` and `phygap bench quality` both print this report.
//!
//! [`GroundTruth::discover`] finds the extras of a capture folder laid out as
//! `shared/data/DATA_FORMAT.md` describes (`scene.json` → `env_map.relight`, `mesh.ply`).

use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::io::capture::Capture;
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
        let relight_envmap = std::fs::read_to_string(capture_dir.join("scene.json"))
            .ok()
            .and_then(|text| serde_json::from_str::<serde_json::Value>(&text).ok())
            .and_then(|scene| scene["env_map"]["relight"].as_str().map(str::to_owned))
            .map(|relative| capture_dir.join(relative))
            .filter(|path| path.is_file());
        let mesh = Some(capture_dir.join("mesh.ply")).filter(|path| path.is_file());
        GroundTruth {
            relight_envmap,
            mesh,
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
}

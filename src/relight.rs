//! Relighting: replace a model's environment light by a user's lat-long map (EXR or HDR,
//! CAPTURE_FORMAT.md §5, optionally rotated about the world's up axis), rebuild its prefilters and
//! render S0 (and the Stokes images) from a set of cameras.

use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::capture::{self, CaptureError};
use crate::envmap::{CubeMap, EnvMapError};
use crate::model::{Model, ModelError, TEST_CAMERAS_FILE};
use crate::reconstruction::{Reconstruction, ReconstructionError};

#[derive(Debug, Error)]
pub enum RelightError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error("environment map: {0}")]
    EnvMap(#[from] EnvMapError),
    #[error(transparent)]
    Cameras(#[from] CaptureError),
    #[error(transparent)]
    Reconstruction(#[from] ReconstructionError),
    #[error("no cameras: pass a transforms file (the model has no {TEST_CAMERAS_FILE})")]
    NoCameras,
    #[error("rotation must be a finite number of degrees, got {0}")]
    BadRotation(f64),
}

/// Images written per camera by [`relight`].
pub const RELIGHT_KINDS: [&str; 3] = ["s0", "s1", "s2"];

/// A model lit by the map at `envmap` (rotated by `rotate_deg` about the up axis).
pub fn relit_reconstruction(
    model: Model,
    envmap: &Path,
    rotate_deg: f64,
) -> Result<Reconstruction, RelightError> {
    if !rotate_deg.is_finite() {
        return Err(RelightError::BadRotation(rotate_deg));
    }
    let up = model.world_up()?;
    let cube = CubeMap::load_latlong(envmap, up, model.envmap.size)?;
    let cube = if rotate_deg == 0.0 {
        cube
    } else {
        cube.rotated_about_up(rotate_deg, up)
    };
    let mut reconstruction = Reconstruction::new(model)?;
    reconstruction.set_envmap(cube)?;
    Ok(reconstruction)
}

/// Relights the model in `model_dir` and renders `cameras` (a transforms file; default: the
/// model's test cameras) into `out_dir/<kind>/NNN.exr|png`. Returns the files written.
pub fn relight(
    model_dir: &Path,
    envmap: &Path,
    cameras: Option<&Path>,
    out_dir: &Path,
    rotate_deg: f64,
) -> Result<Vec<PathBuf>, RelightError> {
    let _span = tracing::info_span!("relight", envmap = %envmap.display()).entered();
    let model = Model::load(model_dir)?;
    let default_cameras = model_dir.join(TEST_CAMERAS_FILE);
    let cameras_file = match cameras {
        Some(path) => path.to_owned(),
        None if default_cameras.exists() => default_cameras,
        None => return Err(RelightError::NoCameras),
    };
    let cameras = capture::load_cameras(&cameras_file)?;
    let reconstruction = relit_reconstruction(model, envmap, rotate_deg)?;
    Ok(reconstruction.render_to_dir(&cameras, out_dir, &RELIGHT_KINDS)?)
}

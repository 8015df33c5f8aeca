//! Relighting: replace a model's environment light by a user's lat-long map (EXR or HDR,
//! CAPTURE_FORMAT.md §5, optionally rotated about the world's up axis), rebuild its prefilters and
//! render S0 (and the Stokes images) from a set of cameras.

use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::core::envmap::{CubeMap, EnvMapError};
use crate::io::capture::{self, CaptureError};
use crate::io::model::{Model, ModelError, TEST_CAMERAS_FILE};
use crate::pipeline::reconstruction::{Reconstruction, ReconstructionError};

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

/// The lat-long map at `envmap` as a cube map for `model` (mapped with its world up, at its face
/// size), turned by `rotate_deg` about the up axis.
pub fn relight_cube(
    model: &Model,
    envmap: &Path,
    rotate_deg: f64,
) -> Result<CubeMap, RelightError> {
    if !rotate_deg.is_finite() {
        return Err(RelightError::BadRotation(rotate_deg));
    }
    let up = model.world_up()?;
    let cube = CubeMap::load_latlong(envmap, up, model.envmap.size)?;
    Ok(if rotate_deg == 0.0 {
        cube
    } else {
        cube.rotated_about_up(rotate_deg, up)
    })
}

/// A model lit by the map at `envmap` (rotated by `rotate_deg` about the up axis).
pub fn relit_reconstruction(
    mut model: Model,
    envmap: &Path,
    rotate_deg: f64,
) -> Result<Reconstruction, RelightError> {
    // Swapped in before the reconstruction is built, so the new map is prefiltered and GridMap's
    // probes are rendered once, under the new light only.
    model.envmap = relight_cube(&model, envmap, rotate_deg)?;
    Ok(Reconstruction::new(model)?)
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

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use glam::DVec3;

    use super::*;
    use crate::core::config::{BackendChoice, Mode, TrainConfig};
    use crate::core::envmap::{texel_dir, NUM_FACES};
    use crate::core::mesh::cameras_around;
    use crate::io::model::ModelInfo;

    const SIZE: usize = 16;

    /// A sphere of surfels under a smooth sky, "trained" for 100 iterations.
    fn sphere_model(gridmap: bool) -> Model {
        let radiance: Vec<f64> = (0..NUM_FACES * SIZE * SIZE)
            .flat_map(|t| {
                let (face, rest) = (t / (SIZE * SIZE), t % (SIZE * SIZE));
                let d = texel_dir(SIZE, face, rest % SIZE, rest / SIZE);
                let v = 0.3 + 1.2 * d.z.max(0.0) + 0.6 * (d.x + 1.0);
                [v, 0.8 * v, 0.5 * v + 0.2]
            })
            .collect();
        let surfels =
            crate::testing::sphere_surfels(DVec3::ZERO, 1.0, 3000, DVec3::new(0.5, 0.4, 0.3));
        let config = TrainConfig {
            gridmap,
            iterations: 100.into(),
            envmap_resolution: SIZE as u32,
            backend: BackendChoice::Cpu,
            ..TrainConfig::default()
        };
        let train_cameras = cameras_around(12, 4.0, 48, 40f64.to_radians())
            .into_iter()
            .enumerate()
            .map(|(i, c)| (format!("{i:03}"), c))
            .collect();
        Model {
            info: ModelInfo {
                mode: Mode::Full,
                world_up: [0.0, 0.0, 1.0],
                polarizer_angles_deg: BTreeMap::new(),
                iterations: 100,
                train_seconds: 0.0,
                num_surfels: surfels.len(),
                backend: "cpu".into(),
                working_resolution: None,
                refined_poses: None,
                silhouette_offset_px: None,
                frame_registration: None,
            },
            config,
            surfels,
            envmap: CubeMap::from_radiance(SIZE, &radiance).unwrap(),
            train_cameras,
        }
    }

    #[test]
    fn a_model_renders_with_the_mip_chain_it_was_trained_with() {
        let camera = cameras_around(5, 3.5, 40, 45f64.to_radians())[2];
        let render = |levels_per_size: u8| {
            let dir = tempfile::tempdir().unwrap();
            let mut model = sphere_model(false);
            model.config.mip_levels_per_size = levels_per_size;
            model.save(dir.path()).unwrap();
            let loaded = Reconstruction::new(Model::load(dir.path()).unwrap()).unwrap();
            let levels = loaded.environment().plan().roughness.len();
            (levels, loaded.scene().render(&camera).unwrap().shaded.s0)
        };
        let (method_levels, method) = render(1);
        let (fine_levels, fine) = render(2);
        // 16² base: METHOD.md's 16², 8², 4²; with two per size the sharpest at 16², three at 8²
        // (roughness 0.08 … 0.5) and r = 1 at 4².
        assert_eq!((method_levels, fine_levels), (3, 5));
        assert_ne!(method, fine, "the chains shade the sphere differently");
    }

    #[test]
    fn relighting_with_the_models_own_exported_map_reproduces_its_renders() {
        for gridmap in [false, true] {
            let dir = tempfile::tempdir().unwrap();
            let model = sphere_model(gridmap);
            model.save(dir.path()).unwrap();
            let loaded = Model::load(dir.path()).unwrap();
            assert_eq!(loaded.train_cameras.len(), 12);
            let plain = Reconstruction::new(loaded.clone()).unwrap();
            assert_eq!(plain.gridmap().is_some(), gridmap);
            let relit = relit_reconstruction(loaded, &dir.path().join("envmap.exr"), 0.0).unwrap();
            assert_eq!(relit.gridmap().is_some(), gridmap);
            let camera = cameras_around(5, 3.5, 40, 45f64.to_radians())[2];
            let a = plain.scene().render(&camera).unwrap();
            let b = relit.scene().render(&camera).unwrap();
            // The relit copy of the plain reconstruction (GridMap's mesh reused, not extracted
            // again) renders exactly what the freshly built one does.
            let cube = relight_cube(&plain.model, &dir.path().join("envmap.exr"), 0.0).unwrap();
            let copy = plain.relit(cube).unwrap();
            assert_eq!(copy.gridmap().is_some(), gridmap);
            assert_eq!(copy.scene().render(&camera).unwrap().shaded.s0, b.shaded.s0);
            let (mut worst, mut sum, mut count) = (0.0f64, 0.0, 0);
            for p in 0..a.shaded.s0.len() {
                if a.gbuffers().alpha[p] < 0.5 {
                    continue;
                }
                let (x, y) = (a.shaded.s0[p], b.shaded.s0[p]);
                let relative = ((x - y).abs() / x.abs().max(DVec3::splat(1e-3))).max_element();
                worst = worst.max(relative);
                sum += relative;
                count += 1;
            }
            let mean = sum / count as f64;
            println!("gridmap {gridmap}: relit vs plain S0 relative error mean {mean:.2e}, max {worst:.2e}");
            assert!(count > 300);
            // Export (bilinear to 512×256) and import (4×4 supersampled) smooth the map slightly.
            assert!(mean < 2e-3 && worst < 1e-2, "mean {mean}, max {worst}");
            // A different map is not mistaken for the same one.
            let rotated = relit_reconstruction(
                Model::load(dir.path()).unwrap(),
                &dir.path().join("envmap.exr"),
                90.0,
            )
            .unwrap();
            let c = rotated.scene().render(&camera).unwrap();
            let changed = (0..a.shaded.s0.len())
                .filter(|&p| a.gbuffers().alpha[p] > 0.5)
                .map(|p| ((a.shaded.s0[p] - c.shaded.s0[p]).abs() / a.shaded.s0[p]).max_element())
                .fold(0.0, f64::max);
            assert!(changed > 0.05, "{changed}");
        }
    }
}

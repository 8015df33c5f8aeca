//! Under `pose_refinement: auto`, whether the capture's poses are estimated, decided where
//! refinement would start (`refine_views_from`): once the surfels have a shape they stand for
//! the consensus of the views, and each view's mask lies beside the silhouette it renders by that
//! view's own pose error ([`crate::core::silhouette`]). Poses from structure-from-motion, off by
//! a fraction of a degree, put the masks a pixel or more beside it; on exact poses refinement
//! only drifts. What neighbouring views share (a shape the surfels have not matched yet) is no
//! pose error and is left out ([`crate::core::view_spread`]).
//!
//! Colour refinement has no such test: the views' brightness over the model's prediction varies
//! from view to view as much on a clean glossy object, by its highlights (homer: 0.33 RMS in
//! logarithms, each view's own part, at this point of the run), as on the knot exposed ±20 % per
//! view (0.37).

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::state::TrainState;
use super::{Run, TrainError};
use crate::core::silhouette::{own_offset, silhouette_shift};

/// Poses are refined where the masks lie farther than this beside the rendered silhouettes,
/// counting what each view does not share with its neighbours (RMS pixels at the working
/// resolution). Measured at the default `refine_views_from`: exact poses give 0.24 px (knot),
/// 0.33 px (homer) and 0.72 px (sphere, whose unseen underside the surfels have not matched by
/// then); the knot with poses off by 0.5° and 1 % of its radius, 2.9 px.
pub const ESTIMATED_POSES_PX: f64 = 1.0;

/// Whether a silhouette offset says the poses were estimated.
pub fn estimated(silhouette_offset_px: Option<f64>) -> bool {
    silhouette_offset_px.is_some_and(|px| px > ESTIMATED_POSES_PX)
}

/// The decision's evidence in words, for the run's [`crate::core::events::TrainEvent::Decided`].
pub fn evidence(silhouette_offset_px: Option<f64>) -> String {
    match silhouette_offset_px {
        Some(px) => format!(
            "the masks lie {px:.2} px RMS beside the rendered silhouettes, each view's own part \
             (refined above {ESTIMATED_POSES_PX} px)"
        ),
        None => "too few views with an outline to measure the poses by".to_owned(),
    }
}

/// Renders every training view's silhouette under the current surfels and poses and measures how
/// far the masks lie beside them, each view's own part, RMS pixels (`None` where fewer views than
/// [`crate::core::view_spread::NEIGHBOURS`] + 1 had an outline to align).
pub(super) fn silhouette_offset(run: &Run, state: &TrainState) -> Result<Option<f64>, TrainError> {
    let _span = tracing::info_span!("estimated_poses", iteration = state.iteration).entered();
    let rendered = (0..run.targets.len())
        .map(|k| {
            let camera = run.poses.camera(&state.poses, k);
            let alpha = run
                .backend
                .forward(&state.surfels, &camera, &run.settings)?
                .gbuffers
                .alpha;
            Ok((alpha, camera))
        })
        .collect::<Result<Vec<_>, TrainError>>()?;
    let centre = run.poses.centre();
    let shifts: Vec<(DVec3, DVec2)> = rendered
        .into_par_iter()
        .zip(&run.targets)
        .filter_map(|((alpha, camera), target)| {
            let (width, height) = (camera.width as usize, camera.height as usize);
            let shift = silhouette_shift(&alpha, &target.mask, width, height)?;
            Some(((camera.origin() - centre).normalize(), shift))
        })
        .collect();
    let offset = own_offset(&shifts);
    tracing::info!(
        views = shifts.len(),
        silhouette_offset_px = offset,
        "estimated poses"
    );
    Ok(offset)
}

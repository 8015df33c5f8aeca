//! Which surfels no training view sees: those whose centre lies well behind the rendered surface
//! in every training view that has it in frame. The volumetric initialization (METHOD.md §7)
//! leaves surfels deep inside the object; while the surface in front of them is opaque they
//! receive almost no gradient, but an opacity reset makes every surfel nearly transparent, and
//! they come back into view, regain opacity where they fit the image and show through the surface
//! as holes (docs/design/experiments.md, *Pruning hidden surfels*). Pruning them just before the reset removes
//! nothing any view shows.
//!
//! The test, per view and surfel: project the centre; outside the image or before the near plane,
//! the view says nothing. Where the rendered opacity at that pixel is below ½ nothing solid lies in
//! front, so the surfel counts as seen. Otherwise it is *behind* when its centre depth exceeds the
//! farthest rendered (α-normalized mean) depth of the pixel and its eight neighbours by more than
//! three of its own larger scale: a surfel of the surface the pixel shows lies within about its
//! own extent of the blended depth, and the neighbours cover a surface seen at a grazing angle,
//! whose depth changes by more than that from one pixel to the next.
//! The mean depth itself leans backwards where a little weight passes the surface (a pixel of
//! opacity 0.98 over surfels a radius behind), which errs towards keeping a surfel; the spread of
//! the composited depths (`depth_sq`) was tried as a further margin and kept surfels a third of a
//! radius behind an opaque shell, since those small far weights dominate it. Hidden: in frame in
//! at least one view and behind in every one of them. Scale-free: nothing here depends on the
//! object's size or the image's resolution.
//!
//! Threading: the views are rendered one after another by the engine; each view's test runs
//! rayon-parallel over surfels. The result does not depend on the number of threads.

use glam::DVec3;
use rayon::prelude::*;

use crate::core::camera::Camera;
use crate::core::engine::Backend;
use crate::core::raster::{GBuffers, RasterError, RasterSettings};
use crate::core::surfels::Surfels;

/// Rendered opacity from which a pixel counts as showing a surface.
const SOLID_ALPHA: f64 = 0.5;
/// How many of its own larger scale a centre must lie behind the rendered depth to count as
/// hidden there.
const BEHIND_SIGMAS: f64 = 3.0;

/// What one view says of one surfel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Seen {
    /// Outside the image or before the near plane.
    OutOfFrame,
    /// At or before the surface the view renders at its pixel (or no solid surface there).
    InView,
    /// Well behind the rendered surface.
    Behind,
}

/// Per surfel, whether every training view that frames it renders a surface well in front of it.
pub fn hidden_surfels(
    surfels: &Surfels,
    cameras: &[Camera],
    backend: &dyn Backend,
    settings: &RasterSettings,
) -> Result<Vec<bool>, RasterError> {
    let _span = tracing::info_span!("hidden_surfels", surfels = surfels.len()).entered();
    let n = surfels.len();
    // Per surfel: framed by some view, and behind in every view that framed it.
    let mut framed = vec![false; n];
    let mut behind_everywhere = vec![true; n];
    for camera in cameras {
        let rendered = backend.forward(surfels, camera, settings)?;
        let gb = &rendered.gbuffers;
        (framed.par_iter_mut(), behind_everywhere.par_iter_mut())
            .into_par_iter()
            .enumerate()
            .for_each(|(i, (framed, behind))| {
                match seen_from(surfels, i, camera, gb, settings.near) {
                    Seen::OutOfFrame => {}
                    Seen::InView => {
                        *framed = true;
                        *behind = false;
                    }
                    Seen::Behind => *framed = true,
                }
            });
    }
    Ok(framed
        .into_iter()
        .zip(behind_everywhere)
        .map(|(framed, behind)| framed && behind)
        .collect())
}

/// What `camera`'s rendered G-buffers `gb` say of surfel `i`.
fn seen_from(surfels: &Surfels, i: usize, camera: &Camera, gb: &GBuffers, near: f64) -> Seen {
    let Some((x, y, z)) = camera.project(DVec3::from_array(surfels.position[i])) else {
        return Seen::OutOfFrame;
    };
    if z <= near || !(x >= 0.0 && y >= 0.0 && x < gb.width as f64 && y < gb.height as f64) {
        return Seen::OutOfFrame;
    }
    let (px, py) = (x as usize, y as usize);
    let alpha = gb.alpha[py * gb.width + px];
    if alpha.is_nan() || alpha < SOLID_ALPHA {
        return Seen::InView;
    }
    // The farthest solid depth of the pixel and its 8 neighbours: where the surface is seen at
    // a grazing angle its depth changes by more than a surfel's extent from pixel to pixel.
    let mut surface = f64::NEG_INFINITY;
    for ny in py.saturating_sub(1)..(py + 2).min(gb.height) {
        for nx in px.saturating_sub(1)..(px + 2).min(gb.width) {
            let k = ny * gb.width + nx;
            if gb.alpha[k] >= SOLID_ALPHA {
                surface = surface.max(gb.depth[k]);
            }
        }
    }
    let [su, sv] = surfels.log_scale[i];
    let extent = su.max(sv).exp();
    if z > surface + BEHIND_SIGMAS * extent {
        Seen::Behind
    } else {
        Seen::InView
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::raster::fast::FastBackend;
    use crate::pipeline::bench::shell_surfels;

    /// A shell of surfels with a cluster deep inside it and one surfel outside every view: seen
    /// from all around, the inner cluster is hidden, every shell surfel and the stray are not.
    #[test]
    fn surfels_inside_an_opaque_shell_are_hidden_and_the_shell_is_not() {
        let mut surfels = shell_surfels(6000, 3);
        let first_inner = surfels.len();
        // 200 copies of shell surfels moved to a third of the shell's radius, and one far away.
        surfels.extend_from_indices(&(0..201).map(|i| i * 29).collect::<Vec<_>>());
        for p in &mut surfels.position[first_inner..] {
            *p = p.map(|v| v / 3.0);
        }
        let stray_index = surfels.len() - 1;
        surfels.position[stray_index] = [40.0, 40.0, 40.0];
        // Opaque: a surface the inner surfels cannot be seen through.
        surfels.opacity.iter_mut().for_each(|o| *o = 4.0);

        // Around the equator at three heights, and from above and below: every point of the
        // shell is seen within about 60 degrees of its normal by some view.
        let mut eyes: Vec<DVec3> = (0..8)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 8.0;
                DVec3::new(3.5 * a.cos(), 3.5 * a.sin(), 1.2 * (k % 3) as f64 - 1.2)
            })
            .collect();
        eyes.extend([DVec3::new(0.4, 0.0, 3.5), DVec3::new(-0.4, 0.2, -3.5)]);
        let cameras: Vec<Camera> = eyes
            .into_iter()
            .map(|eye| Camera::look_at(96, 96, 0.8, eye, DVec3::ZERO, DVec3::Z))
            .collect();
        let settings = RasterSettings::default();
        let backend = FastBackend::new();
        let hidden = hidden_surfels(&surfels, &cameras, &backend, &settings).unwrap();

        let inner_hidden = hidden[first_inner..stray_index]
            .iter()
            .filter(|&&h| h)
            .count();
        let shell_hidden = hidden[..first_inner].iter().filter(|&&h| h).count();
        assert_eq!(inner_hidden, 200, "every inner surfel is hidden");
        assert_eq!(shell_hidden, 0, "no shell surfel is hidden");
        assert!(
            !hidden[stray_index],
            "a surfel no view frames is not hidden"
        );

        // Made transparent, the shell no longer hides them.
        let mut clear = surfels.clone();
        clear.opacity[..first_inner]
            .iter_mut()
            .for_each(|o| *o = -8.0);
        let hidden = hidden_surfels(&clear, &cameras, &backend, &settings).unwrap();
        assert!(hidden.iter().all(|&h| !h));
    }
}

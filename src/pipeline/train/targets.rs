//! What each view is fitted to, converted once to f64: the photometric target (S0, an image behind a
//! polarizer, or a plain image), S1/S2 where the view has full Stokes and the run uses them, the
//! mask, and which polarizer angle (known or learned) the view was taken behind.

use crate::core::config::Mode;
use crate::core::step::{Polarizer, ViewTarget};
use crate::formats::image_io::Image;
use crate::io::capture::{Capture, Measurement, PolarizerAngle, View};

fn to_f64(img: &Image) -> Vec<f64> {
    img.to_rgb().data.iter().map(|&v| f64::from(v)).collect()
}

/// The target of `view` under the resolved `mode` (never `Auto`).
pub fn view_target(index: usize, view: &View, mode: Mode) -> ViewTarget {
    let mask = view.mask.data.iter().map(|&v| f64::from(v)).collect();
    let (photometric, stokes, polarizer) = match (&view.measurement, mode) {
        (Measurement::Stokes { s0, s1, s2 }, Mode::Full | Mode::Partial) => {
            (to_f64(s0), Some((to_f64(s1), to_f64(s2))), None)
        }
        (Measurement::Stokes { s0, .. }, _) => (to_f64(s0), None, None),
        (Measurement::Polarizer { image, angle }, Mode::Partial | Mode::Full) => {
            let polarizer = match angle {
                PolarizerAngle::Known { degrees } => Polarizer::Fixed(degrees.to_radians()),
                PolarizerAngle::Group(name) => Polarizer::Learned(name.clone()),
            };
            (to_f64(image), None, Some(polarizer))
        }
        // In rgb mode an image behind a polarizer is fitted as an ordinary image.
        (Measurement::Polarizer { image, .. } | Measurement::Rgb { image }, _) => {
            (to_f64(image), None, None)
        }
    };
    ViewTarget {
        view: index,
        photometric,
        stokes,
        polarizer,
        mask,
    }
}

/// Resolves `Mode::Auto` from the training views: full if all have Stokes, partial if any is behind a
/// polarizer, rgb otherwise.
pub fn resolve_mode(capture: &Capture, requested: Mode) -> Mode {
    if requested != Mode::Auto {
        return requested;
    }
    let train: Vec<&View> = capture.train_views().collect();
    if train
        .iter()
        .all(|v| matches!(v.measurement, Measurement::Stokes { .. }))
    {
        Mode::Full
    } else if train
        .iter()
        .any(|v| matches!(v.measurement, Measurement::Polarizer { .. }))
    {
        Mode::Partial
    } else {
        Mode::Rgb
    }
}

/// Names of the learned polarizer groups among the training views, sorted.
pub fn learned_groups(targets: &[ViewTarget]) -> Vec<String> {
    let mut names: Vec<String> = targets
        .iter()
        .filter_map(|t| match &t.polarizer {
            Some(Polarizer::Learned(name)) => Some(name.clone()),
            _ => None,
        })
        .collect();
    names.sort();
    names.dedup();
    names
}

//! What each view is fitted to, borrowed from the capture's views (copied only where an image
//! is not RGB, or shows a background beyond the mask, which is made black, past a rim of a few
//! pixels where the background is dark: [`crate::core::background`]): the photometric target
//! (S0, an image behind a polarizer, or a plain image), S1/S2 where the view has full Stokes and
//! the run uses them, the mask, and which polarizer angle (known or learned) the view was taken
//! behind; and, from the run's settings, how far each pixel's polarization can be trusted and
//! where the mask loss leaves the mask's edge alone.

use std::borrow::Cow;

use crate::core::background::{beyond_mask, black_beyond, is_dark_background, DARK_RIM_PX};
use crate::core::config::{Mode, TrainConfig};
use crate::core::mask_band::mask_loss_weights;
use crate::core::polarization_confidence::polarization_confidence;
use crate::core::step::{Polarizer, ViewTarget};
use crate::formats::image_io::Image;
use crate::io::capture::{Capture, Measurement, PolarizerAngle, View};

/// `img`'s samples as interleaved RGB: its own when it is RGB, else a converted copy.
fn rgb(img: &Image) -> Cow<'_, [f32]> {
    if img.channels == 3 {
        Cow::Borrowed(&img.data)
    } else {
        Cow::Owned(img.to_rgb().data)
    }
}

/// The target of `view` under the resolved `mode` (never `Auto`), with `config`'s
/// `polarization_snr` and `mask_edge_px`.
pub fn view_target<'a>(
    index: usize,
    view: &'a View,
    mode: Mode,
    config: &TrainConfig,
) -> ViewTarget<'a> {
    let mask = Cow::Borrowed(view.mask.data.as_slice());
    let (photometric, stokes, polarizer) = match (&view.measurement, mode) {
        (Measurement::Stokes { s0, s1, s2 }, Mode::Full | Mode::Partial) => {
            (rgb(s0), Some((rgb(s1), rgb(s2))), None)
        }
        (Measurement::Stokes { s0, .. }, _) => (rgb(s0), None, None),
        (Measurement::Polarizer { image, angle }, Mode::Partial | Mode::Full) => {
            let polarizer = match angle {
                PolarizerAngle::Known { degrees } => Polarizer::Fixed(degrees.to_radians()),
                PolarizerAngle::Group(name) => Polarizer::Learned(name.clone()),
            };
            (rgb(image), None, Some(polarizer))
        }
        // In rgb mode an image behind a polarizer is fitted as an ordinary image.
        (Measurement::Polarizer { image, .. } | Measurement::Rgb { image }, _) => {
            (rgb(image), None, None)
        }
    };
    let (width, height) = (view.mask.width, view.mask.height);
    let kept_px = if is_dark_background(&photometric, &mask, width, height) {
        config.mask_edge_px.max(DARK_RIM_PX)
    } else {
        config.mask_edge_px
    };
    let beyond = beyond_mask(&mask, width, height, kept_px);
    let photometric = black_beyond(photometric, &beyond);
    let stokes = stokes.map(|(s1, s2)| (black_beyond(s1, &beyond), black_beyond(s2, &beyond)));
    let polarization_confidence = match &stokes {
        Some((s1, s2)) if config.polarization_snr => Some(polarization_confidence(
            &photometric,
            s1,
            s2,
            &mask,
            width,
            height,
        )),
        _ => None,
    };
    let mask_weight = (config.mask_edge_px > 0)
        .then(|| mask_loss_weights(&mask, width, height, config.mask_edge_px));
    ViewTarget {
        view: index,
        photometric,
        stokes,
        polarizer,
        mask,
        gain: 1.0,
        polarization_confidence,
        mask_weight,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb_images_are_borrowed_and_others_expanded() {
        let colour = Image::from_fn(3, 2, 3, |x, y, out| {
            out.copy_from_slice(&[x as f32, y as f32, 0.5]);
        });
        let borrowed = rgb(&colour);
        assert!(matches!(borrowed, Cow::Borrowed(_)));
        assert_eq!(borrowed.as_ptr(), colour.data.as_ptr());
        let grey = Image::from_fn(3, 2, 1, |x, y, out| out[0] = (x + 3 * y) as f32);
        let expanded = rgb(&grey);
        assert!(matches!(expanded, Cow::Owned(_)));
        assert_eq!(expanded.len(), 18);
        assert_eq!(&expanded[12..15], &[4.0, 4.0, 4.0]);
    }

    /// A 12 × 10 view of a 4 × 4 object in the middle whose Stokes images hold `background`
    /// everywhere off the object (and 0.5, 0.1, -0.1 on it).
    fn stokes_view(background: f32) -> View {
        use crate::core::camera::Camera;
        use crate::io::capture::{GroundTruth, Split};
        let (w, h) = (12, 10);
        let on_object = |x: usize, y: usize| (4..8).contains(&x) && (3..7).contains(&y);
        let image = |value: f32| {
            Image::from_fn(w, h, 3, |x, y, out| {
                out.fill(if on_object(x, y) { value } else { background });
            })
        };
        View {
            name: "frame 0".to_owned(),
            frame_index: 0,
            split: Split::Train,
            camera: Camera::look_at(
                w as u32,
                h as u32,
                0.7,
                glam::DVec3::Z * 4.0,
                glam::DVec3::ZERO,
                glam::DVec3::Y,
            ),
            measurement: Measurement::Stokes {
                s0: image(0.5),
                s1: image(0.1),
                s2: image(-0.1),
            },
            mask: Image::from_fn(w, h, 1, |x, y, out| {
                out[0] = f32::from(u8::from(on_object(x, y)))
            }),
            ground_truth: GroundTruth::default(),
        }
    }

    #[test]
    fn a_photographed_background_is_black_in_every_target_and_the_object_untouched() {
        let view = stokes_view(0.3);
        // By default off the mask is black; with a mask-edge band the images keep their values
        // within it.
        for band in [0, 2] {
            let config = TrainConfig {
                mask_edge_px: band,
                ..TrainConfig::default()
            };
            let target = view_target(0, &view, Mode::Full, &config);
            let (s1, s2) = target.stokes.as_ref().expect("full Stokes");
            for (samples, on_object) in [(&target.photometric, 0.5), (s1, 0.1), (s2, -0.1)] {
                assert!(matches!(samples, Cow::Owned(_)));
                for (p, pixel) in samples.chunks_exact(3).enumerate() {
                    let (x, y) = (p % 12, p / 12);
                    let expected = if (4..8).contains(&x) && (3..7).contains(&y) {
                        on_object
                    } else if band == 2 && (2..10).contains(&x) && (1..9).contains(&y) {
                        0.3
                    } else {
                        0.0
                    };
                    assert_eq!(pixel, [expected; 3], "band {band}, pixel ({x}, {y})");
                }
            }
        }
    }

    /// A view over a dark backdrop (its noise at 2 % of the object's brightness) whose mask is
    /// eroded by a pixel keeps the object's rim that the mask misses, and the backdrop within two
    /// pixels of the mask; farther out the noise is black. At 6 % the backdrop is no longer dark
    /// and is black from the mask's edge, rim and all.
    #[test]
    fn a_dark_background_keeps_the_rim_an_eroded_mask_misses() {
        for (background, dark) in [(0.01, true), (0.03, false)] {
            let mut view = stokes_view(background);
            view.mask = Image::from_fn(12, 10, 1, |x, y, out| {
                out[0] = f32::from(u8::from((5..7).contains(&x) && (4..6).contains(&y)))
            });
            let target = view_target(0, &view, Mode::Full, &TrainConfig::default());
            let (s1, _) = target.stokes.as_ref().unwrap();
            let at = |x: usize, y: usize| 3 * (y * 12 + x);
            // (4, 3): the object, a pixel outside the mask; (3, 3): the backdrop, two pixels
            // outside; (2, 3) and (0, 0): the backdrop, farther.
            if dark {
                assert_eq!(target.photometric[at(4, 3)], 0.5);
                assert_eq!(s1[at(4, 3)], 0.1);
                assert_eq!(target.photometric[at(3, 3)], background);
            } else {
                assert_eq!(target.photometric[at(4, 3)], 0.0);
                assert_eq!(s1[at(4, 3)], 0.0);
                assert_eq!(target.photometric[at(3, 3)], 0.0);
            }
            assert_eq!(target.photometric[at(2, 3)], 0.0);
            assert_eq!(target.photometric[at(0, 0)], 0.0);
        }
    }

    #[test]
    fn a_rendered_capture_s_targets_are_borrowed_from_it() {
        let view = stokes_view(0.0);
        let target = view_target(0, &view, Mode::Full, &TrainConfig::default());
        let Measurement::Stokes { s0, .. } = &view.measurement else {
            unreachable!()
        };
        assert!(matches!(target.photometric, Cow::Borrowed(_)));
        assert_eq!(target.photometric.as_ptr(), s0.data.as_ptr());
        assert!(target
            .stokes
            .iter()
            .all(|(a, b)| matches!((a, b), (Cow::Borrowed(_), Cow::Borrowed(_)))));
    }
}

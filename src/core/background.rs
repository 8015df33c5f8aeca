//! The part of a view the model does not represent: what lies beyond the object's mask.
//!
//! Renders are α-premultiplied, black where no surfel is, and the shared captures are rendered the
//! same way. A photograph is not: beyond the mask it shows the table, the room, the clutter. Fitted
//! as it is, that background asks the photometric loss for surfels where the mask loss asks for
//! none, and the two settle on floaters and a haze around the object. So the training targets are
//! black wherever the mask says background, the same thing the mask loss says. Where the mask is
//! not trusted to the pixel (`--mask-edge-px`, [`crate::core::mask_band`]), the images keep their
//! values within that band, so they, not the mask, place the contour.
//!
//! A view whose background is dark ([`is_dark_background`]: a rendered capture, a black backdrop,
//! a sensor's noise) keeps its images within [`DARK_RIM_PX`] of the mask: blacking out a dark
//! background changes only the pixels where the mask is wrong, and next to an eroded mask those
//! are the object's rim. Farther out only the noise is left, and it is made black like any
//! background (fitted, it grows a haze of faint surfels around the object).
//!
//! Threading: single-threaded separable passes over the mask (once per view and run).

use std::borrow::Cow;

use crate::core::mask_band::window_any;

/// How far beyond the mask [`background_and_object_sums`]'s callers start measuring a capture's
/// background: past an anti-aliased contour, whose partly covered pixels are the object's.
pub const MEASURED_BEYOND_PX: u32 = 2;

/// Background at most this fraction of the object's mean brightness is dark: the images keep a
/// rim of [`DARK_RIM_PX`] beyond the mask. A sensor's noise over a black backdrop reads 0.03
/// (12 bits, read noise 0.5 % of full scale); a photographed table and room read about as bright
/// as the object.
pub const DARK_BACKGROUND_LEVEL: f64 = 0.05;

/// How far beyond the mask a dark background keeps its values: masks a pixel or two short of
/// the object (matting, a threshold, a mask drawn at another resolution) leave its rim there.
pub const DARK_RIM_PX: u32 = 2;

/// Whether the view whose interleaved `samples` and `mask` (object where ≥ ½) these are shows a
/// dark background: its [`background_level`] at most [`DARK_BACKGROUND_LEVEL`]. A view without
/// pixels beyond its mask, or without an object, counts as dark (there is nothing to black out,
/// or nothing to compare with).
pub fn is_dark_background(samples: &[f32], mask: &[f32], width: usize, height: usize) -> bool {
    background_level(measured_sums(samples, mask, width, height))
        .is_none_or(|level| level <= DARK_BACKGROUND_LEVEL)
}

/// [`background_and_object_sums`] of a view with the background measured farther than
/// [`MEASURED_BEYOND_PX`] beyond its `width × height` `mask`.
pub fn measured_sums(
    samples: &[f32],
    mask: &[f32],
    width: usize,
    height: usize,
) -> [(f64, usize); 2] {
    let beyond = beyond_mask(mask, width, height, MEASURED_BEYOND_PX);
    background_and_object_sums(samples, mask, &beyond)
}

/// The background's mean over the object's, from [`background_and_object_sums`]' pairs (of one
/// view, or added over several): 0 for a render, about 1 for a photographed table and room;
/// `None` when either has no samples.
pub fn background_level([background, object]: [(f64, usize); 2]) -> Option<f64> {
    let mean = |(sum, count): (f64, usize)| sum / count as f64;
    (background.1 > 0 && object.1 > 0)
        .then(|| mean(background) / mean(object).max(f64::MIN_POSITIVE))
}

/// Whether each pixel of a `width × height` `mask` (object where ≥ ½) lies farther than
/// `margin_px` (Chebyshev distance) from every object pixel; with 0, whether it is background.
pub fn beyond_mask(mask: &[f32], width: usize, height: usize, margin_px: u32) -> Vec<bool> {
    assert_eq!(
        mask.len(),
        width * height,
        "beyond_mask: the mask is not {width}×{height}"
    );
    let object: Vec<bool> = mask.iter().map(|&m| m >= 0.5).collect();
    window_any(&object, width, height, margin_px as usize)
        .into_iter()
        .map(|near| !near)
        .collect()
}

/// Interleaved `samples` (any channel count) with every pixel that is `beyond` made 0: borrowed
/// unchanged when those pixels are already 0 (or the sizes disagree), a copy otherwise.
pub fn black_beyond<'a>(samples: Cow<'a, [f32]>, beyond: &[bool]) -> Cow<'a, [f32]> {
    let Some(channels) = channels_of(&samples, beyond) else {
        return samples;
    };
    if !samples
        .chunks_exact(channels)
        .zip(beyond)
        .any(|(pixel, &b)| b && pixel.iter().any(|&v| v != 0.0))
    {
        return samples;
    }
    let mut owned = samples.into_owned();
    for (pixel, _) in owned
        .chunks_exact_mut(channels)
        .zip(beyond)
        .filter(|(_, &b)| b)
    {
        pixel.fill(0.0);
    }
    Cow::Owned(owned)
}

/// The mean of `samples` over the `beyond` pixels and over the object's (the `mask` at ½ or
/// more), all channels together, as (sum, count) pairs that add across views: a rendered capture's
/// background mean is 0, a photograph's is often as bright as its object. Zero counts where the
/// sizes disagree.
pub fn background_and_object_sums(
    samples: &[f32],
    mask: &[f32],
    beyond: &[bool],
) -> [(f64, usize); 2] {
    let mut sums = [(0.0, 0); 2];
    let Some(channels) = channels_of(samples, beyond) else {
        return sums;
    };
    for ((pixel, &m), &b) in samples.chunks_exact(channels).zip(mask).zip(beyond) {
        let which = match (b, m >= 0.5) {
            (true, _) => 0,
            (false, true) => 1,
            (false, false) => continue,
        };
        sums[which].0 += pixel.iter().map(|&v| f64::from(v)).sum::<f64>();
        sums[which].1 += channels;
    }
    sums
}

/// Samples per pixel, when `samples` is a whole number of them for the `beyond` pixels (a
/// loaded capture's images and masks always agree).
fn channels_of(samples: &[f32], beyond: &[bool]) -> Option<usize> {
    let agree = !beyond.is_empty() && samples.len().is_multiple_of(beyond.len());
    debug_assert!(
        agree,
        "{} samples for {} pixels",
        samples.len(),
        beyond.len()
    );
    agree.then(|| samples.len() / beyond.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 9 × 7 mask with a 3 × 3 object at columns 3–5, rows 2–4.
    fn square() -> (Vec<f32>, usize, usize) {
        let (w, h) = (9, 7);
        let mask = (0..w * h)
            .map(|p| {
                f32::from(u8::from(
                    (3..6).contains(&(p % w)) && (2..5).contains(&(p / w)),
                ))
            })
            .collect();
        (mask, w, h)
    }

    #[test]
    fn a_background_is_dark_up_to_a_twentieth_of_the_object() {
        let (mask, w, h) = square();
        // The object at 0.8; everything else at `level` × 0.8, in two channels.
        let view = |level: f32| -> Vec<f32> {
            mask.iter()
                .flat_map(|&m| [if m >= 0.5 { 0.8 } else { level * 0.8 }; 2])
                .collect()
        };
        assert!(is_dark_background(&view(0.0), &mask, w, h));
        assert!(is_dark_background(&view(0.04), &mask, w, h));
        assert!(!is_dark_background(&view(0.06), &mask, w, h));
        assert!(!is_dark_background(&view(1.0), &mask, w, h));
        // An object filling the view leaves nothing to measure, nor does an empty mask.
        let full = vec![1.0; w * h];
        assert!(is_dark_background(&vec![0.5; w * h], &full, w, h));
        assert!(is_dark_background(
            &vec![0.5; w * h],
            &vec![0.0; w * h],
            w,
            h
        ));
    }

    #[test]
    fn the_margin_keeps_the_pixels_near_the_object() {
        let (mask, w, h) = square();
        let beyond = beyond_mask(&mask, w, h, 1);
        // Columns 2–6 and rows 1–5 are within one pixel of the object; the rest is beyond.
        for (p, &b) in beyond.iter().enumerate() {
            let (x, y) = (p % w, p / w);
            let near = (2..7).contains(&x) && (1..6).contains(&y);
            assert_eq!(b, !near, "pixel ({x}, {y})");
        }
        assert!(beyond_mask(&mask, w, h, 9).iter().all(|&b| !b));
        assert!(beyond_mask(&[1.0; 63], w, h, 0).iter().all(|&b| !b));
    }

    #[test]
    fn a_cluttered_background_is_blackened_and_the_object_kept() {
        let (mask, w, h) = square();
        let beyond = beyond_mask(&mask, w, h, 2);
        let photo: Vec<f32> = (0..w * h * 3).map(|i| 0.1 + i as f32).collect();
        let target = black_beyond(Cow::Borrowed(&photo), &beyond);
        assert!(matches!(target, Cow::Owned(_)));
        for p in 0..w * h {
            let expected = if beyond[p] {
                [0.0; 3]
            } else {
                [
                    0.1 + 3.0 * p as f32,
                    1.1 + 3.0 * p as f32,
                    2.1 + 3.0 * p as f32,
                ]
            };
            assert_eq!(&target[3 * p..3 * p + 3], &expected, "pixel {p}");
        }
        let [background, object] = background_and_object_sums(&target, &mask, &beyond);
        assert_eq!(background, (0.0, 3 * (w * h - 7 * 7)));
        assert_eq!(object.1, 27);
        // The object's pixels 21–23, 30–32, 39–41: mean of 3p + 1.1 over them.
        let mean = object.0 / object.1 as f64;
        assert!((mean - (3.0 * 31.0 + 1.1)).abs() < 1e-4, "{mean}");
    }

    #[test]
    fn a_black_background_is_borrowed_untouched() {
        let (mask, w, h) = square();
        let beyond = beyond_mask(&mask, w, h, 0);
        let rendered: Vec<f32> = mask.iter().map(|&m| 0.25 * m).collect();
        let target = black_beyond(Cow::Borrowed(&rendered), &beyond);
        assert!(matches!(target, Cow::Borrowed(_)));
        assert_eq!(target.as_ptr(), rendered.as_ptr());
        let [background, _] = background_and_object_sums(&rendered, &mask, &beyond);
        assert_eq!(background.0, 0.0);
    }
}

//! The band around a mask's edge where the mask loss does not insist.
//!
//! A real mask is off by a pixel or two along the object's contour (a matting network, a
//! threshold, a dilated hand-drawn mask), and the mask loss then pulls the silhouette to the
//! wrong place against the photometric loss, which sees the true one. Within `band_px` pixels of
//! the edge (Chebyshev distance, either side, the mask binarized at ½) the mask loss weighs a
//! pixel 0, everywhere else 1; the photometric loss still fits every pixel, so the silhouette
//! follows the images there.
//!
//! Threading: single-threaded separable passes (a run computes it once per view).

/// The mask loss's weight of each pixel of a `width × height` `mask`: 0 within `band_px` of its
/// edge, 1 elsewhere (all 1 for `band_px` 0 or a mask without an edge).
pub fn mask_loss_weights(mask: &[f32], width: usize, height: usize, band_px: u32) -> Vec<f32> {
    assert_eq!(
        mask.len(),
        width * height,
        "mask_loss_weights: the mask is not {width}×{height}"
    );
    let object: Vec<bool> = mask.iter().map(|&m| m >= 0.5).collect();
    let radius = band_px as usize;
    // A pixel is in the band when its (2r+1)² window holds both object and background.
    let any_object = window_any(&object, width, height, radius);
    let background: Vec<bool> = object.iter().map(|&o| !o).collect();
    let any_background = window_any(&background, width, height, radius);
    any_object
        .iter()
        .zip(&any_background)
        .map(|(&o, &b)| if o && b { 0.0 } else { 1.0 })
        .collect()
}

/// Whether any pixel of each pixel's `(2 radius + 1)²` window (clipped to the image) is set.
pub(crate) fn window_any(set: &[bool], width: usize, height: usize, radius: usize) -> Vec<bool> {
    let rows = pass(set, width, height, radius, 1, width);
    pass(&rows, height, width, radius, width, 1)
}

/// One direction of [`window_any`]: along lines of `length` samples `step` apart, `count` lines
/// starting `stride` apart.
fn pass(
    set: &[bool],
    length: usize,
    count: usize,
    radius: usize,
    step: usize,
    stride: usize,
) -> Vec<bool> {
    let mut out = vec![false; set.len()];
    for line in 0..count {
        let at = |i: usize| line * stride + i * step;
        // Index of the last set sample at or before i, for a running window test.
        let mut last_set: Option<usize> = None;
        let mut next_set = (0..length).find(|&i| set[at(i)]);
        for i in 0..length {
            if set[at(i)] {
                last_set = Some(i);
            }
            if next_set.is_some_and(|n| n < i) {
                next_set = (i..length).find(|&j| set[at(j)]);
            }
            let before = last_set.is_some_and(|j| i - j <= radius);
            let after = next_set.is_some_and(|j| j - i <= radius);
            out[at(i)] = before || after;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The weights by brute force: a pixel's window searched directly.
    fn brute_force(mask: &[f32], width: usize, height: usize, r: usize) -> Vec<f32> {
        (0..width * height)
            .map(|p| {
                let (x, y) = (p % width, p / width);
                let (mut object, mut background) = (false, false);
                for yy in y.saturating_sub(r)..(y + r + 1).min(height) {
                    for xx in x.saturating_sub(r)..(x + r + 1).min(width) {
                        if mask[yy * width + xx] >= 0.5 {
                            object = true;
                        } else {
                            background = true;
                        }
                    }
                }
                if object && background {
                    0.0
                } else {
                    1.0
                }
            })
            .collect()
    }

    #[test]
    fn matches_a_direct_window_search_on_random_masks() {
        let mut state = 12_345_u64;
        let mut random = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            (state >> 33) as f32 / (1u64 << 31) as f32
        };
        for (width, height) in [(17, 11), (1, 9), (8, 1), (23, 23)] {
            let mask: Vec<f32> = (0..width * height).map(|_| random()).collect();
            for r in 0..4 {
                assert_eq!(
                    mask_loss_weights(&mask, width, height, r as u32),
                    brute_force(&mask, width, height, r),
                    "{width}×{height}, band {r}"
                );
            }
        }
    }

    #[test]
    fn a_disc_gets_a_ring_of_the_band_s_width() {
        let size = 40;
        let mask: Vec<f32> = (0..size * size)
            .map(|p| {
                let (x, y) = ((p % size) as f64 - 19.5, (p / size) as f64 - 19.5);
                f32::from(u8::from(x.hypot(y) < 12.0))
            })
            .collect();
        let weights = mask_loss_weights(&mask, size, size, 2);
        // The centre and the corners are outside the band, the contour inside it.
        assert_eq!(weights[20 * size + 20], 1.0);
        assert_eq!(weights[0], 1.0);
        assert_eq!(weights[20 * size + 8], 0.0); // x = 8: 11.5 from the centre, object
        assert_eq!(weights[20 * size + 6], 0.0); // x = 6: 13.5, background within 2 px
        assert_eq!(weights[20 * size + 4], 1.0); // x = 4: 15.5, background beyond the band
        assert!(mask_loss_weights(&mask, size, size, 0)
            .iter()
            .all(|&w| w == 1.0));
    }
}

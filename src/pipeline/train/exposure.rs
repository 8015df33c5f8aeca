//! Exposure normalization: a run fits its views divided by one *radiance scale* per capture, so
//! that the same object photographed brighter or darker trains the same way.
//!
//! Without it a run's balance depends on the capture's exposure: the photometric gradients on the
//! geometry grow with the image's brightness while the regularizers' do not, densification
//! compares those gradients with a fixed threshold, SSIM's stabilizing constants and the light's
//! activation (a sigmoid below 0.5) are in absolute units, and the light starts at a fixed 0.5.
//! Measured: the synthetic creature's full-Stokes views divided by 2.92 (what a raw camera's
//! sensor units did to them) trained to 8.67° normal error instead of 5.88°.
//!
//! The scale is the capture's [`radiance_level`] (a bright percentile of S0 over the objects of
//! the training views) over [`REFERENCE_LEVEL`]. Each view's samples are multiplied by its
//! inverse as the run reads them ([`ViewTarget::gain`]; nothing is copied); the run's light is in
//! units of the scale, and the model's light is saved back in the capture's units
//! (`capture = scale × run`). Dividing by a power of two is exact, so a capture scaled by one
//! trains to the same surfels bit for bit.

use crate::core::envmap::{CubeMap, EnvMapError};
use crate::core::step::ViewTarget;

/// The percentile of the object's S0 that sets the level: bright enough to follow the
/// exposure's highlights, below the few pixels that clip or catch a light source.
pub const LEVEL_PERCENTILE: f64 = 0.999;

/// The level a run's views are scaled to. It is the level of the Mitsuba captures the defaults
/// were set on (2.40, 2.13 and 1.81: the knot, the sphere and the homer figure), so that their
/// runs train at about the exposure they were tuned at.
pub const REFERENCE_LEVEL: f64 = 2.0;

/// The [`LEVEL_PERCENTILE`] of the captured S0 inside the masks of `targets` (each pixel's
/// brightest channel, before any gain; a view behind a polarizer counts twice its intensity, its
/// S0 if unpolarized), or `None` when no masked pixel is positive and finite.
pub fn radiance_level(targets: &[ViewTarget]) -> Option<f64> {
    let mut values: Vec<f32> = targets
        .iter()
        .flat_map(|t| {
            let gain = if t.polarizer.is_some() { 2.0 } else { 1.0 };
            t.photometric
                .chunks_exact(3)
                .zip(t.mask.iter())
                .filter(|(_, &m)| m > 0.5)
                .map(move |(rgb, _)| gain * rgb[0].max(rgb[1]).max(rgb[2]))
        })
        .filter(|v| v.is_finite() && *v > 0.0)
        .collect();
    if values.is_empty() {
        return None;
    }
    let rank = ((values.len() - 1) as f64 * LEVEL_PERCENTILE).round() as usize;
    let (_, level, _) = values.select_nth_unstable_by(rank, f32::total_cmp);
    Some(f64::from(*level))
}

/// The capture's radiance per unit of the run's: [`radiance_level`] / [`REFERENCE_LEVEL`], or 1
/// (the capture's own units) when the views hold no light to measure.
pub fn radiance_scale(targets: &[ViewTarget]) -> f64 {
    radiance_level(targets).map_or(1.0, |level| level / REFERENCE_LEVEL)
}

/// Sets every target's [`ViewTarget::gain`] to `1 / scale`: the run fits its photometric and
/// Stokes samples divided by `scale` (the samples themselves, borrowed or not, are not copied).
pub fn normalize(targets: &mut [ViewTarget], scale: f64) {
    let gain = (1.0 / scale) as f32;
    for target in targets {
        target.gain = gain;
    }
}

/// The run's learned light `envmap` in the capture's units (its radiance times `scale`), as the
/// model folder holds it.
pub fn in_capture_units(envmap: &CubeMap, scale: f64) -> Result<CubeMap, EnvMapError> {
    if scale == 1.0 {
        return Ok(envmap.clone());
    }
    let radiance: Vec<f64> = envmap.radiance().iter().map(|r| r * scale).collect();
    CubeMap::from_radiance(envmap.size, &radiance)
}

#[cfg(test)]
mod tests {
    use std::borrow::Cow;

    use super::*;
    use crate::core::step::Polarizer;

    fn target(
        photometric: Vec<f32>,
        mask: Vec<f32>,
        polarizer: Option<Polarizer>,
    ) -> ViewTarget<'static> {
        let stokes = Some((
            Cow::Owned(photometric.clone()),
            Cow::Owned(photometric.clone()),
        ));
        ViewTarget {
            view: 0,
            photometric: Cow::Owned(photometric),
            stokes,
            polarizer,
            mask: Cow::Owned(mask),
            gain: 1.0,
            polarization_confidence: None,
            mask_weight: None,
        }
    }

    /// 2,000 object pixels whose brightest channels are 0.001, 0.002, ..., 2.0, and a bright
    /// background that the mask leaves out.
    fn ramp() -> ViewTarget<'static> {
        let mut photometric = Vec::new();
        let mut mask = Vec::new();
        for i in 1..=2000 {
            let v = i as f32 * 0.001;
            photometric.extend([0.5 * v, v, 0.25 * v]);
            mask.push(1.0);
        }
        photometric.extend([50.0; 30]);
        mask.extend([0.0; 10]);
        target(photometric, mask, None)
    }

    #[test]
    fn the_level_is_a_bright_percentile_of_the_objects_brightest_channel() {
        // Rank round(1999 × 0.999) = 1997 of 0.001..2.0: 1.998. The background (50) is outside
        // the mask.
        let level = radiance_level(&[ramp()]).unwrap();
        assert!((level - 1.998).abs() < 1e-6, "{level}");
        // Behind a polarizer the image is about half of S0, so it counts twice.
        let mut polarized = ramp();
        polarized.polarizer = Some(Polarizer::Fixed(0.0));
        let level = radiance_level(&[polarized]).unwrap();
        assert!((level - 3.996).abs() < 1e-5, "{level}");
        // No light: the capture's own units.
        let dark = target(vec![0.0; 6], vec![1.0; 2], None);
        assert_eq!(radiance_level(std::slice::from_ref(&dark)), None);
        assert_eq!(radiance_scale(&[dark]), 1.0);
    }

    #[test]
    fn a_capture_scaled_by_a_power_of_two_is_fitted_to_the_same_bits() {
        let bright = ramp();
        let mut dark = ramp();
        for samples in [&mut dark.photometric, &mut dark.stokes.as_mut().unwrap().0] {
            samples.to_mut().iter_mut().for_each(|v| *v *= 0.125);
        }
        let scales = [
            radiance_scale(std::slice::from_ref(&bright)),
            radiance_scale(std::slice::from_ref(&dark)),
        ];
        assert_eq!(scales[1], scales[0] * 0.125);
        let (mut a, mut b) = ([bright], [dark]);
        normalize(&mut a, scales[0]);
        normalize(&mut b, scales[1]);
        let fitted = |t: &ViewTarget| {
            let (s1, _) = t.stokes.as_ref().unwrap();
            (t.fitted(&t.photometric), t.fitted(s1))
        };
        assert_eq!(fitted(&a[0]), fitted(&b[0]));
        // Fitted at the reference level: the brightest channel of the 1,998th pixel.
        let (photometric, _) = fitted(&a[0]);
        let level = photometric[3 * 1997 + 1];
        assert!((level - REFERENCE_LEVEL).abs() < 1e-6, "{level}");
    }

    #[test]
    fn normalizing_copies_no_samples() {
        let captured = vec![1.0f32, 2.0, 4.0];
        let mut targets = [ViewTarget {
            view: 0,
            photometric: Cow::Borrowed(&captured),
            stokes: None,
            polarizer: None,
            mask: Cow::Owned(vec![1.0]),
            gain: 1.0,
            polarization_confidence: None,
            mask_weight: None,
        }];
        normalize(&mut targets, 2.0);
        assert!(matches!(targets[0].photometric, Cow::Borrowed(_)));
        assert_eq!(targets[0].fitted(&targets[0].photometric), [0.5, 1.0, 2.0]);
    }
}

//! The 8-bit previews of Stokes images, one definition for both sides of the comparison a
//! viewer shows: the model's renders (`renders/{kind}/NNN.png`) and the captured test views
//! (`captured/{kind}/NNN.png`, written by [`write_captured_previews`]). S0 is sRGB-encoded; DoLP
//! is shown as it is, in [0, 1]; AoLP is mapped from [0, π) to [0, 1]. A captured view is shown
//! through its mask, as a render is through its opacity.

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::core::shading;
use crate::formats::image_io::{self, Image, ImageError};
use crate::io::capture::{Capture, Measurement, View};

/// The captured kinds a viewer compares with the renders.
pub const CAPTURED_KINDS: [&str; 3] = ["s0", "dolp", "aolp"];

/// The folder of the captured previews among a job's artifacts.
pub const CAPTURED_DIR: &str = "captured";

/// AoLP in radians as a preview value: [0, π) mapped to [0, 1].
pub fn aolp_preview(aolp: f32) -> f32 {
    aolp.rem_euclid(std::f32::consts::PI) / std::f32::consts::PI
}

/// DoLP and AoLP of each pixel of a Stokes view, from the sums of its colour channels.
pub fn dolp_aolp(s0: &[f64], s1: &[f64], s2: &[f64]) -> (Vec<f64>, Vec<f64>) {
    s0.par_iter()
        .zip(s1)
        .zip(s2)
        .map(|((&a, &b), &c)| (shading::dolp(a, b, c), shading::aolp(b, c)))
        .unzip()
}

/// The previews of one captured view (`None` for DoLP and AoLP of a view without full Stokes),
/// each with whether it is to be sRGB-encoded.
fn captured_view_previews(view: &View) -> Vec<(&'static str, Option<(Image, bool)>)> {
    let mask = &view.mask;
    let masked = |image: &Image| Image {
        data: image
            .data
            .iter()
            .enumerate()
            .map(|(i, &v)| v * mask.data.get(i / image.channels).copied().unwrap_or(1.0))
            .collect(),
        ..image.clone()
    };
    let summed = |image: &Image| -> Vec<f64> {
        image
            .data
            .chunks_exact(image.channels)
            .map(|p| p.iter().map(|&v| f64::from(v)).sum())
            .collect()
    };
    let grey = |like: &Image, values: Vec<f64>| Image {
        width: like.width,
        height: like.height,
        channels: 1,
        data: values.into_iter().map(|v| v as f32).collect(),
    };
    match &view.measurement {
        Measurement::Stokes { s0, s1, s2 } => {
            let (dolp, aolp) = dolp_aolp(&summed(s0), &summed(s1), &summed(s2));
            let aolp = aolp.into_iter().map(|v| f64::from(aolp_preview(v as f32)));
            vec![
                ("s0", Some((masked(s0), true))),
                ("dolp", Some((masked(&grey(s0, dolp)), false))),
                ("aolp", Some((masked(&grey(s0, aolp.collect())), false))),
            ]
        }
        Measurement::Rgb { image } | Measurement::Polarizer { image, .. } => vec![
            ("s0", Some((masked(image), true))),
            ("dolp", None),
            ("aolp", None),
        ],
    }
}

/// Writes `OUT/{s0,dolp,aolp}/NNN.png` for the capture's test views, numbered as the renders of
/// its test cameras are (DoLP and AoLP only for views with full Stokes). Returns the files.
pub fn write_captured_previews(capture: &Capture, out: &Path) -> Result<Vec<PathBuf>, ImageError> {
    let _span = tracing::info_span!("captured_previews").entered();
    let mut written = Vec::new();
    for (index, view) in capture.test_views().enumerate() {
        for (kind, preview) in captured_view_previews(view) {
            let Some((image, srgb)) = preview else {
                continue;
            };
            let dir = out.join(kind);
            std::fs::create_dir_all(&dir).map_err(|source| ImageError::Io {
                path: dir.clone(),
                source,
            })?;
            let path = dir.join(format!("{index:03}.png"));
            image_io::write_png(&path, &image, srgb)?;
            written.push(path);
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aolp_previews_wrap_half_turns_into_the_unit_interval() {
        use std::f32::consts::PI;
        for (angle, expected) in [(0.0, 0.0), (PI / 2.0, 0.5), (-PI / 4.0, 0.75), (PI, 0.0)] {
            assert!((aolp_preview(angle) - expected).abs() < 1e-6, "{angle}");
        }
    }

    #[test]
    fn captured_previews_follow_the_views_and_their_masks() {
        let dir = tempfile::tempdir().unwrap();
        let options = crate::pipeline::synth::SynthOptions {
            views: 9,
            size: 16,
            ..Default::default()
        };
        crate::pipeline::synth::synth(dir.path(), &options).unwrap();
        let capture = crate::io::capture::load(dir.path()).unwrap();
        let out = dir.path().join("previews");
        let written = write_captured_previews(&capture, &out).unwrap();
        let tests = capture.test_views().count();
        assert_eq!(written.len(), 3 * tests);
        let view = capture.test_views().next().unwrap();
        let (s0, _) = image_io::read_image(&out.join("s0/000.png")).unwrap();
        let Measurement::Stokes { s0: captured, .. } = &view.measurement else {
            panic!("synth writes full Stokes");
        };
        for p in 0..s0.num_pixels() {
            let expected = captured.data[3 * p] * view.mask.data[p];
            let encoded = image_io::linear_to_srgb(expected).clamp(0.0, 1.0);
            assert!(
                (s0.data[3 * p] - encoded).abs() <= 0.5 / 255.0 + 1e-6,
                "pixel {p}"
            );
        }
        let (dolp, _) = image_io::read_image(&out.join("dolp/000.png")).unwrap();
        let outside = (0..dolp.num_pixels()).find(|&p| view.mask.data[p] == 0.0);
        assert_eq!(dolp.data[outside.expect("background pixels")], 0.0);
    }
}

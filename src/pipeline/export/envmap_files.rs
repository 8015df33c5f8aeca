//! The learned environment map as files for other tools, beside the lat-long OpenEXR the model
//! folder already holds (`envmap.exr`): Radiance HDR (`envmap.hdr`, RGBE: 8-bit mantissas with a
//! shared exponent, about 1% precision, read by nearly every renderer and image viewer) and an
//! 8-bit preview (`envmap.png`).
//!
//! The preview is tone-mapped with Reinhard et al.'s global operator (2002): the radiance is scaled
//! so that its log-average luminance becomes the key 0.18 (the log-average weighted by each lat-long
//! row's solid angle, sin θ, so the stretched poles do not count more than the horizon), luminance L
//! is compressed to L / (1 + L) with the colour's hue and saturation kept, and the result is
//! sRGB-encoded. Any overall scale of the radiance gives the same preview; the sun or a lamp stays
//! below white, never clipped flat.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use crate::formats::image_io::{self, Image, ImageError};

/// Radiance HDR copy of the environment map.
pub const ENVMAP_HDR_FILE: &str = "envmap.hdr";
/// Tone-mapped preview of the environment map.
pub const ENVMAP_PNG_FILE: &str = "envmap.png";
/// The log-average luminance the preview maps to (Reinhard's "key" of a middle-grey scene).
pub const PREVIEW_KEY: f64 = 0.18;

/// Rec. 709 luminance of linear RGB.
fn luminance(rgb: [f64; 3]) -> f64 {
    0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
}

/// RGB radiance of pixel `p` with non-finite and negative values as 0.
fn radiance(img: &Image, p: usize) -> [f64; 3] {
    let clean = |v: f32| {
        if v.is_finite() {
            f64::from(v).max(0.0)
        } else {
            0.0
        }
    };
    let s = &img.data[p * 3..p * 3 + 3];
    [clean(s[0]), clean(s[1]), clean(s[2])]
}

/// Writes a lat-long (or any) image as Radiance HDR (RGBE, run-length encoded). Channels other than
/// RGB are converted ([`Image::to_rgb`]); non-finite and negative values are written as 0.
pub fn write_hdr(path: &Path, img: &Image) -> Result<(), ImageError> {
    let encode = |message: String| ImageError::Encode {
        path: path.to_owned(),
        message,
    };
    let rgb = img.to_rgb();
    let pixels: Vec<image::Rgb<f32>> = (0..rgb.num_pixels())
        .map(|p| image::Rgb(radiance(&rgb, p).map(|v| v as f32)))
        .collect();
    let file = std::fs::File::create(path).map_err(|source| ImageError::Io {
        path: path.to_owned(),
        source,
    })?;
    let mut out = std::io::BufWriter::new(file);
    image::codecs::hdr::HdrEncoder::new(&mut out)
        .encode(&pixels, rgb.width, rgb.height)
        .map_err(|e| encode(e.to_string()))?;
    std::io::Write::flush(&mut out).map_err(|e| encode(e.to_string()))
}

/// The exposure that maps the log-average luminance of lat-long `img` (rows weighted by sin θ,
/// θ = π i / (H − 1) as phygap's lat-long maps are sampled) to [`PREVIEW_KEY`]; 1 for a black map.
pub fn preview_exposure(img: &Image) -> f64 {
    let rgb = img.to_rgb();
    let (mut sum, mut weight) = (0.0, 0.0);
    for y in 0..rgb.height {
        let theta = if rgb.height > 1 {
            PI * y as f64 / (rgb.height - 1) as f64
        } else {
            0.5 * PI
        };
        // The pole rows still count a little (a quarter row's worth of solid angle).
        let w = theta.sin().max(0.25 * PI / rgb.height.max(1) as f64);
        for x in 0..rgb.width {
            let l = luminance(radiance(&rgb, y * rgb.width + x));
            sum += w * (1e-6 + l).ln();
            weight += w;
        }
    }
    if weight <= 0.0 {
        return 1.0;
    }
    let log_average = (sum / weight).exp();
    if log_average <= 2e-6 {
        1.0
    } else {
        PREVIEW_KEY / log_average
    }
}

/// The preview's linear display values in [0, 1] (before sRGB encoding): Reinhard's global
/// operator on luminance at [`preview_exposure`], hue kept, channels clamped.
pub fn tone_mapped(img: &Image) -> Image {
    let rgb = img.to_rgb();
    let exposure = preview_exposure(&rgb);
    let mut out = Image::filled(rgb.width, rgb.height, 3, 0.0);
    for p in 0..rgb.num_pixels() {
        let scaled = radiance(&rgb, p).map(|v| v * exposure);
        let l = luminance(scaled);
        let factor = 1.0 / (1.0 + l);
        for (o, v) in out.data[p * 3..p * 3 + 3].iter_mut().zip(scaled) {
            *o = (v * factor).clamp(0.0, 1.0) as f32;
        }
    }
    out
}

/// Writes the tone-mapped preview of `img` as an 8-bit sRGB PNG of the same size.
pub fn write_preview_png(path: &Path, img: &Image) -> Result<(), ImageError> {
    image_io::write_png(path, &tone_mapped(img), true)
}

/// Writes `envmap.hdr` and `envmap.png` of lat-long `latlong` into `dir`; returns their paths.
pub fn write_envmap_files(dir: &Path, latlong: &Image) -> Result<Vec<PathBuf>, ImageError> {
    let _span = tracing::info_span!("envmap_files", width = latlong.width).entered();
    let hdr = dir.join(ENVMAP_HDR_FILE);
    write_hdr(&hdr, latlong)?;
    let png = dir.join(ENVMAP_PNG_FILE);
    write_preview_png(&png, latlong)?;
    Ok(vec![hdr, png])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 64 × 32 lat-long sky: a blue-to-white gradient over five decades, a sun of 2000 near
    /// the top, a dark ground.
    fn sky() -> Image {
        Image::from_fn(64, 32, 3, |x, y, out| {
            let t = y as f32 / 31.0;
            let sky = 10f32.powf(2.0 - 5.0 * t);
            out.copy_from_slice(&[0.6 * sky, 0.8 * sky, sky * (1.0 + 0.01 * x as f32)]);
            if (10..13).contains(&x) && (3..5).contains(&y) {
                out.copy_from_slice(&[2000.0, 1900.0, 1700.0]);
            }
        })
    }

    #[test]
    fn hdr_round_trips_within_rgbe_precision() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(ENVMAP_HDR_FILE);
        let img = sky();
        write_hdr(&path, &img).unwrap();
        let read = image::open(&path).unwrap().to_rgb32f();
        assert_eq!(read.dimensions(), (64, 32));
        let (back, format) = image_io::read_image(&path).unwrap();
        assert_eq!(format, image_io::ImageFormat::Hdr);
        assert_eq!(back.data, read.into_raw());
        let mut worst = 0.0f64;
        for p in 0..img.num_pixels() {
            let a = radiance(&img, p);
            let b = radiance(&back, p);
            // RGBE shares one exponent per pixel: each channel is exact to 1/256 of the largest.
            let largest = a.iter().copied().fold(0.0, f64::max);
            for c in 0..3 {
                worst = worst.max((a[c] - b[c]).abs() / largest);
            }
        }
        println!("HDR round trip: worst error {worst:.2e} of the pixel's largest channel");
        assert!(worst < 0.01, "{worst}");
        // Negative and non-finite radiance is written as black, not as garbage.
        let mut broken = Image::filled(4, 2, 3, 1.0);
        broken.data[0] = -3.0;
        broken.data[4] = f32::NAN;
        write_hdr(&path, &broken).unwrap();
        let (back, _) = image_io::read_image(&path).unwrap();
        assert_eq!((back.data[0], back.data[4], back.data[5]), (0.0, 0.0, 1.0));
    }

    #[test]
    fn the_png_preview_has_the_maps_size_and_its_structure() {
        let dir = tempfile::tempdir().unwrap();
        let img = sky();
        let written = write_envmap_files(dir.path(), &img).unwrap();
        assert_eq!(written[1], dir.path().join(ENVMAP_PNG_FILE));
        let png = image::open(&written[1]).unwrap().to_rgb8();
        assert_eq!(png.dimensions(), (64, 32));
        let levels: std::collections::BTreeSet<[u8; 3]> = png.pixels().map(|p| p.0).collect();
        assert!(levels.len() > 32, "not constant: {} colours", levels.len());
        // The sun is the brightest and still below white; the sky darkens towards the ground.
        let grey = |x: u32, y: u32| {
            png.get_pixel(x, y)
                .0
                .iter()
                .map(|&v| u32::from(v))
                .sum::<u32>()
        };
        assert!(
            grey(11, 3) > grey(40, 3) && grey(11, 3) < 3 * 255,
            "{}",
            grey(11, 3)
        );
        assert!((1..32).all(|y| grey(40, y) <= grey(40, y - 1)));
        assert!(grey(40, 31) < grey(40, 16) && grey(40, 16) < grey(40, 0));
        // Blue stays bluer than red (hue kept).
        let p = png.get_pixel(40, 16).0;
        assert!(p[2] > p[0], "{p:?}");
        // Exposure normalizes the scale away: 100× the radiance, the same preview.
        let brighter = Image {
            data: img.data.iter().map(|v| v * 100.0).collect(),
            ..img.clone()
        };
        let a = tone_mapped(&img);
        let b = tone_mapped(&brighter);
        let diff = a
            .data
            .iter()
            .zip(&b.data)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f32::max);
        assert!(diff < 1e-3, "{diff}");
        // A black map is black, not NaN.
        let black = tone_mapped(&Image::filled(8, 4, 3, 0.0));
        assert!(black.data.iter().all(|&v| v == 0.0));
    }
}

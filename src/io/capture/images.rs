//! Loading the images of one frame into a [`View`]: size, channel-count and finiteness checks,
//! sRGB → linear decoding, polarizer images → Stokes, the image_y_down → image_y_up conversion,
//! and the mask (mask file, else alpha channel, else the whole image).
//!
//! Called once per frame from a rayon parallel iterator; each call is independent.

use crate::formats::image_io::{
    read_header, read_image_within, srgb_to_linear, Image, ImageError, ImageFormat, ImageLimits,
};

use super::error::Problem;
use super::frame::{ColorSpace, FrameSpec, Header, KeyedPath, Source, StokesConvention};
use super::{Measurement, View};

/// A loaded view and the warnings it raised.
pub(crate) struct LoadedView {
    pub view: View,
    /// True when the frame has neither a mask file nor an alpha channel.
    pub whole_image_mask: bool,
    /// The fraction of a raw frame's samples at the sensor's maximum (clipped highlights); 0 for
    /// other frames.
    pub clipped_fraction: f64,
}

/// Mask files store 8-bit values; > 127 is object.
const MASK_THRESHOLD: f32 = 127.5 / 255.0;

/// Loads and checks every image of `spec` (a frame of images: [`super::raw`] loads raw mosaic
/// frames); returns every problem found.
pub(crate) fn load_view(spec: &FrameSpec, header: &Header) -> Result<LoadedView, Vec<Problem>> {
    let mut problems = Vec::new();
    let (width, height) = (spec.camera.width as usize, spec.camera.height as usize);
    let mut read = |file: &KeyedPath, allowed_channels: &[usize], what: &str| {
        read_checked(spec, header, file, (width, height), allowed_channels, what)
            .map_err(|p| problems.push(p))
            .ok()
    };
    let rgb = &[3, 4][..];
    let images: Vec<Option<Image>> = spec
        .source
        .files()
        .into_iter()
        .map(|f| read(f, rgb, "an RGB image"))
        .collect();
    let mask_file = spec
        .mask
        .as_ref()
        .map(|f| read(f, &[1, 2], "a single-channel (grey) mask"));
    let images: Option<Vec<Image>> = images.into_iter().collect();
    let (Some(images), Some(mask_file)) = (images, mask_file.map_or(Some(None), |m| m.map(Some)))
    else {
        return Err(problems);
    };

    let alpha = images
        .iter()
        .find(|i| i.channels == 4)
        .map(|i| i.channel(3));
    let whole_image_mask = mask_file.is_none() && alpha.is_none();
    let mask = match (mask_file, alpha) {
        (Some(file), _) => binarize(&file.channel(0)),
        (None, Some(alpha)) => clamp01(alpha),
        (None, None) => Image::filled(width, height, 1, 1.0),
    };
    let mut rgb: Vec<Image> = images.iter().map(Image::to_rgb).collect();
    let measurement = match &spec.source {
        Source::Stokes(_) => {
            let mut s2 = rgb.pop().expect("three Stokes images");
            let s1 = rgb.pop().expect("three Stokes images");
            let s0 = rgb.pop().expect("three Stokes images");
            if header.stokes_convention == StokesConvention::ImageYDown {
                s2.data.iter_mut().for_each(|v| *v = -*v);
            }
            Measurement::Stokes { s0, s1, s2 }
        }
        Source::Polarizer4(_) => {
            let [i0, i45, i90, i135]: [Image; 4] = rgb.try_into().expect("four polarizer images");
            // In image_y_down the 45° and 135° images trade places (CAPTURE_FORMAT.md §4).
            let (i45, i135) = match header.stokes_convention {
                StokesConvention::ImageYUp => (i45, i135),
                StokesConvention::ImageYDown => (i135, i45),
            };
            Measurement::Stokes {
                s0: combine(&i0, &i90, 1.0),
                s1: combine(&i0, &i90, -1.0),
                s2: combine(&i45, &i135, -1.0),
            }
        }
        Source::Partial { angle, .. } => Measurement::Polarizer {
            image: rgb.pop().expect("one image"),
            angle: angle.clone(),
        },
        Source::Rgb(_) => Measurement::Rgb {
            image: rgb.pop().expect("one image"),
        },
        Source::Raw(_) => unreachable!("raw frames are loaded by raw::load_view"),
    };
    Ok(LoadedView {
        view: View {
            name: spec.name.clone(),
            frame_index: spec.index,
            split: spec.split,
            camera: spec.camera,
            measurement,
            mask,
            ground_truth: spec.ground_truth.clone(),
        },
        whole_image_mask,
        clipped_fraction: 0.0,
    })
}

/// `a + sign · b`, pixel by pixel.
fn combine(a: &Image, b: &Image, sign: f32) -> Image {
    Image {
        data: a
            .data
            .iter()
            .zip(&b.data)
            .map(|(x, y)| x + sign * y)
            .collect(),
        ..a.clone()
    }
}

pub(super) fn binarize(mask: &Image) -> Image {
    Image {
        data: mask
            .data
            .iter()
            .map(|&v| if v > MASK_THRESHOLD { 1.0 } else { 0.0 })
            .collect(),
        ..mask.clone()
    }
}

fn clamp01(mut image: Image) -> Image {
    image.data.iter_mut().for_each(|v| *v = v.clamp(0.0, 1.0));
    image
}

/// Reads one file and checks it; colour channels of 8/16-bit images are linearized per `color_space`.
fn read_checked(
    spec: &FrameSpec,
    header: &Header,
    file: &KeyedPath,
    (width, height): (usize, usize),
    allowed_channels: &[usize],
    what: &str,
) -> Result<Image, Problem> {
    let problem = |message: String| Problem::new(spec.name.clone(), file.key, message);
    let shown = file.relative.display();
    let (mut image, format) = read_sized(file, &[(width, height)], |w, h| {
        format!("{shown} is {w}×{h} pixels but w×h is {width}×{height}")
    })
    .map_err(problem)?;
    if !allowed_channels.contains(&image.channels) {
        return Err(problem(format!(
            "{shown} has {} channel(s); expected {what} ({allowed_channels:?} channels)",
            image.channels
        )));
    }
    if let Some((x, y, c)) = image.first_non_finite() {
        let value = image.pixel(x, y)[c];
        return Err(problem(format!(
            "{shown} has a non-finite pixel value ({value}) at x = {x}, y = {y}, channel {c}"
        )));
    }
    let is_mask = allowed_channels.contains(&1);
    let srgb = match (format, header.color_space) {
        (ImageFormat::Exr | ImageFormat::Hdr, _) => false,
        (_, Some(ColorSpace::Linear)) => false,
        (_, Some(ColorSpace::Srgb)) | (_, None) => true,
    };
    if srgb && !is_mask {
        let colour_channels = image.channels.min(3);
        let channels = image.channels;
        for (i, v) in image.data.iter_mut().enumerate() {
            if i % channels < colour_channels {
                *v = srgb_to_linear(*v);
            }
        }
    }
    Ok(image)
}

/// Reads `file` once its header shows one of `sizes` (width, height); a file of another size is
/// the problem `mismatch` names, decided before any of its pixels is decoded. The message says
/// what is wrong with the file (a missing file is `missing file NAME`).
pub(super) fn read_sized(
    file: &KeyedPath,
    sizes: &[(usize, usize)],
    mismatch: impl FnOnce(usize, usize) -> String,
) -> Result<(Image, ImageFormat), String> {
    let describe = |e: ImageError| match e {
        ImageError::Io { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
            format!("missing file {}", file.relative.display())
        }
        other => other.to_string(),
    };
    let header = read_header(&file.path).map_err(describe)?;
    if !sizes.contains(&(header.width, header.height)) {
        return Err(mismatch(header.width, header.height));
    }
    read_image_within(
        &file.path,
        &ImageLimits::pixels(header.width, header.height),
    )
    .map_err(describe)
}

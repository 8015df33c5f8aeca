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
use super::npy;
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
    let read = |file: &KeyedPath, allowed_channels: &[usize], what: &str| {
        read_checked(spec, header, file, (width, height), allowed_channels, what)
    };
    let images: Vec<Result<Image, Problem>> = match stacked_stokes_file(&spec.source) {
        Some(file) => match read(file, STACKED_STOKES_CHANNELS, "Stokes components") {
            Ok(stack) => split_stokes(&stack).into_iter().map(Ok).collect(),
            Err(problem) => vec![Err(problem)],
        },
        None => spec
            .source
            .files()
            .into_iter()
            .map(|f| {
                let allowed: &[usize] = if is_npy(f) { &[1, 3, 4] } else { &[3, 4] };
                read(f, allowed, "an RGB image")
            })
            .collect(),
    };
    let images: Vec<Option<Image>> = images
        .into_iter()
        .map(|r| r.map_err(|p| problems.push(p)).ok())
        .collect();
    let mask_file = spec.mask.as_ref().map(|f| {
        read(f, MASK_CHANNELS, "a mask")
            .and_then(|image| {
                mask_from_file(&image, &f.relative.display().to_string())
                    .map_err(|message| Problem::new(spec.name.clone(), f.key, message))
            })
            .map_err(|p| problems.push(p))
            .ok()
    });
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
        (Some(file), _) => file,
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

/// Channel counts of one `.npy` file holding a view's Stokes components: S0, S1, S2 (and S3,
/// unused) of a grey image, or of an RGB image (components × RGB, 9 or 12 values a pixel).
const STACKED_STOKES_CHANNELS: &[usize] = &[3, 4, 9, 12];

fn is_npy(file: &KeyedPath) -> bool {
    file.path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"))
}

/// The file of a Stokes frame whose `s0_path`, `s1_path` and `s2_path` name one `.npy` file:
/// its components are stacked in its last axis.
fn stacked_stokes_file(source: &Source) -> Option<&KeyedPath> {
    match source {
        Source::Stokes([s0, s1, s2]) if is_npy(s0) && s0.path == s1.path && s0.path == s2.path => {
            Some(s0)
        }
        _ => None,
    }
}

/// S0, S1 and S2 as RGB images from a stacked-components image (3 or 4 grey components, or 3 or
/// 4 RGB ones).
fn split_stokes(stack: &Image) -> [Image; 3] {
    let per_component = if stack.channels >= 9 { 3 } else { 1 };
    std::array::from_fn(|k| {
        Image::from_fn(stack.width, stack.height, 3, |x, y, out| {
            let p = &stack.pixel(x, y)[k * per_component..(k + 1) * per_component];
            if per_component == 3 {
                out.copy_from_slice(p);
            } else {
                out.fill(p[0]);
            }
        })
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

/// The channel counts a mask file may have: grey, grey + alpha, RGB and RGBA.
pub(super) const MASK_CHANNELS: &[usize] = &[1, 2, 3, 4];

/// Colour channels of a mask that differ by more than this (in [0, 1]) are not grey.
const MASK_GREY_TOLERANCE: f32 = 1.5 / 255.0;

/// The binary object mask (1 = object) of a mask file, whichever of the common layouts it has:
/// one grey channel; three equal colour channels (the black/white RGB masks of IDR, NeuS and DTU
/// datasets); either with an alpha channel. With alpha, a mask whose colour is one value over the
/// whole image (a cutout) is its alpha; otherwise it is its grey value where alpha is opaque.
/// Colour channels that are not equal are an error naming the first pixel where they differ.
pub(super) fn mask_from_file(image: &Image, shown: &str) -> Result<Image, String> {
    let channels = image.channels;
    let colour_channels = match channels {
        1 | 2 => 1,
        3 | 4 => 3,
        n => {
            return Err(format!(
                "{shown} has {n} channel(s); expected a mask: grey, grey + alpha, RGB with equal \
                 channels, or RGBA"
            ))
        }
    };
    if colour_channels == 3 {
        for (p, px) in image.data.chunks_exact(channels).enumerate() {
            let spread = px[..3].iter().copied().fold(f32::MIN, f32::max)
                - px[..3].iter().copied().fold(f32::MAX, f32::min);
            if spread > MASK_GREY_TOLERANCE {
                return Err(format!(
                    "{shown} has 3 colour channels that are not equal (at x = {}, y = {}: R {:.3}, \
                     G {:.3}, B {:.3}); a mask is grey: one channel, or three equal ones \
                     (white = object)",
                    p % image.width,
                    p / image.width,
                    px[0],
                    px[1],
                    px[2]
                ));
            }
        }
    }
    let grey = image.channel(0);
    let has_alpha = channels == 2 || channels == 4;
    if !has_alpha {
        return Ok(binarize(&grey));
    }
    let alpha = image.channel(channels - 1);
    let first = grey.data.first().copied().unwrap_or(0.0);
    let uniform_colour = grey.data.iter().all(|&v| v == first);
    if uniform_colour {
        return Ok(binarize(&alpha));
    }
    let mut mask = binarize(&grey);
    for (m, &a) in mask.data.iter_mut().zip(&alpha.data) {
        if a <= MASK_THRESHOLD {
            *m = 0.0;
        }
    }
    Ok(mask)
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
    if is_npy(file) {
        return read_npy_image(file, sizes, mismatch);
    }
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

/// Channels an `.npy` image may have a pixel (Stokes components × RGB at most).
const MAX_NPY_CHANNELS: u64 = 12;

/// Reads an `.npy` array as an image: H × W (grey), H × W × C, H × W × K × 3 (components × RGB,
/// flattened to 3K channels) or C × H × W (channels first, C ≤ 4, as PyTorch code saves them).
/// Float arrays are linear values, like EXR; the shape is checked against `sizes` before the data
/// is read.
fn read_npy_image(
    file: &KeyedPath,
    sizes: &[(usize, usize)],
    mismatch: impl FnOnce(usize, usize) -> String,
) -> Result<(Image, ImageFormat), String> {
    let largest = sizes
        .iter()
        .map(|&(w, h)| (w * h) as u64)
        .max()
        .unwrap_or(0);
    let limits = npy::NpyLimits::image(largest, MAX_NPY_CHANNELS);
    let missing = |e: npy::NpyError| match e {
        npy::NpyError::Io { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
            format!("missing file {}", file.relative.display())
        }
        other => other.to_string(),
    };
    let header = npy::read_npy_header(&file.path, &limits).map_err(missing)?;
    let layout = npy_image_layout(&header.shape).ok_or_else(|| {
        format!(
            "{} has the shape {:?}; an image array is H×W, H×W×C, H×W×K×3 or C×H×W",
            file.relative.display(),
            header.shape
        )
    })?;
    if !sizes.contains(&(layout.width, layout.height)) {
        return Err(mismatch(layout.width, layout.height));
    }
    let array = npy::read_npy::<f32>(&file.path, &limits).map_err(missing)?;
    let (w, h, c) = (layout.width, layout.height, layout.channels);
    let data = if layout.channels_first {
        let plane = w * h;
        (0..plane * c)
            .map(|i| array.data[(i % c) * plane + i / c])
            .collect()
    } else {
        array.data
    };
    Ok((
        Image {
            width: w,
            height: h,
            channels: c,
            data,
        },
        // Float values, linear like EXR's.
        ImageFormat::Exr,
    ))
}

/// How an image array's axes map to width, height and channels.
struct NpyImageLayout {
    width: usize,
    height: usize,
    channels: usize,
    channels_first: bool,
}

/// The width and height of an image array of `shape` (see [`read_npy_image`]).
pub(crate) fn npy_image_size(shape: &[usize]) -> Option<(usize, usize)> {
    npy_image_layout(shape).map(|l| (l.width, l.height))
}

fn npy_image_layout(shape: &[usize]) -> Option<NpyImageLayout> {
    let layout = |height, width, channels, channels_first| {
        Some(NpyImageLayout {
            width,
            height,
            channels,
            channels_first,
        })
    };
    match *shape {
        [h, w] => layout(h, w, 1, false),
        [c, h, w] if c <= 4 && w > 4 => layout(h, w, c, true),
        [h, w, c] if (1..=MAX_NPY_CHANNELS as usize).contains(&c) => layout(h, w, c, false),
        [h, w, k, 3] if k <= 4 => layout(h, w, 3 * k, false),
        _ => None,
    }
}

//! Reading and writing images: OpenEXR (half or float, channels by name), Radiance HDR,
//! PNG (8/16 bit) and JPEG, into one interleaved f32 [`Image`] type; sRGB transfer functions.
//!
//! Decoding never guesses colour spaces: it reports the file's [`ImageFormat`] so the caller decides
//! (a capture's `color_space` key, CAPTURE_FORMAT.md §1). EXR channels are addressed by name
//! (`R`, `G`, `B`, `A`, or `Y`), never by storage order.
//!
//! Nothing is allocated from a size a file declares before that size is checked: every read goes
//! through [`read_image_within`], which reads the header first ([`read_header`]) and refuses a
//! file over its [`ImageLimits`] before a pixel is decoded (an EXR header can declare a
//! 100000 × 100000 window in a file of a few bytes).

use std::path::{Path, PathBuf};

use thiserror::Error;

/// An interleaved f32 image, row 0 on top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    /// Samples per pixel: 1 (Y), 2 (YA), 3 (RGB) or 4 (RGBA).
    pub channels: usize,
    /// `height × width × channels` samples.
    pub data: Vec<f32>,
}

impl Image {
    /// An image filled with `value`.
    pub fn filled(width: usize, height: usize, channels: usize, value: f32) -> Self {
        Image {
            width,
            height,
            channels,
            data: vec![value; width * height * channels],
        }
    }

    /// Builds an image from a per-pixel function returning `channels` values.
    pub fn from_fn(
        width: usize,
        height: usize,
        channels: usize,
        mut f: impl FnMut(usize, usize, &mut [f32]),
    ) -> Self {
        let mut img = Image::filled(width, height, channels, 0.0);
        for y in 0..height {
            for x in 0..width {
                let i = (y * width + x) * channels;
                f(x, y, &mut img.data[i..i + channels]);
            }
        }
        img
    }

    /// The samples of pixel (x, y).
    pub fn pixel(&self, x: usize, y: usize) -> &[f32] {
        let i = (y * self.width + x) * self.channels;
        &self.data[i..i + self.channels]
    }

    /// Number of pixels.
    pub fn num_pixels(&self) -> usize {
        self.width * self.height
    }

    /// The first three channels as RGB (a one- or two-channel image is broadcast to grey).
    pub fn to_rgb(&self) -> Image {
        if self.channels == 3 {
            return self.clone();
        }
        Image::from_fn(self.width, self.height, 3, |x, y, out| {
            let p = self.pixel(x, y);
            if self.channels >= 3 {
                out.copy_from_slice(&p[..3]);
            } else {
                out.fill(p[0]);
            }
        })
    }

    /// One channel as a single-channel image.
    pub fn channel(&self, c: usize) -> Image {
        Image::from_fn(self.width, self.height, 1, |x, y, out| {
            out[0] = self.pixel(x, y)[c]
        })
    }

    /// Index of the first non-finite sample, if any, as (x, y, channel).
    pub fn first_non_finite(&self) -> Option<(usize, usize, usize)> {
        let i = self.data.iter().position(|v| !v.is_finite())?;
        let p = i / self.channels;
        Some((p % self.width, p / self.width, i % self.channels))
    }
}

/// How a file stores its samples, which fixes its default colour space.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    Exr,
    Hdr,
    Png8,
    Png16,
    Jpeg,
}

impl ImageFormat {
    /// EXR and HDR hold linear radiance; PNG and JPEG are sRGB-encoded unless a capture says otherwise.
    pub fn is_linear_by_default(self) -> bool {
        matches!(self, ImageFormat::Exr | ImageFormat::Hdr)
    }
}

/// Errors of image decoding and encoding; each names the file.
#[derive(Debug, Error)]
pub enum ImageError {
    #[error("{path}: cannot read file: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: unsupported image type (expected .exr, .hdr, .png, .jpg or .jpeg)")]
    UnsupportedExtension { path: PathBuf },
    #[error("{path}: corrupt or unreadable image: {message}")]
    Decode { path: PathBuf, message: String },
    #[error("{path}: EXR has no usable colour channels (found {found:?}; need R,G,B or Y)")]
    ExrChannels { path: PathBuf, found: Vec<String> },
    #[error("{path}: cannot write image: {message}")]
    Encode { path: PathBuf, message: String },
    #[error(
        "{path}: the file declares {width}×{height} pixels ({samples} samples), over the limit of \
         {max_pixels} pixels ({max_samples} samples)"
    )]
    TooLarge {
        path: PathBuf,
        width: usize,
        height: usize,
        samples: u64,
        max_pixels: u64,
        max_samples: u64,
    },
}

/// The most an image file may declare before it is decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageLimits {
    /// Most pixels (width × height) of the image, or of any one layer of an EXR file.
    pub max_pixels: u64,
}

/// Samples per pixel a file may carry within its pixel limit: RGBA. An EXR file may spread them
/// over several layers or name more channels, as long as all of them together stay within
/// `max_pixels × MAX_SAMPLES_PER_PIXEL`.
const MAX_SAMPLES_PER_PIXEL: u64 = 4;

impl ImageLimits {
    /// 2²⁸ pixels (16384 × 16384): more than any camera or environment map, small enough that
    /// one image's decode (4 GiB of f32 RGBA at most) fits a worker.
    pub const DEFAULT: ImageLimits = ImageLimits {
        max_pixels: 1 << 28,
    };

    /// Limits admitting exactly `width × height` pixels (a file that must match a camera).
    pub fn pixels(width: usize, height: usize) -> ImageLimits {
        ImageLimits {
            max_pixels: (width as u64).saturating_mul(height as u64),
        }
    }

    fn max_samples(&self) -> u64 {
        self.max_pixels.saturating_mul(MAX_SAMPLES_PER_PIXEL)
    }
}

impl Default for ImageLimits {
    fn default() -> Self {
        ImageLimits::DEFAULT
    }
}

/// What an image file's header declares, read without decoding any pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageHeader {
    pub width: usize,
    pub height: usize,
    /// Every sample the file holds: width × height × channels, summed over an EXR file's layers.
    pub samples: u64,
}

/// Reads an image file within [`ImageLimits::DEFAULT`]; PNG/JPEG samples are scaled to [0, 1]
/// but not linearized.
pub fn read_image(path: &Path) -> Result<(Image, ImageFormat), ImageError> {
    read_image_within(path, &ImageLimits::DEFAULT)
}

/// The lower-case extension that picks the decoder, after checking the file exists.
fn decoder_extension(path: &Path) -> Result<String, ImageError> {
    if !path.is_file() {
        return Err(ImageError::Io {
            path: path.to_owned(),
            source: std::io::Error::new(std::io::ErrorKind::NotFound, "no such file"),
        });
    }
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase())
        .unwrap_or_default();
    match ext.as_str() {
        "exr" | "hdr" | "png" | "jpg" | "jpeg" => Ok(ext),
        _ => Err(ImageError::UnsupportedExtension {
            path: path.to_owned(),
        }),
    }
}

/// Reads only the header of an image file: its size and sample count.
pub fn read_header(path: &Path) -> Result<ImageHeader, ImageError> {
    if decoder_extension(path)? == "exr" {
        return exr_header(path);
    }
    let (width, height) = image::ImageReader::open(path)
        .map_err(|source| ImageError::Io {
            path: path.to_owned(),
            source,
        })?
        .with_guessed_format()
        .map_err(|source| ImageError::Io {
            path: path.to_owned(),
            source,
        })?
        .into_dimensions()
        .map_err(|e| decode_error(path, e))?;
    let (width, height) = (width as usize, height as usize);
    Ok(ImageHeader {
        width,
        height,
        samples: (width as u64 * height as u64).saturating_mul(MAX_SAMPLES_PER_PIXEL),
    })
}

/// An EXR file's size: its largest layer, and every sample of every layer.
fn exr_header(path: &Path) -> Result<ImageHeader, ImageError> {
    let meta =
        exr::meta::MetaData::read_from_file(path, false).map_err(|e| decode_error(path, e))?;
    let largest = meta
        .headers
        .iter()
        .map(|h| h.layer_size)
        .max_by_key(|size| size.area())
        .ok_or_else(|| decode_error(path, "no layers"))?;
    let samples = meta.headers.iter().fold(0u64, |sum, h| {
        let area = h.layer_size.area() as u64;
        sum.saturating_add(area.saturating_mul(h.channels.list.len() as u64))
    });
    Ok(ImageHeader {
        width: largest.width(),
        height: largest.height(),
        samples,
    })
}

/// Reads an image file after checking its header against `limits`: a file declaring more pixels
/// or samples is [`ImageError::TooLarge`], and nothing of its size is allocated.
pub fn read_image_within(
    path: &Path,
    limits: &ImageLimits,
) -> Result<(Image, ImageFormat), ImageError> {
    let ext = decoder_extension(path)?;
    let header = read_header(path)?;
    let pixels = header.width as u64 * header.height as u64;
    if pixels > limits.max_pixels || header.samples > limits.max_samples() {
        return Err(ImageError::TooLarge {
            path: path.to_owned(),
            width: header.width,
            height: header.height,
            samples: header.samples,
            max_pixels: limits.max_pixels,
            max_samples: limits.max_samples(),
        });
    }
    match ext.as_str() {
        "exr" => read_exr(path).map(|i| (i, ImageFormat::Exr)),
        _ => read_with_image_crate(path, limits),
    }
}

fn decode_error(path: &Path, e: impl std::fmt::Display) -> ImageError {
    ImageError::Decode {
        path: path.to_owned(),
        message: e.to_string(),
    }
}

/// Reads the first layer of an EXR file, picking channels by name: RGB(A) if present, else Y(A).
/// Callers check its header first ([`read_image_within`]).
fn read_exr(path: &Path) -> Result<self::Image, ImageError> {
    use exr::prelude::*;
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .map_err(|e| decode_error(path, e))?;
    let layer = image.layer_data;
    let (width, height) = (layer.size.width(), layer.size.height());
    let channels = &layer.channel_data.list;
    let names: Vec<String> = channels.iter().map(|c| c.name.to_string()).collect();
    let find = |name: &str| names.iter().position(|n| n == name);
    let wanted: Vec<usize> = match (find("R"), find("G"), find("B"), find("Y")) {
        (Some(r), Some(g), Some(b), _) => [Some(r), Some(g), Some(b), find("A")]
            .into_iter()
            .flatten()
            .collect(),
        (_, _, _, Some(y)) => [Some(y), find("A")].into_iter().flatten().collect(),
        _ => {
            return Err(ImageError::ExrChannels {
                path: path.to_owned(),
                found: names,
            })
        }
    };
    let planes: Vec<Vec<f32>> = wanted
        .iter()
        .map(|&c| channels[c].sample_data.values_as_f32().collect())
        .collect();
    let n = planes.len();
    let mut data = vec![0.0f32; width * height * n];
    for (c, plane) in planes.iter().enumerate() {
        for (p, v) in plane.iter().enumerate() {
            data[p * n + c] = *v;
        }
    }
    Ok(self::Image {
        width,
        height,
        channels: n,
        data,
    })
}

fn read_with_image_crate(
    path: &Path,
    limits: &ImageLimits,
) -> Result<(Image, ImageFormat), ImageError> {
    use image::DynamicImage as D;
    let mut reader = image::ImageReader::open(path)
        .and_then(|r| r.with_guessed_format())
        .map_err(|source| ImageError::Io {
            path: path.to_owned(),
            source,
        })?;
    reader.limits(decoder_limits(limits));
    let dynamic = reader.decode().map_err(|e| decode_error(path, e))?;
    let (width, height) = (dynamic.width() as usize, dynamic.height() as usize);
    let format = match &dynamic {
        D::ImageRgb32F(_) | D::ImageRgba32F(_) => ImageFormat::Hdr,
        D::ImageLuma16(_) | D::ImageLumaA16(_) | D::ImageRgb16(_) | D::ImageRgba16(_) => {
            ImageFormat::Png16
        }
        _ if path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png")) =>
        {
            ImageFormat::Png8
        }
        _ => ImageFormat::Jpeg,
    };
    let channels = dynamic.color().channel_count() as usize;
    let data: Vec<f32> = match channels {
        1 => dynamic.to_luma32f().into_raw(),
        2 => dynamic.to_luma_alpha32f().into_raw(),
        3 => dynamic.to_rgb32f().into_raw(),
        _ => dynamic.to_rgba32f().into_raw(),
    };
    Ok((
        Image {
            width,
            height,
            channels: channels.min(4),
            data,
        },
        format,
    ))
}

/// The image crate's limits for a decode within `limits`: the decoder's own buffer (up to 16-bit
/// RGBA, 8 bytes a pixel) or 32-bit float RGBA (16 bytes a pixel, the HDR decoder's).
pub fn decoder_limits(limits: &ImageLimits) -> image::Limits {
    let side = u32::try_from(limits.max_pixels).unwrap_or(u32::MAX);
    let mut decoder = image::Limits::default();
    decoder.max_image_width = Some(side);
    decoder.max_image_height = Some(side);
    decoder.max_alloc = Some(limits.max_pixels.saturating_mul(16).max(1 << 20));
    decoder
}

/// Writes an image as a float EXR with channels named R,G,B(,A) or Y(,A).
pub fn write_exr(path: &Path, img: &self::Image) -> Result<(), ImageError> {
    use exr::prelude::*;
    let names: &[&str] = match img.channels {
        1 => &["Y"],
        2 => &["Y", "A"],
        3 => &["R", "G", "B"],
        4 => &["R", "G", "B", "A"],
        n => {
            return Err(ImageError::Encode {
                path: path.to_owned(),
                message: format!("cannot store {n} channels"),
            })
        }
    };
    let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = names
        .iter()
        .enumerate()
        .map(|(c, name)| {
            let plane: Vec<f32> = img
                .data
                .iter()
                .skip(c)
                .step_by(img.channels)
                .copied()
                .collect();
            AnyChannel::new(*name, FlatSamples::F32(plane))
        })
        .collect();
    let layer = Layer::new(
        (img.width, img.height),
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(list),
    );
    exr::prelude::Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| ImageError::Encode {
            path: path.to_owned(),
            message: e.to_string(),
        })
}

/// Writes an 8-bit PNG; values are clamped to [0, 1], and sRGB-encoded first when `srgb` is set.
pub fn write_png(path: &Path, img: &Image, srgb: bool) -> Result<(), ImageError> {
    let encode = |v: f32| {
        let v = if srgb { linear_to_srgb(v) } else { v };
        (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
    };
    let bytes: Vec<u8> = img.data.iter().map(|&v| encode(v)).collect();
    let color = match img.channels {
        1 => image::ExtendedColorType::L8,
        2 => image::ExtendedColorType::La8,
        3 => image::ExtendedColorType::Rgb8,
        _ => image::ExtendedColorType::Rgba8,
    };
    image::save_buffer(path, &bytes, img.width as u32, img.height as u32, color).map_err(|e| {
        ImageError::Encode {
            path: path.to_owned(),
            message: e.to_string(),
        }
    })
}

/// The sRGB electro-optical transfer function: encoded value → linear.
pub fn srgb_to_linear(v: f32) -> f32 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// Inverse of [`srgb_to_linear`]: linear → encoded value (negative inputs map to 0).
pub fn linear_to_srgb(v: f32) -> f32 {
    if v <= 0.0031308 {
        12.92 * v.max(0.0)
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp(channels: usize) -> Image {
        Image::from_fn(5, 3, channels, |x, y, out| {
            for (c, o) in out.iter_mut().enumerate() {
                *o = (x * 7 + y * 3 + c) as f32 * 0.125 - 0.5;
            }
        })
    }

    #[test]
    fn exr_round_trip_keeps_channels_by_name() {
        let dir = tempfile::tempdir().unwrap();
        for channels in [1, 3, 4] {
            let path = dir.path().join(format!("t{channels}.exr"));
            let img = ramp(channels);
            write_exr(&path, &img).unwrap();
            let (back, format) = read_image(&path).unwrap();
            assert_eq!(format, ImageFormat::Exr);
            assert_eq!(back, img);
        }
    }

    #[test]
    fn png_round_trip_and_srgb_curve() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.png");
        let img = Image::from_fn(4, 2, 3, |x, y, o| o.fill((x + 4 * y) as f32 / 7.0));
        write_png(&path, &img, false).unwrap();
        let (back, format) = read_image(&path).unwrap();
        assert_eq!(format, ImageFormat::Png8);
        for (a, b) in img.data.iter().zip(&back.data) {
            assert!((a - b).abs() <= 0.5 / 255.0 + 1e-6);
        }
        for v in [0.0f32, 0.002, 0.2, 0.5, 1.0] {
            assert!((srgb_to_linear(linear_to_srgb(v)) - v).abs() < 1e-6);
        }
    }

    #[test]
    fn corrupt_and_unknown_files_are_named_errors() {
        let dir = tempfile::tempdir().unwrap();
        let bad = dir.path().join("bad.exr");
        std::fs::write(&bad, b"not an exr").unwrap();
        let e = read_image(&bad).unwrap_err().to_string();
        assert!(e.contains("bad.exr") && e.contains("corrupt"), "{e}");
        let txt = dir.path().join("x.txt");
        std::fs::write(&txt, b"x").unwrap();
        assert!(matches!(
            read_image(&txt),
            Err(ImageError::UnsupportedExtension { .. })
        ));
        assert!(matches!(
            read_image(&dir.path().join("missing.png")),
            Err(ImageError::Io { .. })
        ));
    }

    #[test]
    fn files_declaring_more_than_the_limit_are_refused_before_decoding() {
        use crate::testing::hostile::{exr_declaring, hdr_declaring, png_declaring};
        let dir = tempfile::tempdir().unwrap();
        let (w, h) = (100_000, 100_000);
        for (name, bytes) in [
            ("huge.exr", exr_declaring(w, h)),
            ("huge.png", png_declaring(w, h)),
            ("huge.hdr", hdr_declaring(w, h)),
        ] {
            let path = dir.path().join(name);
            std::fs::write(&path, &bytes).unwrap();
            assert!(bytes.len() < 4096, "{name}: {} bytes", bytes.len());
            let header = read_header(&path).unwrap();
            assert_eq!(
                (header.width, header.height),
                (w as usize, h as usize),
                "{name}"
            );
            match read_image(&path) {
                Err(ImageError::TooLarge {
                    width,
                    height,
                    max_pixels,
                    ..
                }) => assert_eq!(
                    (width, height, max_pixels),
                    (w as usize, h as usize, ImageLimits::DEFAULT.max_pixels)
                ),
                other => panic!("{name}: {other:?}"),
            }
        }
        // Within its limit the same header is decoded, and fails as the truncated file it is.
        let path = dir.path().join("small.exr");
        std::fs::write(&path, exr_declaring(64, 64)).unwrap();
        assert!(matches!(read_image(&path), Err(ImageError::Decode { .. })));
    }

    #[test]
    fn exact_limits_admit_that_size_and_no_more() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.png");
        write_png(&path, &ramp(3).map_unit(), false).unwrap();
        assert!(read_image_within(&path, &ImageLimits::pixels(5, 3)).is_ok());
        let refused = read_image_within(&path, &ImageLimits::pixels(5, 2)).unwrap_err();
        assert!(
            matches!(
                refused,
                ImageError::TooLarge {
                    width: 5,
                    height: 3,
                    max_pixels: 10,
                    ..
                }
            ),
            "{refused:?}"
        );
        // An EXR's samples count every channel: 5 × 3 RGBA is 60 samples.
        let exr = dir.path().join("t.exr");
        write_exr(&exr, &ramp(4)).unwrap();
        let header = read_header(&exr).unwrap();
        assert_eq!((header.width, header.height, header.samples), (5, 3, 60));
    }

    impl Image {
        /// The samples mapped into [0, 1] (for 8-bit round trips).
        fn map_unit(mut self) -> Image {
            self.data.iter_mut().for_each(|v| *v = (*v + 0.5) / 4.0);
            self
        }
    }

    #[test]
    fn non_finite_samples_are_located() {
        let mut img = ramp(3);
        assert_eq!(img.first_non_finite(), None);
        img.data[(2 * 5 + 4) * 3 + 1] = f32::NAN;
        assert_eq!(img.first_non_finite(), Some((4, 2, 1)));
    }
}

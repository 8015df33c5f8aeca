//! Polarization mosaics of Sony's IMX250MZR (mono) and IMX250MYR (colour) sensors, as pure maths on
//! f32 planes: the micro-polarizer layout, the colour sensor's Bayer layer, demosaicing (half
//! resolution, every channel interpolated to the 2×2 block centres, or bilinear full resolution),
//! Stokes S0, S1, S2 by least squares over the four polarizer angles, and the forward model
//! (Stokes → mosaic counts) that tests and simulations use. No file access here (`raw.rs` reads
//! frames).
//!
//! Layout: every 2×2 block holds polarizers at 90° (top left), 45° (top right), 135° (bottom left)
//! and 0° (bottom right), angles as the sensor labels them. On the IMX250MYR each polarizer's
//! half-resolution sub-image is itself an RGGB Bayer mosaic (R top left), so a full colour-
//! polarization pattern repeats every 4×4 pixels.
//!
//! Demosaicing is linear and keeps colours apart (no cross-channel terms), so white-balance gains
//! commute with it and may be applied to the Stokes images afterwards.

use thiserror::Error;

use crate::formats::image_io::Image;

/// The polarizer angles (degrees, as labelled by the sensor) of a 2×2 block, `[row][column]`.
pub const POLARIZER_LAYOUT_DEG: [[u32; 2]; 2] = [[90, 45], [135, 0]];

/// The output order of the four polarizer channels.
pub const CHANNEL_ANGLES_DEG: [u32; 4] = [0, 45, 90, 135];

/// Offset `(column, row)` inside the 2×2 block of each channel of [`CHANNEL_ANGLES_DEG`].
const CHANNEL_OFFSETS: [(usize, usize); 4] = [(1, 1), (1, 0), (0, 0), (0, 1)];

/// A polarization sensor with a 2×2 micro-polarizer mosaic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, clap::ValueEnum)]
pub enum Sensor {
    /// Sony IMX250MZR: monochrome.
    #[serde(rename = "IMX250MZR")]
    #[value(name = "IMX250MZR")]
    Imx250Mzr,
    /// Sony IMX250MYR: an RGGB Bayer mosaic over each polarizer channel.
    #[serde(rename = "IMX250MYR")]
    #[value(name = "IMX250MYR")]
    Imx250Myr,
}

impl Sensor {
    /// The names accepted in a capture (`sensor` key).
    pub const NAMES: [&'static str; 2] = ["IMX250MZR", "IMX250MYR"];

    pub fn from_name(name: &str) -> Option<Sensor> {
        match name.to_ascii_uppercase().as_str() {
            "IMX250MZR" => Some(Sensor::Imx250Mzr),
            "IMX250MYR" => Some(Sensor::Imx250Myr),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Sensor::Imx250Mzr => "IMX250MZR",
            Sensor::Imx250Myr => "IMX250MYR",
        }
    }

    pub fn is_colour(self) -> bool {
        self == Sensor::Imx250Myr
    }

    /// Width and height must be multiples of this: one whole 2×2 polarizer block (mono) or one
    /// whole 4×4 colour-polarization block.
    pub fn block(self) -> usize {
        if self.is_colour() {
            4
        } else {
            2
        }
    }
}

/// How mosaic frames become four polarizer images.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Demosaic {
    /// One output pixel per 2×2 block, each polarizer (and colour) channel interpolated to the
    /// block's centre from its own samples: half the width and height, so the intrinsics are
    /// halved too.
    Half,
    /// Bilinear interpolation of each polarizer (and colour) channel at every sensor pixel.
    #[default]
    Bilinear,
}

impl Demosaic {
    pub fn from_name(name: &str) -> Option<Demosaic> {
        match name {
            "half" => Some(Demosaic::Half),
            "bilinear" => Some(Demosaic::Bilinear),
            _ => None,
        }
    }

    /// Output size of a `width × height` mosaic.
    pub fn output_size(self, width: usize, height: usize) -> (usize, usize) {
        match self {
            Demosaic::Half => (width / 2, height / 2),
            Demosaic::Bilinear => (width, height),
        }
    }
}

/// Errors of the mosaic maths (sizes); file problems are reported by `raw.rs`.
#[derive(Debug, Error, PartialEq, Eq)]
pub enum MosaicError {
    #[error(
        "an {sensor} mosaic must have a width and height that are multiples of {block} (whole {block}×{block} blocks), found {width}×{height}"
    )]
    Size {
        sensor: &'static str,
        block: usize,
        width: usize,
        height: usize,
    },
    #[error("mosaic data holds {found} samples but {width}×{height} needs {expected}")]
    Samples {
        width: usize,
        height: usize,
        expected: usize,
        found: usize,
    },
}

/// A single-plane sensor image, row 0 on top. Samples are linear, black level removed, 1 = the
/// largest count above black.
#[derive(Clone, Debug, PartialEq)]
pub struct Mosaic {
    pub width: usize,
    pub height: usize,
    pub data: Vec<f32>,
}

impl Mosaic {
    pub fn new(width: usize, height: usize, data: Vec<f32>) -> Result<Mosaic, MosaicError> {
        if data.len() != width * height {
            return Err(MosaicError::Samples {
                width,
                height,
                expected: width * height,
                found: data.len(),
            });
        }
        Ok(Mosaic {
            width,
            height,
            data,
        })
    }

    /// Linear samples from raw counts: `(count − black_level) / (2^bit_depth − 1 − black_level)`.
    pub fn from_counts(
        width: usize,
        height: usize,
        counts: &[u16],
        bit_depth: u32,
        black_level: u32,
    ) -> Result<Mosaic, MosaicError> {
        let scale = 1.0 / (max_count(bit_depth) - black_level as f64);
        let data = counts
            .iter()
            .map(|&c| ((c as f64 - black_level as f64) * scale) as f32)
            .collect();
        Mosaic::new(width, height, data)
    }

    /// The inverse of [`Mosaic::from_counts`]: counts rounded to the nearest integer and clamped
    /// to `[0, 2^bit_depth − 1]` (what a sensor with that black level records).
    pub fn to_counts(&self, bit_depth: u32, black_level: u32) -> Vec<u16> {
        let max = max_count(bit_depth);
        let range = max - black_level as f64;
        self.data
            .iter()
            .map(|&v| {
                (black_level as f64 + v as f64 * range)
                    .round()
                    .clamp(0.0, max) as u16
            })
            .collect()
    }

    fn at(&self, x: usize, y: usize) -> f32 {
        self.data[y * self.width + x]
    }

    fn check(&self, sensor: Sensor) -> Result<(), MosaicError> {
        let block = sensor.block();
        if self.width == 0
            || self.height == 0
            || !self.width.is_multiple_of(block)
            || !self.height.is_multiple_of(block)
        {
            return Err(MosaicError::Size {
                sensor: sensor.name(),
                block,
                width: self.width,
                height: self.height,
            });
        }
        Ok(())
    }
}

/// `2^bit_depth − 1`.
pub fn max_count(bit_depth: u32) -> f64 {
    ((1u64 << bit_depth) - 1) as f64
}

/// The four polarizer images in the order of [`CHANNEL_ANGLES_DEG`] (0°, 45°, 90°, 135° as the
/// sensor labels them); one channel (mono) or three (RGB).
#[derive(Clone, Debug, PartialEq)]
pub struct PolarizerImages {
    pub images: [Image; 4],
}

/// Demosaics a frame of `sensor` into its four polarizer images.
pub fn demosaic(
    mosaic: &Mosaic,
    sensor: Sensor,
    mode: Demosaic,
) -> Result<PolarizerImages, MosaicError> {
    mosaic.check(sensor)?;
    let planes: Vec<[Vec<f32>; 4]> = match sensor {
        Sensor::Imx250Mzr => vec![polarization_planes(mosaic, mode)],
        Sensor::Imx250Myr => debayer_sub_images(mosaic)
            .iter()
            .map(|colour| polarization_planes(colour, mode))
            .collect(),
    };
    let (width, height) = mode.output_size(mosaic.width, mosaic.height);
    let channels = planes.len();
    let images = std::array::from_fn(|k| {
        let mut image = Image::filled(width, height, channels, 0.0);
        for (c, plane) in planes.iter().enumerate() {
            for (p, v) in plane[k].iter().enumerate() {
                image.data[p * channels + c] = *v;
            }
        }
        image
    });
    Ok(PolarizerImages { images })
}

/// The four polarizer planes of a mono polarization mosaic, at the output size of `mode`.
fn polarization_planes(mosaic: &Mosaic, mode: Demosaic) -> [Vec<f32>; 4] {
    std::array::from_fn(|k| {
        let (ox, oy) = CHANNEL_OFFSETS[k];
        match mode {
            Demosaic::Half => interpolate_to_block_centres(mosaic, ox, oy),
            Demosaic::Bilinear => interpolate_lattice(mosaic, ox, oy),
        }
    })
}

/// Bilinear interpolation, at the centre of every 2×2 block of `mosaic`, of the samples on the
/// lattice `(ox + 2k, oy + 2l)`: the 2×2 block mean of [`interpolate_lattice`]. A block's own
/// sample lies half a pixel from the centre in x and in y, so it weighs 9/16, the lattice
/// neighbours on the centre's side 3/16 each and the diagonal one 1/16; beyond the outermost
/// lattice rows and columns the nearest ones are repeated.
///
/// Taking a block's four samples as they are would leave each polarizer half a pixel from the
/// centre (where the halved camera puts the view's pixel), in a different direction for each:
/// S1 = I0 − I90 and S2 = I45 − I135 would then also hold half of S0's change across the block, a
/// bias that follows S0's gradient and does not average away when the views are shrunk further.
fn interpolate_to_block_centres(mosaic: &Mosaic, ox: usize, oy: usize) -> Vec<f32> {
    let (w, h) = (mosaic.width / 2, mosaic.height / 2);
    // The lattice neighbour on the side of the block centre; at the border, the sample itself.
    let towards_centre = |k: usize, n: usize, offset: usize| {
        if offset == 0 {
            (k + 1).min(n - 1)
        } else {
            k.saturating_sub(1)
        }
    };
    let sample = |i: usize, j: usize| mosaic.at(2 * i + ox, 2 * j + oy);
    let mut plane = Vec::with_capacity(w * h);
    for j in 0..h {
        let j_next = towards_centre(j, h, oy);
        for i in 0..w {
            let i_next = towards_centre(i, w, ox);
            let own_row = 0.75 * sample(i, j) + 0.25 * sample(i_next, j);
            let next_row = 0.75 * sample(i, j_next) + 0.25 * sample(i_next, j_next);
            plane.push(0.75 * own_row + 0.25 * next_row);
        }
    }
    plane
}

/// Bilinear interpolation, at every pixel of `mosaic`, of the samples on the lattice
/// `(ox + 2k, oy + 2l)`; beyond the outermost lattice rows and columns the nearest ones are
/// repeated.
fn interpolate_lattice(mosaic: &Mosaic, ox: usize, oy: usize) -> Vec<f32> {
    let (w, h) = (mosaic.width, mosaic.height);
    // (index of the lower lattice line, index of the upper one, weight of the upper one).
    let weights = |n: usize, offset: usize| -> Vec<(usize, usize, f32)> {
        let last = (n - 1 - offset) / 2;
        (0..n)
            .map(|p| {
                if p <= offset {
                    (0, 0, 0.0)
                } else {
                    let k = (p - offset) / 2;
                    if k >= last {
                        (last, last, 0.0)
                    } else {
                        (k, k + 1, ((p - offset) % 2) as f32 * 0.5)
                    }
                }
            })
            .collect()
    };
    let (wx, wy) = (weights(w, ox), weights(h, oy));
    let rows = (h - 1 - oy) / 2 + 1;
    // Along x on the lattice rows first, then along y.
    let mut along_x = vec![0.0f32; rows * w];
    for l in 0..rows {
        let y = oy + 2 * l;
        for (x, &(k0, k1, t)) in wx.iter().enumerate() {
            let (a, b) = (mosaic.at(ox + 2 * k0, y), mosaic.at(ox + 2 * k1, y));
            along_x[l * w + x] = a + (b - a) * t;
        }
    }
    let mut out = vec![0.0f32; w * h];
    for (y, &(l0, l1, t)) in wy.iter().enumerate() {
        for x in 0..w {
            let (a, b) = (along_x[l0 * w + x], along_x[l1 * w + x]);
            out[y * w + x] = a + (b - a) * t;
        }
    }
    out
}

/// The colour sensor's mosaic split into three full-resolution mono polarization mosaics
/// (R, G, B): each polarizer's half-resolution RGGB sub-image is demosaiced bilinearly on its own
/// (so no sample of another polarizer leaks in) and scattered back to its sensor pixels.
fn debayer_sub_images(mosaic: &Mosaic) -> [Mosaic; 3] {
    let (w, h) = (mosaic.width, mosaic.height);
    let mut colours: [Mosaic; 3] = std::array::from_fn(|_| Mosaic {
        width: w,
        height: h,
        data: vec![0.0; w * h],
    });
    for (ox, oy) in CHANNEL_OFFSETS {
        let (sw, sh) = (w / 2, h / 2);
        let sub = Mosaic {
            width: sw,
            height: sh,
            data: (0..sw * sh)
                .map(|p| mosaic.at(2 * (p % sw) + ox, 2 * (p / sw) + oy))
                .collect(),
        };
        let rgb = [
            interpolate_lattice(&sub, 0, 0),
            interpolate_green(&sub),
            interpolate_lattice(&sub, 1, 1),
        ];
        for (colour, plane) in colours.iter_mut().zip(&rgb) {
            for (p, v) in plane.iter().enumerate() {
                let (i, j) = (p % sw, p / sw);
                colour.data[(2 * j + oy) * w + 2 * i + ox] = *v;
            }
        }
    }
    colours
}

/// Green of an RGGB mosaic: the samples where `x + y` is odd, and at red and blue pixels the mean
/// of the green neighbours above, below, left and right (those inside the image).
fn interpolate_green(bayer: &Mosaic) -> Vec<f32> {
    let (w, h) = (bayer.width, bayer.height);
    let mut out = vec![0.0f32; w * h];
    for y in 0..h {
        for x in 0..w {
            out[y * w + x] = if (x + y) % 2 == 1 {
                bayer.at(x, y)
            } else {
                let mut sum = 0.0;
                let mut n = 0.0;
                for (dx, dy) in [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)] {
                    let (nx, ny) = (x as i64 + dx, y as i64 + dy);
                    if nx >= 0 && ny >= 0 && (nx as usize) < w && (ny as usize) < h {
                        sum += bayer.at(nx as usize, ny as usize);
                        n += 1.0;
                    }
                }
                sum / n
            };
        }
    }
    out
}

/// The least-squares solution of `I(θ_k) = ½ (S0 + S1 cos 2θ_k + S2 sin 2θ_k)` as a 3×4 matrix:
/// row r gives S_r as a weighted sum of the four intensities. `angles_deg` are in the convention
/// the Stokes images should have.
///
/// For 0°, 45°, 90°, 135° it is S0 = ½ (I0 + I45 + I90 + I135), S1 = I0 − I90, S2 = I45 − I135.
pub fn stokes_solver(angles_deg: [f64; 4]) -> [[f64; 4]; 3] {
    let rows: [[f64; 3]; 4] = angles_deg.map(|a| {
        let t = 2.0 * a.to_radians();
        [0.5, 0.5 * t.cos(), 0.5 * t.sin()]
    });
    // Normal equations AᵀA x = Aᵀ I, solved once for the 3×4 pseudo-inverse.
    let ata = glam::DMat3::from_cols_array_2d(&std::array::from_fn(|c| {
        std::array::from_fn(|r| rows.iter().map(|row| row[r] * row[c]).sum())
    }));
    let inverse = ata.inverse();
    std::array::from_fn(|s| {
        std::array::from_fn(|k| {
            let row = glam::DVec3::from_array(rows[k]);
            inverse.row(s).dot(row)
        })
    })
}

/// S0, S1, S2 from four polarizer images (same size and channel count) taken at `angles_deg`
/// (in the convention the Stokes images should have), by least squares.
pub fn stokes_from_polarizers(images: &[Image; 4], angles_deg: [f64; 4]) -> [Image; 3] {
    let solver = stokes_solver(angles_deg);
    std::array::from_fn(|s| {
        let w = solver[s].map(|v| v as f32);
        let mut out = images[0].clone();
        for (i, v) in out.data.iter_mut().enumerate() {
            *v = w[0] * images[0].data[i]
                + w[1] * images[1].data[i]
                + w[2] * images[2].data[i]
                + w[3] * images[3].data[i];
        }
        out
    })
}

/// The polarizer angles of [`CHANNEL_ANGLES_DEG`] in the image_y_up convention, for a sensor whose
/// labels count towards image-up (`image_y_down = false`) or towards image-down (then the 45° and
/// 135° polarizers trade places).
pub fn channel_angles_image_y_up(image_y_down: bool) -> [f64; 4] {
    CHANNEL_ANGLES_DEG.map(|a| {
        if image_y_down {
            (180.0 - a as f64).rem_euclid(180.0)
        } else {
            a as f64
        }
    })
}

/// The forward model: what `sensor` records of a scene with Stokes images `s0, s1, s2` (image_y_up,
/// three channels for the colour sensor, one or three for mono — the first channel is used).
/// Each pixel gets `I(θ) = ½ (S0 + S1 cos 2θ + S2 sin 2θ)` of its polarizer θ (labels counted as
/// `image_y_down` says) and, on the colour sensor, of its Bayer colour.
pub fn mosaic_from_stokes(
    stokes: [&Image; 3],
    sensor: Sensor,
    image_y_down: bool,
) -> Result<Mosaic, MosaicError> {
    let [s0, s1, s2] = stokes;
    let (w, h) = (s0.width, s0.height);
    let angles = channel_angles_image_y_up(image_y_down);
    let mut data = vec![0.0f32; w * h];
    for y in 0..h {
        for x in 0..w {
            let k = CHANNEL_OFFSETS
                .iter()
                .position(|&o| o == (x % 2, y % 2))
                .expect("every 2×2 offset is a channel");
            let c = match sensor {
                Sensor::Imx250Mzr => 0,
                // RGGB over the half-resolution sub-image.
                Sensor::Imx250Myr => match ((x / 2) % 2, (y / 2) % 2) {
                    (0, 0) => 0,
                    (1, 1) => 2,
                    _ => 1,
                },
            };
            let t = 2.0 * angles[k].to_radians();
            let (a, b, d) = (s0.pixel(x, y)[c], s1.pixel(x, y)[c], s2.pixel(x, y)[c]);
            data[y * w + x] = 0.5 * (a + b * t.cos() as f32 + d * t.sin() as f32);
        }
    }
    let mosaic = Mosaic::new(w, h, data)?;
    mosaic.check(sensor)?;
    Ok(mosaic)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Smooth Stokes images with DoLP ≤ 0.6: S0 a ramp, (S1, S2) rotating across the image.
    fn smooth_stokes(w: usize, h: usize, channels: usize) -> [Image; 3] {
        let s0 = Image::from_fn(w, h, channels, |x, y, o| {
            for (c, v) in o.iter_mut().enumerate() {
                *v = 0.4
                    + 0.3 * (x as f32 / w as f32)
                    + 0.1 * (y as f32 / h as f32)
                    + 0.05 * c as f32;
            }
        });
        let angle = |x: usize, y: usize| 0.05 * x as f32 + 0.03 * y as f32;
        let dolp = |x: usize, c: usize| 0.3 + 0.3 * (x as f32 / w as f32) - 0.05 * c as f32;
        let s1 = Image::from_fn(w, h, channels, |x, y, o| {
            for (c, v) in o.iter_mut().enumerate() {
                *v = s0.pixel(x, y)[c] * dolp(x, c) * (2.0 * angle(x, y)).cos();
            }
        });
        let s2 = Image::from_fn(w, h, channels, |x, y, o| {
            for (c, v) in o.iter_mut().enumerate() {
                *v = s0.pixel(x, y)[c] * dolp(x, c) * (2.0 * angle(x, y)).sin();
            }
        });
        [s0, s1, s2]
    }

    fn max_diff(a: &Image, b: &Image) -> f32 {
        assert_eq!(
            (a.width, a.height, a.channels),
            (b.width, b.height, b.channels)
        );
        a.data
            .iter()
            .zip(&b.data)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f32::max)
    }

    #[test]
    fn the_solver_for_the_sensor_angles_is_the_textbook_formula() {
        let m = stokes_solver([0.0, 45.0, 90.0, 135.0]);
        let expect = [
            [0.5, 0.5, 0.5, 0.5],
            [1.0, 0.0, -1.0, 0.0],
            [0.0, 1.0, 0.0, -1.0],
        ];
        for (row, want) in m.iter().zip(expect) {
            for (v, w) in row.iter().zip(want) {
                assert!((v - w).abs() < 1e-12, "{m:?}");
            }
        }
        // Any four distinct angles recover an exact Stokes vector.
        let angles = [10.0, 50.0, 100.0, 170.0];
        let s = [0.8, 0.2, -0.3];
        let intensities = angles.map(|a: f64| {
            let t = 2.0 * a.to_radians();
            0.5 * (s[0] + s[1] * t.cos() + s[2] * t.sin())
        });
        let m = stokes_solver(angles);
        for (row, want) in m.iter().zip(s) {
            let got: f64 = row.iter().zip(&intensities).map(|(a, b)| a * b).sum();
            assert!((got - want).abs() < 1e-12);
        }
    }

    #[test]
    fn image_y_down_labels_swap_45_and_135() {
        assert_eq!(channel_angles_image_y_up(false), [0.0, 45.0, 90.0, 135.0]);
        assert_eq!(channel_angles_image_y_up(true), [0.0, 135.0, 90.0, 45.0]);
    }

    #[test]
    fn constant_stokes_round_trip_exactly_in_both_modes_and_sensors() {
        for sensor in [Sensor::Imx250Mzr, Sensor::Imx250Myr] {
            let channels = if sensor.is_colour() { 3 } else { 1 };
            let values = [[0.7f32, 0.5, 0.3], [0.2, -0.1, 0.05], [-0.15, 0.1, 0.02]];
            let stokes: [Image; 3] = std::array::from_fn(|s| {
                Image::from_fn(12, 8, channels, |_, _, o| {
                    for (c, v) in o.iter_mut().enumerate() {
                        *v = values[s][c];
                    }
                })
            });
            for (mode, y_down) in [
                (Demosaic::Half, false),
                (Demosaic::Bilinear, false),
                (Demosaic::Half, true),
                (Demosaic::Bilinear, true),
            ] {
                let mosaic =
                    mosaic_from_stokes([&stokes[0], &stokes[1], &stokes[2]], sensor, y_down)
                        .unwrap();
                let pol = demosaic(&mosaic, sensor, mode).unwrap();
                let back = stokes_from_polarizers(&pol.images, channel_angles_image_y_up(y_down));
                let (w, h) = mode.output_size(12, 8);
                for (s, image) in back.iter().enumerate() {
                    assert_eq!(
                        (image.width, image.height, image.channels),
                        (w, h, channels)
                    );
                    for (p, v) in image.data.iter().enumerate() {
                        assert!(
                            (v - values[s][p % channels]).abs() < 1e-6,
                            "{sensor:?} {mode:?} S{s}: {v}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn half_mode_puts_every_channel_at_the_block_centre() {
        // Sample values that name their position: 90° = 0, 45° = 1, 135° = 6, 0° = 7 in the first
        // block of a 6 × 4 mosaic; the next block along a row adds 2, the next block row 12.
        let mosaic = Mosaic::new(6, 4, (0..24).map(|v| v as f32).collect()).unwrap();
        let pol = demosaic(&mosaic, Sensor::Imx250Mzr, Demosaic::Half).unwrap();
        let at = |k: usize| pol.images[k].data.clone();
        // 9/16 of the channel's own sample, 3/16 of each neighbour on the centre's side, 1/16 of
        // the diagonal one; at the border, the sample itself in the neighbour's place.
        let centre = |own: f32, across: f32, along: f32, diagonal: f32| {
            (9.0 * own + 3.0 * across + 3.0 * along + diagonal) / 16.0
        };
        // 0° (bottom right) leans left and up.
        assert_eq!(
            at(0),
            vec![
                7.0,
                centre(9.0, 7.0, 9.0, 7.0),
                centre(11.0, 9.0, 11.0, 9.0),
                centre(19.0, 19.0, 7.0, 7.0),
                centre(21.0, 19.0, 9.0, 7.0),
                centre(23.0, 21.0, 11.0, 9.0),
            ]
        );
        // 90° (top left) leans right and down.
        assert_eq!(
            at(2),
            vec![
                centre(0.0, 2.0, 12.0, 14.0),
                centre(2.0, 4.0, 14.0, 16.0),
                centre(4.0, 4.0, 16.0, 16.0),
                centre(12.0, 14.0, 12.0, 14.0),
                centre(14.0, 16.0, 14.0, 16.0),
                16.0,
            ]
        );
        // 45° (top right) leans left and down, 135° (bottom left) right and up.
        assert_eq!(at(1)[4], centre(15.0, 13.0, 15.0, 13.0));
        assert_eq!(at(3)[1], centre(8.0, 10.0, 8.0, 10.0));
    }

    #[test]
    fn half_mode_is_the_block_mean_of_bilinear_and_sees_a_plane_alike_in_every_channel() {
        let (w, h) = (12, 10);
        let f = |x: f32, y: f32| 0.1 + 0.02 * x + 0.03 * y;
        let mosaic = Mosaic::new(
            w,
            h,
            (0..w * h)
                .map(|p| f((p % w) as f32, (p / w) as f32))
                .collect(),
        )
        .unwrap();
        let half = demosaic(&mosaic, Sensor::Imx250Mzr, Demosaic::Half).unwrap();
        let full = demosaic(&mosaic, Sensor::Imx250Mzr, Demosaic::Bilinear).unwrap();
        for (k, (half, full)) in half.images.iter().zip(&full.images).enumerate() {
            for j in 0..h / 2 {
                for i in 0..w / 2 {
                    let block = [(0, 0), (1, 0), (0, 1), (1, 1)]
                        .map(|(dx, dy)| full.pixel(2 * i + dx, 2 * j + dy)[0]);
                    let mean = block.iter().sum::<f32>() / 4.0;
                    let v = half.pixel(i, j)[0];
                    assert!(
                        (v - mean).abs() < 1e-6,
                        "channel {k} ({i}, {j}): {v} {mean}"
                    );
                    // Away from the border every channel holds the plane at the block's centre
                    // (2i + ½, 2j + ½ in sample coordinates), so an unpolarized ramp has no S1, S2.
                    if (1..w / 2 - 1).contains(&i) && (1..h / 2 - 1).contains(&j) {
                        let at_centre = f(2.0 * i as f32 + 0.5, 2.0 * j as f32 + 0.5);
                        assert!((v - at_centre).abs() < 1e-6, "channel {k} ({i}, {j}): {v}");
                    }
                }
            }
        }
    }

    #[test]
    fn bilinear_mode_reproduces_linear_ramps_inside_the_lattice() {
        // A plane a + b x + c y is reproduced exactly wherever a pixel has lattice samples on both
        // sides (everywhere but the outermost row and column of each channel).
        let (w, h) = (10, 8);
        let f = |x: usize, y: usize| 0.1 + 0.02 * x as f32 + 0.03 * y as f32;
        let mosaic = Mosaic::new(w, h, (0..w * h).map(|p| f(p % w, p / w)).collect()).unwrap();
        let pol = demosaic(&mosaic, Sensor::Imx250Mzr, Demosaic::Bilinear).unwrap();
        for image in &pol.images {
            for y in 1..h - 1 {
                for x in 1..w - 1 {
                    let v = image.pixel(x, y)[0];
                    assert!((v - f(x, y)).abs() < 1e-6, "({x}, {y}): {v}");
                }
            }
        }
    }

    #[test]
    fn smooth_stokes_round_trip_within_the_interpolation_error() {
        for sensor in [Sensor::Imx250Mzr, Sensor::Imx250Myr] {
            let channels = if sensor.is_colour() { 3 } else { 1 };
            let [s0, s1, s2] = smooth_stokes(64, 48, channels);
            let mosaic = mosaic_from_stokes([&s0, &s1, &s2], sensor, false).unwrap();
            let pol = demosaic(&mosaic, sensor, Demosaic::Bilinear).unwrap();
            let back = stokes_from_polarizers(&pol.images, channel_angles_image_y_up(false));
            // Away from the border (4 px, one colour-polarization block), bilinear interpolation
            // of these gently curved images errs by a small fraction of S0.
            let crop = |img: &Image| {
                Image::from_fn(56, 40, channels, |x, y, o| {
                    o.copy_from_slice(img.pixel(x + 4, y + 4))
                })
            };
            for (s, (got, want)) in back.iter().zip([&s0, &s1, &s2]).enumerate() {
                let err = max_diff(&crop(got), &crop(want));
                eprintln!("{sensor:?} bilinear S{s}: max error {err:.2e}");
                let bound = if sensor.is_colour() { 0.02 } else { 0.005 };
                assert!(err < bound, "{sensor:?} S{s}: {err}");
            }
        }
    }

    #[test]
    fn counts_round_trip_and_sizes_are_checked() {
        let mosaic = Mosaic::new(2, 2, vec![0.0, 0.25, 0.5, 1.0]).unwrap();
        let counts = mosaic.to_counts(12, 64);
        assert_eq!(counts, vec![64, 1072, 2080, 4095]);
        let back = Mosaic::from_counts(2, 2, &counts, 12, 64).unwrap();
        assert!(
            max_diff(
                &Image {
                    width: 2,
                    height: 2,
                    channels: 1,
                    data: back.data
                },
                &Image {
                    width: 2,
                    height: 2,
                    channels: 1,
                    data: mosaic.data.clone()
                }
            ) < 1e-3
        );
        let odd = Mosaic::new(5, 4, vec![0.0; 20]).unwrap();
        let e = demosaic(&odd, Sensor::Imx250Mzr, Demosaic::Half).unwrap_err();
        assert_eq!(e.to_string(), "an IMX250MZR mosaic must have a width and height that are multiples of 2 (whole 2×2 blocks), found 5×4");
        let colour = Mosaic::new(6, 4, vec![0.0; 24]).unwrap();
        assert!(matches!(
            demosaic(&colour, Sensor::Imx250Myr, Demosaic::Bilinear),
            Err(MosaicError::Size { block: 4, .. })
        ));
        assert!(matches!(
            Mosaic::new(4, 4, vec![0.0; 15]),
            Err(MosaicError::Samples {
                expected: 16,
                found: 15,
                ..
            })
        ));
    }
}

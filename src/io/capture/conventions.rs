//! Conventions found from the data: which way a capture's polarization angles turn, and whether
//! its 8/16-bit polarizer images are linear or sRGB-encoded, measured on the pixels themselves
//! so that a capture stating the wrong convention is caught before training.
//!
//! **Stokes angle direction.** At the occluding contour of an object the surface normal lies in
//! the image plane, along the 2D normal of the silhouette. There the AoLP ψ is parallel to that
//! normal (diffuse-dominant) or perpendicular to it (specular-dominant): 4·(ψ − θ) ≈ 0, with θ the
//! angle of the contour normal. Each of four hypotheses (the capture as loaded, mirrored ψ → −ψ,
//! turned by 90°, both) is scored by the DoLP-weighted mean of cos 4·(ψ_h − θ) (the *axial fit*,
//! 1: every pixel ∥ or ⊥; about 0: scattered) over the contour pixels whose DoLP is reliable and
//! whose normal is at least [`DISCRIMINATING_DEG`] away from the image axes and the diagonals
//! (where a mirrored AoLP would still look ∥ or ⊥: ψ_mirrored − θ = −2θ − (ψ − θ)). A mirrored
//! convention scatters the relation, so its fit drops to about 0 or below.
//!
//! A turn by 90° keeps the axial fit and swaps ∥ for ⊥, which is exactly the difference between a
//! diffuse- and a specular-dominant contour; the shared captures have both (the sphere's and
//! Homer's contours are ⊥, the knot's mixed), and no profile of DoLP across the contour told them
//! apart on all three (Homer's black gloss has a higher DoLP on the contour than inside, as a
//! diffuse object would). So the offset is reported, not judged: the *relation*, the weighted mean
//! of cos 2·(ψ − θ) (+1: ∥, diffuse-like; −1: ⊥, specular-like), says which reflection the
//! contour shows if the stated offset is right.
//!
//! **Colour space.** Behind ideal polarizers at 0/45/90/135°, I0 + I90 = I45 + I135 = S0 holds in
//! linear values and breaks after a gamma (unless the light is unpolarized). The relative residual
//! Σ|I0 + I90 − I45 − I135| / Σ(I0 + I90 + I45 + I135)/2 over the unclipped object pixels is
//! computed on the files' values as stored and after sRGB → linear decoding; the smaller one
//! names the encoding.

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::core::blur::gaussian_blur;
use crate::formats::image_io::{
    read_image_within, srgb_to_linear, Image, ImageFormat, ImageLimits,
};

use super::frame::{ColorSpace, FrameSpec, Header, Source, StokesConvention};
use super::{Measurement, View};

/// Contour pixels whose normal is nearer than this to an image axis or a diagonal do not vote on
/// the mirror (a mirrored AoLP keeps its ∥/⊥ relation to such a normal).
pub const DISCRIMINATING_DEG: f64 = 10.0;
/// Object pixels within this Chebyshev distance of the background form the contour band.
const CONTOUR_BAND: u32 = 2;
/// Standard deviation in pixels of the blur whose gradient gives the contour normal.
const NORMAL_BLUR_SIGMA: f64 = 1.5;
/// A pixel is reliable when its DoLP is at least this (below, the angle is noise) ...
const MIN_DOLP: f64 = 0.02;
/// ... and its S0 at least this fraction of the view's 90th percentile of object S0.
const MIN_S0_FRACTION: f64 = 0.05;
/// Fewer discriminating contour pixels than this: inconclusive.
const MIN_PIXELS: usize = 200;
/// The axial fit of the winning hypothesis must beat the runner-up's (mirror) by this much.
const MIN_FIT_MARGIN: f64 = 0.25;
/// |relation| below this cannot tell ∥ from ⊥.
const MIN_RELATION: f64 = 0.2;
/// Views scored at most (evenly spaced among the full-Stokes views).
const MAX_VIEWS: usize = 16;
/// Views whose polarizer images are read for the colour-space check, at most.
const MAX_COLOR_VIEWS: usize = 4;
/// Per-angle samples at or above this (of full scale) are clipped and left out.
const CLIP_LEVEL: f32 = 0.98;
/// The colour-space residual of one encoding must be this many times smaller than the other's.
/// Clean 8/16-bit captures give ratios far above it (the wrong encoding leaves 0.3–17 % of S0,
/// the right one under 0.01 % on the shared captures); 8-bit JPEG's compression noise, which
/// decoding amplifies, gives 1.6–2.0 on weakly polarized sRGB objects and must stay undecided.
const COLOR_RATIO: f64 = 3.0;

/// One hypothesis about the capture's Stokes angles, relative to how they were loaded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Hypothesis {
    AsStated,
    Mirrored,
    Rotated90,
    MirroredRotated90,
}

impl Hypothesis {
    pub const ALL: [Hypothesis; 4] = [
        Hypothesis::AsStated,
        Hypothesis::Mirrored,
        Hypothesis::Rotated90,
        Hypothesis::MirroredRotated90,
    ];

    pub fn label(self) -> &'static str {
        match self {
            Hypothesis::AsStated => "as stated",
            Hypothesis::Mirrored => "mirrored",
            Hypothesis::Rotated90 => "+90°",
            Hypothesis::MirroredRotated90 => "mirrored+90°",
        }
    }

    fn mirrored(self) -> bool {
        matches!(self, Hypothesis::Mirrored | Hypothesis::MirroredRotated90)
    }

    fn rotated(self) -> bool {
        matches!(self, Hypothesis::Rotated90 | Hypothesis::MirroredRotated90)
    }
}

/// What the data says of the stated convention.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The stated convention fits.
    Consistent,
    /// The angles run the other way (image_y_up ↔ image_y_down).
    Flipped,
    /// Too little evidence, or none of the hypotheses stands out.
    Inconclusive,
}

/// The score of one hypothesis.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct HypothesisScore {
    pub hypothesis: Hypothesis,
    /// DoLP-weighted mean of cos 4(ψ − θ) over the discriminating contour pixels (1: ∥ or ⊥).
    pub axial_fit: f64,
    /// DoLP-weighted mean of cos 2(ψ − θ) over the same pixels (+1: ∥ everywhere, −1: ⊥).
    pub relation: f64,
}

/// Evidence on the Stokes angle convention.
#[derive(Clone, Debug, Serialize)]
pub struct StokesEvidence {
    /// The convention the capture states (or the default), e.g. `image_y_up`.
    pub stated: String,
    pub views: usize,
    /// Contour pixels with a reliable DoLP.
    pub contour_pixels: usize,
    /// Of those, the ones whose normal is away from the axes and diagonals: the pixels scored.
    pub pixels: usize,
    pub scores: Vec<HypothesisScore>,
    pub verdict: Verdict,
    /// One sentence: the verdict and the figures behind it.
    pub explanation: String,
}

/// An encoding of 8/16-bit images.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Encoding {
    Linear,
    Srgb,
}

impl Encoding {
    pub fn label(self) -> &'static str {
        match self {
            Encoding::Linear => "linear",
            Encoding::Srgb => "sRGB",
        }
    }
}

/// Evidence on the colour space of the 8/16-bit polarizer images.
#[derive(Clone, Debug, Serialize)]
pub struct ColorEvidence {
    /// The colour space the capture states, or `sRGB (default for PNG/JPEG)`.
    pub stated: String,
    pub stated_encoding: Encoding,
    pub views: usize,
    pub pixels: usize,
    /// Relative residual of I0 + I90 = I45 + I135 on the values as stored.
    pub residual_as_stored: f64,
    /// The same after sRGB → linear decoding.
    pub residual_srgb_decoded: f64,
    /// The encoding the data fits, `None` when neither residual is [`COLOR_RATIO`] times smaller.
    pub fits: Option<Encoding>,
    pub explanation: String,
}

/// Both checks; either is `None` where the capture has nothing to measure it on.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ConventionsReport {
    pub stokes: Option<StokesEvidence>,
    pub color: Option<ColorEvidence>,
}

impl ConventionsReport {
    /// A warning for each check whose data contradicts what the capture states.
    pub fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        if let Some(s) = &self.stokes {
            if s.verdict == Verdict::Flipped {
                warnings.push(format!(
                    "the capture states stokes_convention {} but its polarization angles \
                     contradict it: {}",
                    s.stated, s.explanation
                ));
            }
        }
        if let Some(c) = &self.color {
            if c.fits.is_some_and(|fits| fits != c.stated_encoding) {
                warnings.push(format!(
                    "the capture's 8/16-bit polarizer images are read as {} but their values \
                     contradict it: {}",
                    c.stated, c.explanation
                ));
            }
        }
        warnings
    }
}

/// Accumulated sums of the Stokes check over views.
#[derive(Clone, Copy, Debug, Default)]
struct StokesSums {
    views: usize,
    contour_pixels: usize,
    pixels: usize,
    weight: f64,
    /// Σ w cos 4Δ, Σ w cos 2Δ for the unmirrored and the mirrored AoLP.
    cos4: [f64; 2],
    cos2: [f64; 2],
}

impl StokesSums {
    fn merge(&mut self, o: &StokesSums) {
        self.views += o.views;
        self.contour_pixels += o.contour_pixels;
        self.pixels += o.pixels;
        self.weight += o.weight;
        for k in 0..2 {
            self.cos4[k] += o.cos4[k];
            self.cos2[k] += o.cos2[k];
        }
    }
}

/// Chebyshev distance of every pixel to the nearest background pixel (0 on background), up to
/// `limit` (pixels farther get `limit + 1`). The image border counts as background.
fn distance_to_background(mask: &Image, limit: u32) -> Vec<u32> {
    let (w, h) = (mask.width, mask.height);
    let mut distance: Vec<u32> = (0..w * h)
        .map(|i| {
            if mask.data[i * mask.channels] >= 0.5 {
                limit + 1
            } else {
                0
            }
        })
        .collect();
    for d in 1..=limit {
        let previous = distance.clone();
        for y in 0..h {
            for x in 0..w {
                let i = y * w + x;
                if previous[i] <= d {
                    continue;
                }
                let at_border = x == 0 || y == 0 || x + 1 == w || y + 1 == h;
                let near = at_border
                    || (y - 1..=y + 1)
                        .any(|yy| (x - 1..=x + 1).any(|xx| previous[yy * w + xx] == d - 1));
                if near {
                    distance[i] = d;
                }
            }
        }
    }
    distance
}

/// The mask blurred by a Gaussian of [`NORMAL_BLUR_SIGMA`] pixels (separable, clamped edges).
fn blurred(mask: &Image) -> Vec<f64> {
    let values: Vec<f64> = mask
        .data
        .chunks_exact(mask.channels)
        .map(|pixel| f64::from(pixel[0]))
        .collect();
    gaussian_blur(&values, mask.width, mask.height, NORMAL_BLUR_SIGMA)
}

/// The Stokes check's sums over one view (S0–S2 RGB, already in the stated convention, made
/// image_y_up; mask one channel).
fn view_sums(s0: &Image, s1: &Image, s2: &Image, mask: &Image) -> StokesSums {
    let (w, h) = (mask.width, mask.height);
    let mut sums = StokesSums {
        views: 1,
        ..StokesSums::default()
    };
    let sum3 = |img: &Image, i: usize| -> f64 {
        img.data[i * img.channels..i * img.channels + img.channels.min(3)]
            .iter()
            .map(|&v| v as f64)
            .sum()
    };
    let object: Vec<usize> = (0..w * h)
        .filter(|&i| mask.data[i * mask.channels] >= 0.5)
        .collect();
    if object.len() < 16 {
        return sums;
    }
    let mut s0_object: Vec<f64> = object.iter().map(|&i| sum3(s0, i)).collect();
    s0_object.sort_by(f64::total_cmp);
    let s0_floor = MIN_S0_FRACTION * s0_object[s0_object.len() * 9 / 10];
    let distance = distance_to_background(mask, CONTOUR_BAND);
    let smooth = blurred(mask);
    let discriminating = DISCRIMINATING_DEG.to_radians();
    let eighth = std::f64::consts::FRAC_PI_4;
    for &i in &object {
        if !(1..=CONTOUR_BAND).contains(&distance[i]) {
            continue;
        }
        let (a, b, c) = (sum3(s0, i), sum3(s1, i), sum3(s2, i));
        if a.is_nan() || a <= s0_floor {
            continue;
        }
        let dolp = (b * b + c * c).sqrt() / a;
        if !(MIN_DOLP..=1.5).contains(&dolp) {
            continue;
        }
        let dolp = dolp.min(1.0);
        let (x, y) = (i % w, i / w);
        let (x0, x1) = (x.saturating_sub(1), (x + 1).min(w - 1));
        let (y0, y1) = (y.saturating_sub(1), (y + 1).min(h - 1));
        let gx = smooth[y * w + x1] - smooth[y * w + x0];
        let gy_down = smooth[y1 * w + x] - smooth[y0 * w + x];
        if gx.hypot(gy_down) < 1e-3 {
            continue;
        }
        sums.contour_pixels += 1;
        // The normal's angle from image-right toward image-up (its sign does not matter mod π).
        let theta = (-gy_down).atan2(gx);
        let off_axis = theta.rem_euclid(eighth);
        if off_axis < discriminating || off_axis > eighth - discriminating {
            continue;
        }
        let psi = 0.5 * c.atan2(b);
        sums.pixels += 1;
        sums.weight += dolp;
        for (k, psi) in [psi, -psi].into_iter().enumerate() {
            let delta = psi - theta;
            sums.cos4[k] += dolp * (4.0 * delta).cos();
            sums.cos2[k] += dolp * (2.0 * delta).cos();
        }
    }
    sums
}

/// Scores the hypotheses on the full-Stokes views of `views` (as loaded: image_y_up, after the
/// stated convention was applied). `None` without a full-Stokes view with a mask.
pub fn stokes_evidence(views: &[View], stated: &str) -> Option<StokesEvidence> {
    use rayon::prelude::*;
    let stokes: Vec<&View> = views
        .iter()
        .filter(|v| matches!(v.measurement, Measurement::Stokes { .. }))
        .filter(|v| v.mask.data.iter().any(|&m| m < 0.5))
        .collect();
    if stokes.is_empty() {
        return None;
    }
    let step = stokes.len().div_ceil(MAX_VIEWS);
    let picked: Vec<&View> = stokes.into_iter().step_by(step).collect();
    let per_view: Vec<StokesSums> = picked
        .par_iter()
        .map(|view| match &view.measurement {
            Measurement::Stokes { s0, s1, s2 } => view_sums(s0, s1, s2, &view.mask),
            _ => StokesSums::default(),
        })
        .collect();
    let mut sums = StokesSums::default();
    per_view.iter().for_each(|s| sums.merge(s));
    Some(evidence_from(&sums, stated))
}

fn evidence_from(sums: &StokesSums, stated: &str) -> StokesEvidence {
    let weight = sums.weight.max(f64::MIN_POSITIVE);
    let scores: Vec<HypothesisScore> = Hypothesis::ALL
        .iter()
        .map(|&h| {
            let k = usize::from(h.mirrored());
            let sign = if h.rotated() { -1.0 } else { 1.0 };
            HypothesisScore {
                hypothesis: h,
                axial_fit: sums.cos4[k] / weight,
                relation: sign * sums.cos2[k] / weight,
            }
        })
        .collect();
    let (fit_stated, fit_mirrored) = (scores[0].axial_fit, scores[1].axial_fit);
    let mirrored = if sums.pixels < MIN_PIXELS {
        None
    } else if fit_stated > fit_mirrored + MIN_FIT_MARGIN {
        Some(false)
    } else if fit_mirrored > fit_stated + MIN_FIT_MARGIN {
        Some(true)
    } else {
        None
    };
    let relation = mirrored.map(|m| scores[usize::from(m)].relation);
    let verdict = match mirrored {
        None => Verdict::Inconclusive,
        Some(false) => Verdict::Consistent,
        Some(true) => Verdict::Flipped,
    };
    let relation_words = match relation {
        Some(r) if r >= MIN_RELATION => format!(
            "contour AoLP ∥ its normal, diffuse-like (relation {r:+.2}; ⊥ under a 90° offset, \
             which the silhouette cannot tell apart)"
        ),
        Some(r) if r <= -MIN_RELATION => format!(
            "contour AoLP ⊥ its normal, specular-like (relation {r:+.2}; ∥ under a 90° offset, \
             which the silhouette cannot tell apart)"
        ),
        Some(r) => format!("contour AoLP a mix of ∥ and ⊥ (relation {r:+.2})"),
        None => "relation undetermined".to_owned(),
    };
    let explanation = format!(
        "{verdict}: axial fit of AoLP to the silhouette normal {:+.2} as stated (and +90°), \
         {:+.2} mirrored (and mirrored+90°) over {} contour pixels of {} view(s) ({} more near \
         the axes or diagonals not scored); {relation_words}",
        scores[0].axial_fit,
        scores[1].axial_fit,
        sums.pixels,
        sums.views,
        sums.contour_pixels - sums.pixels,
        verdict = match verdict {
            Verdict::Consistent => format!("consistent with {stated}"),
            Verdict::Flipped => format!(
                "flipped: the angles run the other way ({})",
                if stated == "image_y_up" {
                    "image_y_down"
                } else {
                    "image_y_up"
                }
            ),
            Verdict::Inconclusive => "inconclusive".to_owned(),
        },
    );
    StokesEvidence {
        stated: stated.to_owned(),
        views: sums.views,
        contour_pixels: sums.contour_pixels,
        pixels: sums.pixels,
        scores,
        verdict,
        explanation,
    }
}

/// Residual sums of the colour-space check: (Σ|residual|, Σ S0) as stored and decoded, pixels.
#[derive(Clone, Copy, Debug, Default)]
struct ColorSums {
    raw: (f64, f64),
    decoded: (f64, f64),
    pixels: usize,
}

/// The colour-space sums over one view's four polarizer images (values as stored, in [0, 1]),
/// over the object pixels of `mask` (every pixel without one).
fn color_sums(images: &[Image; 4], mask: Option<&Image>) -> ColorSums {
    let mut sums = ColorSums::default();
    let [i0, i45, i90, i135] = images;
    let colour = i0.channels.min(3);
    for p in 0..i0.width * i0.height {
        if mask.is_some_and(|m| m.data[p * m.channels] < 0.5) {
            continue;
        }
        for c in 0..colour {
            let v = [i0, i45, i90, i135].map(|img| img.data[p * img.channels + c]);
            if v.iter().any(|&x| x >= CLIP_LEVEL) || v.iter().all(|&x| x <= 0.0) {
                continue;
            }
            let residual = |[a, b, c, d]: [f64; 4]| ((a + c - b - d).abs(), 0.5 * (a + b + c + d));
            let raw = residual(v.map(f64::from));
            let decoded = residual(v.map(|x| f64::from(srgb_to_linear(x))));
            sums.raw.0 += raw.0;
            sums.raw.1 += raw.1;
            sums.decoded.0 += decoded.0;
            sums.decoded.1 += decoded.1;
            sums.pixels += 1;
        }
    }
    sums
}

fn color_evidence_from(
    sums: &ColorSums,
    views: usize,
    stated: Option<ColorSpace>,
) -> ColorEvidence {
    let ratio = |(r, s): (f64, f64)| if s > 0.0 { r / s } else { 0.0 };
    let (raw, decoded) = (ratio(sums.raw), ratio(sums.decoded));
    let fits = if sums.pixels == 0 {
        None
    } else if decoded * COLOR_RATIO < raw {
        Some(Encoding::Srgb)
    } else if raw * COLOR_RATIO < decoded {
        Some(Encoding::Linear)
    } else {
        None
    };
    let (stated_label, stated_encoding) = match stated {
        Some(ColorSpace::Linear) => ("linear".to_owned(), Encoding::Linear),
        Some(ColorSpace::Srgb) => ("sRGB".to_owned(), Encoding::Srgb),
        None => ("sRGB (the default for PNG/JPEG)".to_owned(), Encoding::Srgb),
    };
    let explanation = format!(
        "{}: I0 + I90 − I45 − I135 is {:.3} % of S0 on the values as stored and {:.3} % after \
         sRGB decoding, over {} samples of {} view(s)",
        match fits {
            Some(e) => format!("{} fits", e.label()),
            None => "inconclusive".to_owned(),
        },
        100.0 * raw,
        100.0 * decoded,
        sums.pixels,
        views
    );
    ColorEvidence {
        stated: stated_label,
        stated_encoding,
        views,
        pixels: sums.pixels,
        residual_as_stored: raw,
        residual_srgb_decoded: decoded,
        fits,
        explanation,
    }
}

/// The colour-space evidence of the frames whose four polarizer images are 8/16-bit files (up to
/// [`MAX_COLOR_VIEWS`] of them, read again as stored); `None` without such a frame.
fn color_evidence(frames: &[FrameSpec], header: &Header) -> Option<ColorEvidence> {
    use rayon::prelude::*;
    let candidates: Vec<(&FrameSpec, [PathBuf; 4])> = frames
        .iter()
        .filter_map(|f| match &f.source {
            Source::Polarizer4(files) => Some((f, files.clone().map(|k| k.path))),
            _ => None,
        })
        .collect();
    if candidates.is_empty() {
        return None;
    }
    let step = candidates.len().div_ceil(MAX_COLOR_VIEWS);
    let picked: Vec<_> = candidates.into_iter().step_by(step).collect();
    let per_view: Vec<Option<ColorSums>> = picked
        .par_iter()
        .map(|(spec, files)| {
            let limits =
                ImageLimits::pixels(spec.camera.width as usize, spec.camera.height as usize);
            let read = |path: &PathBuf| read_image_within(path, &limits).ok();
            let images: Vec<(Image, ImageFormat)> = files.iter().filter_map(read).collect();
            // EXR/HDR files are linear by nature: nothing to find out.
            if images
                .iter()
                .any(|(_, format)| format.is_linear_by_default())
            {
                return None;
            }
            let images: Vec<Image> = images.into_iter().map(|(i, _)| i).collect();
            let images: [Image; 4] = images.try_into().ok()?;
            let same = images.iter().all(|i| {
                (i.width, i.height, i.channels)
                    == (images[0].width, images[0].height, images[0].channels)
            });
            if !same {
                return None;
            }
            let mask = spec
                .mask
                .as_ref()
                .and_then(|m| read(&m.path))
                .map(|(m, _)| m)
                .filter(|m| (m.width, m.height) == (images[0].width, images[0].height));
            Some(color_sums(&images, mask.as_ref()))
        })
        .collect();
    let mut sums = ColorSums::default();
    let mut views = 0;
    for s in per_view.iter().flatten() {
        views += 1;
        sums.raw.0 += s.raw.0;
        sums.raw.1 += s.raw.1;
        sums.decoded.0 += s.decoded.0;
        sums.decoded.1 += s.decoded.1;
        sums.pixels += s.pixels;
    }
    (views > 0).then(|| color_evidence_from(&sums, views, header.color_space))
}

/// Both checks on a capture loaded from `path` (as given to [`super::load`]), its transforms
/// document read again for what it states (a COLMAP capture states nothing: image_y_up, and it
/// has no polarizer files).
pub fn check_capture(path: &Path, capture: &super::Capture) -> ConventionsReport {
    // A dataset layout states its conventions through the document it is read as (its
    // `capture.json`), as the loader reads it; a COLMAP folder states none.
    let document = if super::colmap::find_model(path).is_some() {
        None
    } else if let Some(location) = super::layouts::find_layout(path) {
        super::layouts::import(path, &location)
            .ok()
            .map(|imported| imported.document)
    } else {
        super::read_document(&super::transforms_path(path)).ok()
    };
    let parsed = document.map(|document| super::frame::parse(&capture.root, &document));
    match parsed {
        Some(parsed) => check(&parsed.frames, &parsed.header, &capture.views),
        None => ConventionsReport {
            stokes: stokes_evidence(&capture.views, "image_y_up"),
            color: None,
        },
    }
}

/// Both checks on a capture being loaded: its parsed frames and header, and its loaded views.
pub(crate) fn check(frames: &[FrameSpec], header: &Header, views: &[View]) -> ConventionsReport {
    let stated = match header.stokes_convention {
        StokesConvention::ImageYUp => "image_y_up",
        StokesConvention::ImageYDown => "image_y_down",
    };
    ConventionsReport {
        stokes: stokes_evidence(views, stated),
        color: color_evidence(frames, header),
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use serde_json::json;

    use super::*;
    use crate::formats::image_io::{linear_to_srgb, write_exr, write_png};

    const SIZE: usize = 128;

    /// Stokes images of a disc (or, with `square`, an axis-aligned square) whose contour AoLP is
    /// ⊥ (`specular`) or ∥ to the contour normal, DoLP 0.3, S0 1; and its mask.
    fn synthetic(square: bool, specular: bool) -> (Image, Image, Image, Image) {
        let c = SIZE as f64 / 2.0;
        let inside = |x: f64, y: f64| {
            if square {
                (x - c).abs() < 40.0 && (y - c).abs() < 40.0
            } else {
                (x - c).hypot(y - c) < 40.0
            }
        };
        let mask = Image::from_fn(SIZE, SIZE, 1, |x, y, out| {
            out[0] = f32::from(inside(x as f64 + 0.5, y as f64 + 0.5));
        });
        let stokes = |component: usize| {
            Image::from_fn(SIZE, SIZE, 3, |x, y, out| {
                let (dx, dy) = (x as f64 + 0.5 - c, y as f64 + 0.5 - c);
                // The outward normal's angle from image-right toward image-up.
                let theta = if square {
                    if dx.abs() > dy.abs() {
                        0.0
                    } else {
                        std::f64::consts::FRAC_PI_2
                    }
                } else {
                    (-dy).atan2(dx)
                };
                let psi = theta
                    + if specular {
                        std::f64::consts::FRAC_PI_2
                    } else {
                        0.0
                    };
                let v = match component {
                    0 => 1.0,
                    1 => 0.3 * (2.0 * psi).cos(),
                    _ => 0.3 * (2.0 * psi).sin(),
                };
                let on = inside(x as f64 + 0.5, y as f64 + 0.5);
                out.fill(if on { v as f32 } else { 0.0 });
            })
        };
        (stokes(0), stokes(1), stokes(2), mask)
    }

    fn verdict_of(s0: &Image, s1: &Image, s2: &Image, mask: &Image) -> StokesEvidence {
        evidence_from(&view_sums(s0, s1, s2, mask), "image_y_up")
    }

    #[test]
    fn a_disc_is_consistent_as_rendered_and_flipped_mirrored() {
        for specular in [true, false] {
            let (s0, s1, s2, mask) = synthetic(false, specular);
            let e = verdict_of(&s0, &s1, &s2, &mask);
            assert_eq!(e.verdict, Verdict::Consistent, "{}", e.explanation);
            assert!(e.scores[0].axial_fit > 0.9, "{}", e.explanation);
            assert!(e.scores[1].axial_fit < 0.1, "{}", e.explanation);
            // The relation says ∥ or ⊥; the +90° hypothesis says the opposite.
            let expected = if specular { -1.0 } else { 1.0 };
            assert!(
                (e.scores[0].relation - expected).abs() < 0.1,
                "{:?}",
                e.scores
            );
            assert!(
                (e.scores[2].relation + expected).abs() < 0.1,
                "{:?}",
                e.scores
            );
            assert!(e.pixels >= MIN_PIXELS, "{}", e.pixels);

            let mirrored = Image {
                data: s2.data.iter().map(|v| -v).collect(),
                ..s2.clone()
            };
            let e = verdict_of(&s0, &s1, &mirrored, &mask);
            assert_eq!(e.verdict, Verdict::Flipped, "{}", e.explanation);
            assert!(e.scores[1].axial_fit > 0.9, "{}", e.explanation);
        }
    }

    #[test]
    fn an_axis_aligned_square_is_inconclusive() {
        // On horizontal and vertical contours a mirrored AoLP is still ∥ or ⊥.
        let (s0, s1, s2, mask) = synthetic(true, true);
        let e = verdict_of(&s0, &s1, &s2, &mask);
        assert_eq!(e.verdict, Verdict::Inconclusive, "{}", e.explanation);
        assert!(
            e.contour_pixels > 500 && e.pixels < MIN_PIXELS,
            "{}",
            e.explanation
        );
    }

    #[test]
    fn unpolarized_or_dim_pixels_do_not_vote() {
        let (s0, s1, s2, mask) = synthetic(false, true);
        let scaled = |img: &Image, k: f32| Image {
            data: img.data.iter().map(|v| v * k).collect(),
            ..img.clone()
        };
        // DoLP 0.3 % < MIN_DOLP everywhere.
        let e = verdict_of(&s0, &scaled(&s1, 0.01), &scaled(&s2, 0.01), &mask);
        assert_eq!((e.pixels, e.verdict), (0, Verdict::Inconclusive));
    }

    /// Four polarizer images of a DoLP-0.4 ramp, as linear values in [0.05, 0.85].
    fn polarizer_images() -> [Image; 4] {
        [0.0f64, 45.0, 90.0, 135.0].map(|deg| {
            Image::from_fn(64, 64, 3, |x, y, out| {
                let s0 = 0.1 + 0.7 * x as f64 / 63.0;
                let psi = (y as f64 * 3.0).to_radians();
                let t = 2.0 * deg.to_radians();
                let i = 0.5
                    * s0
                    * (1.0 + 0.4 * ((2.0 * psi).cos() * t.cos() + (2.0 * psi).sin() * t.sin()));
                out.fill((2.0 * i) as f32 * 0.5);
            })
        })
    }

    #[test]
    fn the_polarizer_identity_names_the_encoding() {
        let linear = polarizer_images();
        let sums = color_sums(&linear, None);
        let e = color_evidence_from(&sums, 1, None);
        assert_eq!(e.fits, Some(Encoding::Linear), "{}", e.explanation);
        assert!(e.residual_as_stored < 1e-6, "{}", e.explanation);
        assert!(e.residual_srgb_decoded > 0.02, "{}", e.explanation);
        let encoded = linear.clone().map(|i| Image {
            data: i.data.iter().map(|&v| linear_to_srgb(v)).collect(),
            ..i
        });
        let e = color_evidence_from(&color_sums(&encoded, None), 1, Some(ColorSpace::Linear));
        assert_eq!(e.fits, Some(Encoding::Srgb), "{}", e.explanation);
        assert!(e.residual_srgb_decoded < 1e-5, "{}", e.explanation);
        let report = ConventionsReport {
            stokes: None,
            color: Some(e),
        };
        let warnings = report.warnings();
        assert_eq!(warnings.len(), 1);
        assert!(warnings[0].contains("read as linear") && warnings[0].contains("sRGB fits"));
        // Unpolarized light satisfies the identity in any encoding: inconclusive.
        let flat = [0; 4].map(|_| Image::from_fn(8, 8, 3, |x, _, o| o.fill(x as f32 / 9.0)));
        assert_eq!(
            color_evidence_from(&color_sums(&flat, None), 1, None).fits,
            None
        );
    }

    /// Writes the 16-bit PNG `image` (values clamped to [0, 1], sRGB-encoded with `srgb`).
    fn write_png16(path: &Path, image: &Image, srgb: bool) {
        let data: Vec<u16> = image
            .data
            .iter()
            .map(|&v| {
                let v = if srgb { linear_to_srgb(v) } else { v };
                (v.clamp(0.0, 1.0) * 65535.0).round() as u16
            })
            .collect();
        image::ImageBuffer::<image::Rgb<u16>, Vec<u16>>::from_raw(
            image.width as u32,
            image.height as u32,
            data,
        )
        .unwrap()
        .save(path)
        .unwrap();
    }

    /// How the copy of a shared capture stores its measurement.
    #[derive(Clone, Copy, PartialEq)]
    enum Copy {
        /// S0–S2 EXR, S2 negated when `mirrored`.
        Stokes { mirrored: bool },
        /// Four 16-bit PNG polarizer images, sRGB-encoded or linear.
        Polarizer { srgb: bool },
    }

    /// A copy of `views` (of a loaded shared capture) in `dir`, stating `top` keys.
    fn write_copy(dir: &Path, views: &[&View], copy: Copy, top: serde_json::Value) {
        let mut frames = Vec::new();
        for (k, view) in views.iter().enumerate() {
            let Measurement::Stokes { s0, s1, s2 } = &view.measurement else {
                panic!("full-Stokes views");
            };
            let mut frame = json!({
                "transform_matrix": view.camera.c2w.transpose().to_cols_array_2d(),
                "mask_path": format!("mask{k}.png"),
                "split": if k == 0 { "test" } else { "train" },
            });
            write_png(&dir.join(format!("mask{k}.png")), &view.mask, false).unwrap();
            match copy {
                Copy::Stokes { mirrored } => {
                    let s2 = Image {
                        data: s2
                            .data
                            .iter()
                            .map(|&v| if mirrored { -v } else { v })
                            .collect(),
                        ..s2.clone()
                    };
                    for (name, image) in [("s0", s0), ("s1", s1), ("s2", &s2)] {
                        write_exr(&dir.join(format!("{name}_{k}.exr")), image).unwrap();
                        frame[format!("{name}_path")] = format!("{name}_{k}.exr").into();
                    }
                }
                Copy::Polarizer { srgb } => {
                    // Exposed so that the object's 99th percentile of S0 sits at 0.8 of full scale.
                    let mut object: Vec<f32> = s0
                        .data
                        .chunks(3)
                        .zip(&view.mask.data)
                        .filter(|(_, &m)| m > 0.5)
                        .map(|(p, _)| p.iter().copied().fold(0.0, f32::max))
                        .collect();
                    object.sort_by(f32::total_cmp);
                    let gain = 0.8 / object[object.len() * 99 / 100].max(1e-6);
                    for deg in [0u32, 45, 90, 135] {
                        let t = 2.0 * (deg as f32).to_radians();
                        let image = Image {
                            data: (0..s0.data.len())
                                .map(|i| {
                                    gain * 0.5
                                        * (s0.data[i] + s1.data[i] * t.cos() + s2.data[i] * t.sin())
                                })
                                .collect(),
                            ..s0.clone()
                        };
                        let name = format!("pol{deg:03}_{k}.png");
                        write_png16(&dir.join(&name), &image, srgb);
                        frame[format!("pol{deg:03}_path")] = name.into();
                    }
                }
            }
            frames.push(frame);
        }
        let s0 = &views[0].camera;
        let mut document = json!({
            "w": s0.width, "h": s0.height, "fl_x": s0.fx, "fl_y": s0.fy, "cx": s0.cx, "cy": s0.cy,
            "world_up": [0, 0, 1], "frames": frames,
        });
        for (key, value) in top.as_object().unwrap() {
            document[key] = value.clone();
        }
        std::fs::write(dir.join("transforms.json"), document.to_string()).unwrap();
    }

    /// Loads a copy and runs the checks as `phygap inspect` does.
    fn checked(dir: &Path) -> (ConventionsReport, Vec<String>) {
        let capture = super::super::load(dir).unwrap();
        (check_capture(dir, &capture), capture.warnings)
    }

    /// Every shared capture: as shipped its convention is consistent; a copy with its angles
    /// mirrored is flipped (warned about when it states image_y_up, consistent when it states
    /// image_y_down); per-angle 16-bit PNGs written sRGB-encoded are found sRGB (warned about
    /// when the capture says linear), and written linear are found linear.
    #[test]
    fn shared_captures_flipped_or_srgb_encoded_are_detected() {
        let Some(data) = crate::testing::shared_data_dir() else {
            return;
        };
        for scene in ["sphere", "knot", "homer"] {
            let capture = super::super::load(&data.join(scene)).unwrap();
            let report = check_capture(&data.join(scene), &capture);
            let stokes = report.stokes.expect("full-Stokes views");
            eprintln!("{scene}: {}", stokes.explanation);
            assert_eq!(
                stokes.verdict,
                Verdict::Consistent,
                "{scene}: {}",
                stokes.explanation
            );
            assert!(
                report.color.is_none(),
                "{scene}: EXR polarizer images are linear"
            );
            assert!(
                capture.warnings.is_empty(),
                "{scene}: {:?}",
                capture.warnings
            );

            // Five views, evenly spread.
            let views: Vec<&View> = capture.views.iter().step_by(11).take(5).collect();
            let dir = tempfile::tempdir().unwrap();
            write_copy(
                dir.path(),
                &views,
                Copy::Stokes { mirrored: true },
                json!({}),
            );
            let (report, warnings) = checked(dir.path());
            let stokes = report.stokes.unwrap();
            eprintln!("{scene} mirrored: {}", stokes.explanation);
            assert_eq!(
                stokes.verdict,
                Verdict::Flipped,
                "{scene}: {}",
                stokes.explanation
            );
            assert!(
                warnings
                    .iter()
                    .any(|w| w.contains("states stokes_convention image_y_up")),
                "{scene}: {warnings:?}"
            );
            let down = json!({"stokes_convention": "image_y_down"});
            write_copy(dir.path(), &views, Copy::Stokes { mirrored: true }, down);
            let (report, warnings) = checked(dir.path());
            assert_eq!(
                report.stokes.unwrap().verdict,
                Verdict::Consistent,
                "{scene}"
            );
            assert!(warnings.is_empty(), "{scene}: {warnings:?}");

            let linear = json!({"color_space": "linear"});
            write_copy(
                dir.path(),
                &views,
                Copy::Polarizer { srgb: true },
                linear.clone(),
            );
            let (report, warnings) = checked(dir.path());
            let color = report.color.unwrap();
            eprintln!("{scene} sRGB: {}", color.explanation);
            assert_eq!(
                color.fits,
                Some(Encoding::Srgb),
                "{scene}: {}",
                color.explanation
            );
            assert!(
                color.residual_as_stored > 5.0 * color.residual_srgb_decoded,
                "{scene}: {}",
                color.explanation
            );
            assert!(
                warnings
                    .iter()
                    .any(|w| w.contains("read as linear") && w.contains("sRGB fits")),
                "{scene}: {warnings:?}"
            );
            // Stated by default (PNG: sRGB): nothing to warn about.
            write_copy(
                dir.path(),
                &views,
                Copy::Polarizer { srgb: true },
                json!({}),
            );
            let (report, warnings) = checked(dir.path());
            assert_eq!(report.color.unwrap().fits, Some(Encoding::Srgb), "{scene}");
            assert!(warnings.is_empty(), "{scene}: {warnings:?}");
            // Linear PNGs read as sRGB by default are caught too.
            write_copy(
                dir.path(),
                &views,
                Copy::Polarizer { srgb: false },
                json!({}),
            );
            let (report, warnings) = checked(dir.path());
            let color = report.color.unwrap();
            eprintln!("{scene} linear PNG: {}", color.explanation);
            assert_eq!(
                color.fits,
                Some(Encoding::Linear),
                "{scene}: {}",
                color.explanation
            );
            assert!(
                warnings.iter().any(|w| w.contains("read as sRGB")),
                "{scene}: {warnings:?}"
            );
            write_copy(dir.path(), &views, Copy::Polarizer { srgb: false }, linear);
            let (_, warnings) = checked(dir.path());
            assert!(warnings.is_empty(), "{scene}: {warnings:?}");
        }
    }
}

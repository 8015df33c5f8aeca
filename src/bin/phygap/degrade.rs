//! `phygap degrade CAPTURE --out DIR [--preset machine-vision] [settings]`: a realistic capture
//! from a clean one (sensor bit depth and Poisson-Gaussian noise, JPEG, per-view exposure and
//! white balance, vignetting, pose noise, mask erosion/dilation, a polarizer angle offset, a
//! cluttered backdrop); the
//! model is [`phygap::io::capture::degrade`]'s.

use std::path::PathBuf;

use anyhow::Result;
use clap::{Args, ValueEnum};

use phygap::io::capture::degrade::{self, DegradeOptions, OutputFormat};

/// Starting points for the settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Preset {
    /// Nothing changed but the storage (16-bit, no noise).
    None,
    /// 12-bit, 10,000 e⁻ full well, read noise 0.5 % of full scale, exposure ±20 %, white
    /// balance ±10 %, pose noise 0.5° and 1 % of the object's radius, masks ±2 px.
    MachineVision,
}

/// How the per-angle images are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Float EXR in the clean capture's radiance units (after quantization and noise).
    Exr,
    /// 16-bit PNG holding the sensor's values linearly (`color_space: linear`).
    Png,
    /// 8-bit sRGB JPEG (needs --bits 8 or less; --jpeg-quality).
    Jpeg,
}

/// Arguments of `phygap degrade`.
#[derive(Args, Debug)]
pub struct DegradeArgs {
    /// The clean capture (full-Stokes views).
    pub capture: PathBuf,
    /// Folder to write the degraded capture to (transforms.json, pol000…pol135/, mask/,
    /// degrade.json with the settings and the true poses).
    #[arg(long)]
    pub out: PathBuf,
    /// Settings to start from; each flag below overrides its part.
    #[arg(long, value_enum, default_value = "none")]
    pub preset: Preset,
    /// Storage of the per-angle images.
    #[arg(long, value_enum)]
    pub format: Option<Format>,
    /// Sensor bit depth (1–16).
    #[arg(long)]
    pub bits: Option<u32>,
    /// Full-well capacity in electrons (shot noise); 0: none.
    #[arg(long)]
    pub full_well: Option<f64>,
    /// Read noise, standard deviation as a fraction of full scale.
    #[arg(long)]
    pub read_noise: Option<f64>,
    /// JPEG quality 1–100 (implies --format jpeg).
    #[arg(long)]
    pub jpeg_quality: Option<u8>,
    /// Per-view exposure uniform in 1 ± this.
    #[arg(long)]
    pub exposure: Option<f64>,
    /// Per-view, per-channel white-balance gain uniform in 1 ± this.
    #[arg(long)]
    pub white_balance: Option<f64>,
    /// Vignetting: brightness 1 − this at the image corners.
    #[arg(long)]
    pub vignetting: Option<f64>,
    /// Pose rotation noise: root mean square of the rotation angle, in degrees.
    #[arg(long)]
    pub rotation_deg: Option<f64>,
    /// Pose translation noise: root mean square of the shift, as a fraction of the object's radius.
    #[arg(long)]
    pub translation: Option<f64>,
    /// Masks eroded or dilated per view by a whole number of pixels in ±this.
    #[arg(long)]
    pub mask_px: Option<u32>,
    /// Polarizer angle offset in degrees (the polarizers sit this far off 0/45/90/135°).
    #[arg(long, allow_hyphen_values = true)]
    pub polarizer_offset_deg: Option<f64>,
    /// A distant cluttered backdrop behind the object, its mean this fraction of the object's
    /// bright level (0: black, as rendered); what a photograph shows beyond the mask.
    #[arg(long)]
    pub background: Option<f64>,
    /// Seed of every random draw.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
}

impl DegradeArgs {
    /// The preset, then the flags given.
    pub fn options(&self) -> DegradeOptions {
        let mut o = match self.preset {
            Preset::None => DegradeOptions::default(),
            Preset::MachineVision => DegradeOptions::machine_vision(),
        };
        let set = |target: &mut f64, value: Option<f64>| {
            if let Some(v) = value {
                *target = v;
            }
        };
        o.bit_depth = self.bits.unwrap_or(o.bit_depth);
        if let Some(well) = self.full_well {
            o.full_well = (well > 0.0).then_some(well);
        }
        set(&mut o.read_noise, self.read_noise);
        set(&mut o.exposure_range, self.exposure);
        set(&mut o.white_balance_range, self.white_balance);
        set(&mut o.vignetting, self.vignetting);
        set(&mut o.rotation_sigma_deg, self.rotation_deg);
        set(&mut o.translation_sigma, self.translation);
        set(&mut o.polarizer_offset_deg, self.polarizer_offset_deg);
        set(&mut o.background, self.background);
        o.mask_px = self.mask_px.unwrap_or(o.mask_px);
        if let Some(quality) = self.jpeg_quality {
            o.jpeg_quality = quality;
            o.format = OutputFormat::Jpeg;
        }
        if let Some(format) = self.format {
            o.format = match format {
                Format::Exr => OutputFormat::Exr,
                Format::Png => OutputFormat::Png,
                Format::Jpeg => OutputFormat::Jpeg,
            };
        }
        if o.format == OutputFormat::Jpeg && self.bits.is_none() {
            o.bit_depth = o.bit_depth.min(8);
        }
        o.seed = self.seed;
        o
    }
}

/// Degrades the capture and prints what was drawn.
pub fn run(args: &DegradeArgs) -> Result<()> {
    let options = args.options();
    let record = degrade::degrade(&args.capture, &args.out, &options)?;
    let n = record.views.len() as f64;
    let rms = |f: &dyn Fn(&degrade::ViewRecord) -> f64| {
        (record.views.iter().map(|v| f(v).powi(2)).sum::<f64>() / n).sqrt()
    };
    println!(
        "wrote {} views to {} (gain {:.4} of full scale per unit radiance; object radius {:.3})",
        record.views.len(),
        args.out.display(),
        record.gain,
        record.object_radius
    );
    println!(
        "pose error rms {:.3}° and {:.4} ({:.2} % of the radius); exposure {:.3}–{:.3}; \
         masks {:+}…{:+} px; true poses and settings in degrade.json",
        rms(&|v| v.rotation_error_deg),
        rms(&|v| v.translation_error),
        100.0 * rms(&|v| v.translation_error) / record.object_radius.max(f64::MIN_POSITIVE),
        record
            .views
            .iter()
            .map(|v| v.exposure)
            .fold(f64::INFINITY, f64::min),
        record.views.iter().map(|v| v.exposure).fold(0.0, f64::max),
        record.views.iter().map(|v| v.mask_px).min().unwrap_or(0),
        record.views.iter().map(|v| v.mask_px).max().unwrap_or(0),
    );
    Ok(())
}

//! `phygap synth --out DIR [--shape sphere|torus|creature] [--texture plain|checker] [--views N]
//! [--size PX] [--raw IMX250MZR|IMX250MYR [--bit-depth B]] [--layout idr|llff]`: render a small
//! full-Stokes sample capture with the project's own renderer, or (with `--raw`) the raw mosaic
//! frames a polarization camera would record of it, or (with `--layout`) the capture as a dataset
//! in the IDR/NeuS or LLFF layout ships.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::io::capture::layouts::LayoutKind;
use phygap::io::capture::mosaic::Sensor;
use phygap::io::capture::simulate::{self, SimulateOptions};
use phygap::io::capture::{self, Measurement};
use phygap::pipeline::synth::{self, Shape, SynthOptions, Texture};

#[derive(Args, Debug)]
pub struct SynthArgs {
    /// Folder to write the capture into.
    #[arg(long)]
    pub out: PathBuf,
    #[arg(long, value_enum, default_value = "sphere")]
    pub shape: Shape,
    /// Albedo pattern.
    #[arg(long, value_enum, default_value = "plain")]
    pub texture: Texture,
    /// Number of views (every 8th is a test view).
    #[arg(long, default_value_t = 24)]
    pub views: usize,
    /// Image size in pixels: `N` (square) or `WxH` (e.g. `1224x1024`, a polarization camera's
    /// half-resolution views).
    #[arg(long, default_value = "96", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Write raw mosaic frames of this sensor instead of Stokes images (the full-Stokes rendering
    /// goes to `OUT/reference`); the full count range is the brightest S0.
    #[arg(long, value_enum)]
    pub raw: Option<Sensor>,
    /// Bits per sample of the raw frames.
    #[arg(long, default_value_t = 12, value_parser = clap::value_parser!(u32).range(8..=16))]
    pub bit_depth: u32,
    /// Write the capture in a dataset layout instead of `transforms.json` (its transforms form
    /// goes to `OUT/reference`): `idr` (per-angle 8-bit JPEG folders I-00 … I-135,
    /// `masks/NNN_pseudo.png`, `cameras_sphere.npz`) or `llff` (16-bit PNG folders pol000 …
    /// pol135, `masks/img_NNN.png`, `poses_bounds.npy`).
    #[arg(long, value_enum, conflicts_with = "raw")]
    pub layout: Option<Layout>,
}

/// A dataset layout `--layout` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Layout {
    Idr,
    Llff,
}

/// `N` or `WxH`.
fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .map_err(|_| format!("`{text}`: expected N or WxH"))
    };
    match text.split_once(['x', 'X', '×']) {
        Some((w, h)) => Ok((side(w)?, side(h)?)),
        None => side(text).map(|n| (n, n)),
    }
}

pub fn run(args: &SynthArgs) -> Result<()> {
    let (width, height) = args.size;
    let options = SynthOptions {
        shape: args.shape,
        views: args.views,
        size: width,
        height: Some(height),
        texture: args.texture,
        ..SynthOptions::default()
    };
    if let Some(sensor) = args.raw {
        let reference = args.out.join("reference");
        synth::synth(&reference, &options)?;
        // The rendering is ours and the user asked for its size: no budget on its decoded bytes
        // (48 views of 2448 × 2048 hold 9 GB).
        let limits = capture::CaptureLimits {
            max_decoded_bytes: u64::MAX,
            ..capture::CaptureLimits::DEFAULT
        };
        let capture = capture::load_within(&reference, &limits)?;
        let full_scale = capture
            .views
            .iter()
            .filter_map(|v| match &v.measurement {
                Measurement::Stokes { s0, .. } => s0.data.iter().copied().reduce(f32::max),
                _ => None,
            })
            .fold(0.0, f32::max);
        let raw = SimulateOptions {
            sensor,
            bit_depth: args.bit_depth,
            full_scale,
            ..SimulateOptions::default()
        };
        simulate::write_raw_capture(&capture, &args.out, &raw)?;
        println!(
            "wrote {} {}-bit {} mosaic frames ({}×{}) of a {:?} to {} (full-Stokes rendering in {})",
            args.views,
            args.bit_depth,
            sensor.name(),
            width,
            height,
            args.shape,
            args.out.display(),
            reference.display()
        );
        return Ok(());
    }
    if let Some(layout) = args.layout {
        let kind = match layout {
            Layout::Idr => LayoutKind::Idr,
            Layout::Llff => LayoutKind::Llff,
        };
        let written = synth::synth_layout(&args.out, &options, kind)?;
        println!(
            "wrote a {}-view {}×{} capture of a {:?} in the {} layout to {} (exposure ×{:.4}: \
             the brightest polarizer sample is 1; the transforms.json form is in {})",
            written.views,
            width,
            height,
            args.shape,
            kind.name(),
            args.out.display(),
            written.exposure,
            args.out.join("reference").display()
        );
        return Ok(());
    }
    synth::synth(&args.out, &options)?;
    println!(
        "wrote a {}-view {}×{} full-Stokes capture of a {:?} to {}",
        args.views,
        width,
        height,
        args.shape,
        args.out.display()
    );
    Ok(())
}

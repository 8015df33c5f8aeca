//! `phygap synth --out DIR [--shape sphere|torus|creature] [--texture plain|checker] [--views N]
//! [--size PX]`: render a small full-Stokes sample capture with the project's own renderer.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

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
    /// Image width and height in pixels.
    #[arg(long, default_value_t = 96)]
    pub size: u32,
}

pub fn run(args: &SynthArgs) -> Result<()> {
    let options = SynthOptions {
        shape: args.shape,
        views: args.views,
        size: args.size,
        texture: args.texture,
        ..SynthOptions::default()
    };
    synth::synth(&args.out, &options)?;
    println!(
        "wrote a {}-view {}×{} full-Stokes capture of a {:?} to {}",
        args.views,
        args.size,
        args.size,
        args.shape,
        args.out.display()
    );
    Ok(())
}

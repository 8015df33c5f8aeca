//! `phygap render MODEL --cameras TRANSFORMS.json --out DIR`: novel views of a trained model — S0,
//! S1, S2, DoLP, AoLP, normal, albedo, roughness, IoR, diffuse, specular and α — as EXR + PNG.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::io::capture;
use phygap::io::model::Model;
use phygap::pipeline::reconstruction::{Reconstruction, OUTPUT_KINDS};

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// Transforms file (or capture folder) whose frames give the cameras; images are not needed.
    #[arg(long)]
    pub cameras: PathBuf,
    /// Output folder: one sub-folder per output kind, files NNN.exr / NNN.png per camera.
    #[arg(long)]
    pub out: PathBuf,
    #[arg(long, help = crate::GRIDMAP_OVERRIDE_HELP)]
    pub gridmap: Option<crate::Switch>,
}

pub fn run(args: &RenderArgs) -> Result<()> {
    let mut model = Model::load(&args.model)?;
    crate::override_gridmap(&mut model, args.gridmap);
    let reconstruction = Reconstruction::new(model)?;
    let cameras = capture::load_cameras(&args.cameras)?;
    let files = reconstruction.render_to_dir(&cameras, &args.out, &OUTPUT_KINDS)?;
    println!(
        "rendered {} views ({} files) into {}",
        cameras.len(),
        files.len(),
        args.out.display()
    );
    Ok(())
}

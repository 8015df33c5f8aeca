//! `phygap relight MODEL --envmap FILE.exr|FILE.hdr [--cameras TRANSFORMS.json] --out DIR
//! [--rotate DEG] [--stokes]`: the model under another environment (GridMap rebuilt for it when the
//! model uses GridMap), S0 as EXR + PNG per camera, and S1/S2 with `--stokes`.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

use phygap::io::capture;
use phygap::io::model::{Model, TEST_CAMERAS_FILE};
use phygap::pipeline::relight::{relit_reconstruction, RELIGHT_KINDS};

#[derive(Args, Debug)]
pub struct RelightArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// Lat-long environment map (linear HDR), mapped with the model's world up.
    #[arg(long)]
    pub envmap: PathBuf,
    /// Transforms file (or capture folder) giving the cameras (default: the model's test cameras).
    #[arg(long)]
    pub cameras: Option<PathBuf>,
    /// Output folder: `s0/NNN.exr|png` (and `s1/`, `s2/` with --stokes).
    #[arg(long)]
    pub out: PathBuf,
    /// Rotation of the map about the world's up axis, degrees.
    #[arg(long, default_value_t = 0.0)]
    pub rotate: f64,
    /// Also write the S1 and S2 images.
    #[arg(long)]
    pub stokes: bool,
    #[arg(long, help = crate::GRIDMAP_OVERRIDE_HELP)]
    pub gridmap: Option<crate::Switch>,
}

pub fn run(args: &RelightArgs) -> Result<()> {
    let mut model = Model::load(&args.model)?;
    crate::override_gridmap(&mut model, args.gridmap);
    let cameras_file = args
        .cameras
        .clone()
        .unwrap_or_else(|| args.model.join(TEST_CAMERAS_FILE));
    let cameras = capture::load_cameras(&cameras_file)?;
    let reconstruction = relit_reconstruction(model, &args.envmap, args.rotate)?;
    let kinds: &[&str] = if args.stokes {
        &RELIGHT_KINDS
    } else {
        &RELIGHT_KINDS[..1]
    };
    let files = reconstruction.render_to_dir(&cameras, &args.out, kinds)?;
    println!(
        "relit {} views ({} files) into {}",
        cameras.len(),
        files.len(),
        args.out.display()
    );
    Ok(())
}

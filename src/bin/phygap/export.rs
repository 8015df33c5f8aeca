//! `phygap export MODEL --out DIR`: the model's deliverables (surfels.ply, mesh.ply, model.glb,
//! envmap.exr/.hdr/.png, config, metrics, test-view renders) in one folder.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;

#[derive(Args, Debug)]
pub struct ExportArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// Folder to write.
    #[arg(long)]
    pub out: PathBuf,
}

pub fn run(args: &ExportArgs) -> Result<()> {
    let files = phygap::pipeline::export::export(&args.model, &args.out)?;
    for f in &files {
        println!("{}", f.display());
    }
    Ok(())
}

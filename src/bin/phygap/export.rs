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
    /// Most triangles of model.glb's mesh (simplified by quadric error, further where the surface
    /// is smooth enough; 0: the dense mesh); default: the model's config's `mesh_triangles`
    /// (100,000 unless trained with another). mesh.ply stays dense.
    #[arg(long)]
    pub mesh_triangles: Option<u32>,
}

pub fn run(args: &ExportArgs) -> Result<()> {
    let files = phygap::pipeline::export::export_with(&args.model, &args.out, args.mesh_triangles)?;
    for f in &files {
        println!("{}", f.display());
    }
    Ok(())
}

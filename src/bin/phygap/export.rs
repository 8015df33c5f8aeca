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
    /// How model.glb carries the materials: `textures` (UV atlas with baked base colour,
    /// metallic-roughness and normal maps) or `vertex` (per-vertex colour and roughness);
    /// default: the model's config's `mesh_materials` (textures unless trained with another).
    #[arg(long, value_enum)]
    pub mesh_materials: Option<phygap::core::config::MeshMaterials>,
}

pub fn run(args: &ExportArgs) -> Result<()> {
    let options = phygap::pipeline::export::ExportOptions {
        mesh_triangles: args.mesh_triangles,
        mesh_materials: args.mesh_materials,
    };
    let files = phygap::pipeline::export::export_with(&args.model, &args.out, options)?;
    for f in &files {
        println!("{}", f.display());
    }
    Ok(())
}

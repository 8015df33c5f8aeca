//! `phygap mesh MODEL --out mesh.ply|mesh.obj [--resolution R]`: the model's surface as a triangle
//! mesh (depth of the surfels from the training cameras, TSDF fusion, marching cubes, largest
//! component).

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use clap::Args;

use phygap::io::model::Model;
use phygap::pipeline::mesh_extraction::{self, DEFAULT_MESH_RESOLUTION};

#[derive(Args, Debug)]
pub struct MeshArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// Output file; the extension (.ply or .obj) chooses the format.
    #[arg(long)]
    pub out: PathBuf,
    /// TSDF voxels along the longest side of the object.
    #[arg(long, default_value_t = DEFAULT_MESH_RESOLUTION)]
    pub resolution: usize,
}

pub fn run(args: &MeshArgs) -> Result<()> {
    let start = Instant::now();
    let model = Model::load(&args.model)?;
    let mesh = mesh_extraction::extract_from_model(&model, args.resolution)?;
    mesh_extraction::write_mesh(&mesh, &args.out)?;
    println!(
        "wrote {} ({} vertices, {} triangles) in {:.2} s",
        args.out.display(),
        mesh.vertices.len(),
        mesh.triangles.len(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}

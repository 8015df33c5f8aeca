//! `phygap mesh MODEL --out mesh.ply|mesh.obj [--resolution R] [--mesh-triangles N] [--gt GT.ply]`:
//! the model's surface as a triangle mesh (depth of the surfels from the training cameras, TSDF
//! fusion, marching cubes, largest component, holes closed, bilateral normal smoothing), dense or
//! simplified to a triangle budget; prints how much of the surface the cameras observed and, given
//! a ground-truth mesh, the Chamfer-L1 and normal errors of the dense and written meshes.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use clap::Args;

use phygap::core::mesh::{chamfer_l1, normal_mae_deg, TriangleMesh};
use phygap::io::model::Model;
use phygap::pipeline::mesh_extraction::{self, MeshResolution};

#[derive(Args, Debug)]
pub struct MeshArgs {
    /// Model folder written by `phygap train`.
    pub model: PathBuf,
    /// Output file; the extension (.ply or .obj) chooses the format.
    #[arg(long)]
    pub out: PathBuf,
    /// TSDF voxels along the longest side of the object; default: a voxel about a pixel's
    /// footprint at the object in the training views, 64 to 256 voxels.
    #[arg(long)]
    pub resolution: Option<usize>,
    /// Simplify to at most this many triangles (quadric error, further where the surface is
    /// smooth enough, as the export's model.glb); default: the dense mesh.
    #[arg(long)]
    pub mesh_triangles: Option<usize>,
    /// Ground-truth mesh: print the Chamfer-L1 distance and the normal error (mean angle) of the
    /// dense and the written mesh against it.
    #[arg(long)]
    pub gt: Option<PathBuf>,
}

pub fn run(args: &MeshArgs) -> Result<()> {
    let start = Instant::now();
    let model = Model::load(&args.model)?;
    let resolution = args
        .resolution
        .map_or(MeshResolution::FromViews, MeshResolution::Voxels);
    let deliverable = mesh_extraction::extract_deliverable(&model, resolution)?;
    println!(
        "surface observed: {:.1}% of its area ({} hole{} closed, {} along the surface around it), voxel {:.4} ({} along the longest side)",
        100.0 * deliverable.observed_fraction,
        deliverable.holes,
        if deliverable.holes == 1 { "" } else { "s" },
        deliverable.holes_continued,
        deliverable.voxel,
        deliverable.resolution
    );
    let simplified = args.mesh_triangles.filter(|&n| n > 0).map(|budget| {
        let (mesh, report) = mesh_extraction::simplify_deliverable(&deliverable, budget);
        println!(
            "simplified: {} → {} triangles (budget {budget}, error {:.2e})",
            report.triangles_before, report.triangles_after, report.error
        );
        mesh
    });
    let mesh = simplified.as_ref().unwrap_or(&deliverable.mesh);
    mesh_extraction::write_mesh(mesh, &args.out)?;
    println!(
        "wrote {} ({} vertices, {} triangles, {} boundary edges) in {:.2} s",
        args.out.display(),
        mesh.vertices.len(),
        mesh.triangles.len(),
        mesh.boundary_edges(),
        start.elapsed().as_secs_f64()
    );
    if let Some(gt_path) = &args.gt {
        let gt = TriangleMesh::read_ply(gt_path)?;
        let report = |name: &str, mesh: &TriangleMesh| -> Result<()> {
            println!(
                "{name}: Chamfer-L1 to GT {:.5}, normal error {:.2}°",
                chamfer_l1(mesh, &gt)?,
                normal_mae_deg(mesh, &gt)?
            );
            Ok(())
        };
        report("dense", &deliverable.mesh)?;
        let (observed, caps) = deliverable
            .mesh
            .split_triangles(deliverable.observed_triangles);
        let part_error = |part: &TriangleMesh| -> Result<String> {
            Ok(if part.triangles.is_empty() {
                "-".to_owned()
            } else {
                format!("{:.2}°", normal_mae_deg(part, &gt)?)
            })
        };
        println!(
            "dense normal error: observed surface {}, caps {}",
            part_error(&observed)?,
            part_error(&caps)?
        );
        if let Some(light) = &simplified {
            report("simplified", light)?;
            println!(
                "simplified to dense: Chamfer-L1 {:.5}",
                chamfer_l1(light, &deliverable.mesh)?
            );
        }
    }
    Ok(())
}

//! Prints timings of TSDF mesh extraction (analytic sphere depth, 48 views of 256×256 at R = 128
//! and 256) and of the BVH on the knot GT mesh (or an icosphere when the shared data is absent).
//!
//! `cargo run --release --example mesh_bench`

use std::path::Path;

use phygap::core::mesh::bench::{time_extraction, time_ray_tracing};
use phygap::core::mesh::TriangleMesh;

fn main() -> anyhow::Result<()> {
    println!("rayon threads: {}", rayon::current_num_threads());
    for resolution in [128, 256] {
        let t = time_extraction(resolution, 48, 256)?;
        println!(
            "extract_mesh R={} views={} {}x{}: {:.2} s, {} vertices, {} triangles, worst radial error {:.3} voxel",
            t.resolution, t.views, t.image_size, t.image_size, t.seconds, t.vertices, t.triangles, t.worst_error_voxels
        );
    }
    let knot = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../shared/data/knot/mesh.ply"
    ));
    let (name, mesh) = if knot.is_file() {
        ("knot", TriangleMesh::read_ply(knot)?)
    } else {
        (
            "icosphere",
            TriangleMesh::icosphere(glam::DVec3::ZERO, 1.0, 5),
        )
    };
    let r = time_ray_tracing(&mesh, 1_000_000);
    println!(
        "bvh on {name}: {} triangles, {} nodes, build {:.1} ms; {} rays, {:.1}% hit; closest hit {:.2} Mrays/s ({:.2} Mrays/s one thread), occlusion {:.2} Mrays/s, closest point {:.2} M queries/s",
        r.triangles,
        r.nodes,
        1e3 * r.build_seconds,
        r.rays,
        100.0 * r.hit_fraction,
        r.rays_per_second / 1e6,
        r.rays_per_second_single_thread / 1e6,
        r.occlusion_rays_per_second / 1e6,
        r.closest_point_queries_per_second / 1e6
    );
    Ok(())
}

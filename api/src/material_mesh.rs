//! The extracted mesh with the learned materials on its vertices, for viewers that draw a mesh
//! with a physically based material (the web page's three.js viewer, MeshLab, Blender). The mesh
//! (`mesh.ply`) only has positions and normals; the materials live on the surfels
//! (`surfels.ply`). Each vertex takes an opacity- and distance-weighted mean of the albedo,
//! roughness and IoR of its nearest opaque surfels.
//!
//! Output: a binary little-endian PLY with vertex `x y z` (`nx ny nz` when the mesh has normals),
//! `red green blue` (the albedo, sRGB-encoded 8-bit, as PLY viewers expect colours), `roughness`
//! (Disney r, the same perceptual roughness as three.js and glTF) and `ior` (float32), and the
//! mesh's faces as `vertex_indices`.

use glam::DVec3;
use phygap::core::kdtree::KdTree;
use phygap::core::surfels::ply::surfels_from_ply;
use phygap::core::surfels::Surfel;
use phygap::formats::ply::{
    parse_ply, to_binary_le, Element, Ply, PlyError, PlyFormat, ScalarType,
};
use thiserror::Error;

/// Surfels averaged per vertex.
const NEIGHBOURS: usize = 8;

/// Surfels at least this opaque carry the surface's material (the rest are fading or floaters).
const OPAQUE: f64 = 0.5;

/// Why the material mesh could not be built.
#[derive(Debug, Error)]
pub enum MaterialMeshError {
    #[error("mesh.ply: {0}")]
    Mesh(PlyError),
    #[error("surfels.ply: {0}")]
    Surfels(PlyError),
    #[error("surfels.ply holds no surfels")]
    NoSurfels,
    #[error("writing the mesh: {0}")]
    Write(PlyError),
}

/// Material values of one vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexMaterial {
    /// Linear albedo.
    pub albedo: DVec3,
    pub roughness: f64,
    pub ior: f64,
}

/// The materials of `points`, each from its nearest surfels (opaque ones when there are any).
pub fn transfer_materials(
    points: &[DVec3],
    surfels: &[Surfel],
) -> Result<Vec<VertexMaterial>, MaterialMeshError> {
    let opaque: Vec<&Surfel> = surfels.iter().filter(|s| s.opacity >= OPAQUE).collect();
    let sources: Vec<&Surfel> = if opaque.is_empty() {
        surfels.iter().collect()
    } else {
        opaque
    };
    if sources.is_empty() {
        return Err(MaterialMeshError::NoSurfels);
    }
    let centres: Vec<DVec3> = sources.iter().map(|s| s.position).collect();
    let tree = KdTree::build(&centres);
    Ok(points
        .iter()
        .map(|&p| {
            let nearest = tree.k_nearest(p, NEIGHBOURS);
            // A Gaussian falloff whose width is the farthest neighbour's distance: the nearest
            // surfels dominate, and a vertex between two materials blends them smoothly.
            let width2 = nearest.last().map_or(1.0, |n| n.1).max(1e-12);
            let mut sum = VertexMaterial {
                albedo: DVec3::ZERO,
                roughness: 0.0,
                ior: 0.0,
            };
            let mut total = 0.0;
            for &(index, distance2) in &nearest {
                let surfel = sources[index];
                let weight = surfel.opacity.max(1e-3) * (-distance2 / (2.0 * width2)).exp();
                sum.albedo += weight * surfel.albedo;
                sum.roughness += weight * surfel.roughness;
                sum.ior += weight * surfel.ior;
                total += weight;
            }
            VertexMaterial {
                albedo: sum.albedo / total,
                roughness: sum.roughness / total,
                ior: sum.ior / total,
            }
        })
        .collect())
}

/// sRGB encoding of a linear value in [0, 1], as an 8-bit level.
fn srgb_level(linear: f64) -> f64 {
    let v = linear.clamp(0.0, 1.0) as f32;
    (phygap::formats::image::linear_to_srgb(v) * 255.0).round() as f64
}

/// `mesh.ply` and `surfels.ply` (their bytes) → the material mesh's PLY bytes.
pub fn material_mesh_ply(
    mesh_ply: &[u8],
    surfels_ply: &[u8],
) -> Result<Vec<u8>, MaterialMeshError> {
    let mesh = parse_ply(mesh_ply).map_err(MaterialMeshError::Mesh)?;
    let vertex = mesh
        .require_element("vertex")
        .map_err(MaterialMeshError::Mesh)?;
    let column = |name: &str| vertex.require_scalar(name).map_err(MaterialMeshError::Mesh);
    let (x, y, z) = (column("x")?, column("y")?, column("z")?);
    let points: Vec<DVec3> = (0..vertex.count)
        .map(|i| DVec3::new(x[i], y[i], z[i]))
        .collect();
    let raw = surfels_from_ply(&parse_ply(surfels_ply).map_err(MaterialMeshError::Surfels)?)
        .map_err(MaterialMeshError::Surfels)?;
    let surfels: Vec<Surfel> = (0..raw.len()).map(|i| raw.get(i)).collect();
    let materials = transfer_materials(&points, &surfels)?;

    let mut out_vertex = Element::new("vertex", vertex.count)
        .with_scalar("x", ScalarType::F32, x.to_vec())
        .with_scalar("y", ScalarType::F32, y.to_vec())
        .with_scalar("z", ScalarType::F32, z.to_vec());
    if let (Some(nx), Some(ny), Some(nz)) = (
        vertex.scalar("nx"),
        vertex.scalar("ny"),
        vertex.scalar("nz"),
    ) {
        out_vertex = out_vertex
            .with_scalar("nx", ScalarType::F32, nx.to_vec())
            .with_scalar("ny", ScalarType::F32, ny.to_vec())
            .with_scalar("nz", ScalarType::F32, nz.to_vec());
    }
    for (c, name) in ["red", "green", "blue"].into_iter().enumerate() {
        let levels = materials.iter().map(|m| srgb_level(m.albedo[c])).collect();
        out_vertex = out_vertex.with_scalar(name, ScalarType::U8, levels);
    }
    out_vertex = out_vertex
        .with_scalar(
            "roughness",
            ScalarType::F32,
            materials.iter().map(|m| m.roughness).collect(),
        )
        .with_scalar(
            "ior",
            ScalarType::F32,
            materials.iter().map(|m| m.ior).collect(),
        );
    let mut elements = vec![out_vertex];
    if let Some(face) = mesh.element("face") {
        let polygons = face
            .list("vertex_indices")
            .or_else(|| face.list("vertex_index"))
            .unwrap_or_default()
            .to_vec();
        elements.push(Element::new("face", face.count).with_list(
            "vertex_indices",
            ScalarType::U8,
            ScalarType::I32,
            polygons,
        ));
    }
    let ply = Ply {
        format: PlyFormat::BinaryLittleEndian,
        comments: vec![
            "phygap mesh with learned materials (albedo as sRGB colour, roughness, ior)".into(),
        ],
        elements,
    };
    to_binary_le(&ply).map_err(MaterialMeshError::Write)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DMat3, DVec2};

    fn surfel(position: DVec3, albedo: DVec3, roughness: f64, ior: f64, opacity: f64) -> Surfel {
        Surfel {
            position,
            scale: DVec2::splat(0.01),
            rotation: DMat3::IDENTITY,
            opacity,
            albedo,
            roughness,
            ior,
        }
    }

    #[test]
    fn each_vertex_takes_the_material_of_the_surfels_around_it() {
        // A red rough cluster at x = -1 and a blue smooth one at x = +1, plus a transparent
        // floater (green) right on the first vertex that must be ignored.
        let mut surfels = Vec::new();
        for k in 0..10 {
            let jitter = DVec3::new(0.0, 0.01 * k as f64, 0.0);
            surfels.push(surfel(
                DVec3::new(-1.0, 0.0, 0.0) + jitter,
                DVec3::new(0.8, 0.1, 0.1),
                0.9,
                1.4,
                0.95,
            ));
            surfels.push(surfel(
                DVec3::new(1.0, 0.0, 0.0) + jitter,
                DVec3::new(0.1, 0.1, 0.8),
                0.1,
                2.0,
                0.95,
            ));
        }
        surfels.push(surfel(
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            0.5,
            1.7,
            0.05,
        ));
        let points = [DVec3::new(-1.0, 0.0, 0.0), DVec3::new(1.0, 0.05, 0.0)];
        let m = transfer_materials(&points, &surfels).unwrap();
        assert!(
            (m[0].albedo - DVec3::new(0.8, 0.1, 0.1)).length() < 1e-9,
            "{:?}",
            m[0]
        );
        assert!((m[0].roughness - 0.9).abs() < 1e-9 && (m[0].ior - 1.4).abs() < 1e-9);
        assert!(
            (m[1].albedo - DVec3::new(0.1, 0.1, 0.8)).length() < 1e-9,
            "{:?}",
            m[1]
        );
        assert!((m[1].roughness - 0.1).abs() < 1e-9 && (m[1].ior - 2.0).abs() < 1e-9);
        assert!(matches!(
            transfer_materials(&points, &[]),
            Err(MaterialMeshError::NoSurfels)
        ));
    }

    #[test]
    fn garbage_inputs_are_errors_not_panics() {
        assert!(matches!(
            material_mesh_ply(b"not a ply", b"ply\n"),
            Err(MaterialMeshError::Mesh(_))
        ));
        let triangle = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        assert!(matches!(
            material_mesh_ply(triangle, b"junk"),
            Err(MaterialMeshError::Surfels(_))
        ));
    }
}

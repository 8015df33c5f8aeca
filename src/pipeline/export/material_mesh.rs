//! The extracted mesh with the learned materials on its vertices, for viewers that draw a mesh
//! with a physically based material (the web page's three.js viewer, MeshLab, Blender). The mesh
//! (`mesh.ply`) only has positions and normals; the materials live on the surfels
//! (`surfels.ply`). Each vertex takes an opacity- and distance-weighted mean of the albedo,
//! roughness and IoR of its nearest opaque surfels ([`super::materials`], which the
//! export's `model.glb` uses too).
//!
//! Output: a binary little-endian PLY with vertex `x y z` (`nx ny nz` when the mesh has normals),
//! `red green blue` (the albedo, sRGB-encoded 8-bit, as PLY viewers expect colours), `roughness`
//! (Disney r, the same perceptual roughness as three.js and glTF) and `ior` (float32), and the
//! mesh's faces as `vertex_indices`.

use super::materials::{surfel_list, transfer_materials, MaterialError};
use crate::core::surfels::ply::surfels_from_ply;
use crate::formats::ply::{parse_ply, to_binary_le, Element, Ply, PlyError, PlyFormat, ScalarType};
use glam::DVec3;
use thiserror::Error;

/// Why the material mesh could not be built.
#[derive(Debug, Error)]
pub enum MaterialMeshError {
    #[error("mesh.ply: {0}")]
    Mesh(PlyError),
    #[error("surfels.ply: {0}")]
    Surfels(PlyError),
    #[error("surfels.ply: {0}")]
    Materials(#[from] MaterialError),
    #[error("writing the mesh: {0}")]
    Write(PlyError),
}

/// sRGB encoding of a linear value in [0, 1], as an 8-bit level.
fn srgb_level(linear: f64) -> f64 {
    let v = linear.clamp(0.0, 1.0) as f32;
    (crate::formats::image_io::linear_to_srgb(v) * 255.0).round() as f64
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
    let materials = transfer_materials(&points, &surfel_list(&raw))?;

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

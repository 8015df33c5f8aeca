//! Triangle meshes from and to PLY files: float `x y z` (and `nx ny nz` when present) per vertex,
//! `list uchar int vertex_indices` (polygons are fan-triangulated on reading) and an optional
//! `uchar material_id` per face — the layout of the datasets' GT `mesh.ply` (DATA_FORMAT.md §8).

use std::path::Path;

use glam::DVec3;

use crate::ply::{read_ply, write_ply, Element, Ply, PlyError, PlyFormat, ScalarType};

/// An indexed triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    pub positions: Vec<DVec3>,
    /// Per-vertex normals, or empty.
    pub normals: Vec<DVec3>,
    /// Vertex indices, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// Per-triangle material ids, or empty.
    pub material_ids: Vec<u8>,
}

impl TriangleMesh {
    /// The three corners of triangle `t`.
    pub fn corners(&self, t: usize) -> [DVec3; 3] {
        self.triangles[t].map(|i| self.positions[i as usize])
    }
}

/// Reads a triangle mesh from a PLY file.
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, PlyError> {
    mesh_from_ply(&read_ply(path)?)
}

/// Extracts the triangle mesh of a PLY document.
pub fn mesh_from_ply(ply: &Ply) -> Result<TriangleMesh, PlyError> {
    let vertex = ply.require_element("vertex")?;
    let column = |name: &str| vertex.require_scalar(name);
    let (x, y, z) = (column("x")?, column("y")?, column("z")?);
    let positions: Vec<DVec3> = (0..vertex.count)
        .map(|i| DVec3::new(x[i], y[i], z[i]))
        .collect();
    let normals = match (
        vertex.scalar("nx"),
        vertex.scalar("ny"),
        vertex.scalar("nz"),
    ) {
        (Some(nx), Some(ny), Some(nz)) => (0..vertex.count)
            .map(|i| DVec3::new(nx[i], ny[i], nz[i]))
            .collect(),
        _ => Vec::new(),
    };
    let mut triangles = Vec::new();
    let mut material_ids = Vec::new();
    if let Some(face) = ply.element("face") {
        let lists = face
            .list("vertex_indices")
            .or_else(|| face.list("vertex_index"))
            .ok_or_else(|| PlyError::MissingProperty {
                element: "face".into(),
                property: "vertex_indices".into(),
            })?;
        let materials = face.scalar("material_id");
        for (row, list) in lists.iter().enumerate() {
            let index = |v: f64| -> Result<u32, PlyError> {
                if v >= 0.0 && (v as usize) < positions.len() && v.fract() == 0.0 {
                    Ok(v as u32)
                } else {
                    Err(PlyError::Body {
                        element: "face".into(),
                        row,
                        message: format!("vertex index {v} out of range (0..{})", positions.len()),
                    })
                }
            };
            if list.len() < 3 {
                return Err(PlyError::Body {
                    element: "face".into(),
                    row,
                    message: format!("a face needs 3 or more vertices, found {}", list.len()),
                });
            }
            for k in 1..list.len() - 1 {
                triangles.push([index(list[0])?, index(list[k])?, index(list[k + 1])?]);
                if let Some(m) = materials {
                    material_ids.push(m[row].clamp(0.0, 255.0) as u8);
                }
            }
        }
    }
    Ok(TriangleMesh {
        positions,
        normals,
        triangles,
        material_ids,
    })
}

/// The PLY document of a mesh (float positions and normals, int indices, uchar material ids).
pub fn mesh_to_ply(mesh: &TriangleMesh) -> Result<Ply, PlyError> {
    let n = mesh.positions.len();
    let axis = |v: &[DVec3], a: usize| v.iter().map(|p| p[a]).collect::<Vec<f64>>();
    let mut vertex = Element::new("vertex", n)
        .with_scalar("x", ScalarType::F32, axis(&mesh.positions, 0))
        .with_scalar("y", ScalarType::F32, axis(&mesh.positions, 1))
        .with_scalar("z", ScalarType::F32, axis(&mesh.positions, 2));
    if !mesh.normals.is_empty() {
        if mesh.normals.len() != n {
            return Err(PlyError::Invalid {
                element: "vertex".into(),
                message: format!("{} normals for {n} vertices", mesh.normals.len()),
            });
        }
        vertex = vertex
            .with_scalar("nx", ScalarType::F32, axis(&mesh.normals, 0))
            .with_scalar("ny", ScalarType::F32, axis(&mesh.normals, 1))
            .with_scalar("nz", ScalarType::F32, axis(&mesh.normals, 2));
    }
    let lists = mesh
        .triangles
        .iter()
        .map(|t| t.iter().map(|&i| i as f64).collect())
        .collect();
    let mut face = Element::new("face", mesh.triangles.len()).with_list(
        "vertex_indices",
        ScalarType::U8,
        ScalarType::I32,
        lists,
    );
    if !mesh.material_ids.is_empty() {
        let ids = mesh.material_ids.iter().map(|&m| m as f64).collect();
        face = face.with_scalar("material_id", ScalarType::U8, ids);
    }
    Ok(Ply {
        format: PlyFormat::BinaryLittleEndian,
        comments: vec!["written by phygap".into()],
        elements: vec![vertex, face],
    })
}

/// Writes a mesh as binary little-endian PLY.
pub fn write_mesh(path: &Path, mesh: &TriangleMesh) -> Result<(), PlyError> {
    write_ply(path, &mesh_to_ply(mesh)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetrahedron() -> TriangleMesh {
        let positions = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
        ];
        let normals = positions
            .iter()
            .map(|p| (*p - DVec3::splat(0.25)).normalize())
            .collect();
        TriangleMesh {
            positions,
            normals,
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
            material_ids: vec![1, 1, 2, 2],
        }
    }

    #[test]
    fn mesh_round_trip() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.ply");
        let mesh = tetrahedron();
        write_mesh(&path, &mesh).unwrap();
        let back = read_mesh(&path).unwrap();
        assert_eq!(back.triangles, mesh.triangles);
        assert_eq!(back.material_ids, mesh.material_ids);
        assert_eq!(back.positions, mesh.positions, "exact in f32");
        for (a, b) in back.normals.iter().zip(&mesh.normals) {
            assert!((*a - *b).length() < 1e-7);
        }
        // The header is the GT mesh's layout.
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        assert!(text.contains("property list uchar int vertex_indices\nproperty uchar material_id"));
    }

    #[test]
    fn polygons_are_fan_triangulated_and_bad_indices_rejected() {
        let quad = b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
        let mesh = mesh_from_ply(&crate::ply::parse_ply(quad).unwrap()).unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert!(mesh.normals.is_empty());
        let bad = String::from_utf8_lossy(quad).replace("4 0 1 2 3", "3 0 1 9");
        let e = mesh_from_ply(&crate::ply::parse_ply(bad.as_bytes()).unwrap()).unwrap_err();
        assert!(e.to_string().contains("vertex index 9 out of range"), "{e}");
    }

    #[test]
    fn reads_the_shared_gt_meshes() {
        let data = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data"));
        if !data.exists() {
            eprintln!("skipping: ../shared/data not found");
            return;
        }
        let knot = read_mesh(&data.join("knot/mesh.ply")).unwrap();
        assert_eq!((knot.positions.len(), knot.triangles.len()), (16384, 32768));
        assert!(knot.material_ids.iter().all(|&m| m == 1));
        let sphere = read_mesh(&data.join("sphere/mesh.ply")).unwrap();
        assert_eq!(
            (sphere.positions.len(), sphere.triangles.len()),
            (10242, 20480)
        );
        for (p, n) in sphere.positions.iter().zip(&sphere.normals) {
            assert!((p.length() - 1.0).abs() < 1e-6 && (*p - *n).length() < 1e-5);
        }
        // Counter-clockwise seen from outside: geometric normals point away from the centre.
        for t in 0..sphere.triangles.len() {
            let [a, b, c] = sphere.corners(t);
            assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
        }
    }
}

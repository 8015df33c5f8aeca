//! PLY reading and writing for triangle meshes: a typed layer over the crate's one PLY parser
//! ([`crate::formats::ply`]: ASCII, binary little- and big-endian, any element and property order, every
//! PLY type; unknown elements and properties are ignored).
//!
//! It takes `x y z` and optional `nx ny nz` from `vertex`; `vertex_indices` (or `vertex_index`)
//! from `face`, fan-triangulating polygons; and the optional per-face `material_id` (1-based index
//! into scene.json's materials), repeated on every triangle of its polygon. The writer emits the
//! GT meshes' layout (DATA_FORMAT.md §8): binary little-endian, float positions and normals,
//! `list uchar int vertex_indices`, `uchar material_id` when the mesh has material ids.

use std::path::Path;

use crate::formats::ply::{parse_ply, to_binary_le, Element, Ply, PlyError, PlyFormat, ScalarType};

use super::{MeshError, TriangleMesh};

pub(super) fn read_ply(path: &Path) -> Result<TriangleMesh, MeshError> {
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_ply(&bytes)
        .and_then(|document| mesh_from_ply(&document))
        .map_err(|source| MeshError::Ply {
            path: path.to_path_buf(),
            source,
        })
}

pub(super) fn write_ply(mesh: &TriangleMesh, path: &Path) -> Result<(), MeshError> {
    let bytes = to_binary_le(&mesh_to_ply(mesh)).map_err(|source| MeshError::Ply {
        path: path.to_path_buf(),
        source,
    })?;
    std::fs::write(path, bytes).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// The triangle mesh of a PLY document. A `vertex` element with `x y z` is required; a missing
/// `face` element gives a mesh without triangles. Every index must name a vertex, every polygon
/// have 3 or more corners, every position and normal be finite.
pub(super) fn mesh_from_ply(ply: &Ply) -> Result<TriangleMesh, PlyError> {
    let vertex = ply.require_element("vertex")?;
    let column = |name: &str| vertex.require_scalar(name);
    let (x, y, z) = (column("x")?, column("y")?, column("z")?);
    let vertices: Vec<[f64; 3]> = (0..vertex.count).map(|i| [x[i], y[i], z[i]]).collect();
    let normals: Vec<[f64; 3]> = match (
        vertex.scalar("nx"),
        vertex.scalar("ny"),
        vertex.scalar("nz"),
    ) {
        (Some(nx), Some(ny), Some(nz)) => {
            (0..vertex.count).map(|i| [nx[i], ny[i], nz[i]]).collect()
        }
        _ => Vec::new(),
    };
    let not_finite = |v: &[f64; 3]| !v.iter().all(|c| c.is_finite());
    if let Some(row) = (0..vertex.count)
        .find(|&i| not_finite(&vertices[i]) || normals.get(i).is_some_and(not_finite))
    {
        return Err(PlyError::Body {
            element: "vertex".into(),
            row,
            message: "position or normal is not finite".into(),
        });
    }
    let mut triangles = Vec::new();
    let mut material_ids = Vec::new();
    if let Some(face) = ply.element("face") {
        let polygons = face
            .list("vertex_indices")
            .or_else(|| face.list("vertex_index"))
            .ok_or_else(|| PlyError::MissingProperty {
                element: "face".into(),
                property: "vertex_indices".into(),
            })?;
        let materials = face.scalar("material_id");
        triangles.reserve(polygons.len());
        for (row, polygon) in polygons.iter().enumerate() {
            let face_error = |message: String| PlyError::Body {
                element: "face".into(),
                row,
                message,
            };
            let index = |v: f64| -> Result<u32, PlyError> {
                if v >= 0.0 && v.fract() == 0.0 && v < vertices.len() as f64 {
                    Ok(v as u32)
                } else {
                    Err(face_error(format!(
                        "vertex index {v} out of range (0..{})",
                        vertices.len()
                    )))
                }
            };
            if polygon.len() < 3 {
                return Err(face_error(format!(
                    "a face needs 3 or more vertices, found {}",
                    polygon.len()
                )));
            }
            let material = match materials.map(|m| m[row]) {
                Some(m) if (0.0..=255.0).contains(&m) && m.fract() == 0.0 => Some(m as u8),
                Some(m) => return Err(face_error(format!("material id {m} is not in 0..=255"))),
                None => None,
            };
            for k in 1..polygon.len() - 1 {
                triangles.push([
                    index(polygon[0])?,
                    index(polygon[k])?,
                    index(polygon[k + 1])?,
                ]);
                material_ids.extend(material);
            }
        }
    }
    Ok(TriangleMesh {
        vertices,
        normals,
        triangles,
        material_ids,
    })
}

/// The PLY document of a mesh: float positions (and normals when present), `list uchar int
/// vertex_indices`, `uchar material_id` when present. Normals or material ids whose count does
/// not match, or an index beyond a PLY int, are refused when it is serialized ([`to_binary_le`]
/// names them).
pub(super) fn mesh_to_ply(mesh: &TriangleMesh) -> Ply {
    let axis = |v: &[[f64; 3]], a: usize| v.iter().map(|p| p[a]).collect::<Vec<f64>>();
    let mut vertex = Element::new("vertex", mesh.vertices.len())
        .with_scalar("x", ScalarType::F32, axis(&mesh.vertices, 0))
        .with_scalar("y", ScalarType::F32, axis(&mesh.vertices, 1))
        .with_scalar("z", ScalarType::F32, axis(&mesh.vertices, 2));
    if !mesh.normals.is_empty() {
        vertex = vertex
            .with_scalar("nx", ScalarType::F32, axis(&mesh.normals, 0))
            .with_scalar("ny", ScalarType::F32, axis(&mesh.normals, 1))
            .with_scalar("nz", ScalarType::F32, axis(&mesh.normals, 2));
    }
    let polygons = mesh
        .triangles
        .iter()
        .map(|t| t.iter().map(|&i| i as f64).collect())
        .collect();
    let mut face = Element::new("face", mesh.triangles.len()).with_list(
        "vertex_indices",
        ScalarType::U8,
        ScalarType::I32,
        polygons,
    );
    if !mesh.material_ids.is_empty() {
        let ids = mesh.material_ids.iter().map(|&m| m as f64).collect();
        face = face.with_scalar("material_id", ScalarType::U8, ids);
    }
    Ply {
        format: PlyFormat::BinaryLittleEndian,
        comments: vec!["phygap triangle mesh".into()],
        elements: vec![vertex, face],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// The mesh of PLY bytes.
    fn parse(bytes: &[u8]) -> Result<TriangleMesh, PlyError> {
        mesh_from_ply(&parse_ply(bytes)?)
    }

    fn tetrahedron() -> TriangleMesh {
        let vertices = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let normals = vertices
            .iter()
            .map(|p| {
                (DVec3::from_array(*p) - DVec3::splat(0.25))
                    .normalize()
                    .to_array()
            })
            .collect();
        TriangleMesh {
            vertices: vertices.to_vec(),
            normals,
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
            material_ids: vec![1, 1, 2, 2],
        }
    }

    #[test]
    fn binary_round_trip_keeps_positions_normals_and_faces() {
        let mesh = TriangleMesh::icosphere(DVec3::new(0.1, 0.2, 0.3), 0.7, 2);
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("m.ply");
        mesh.write_ply(&path).unwrap();
        let back = TriangleMesh::read_ply(&path).unwrap();
        assert_eq!(back.triangles, mesh.triangles);
        assert!(back.material_ids.is_empty());
        assert_eq!(back.vertices.len(), mesh.vertices.len());
        for (a, b) in back.vertices.iter().zip(&mesh.vertices) {
            assert!(DVec3::from_array(*a).distance(DVec3::from_array(*b)) < 1e-6);
        }
        for (a, b) in back.normals.iter().zip(&mesh.normals) {
            assert!(DVec3::from_array(*a).distance(DVec3::from_array(*b)) < 1e-6);
        }
    }

    #[test]
    fn material_ids_round_trip_in_the_gt_layout() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.ply");
        let mesh = tetrahedron();
        mesh.write_ply(&path).unwrap();
        let back = TriangleMesh::read_ply(&path).unwrap();
        assert_eq!(back.triangles, mesh.triangles);
        assert_eq!(back.material_ids, mesh.material_ids);
        assert_eq!(back.vertices, mesh.vertices, "exact in f32");
        for (a, b) in back.normals.iter().zip(&mesh.normals) {
            assert!(DVec3::from_array(*a).distance(DVec3::from_array(*b)) < 1e-7);
        }
        // The header is the GT mesh's layout.
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        assert!(text.contains(
            "property float nz\nelement face 4\nproperty list uchar int vertex_indices\n\
             property uchar material_id\nend_header\n"
        ));
    }

    #[test]
    fn inconsistent_meshes_are_refused_on_writing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("bad.ply");
        let mut mesh = tetrahedron();
        mesh.material_ids.pop();
        let e = mesh.write_ply(&path).unwrap_err().to_string();
        assert!(e.contains("`material_id` has 3 values for 4 rows"), "{e}");
        let mut mesh = tetrahedron();
        mesh.normals.pop();
        let e = mesh.write_ply(&path).unwrap_err().to_string();
        assert!(e.contains("`nx` has 3 values for 4 rows"), "{e}");
        let mut mesh = tetrahedron();
        mesh.triangles[2][1] = u32::MAX;
        let e = mesh.write_ply(&path).unwrap_err().to_string();
        assert!(
            e.contains("`vertex_indices` row 2") && e.contains("does not fit a int"),
            "{e}"
        );
        assert!(!path.exists(), "nothing is written for a refused mesh");
    }

    #[test]
    fn ascii_with_reordered_properties_quads_and_extra_elements() {
        let text = "ply\nformat ascii 1.0\ncomment test\nelement material 1\nproperty float shine\n\
                    element vertex 4\nproperty uchar red\nproperty double z\nproperty float x\n\
                    property float y\nproperty list uchar int junk\n\
                    element face 2\nproperty uchar material_id\nproperty list uchar uint vertex_index\n\
                    end_header\n\
                    0.5\n\
                    255 0.0 0 0 0\n1 0.0 1 0 2 7 8\n2 1.5 1 1 0\n3 0 0 1 1 9\n\
                    3 4 0 1 2 3\n7 3 3 2 1\n";
        let mesh = parse(text.as_bytes()).unwrap();
        assert_eq!(
            mesh.vertices,
            vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [1.0, 1.0, 1.5],
                [0.0, 1.0, 0.0]
            ]
        );
        assert!(mesh.normals.is_empty());
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3], [3, 2, 1]]);
        assert_eq!(
            mesh.material_ids,
            vec![3, 3, 7],
            "a quad's id on both its triangles"
        );
    }

    #[test]
    fn big_endian_double_positions_are_read() {
        let mut bytes =
            b"ply\r\nformat binary_big_endian 1.0\r\nelement vertex 3\r\nproperty double x\r\n\
                          property double y\r\nproperty double z\r\nelement face 1\r\n\
                          property list uchar short vertex_indices\r\nend_header\r\n"
                .to_vec();
        for v in [[1.0f64, 2.0, 3.0], [4.0, 5.0, 6.0], [-1.0, 0.25, 8.0]] {
            for x in v {
                bytes.extend_from_slice(&x.to_be_bytes());
            }
        }
        bytes.push(3);
        for i in [2i16, 0, 1] {
            bytes.extend_from_slice(&i.to_be_bytes());
        }
        let mesh = parse(&bytes).unwrap();
        assert_eq!(mesh.vertices[2], [-1.0, 0.25, 8.0]);
        assert_eq!(mesh.triangles, vec![[2, 0, 1]]);
    }

    #[test]
    fn bad_files_are_rejected_with_a_reason() {
        let triangle =
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                        property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
                        end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        assert_eq!(
            parse(triangle.as_bytes()).unwrap().triangles,
            vec![[0, 1, 2]]
        );
        let expect = |text: String, wanted: &[&str]| {
            let e = parse(text.as_bytes()).unwrap_err().to_string();
            assert!(wanted.iter().all(|w| e.contains(w)), "{e}");
        };
        expect(
            triangle.replace("3 0 1 2", "3 0 1 5"),
            &["`face` row 0", "vertex index 5 out of range (0..3)"],
        );
        expect(
            triangle.replace("3 0 1 2", "2 0 1"),
            &["`face` row 0", "3 or more vertices, found 2"],
        );
        expect(
            triangle.replace("1 0 0\n", "1 nan 0\n"),
            &["`vertex` row 1", "not finite"],
        );
        expect(
            triangle.replace("property float y\n", "property float w\n"),
            &["`vertex` has no property `y`"],
        );
        expect(
            triangle.replace("vertex_indices", "corners"),
            &["`face` has no property `vertex_indices`"],
        );
        expect(
            triangle.replace("element vertex", "element point"),
            &["no element `vertex`"],
        );
        expect(
            triangle
                .replace(
                    "vertex_indices\n",
                    "vertex_indices\nproperty short material_id\n",
                )
                .replace("3 0 1 2", "3 0 1 2 300"),
            &["`face` row 0", "material id 300"],
        );
        let truncated =
            "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n\
                         property float y\nproperty float z\nend_header\n";
        expect(truncated.into(), &["`vertex` row 0", "ends early"]);
        assert!(parse(b"PLY\n").is_err());
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("missing.ply");
        let e = TriangleMesh::read_ply(&missing).unwrap_err();
        assert!(
            matches!(e, MeshError::Io { ref path, .. } if *path == missing),
            "{e}"
        );
        std::fs::write(&missing, &triangle[..40]).unwrap();
        let e = TriangleMesh::read_ply(&missing).unwrap_err();
        assert!(
            matches!(e, MeshError::Ply { ref path, .. } if *path == missing),
            "{e}"
        );
    }

    #[test]
    fn reads_the_shared_ground_truth_meshes() {
        let Some(data) = crate::testing::shared_data_dir() else {
            return;
        };
        for (scene, vertices, faces) in [("knot", 16384, 32768), ("sphere", 10242, 20480)] {
            let mesh = TriangleMesh::read_ply(&data.join(scene).join("mesh.ply")).unwrap();
            assert_eq!(mesh.vertices.len(), vertices, "{scene}");
            assert_eq!(mesh.triangles.len(), faces, "{scene}");
            assert!(mesh.has_normals());
            assert_eq!(mesh.material_ids.len(), faces, "{scene}");
            assert!(
                mesh.material_ids.iter().all(|&m| m == 1),
                "{scene}: one material"
            );
            let radius = mesh
                .vertices
                .iter()
                .map(|v| DVec3::from_array(*v).length())
                .fold(0.0, f64::max);
            assert!(
                (radius - 1.0).abs() < 1e-3,
                "{scene}: bounding radius {radius}"
            );
            for n in &mesh.normals {
                assert!((DVec3::from_array(*n).length() - 1.0).abs() < 1e-4);
            }
            // Counter-clockwise from outside: the signed volume is positive.
            let volume = mesh.signed_volume();
            assert!(volume > 0.0, "{scene}: volume {volume}");
            if scene == "sphere" {
                assert!((volume - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.01);
                // On the unit sphere the normal is the position, and every geometric normal
                // points away from the centre.
                for (p, n) in mesh.vertices.iter().zip(&mesh.normals) {
                    let (p, n) = (DVec3::from_array(*p), DVec3::from_array(*n));
                    assert!((p.length() - 1.0).abs() < 1e-6 && (p - n).length() < 1e-5);
                }
                for t in 0..mesh.triangles.len() {
                    let [a, b, c] = mesh.triangle_corners(t);
                    assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
                }
            }
        }
    }
}

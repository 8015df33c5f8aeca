//! PLY reading and writing for triangle meshes.
//!
//! The reader is generic: ASCII, binary little- and big-endian; any element and property order;
//! scalar and list properties of every PLY type are parsed (unknown ones are skipped). It takes
//! `x y z` and optional `nx ny nz` from `vertex`, and `vertex_indices` (or `vertex_index`) from
//! `face`, fan-triangulating polygons. The writer emits binary little-endian with float positions
//! and normals and `list uchar int vertex_indices`.

use std::io::Write;
use std::path::Path;

use super::{MeshError, TriangleMesh};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Encoding {
    Ascii,
    LittleEndian,
    BigEndian,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &str) -> Option<Self> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

#[derive(Clone, Debug)]
enum PropertyKind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Clone, Debug)]
struct Property {
    name: String,
    kind: PropertyKind,
}

#[derive(Clone, Debug)]
struct Element {
    name: String,
    count: usize,
    properties: Vec<Property>,
}

/// A cursor over the body that yields numbers in file order, whatever the encoding.
struct Body<'a> {
    encoding: Encoding,
    bytes: &'a [u8],
    position: usize,
}

impl Body<'_> {
    fn next_ascii_token(&mut self) -> Option<&str> {
        let rest = &self.bytes[self.position..];
        let start = rest.iter().position(|b| !b.is_ascii_whitespace())?;
        let len = rest[start..]
            .iter()
            .position(|b| b.is_ascii_whitespace())
            .unwrap_or(rest.len() - start);
        self.position += start + len;
        std::str::from_utf8(&rest[start..start + len]).ok()
    }

    fn read(&mut self, scalar: Scalar) -> Result<f64, String> {
        if self.encoding == Encoding::Ascii {
            let token = self
                .next_ascii_token()
                .ok_or_else(|| "the body ends before the last element".to_owned())?;
            return token
                .parse::<f64>()
                .map_err(|_| format!("`{token}` is not a number"));
        }
        let size = scalar.size();
        let raw = self
            .bytes
            .get(self.position..self.position + size)
            .ok_or_else(|| "the body ends before the last element".to_owned())?;
        self.position += size;
        let mut buf = [0u8; 8];
        buf[..size].copy_from_slice(raw);
        if self.encoding == Encoding::BigEndian {
            buf[..size].reverse();
        }
        let le2 = [buf[0], buf[1]];
        let le4 = [buf[0], buf[1], buf[2], buf[3]];
        Ok(match scalar {
            Scalar::I8 => buf[0] as i8 as f64,
            Scalar::U8 => buf[0] as f64,
            Scalar::I16 => i16::from_le_bytes(le2) as f64,
            Scalar::U16 => u16::from_le_bytes(le2) as f64,
            Scalar::I32 => i32::from_le_bytes(le4) as f64,
            Scalar::U32 => u32::from_le_bytes(le4) as f64,
            Scalar::F32 => f32::from_le_bytes(le4) as f64,
            Scalar::F64 => f64::from_le_bytes(buf),
        })
    }

    /// Bytes left, used to cap allocations driven by counts in the header.
    fn remaining(&self) -> usize {
        self.bytes.len() - self.position
    }
}

fn parse_header(text: &str) -> Result<(Encoding, Vec<Element>), String> {
    let mut lines = text.lines().map(str::trim);
    if lines.next() != Some("ply") {
        return Err("does not start with `ply`".into());
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    for line in lines {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["format", kind, _version] => {
                encoding = Some(match *kind {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::LittleEndian,
                    "binary_big_endian" => Encoding::BigEndian,
                    other => return Err(format!("unknown format `{other}`")),
                })
            }
            ["element", name, count] => elements.push(Element {
                name: (*name).to_owned(),
                count: count
                    .parse()
                    .map_err(|_| format!("element `{name}` has a bad count `{count}`"))?,
                properties: Vec::new(),
            }),
            ["property", "list", count, item, name] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| format!("property `{name}` before any element"))?;
                let scalar = |t: &str| {
                    Scalar::parse(t).ok_or_else(|| format!("property `{name}`: unknown type `{t}`"))
                };
                element.properties.push(Property {
                    name: (*name).to_owned(),
                    kind: PropertyKind::List {
                        count: scalar(count)?,
                        item: scalar(item)?,
                    },
                });
            }
            ["property", ty, name] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| format!("property `{name}` before any element"))?;
                let scalar = Scalar::parse(ty)
                    .ok_or_else(|| format!("property `{name}`: unknown type `{ty}`"))?;
                element.properties.push(Property {
                    name: (*name).to_owned(),
                    kind: PropertyKind::Scalar(scalar),
                });
            }
            ["end_header"] => break,
            ["comment", ..] | ["obj_info", ..] | [] => {}
            _ => return Err(format!("unrecognized header line `{line}`")),
        }
    }
    Ok((encoding.ok_or("no `format` line")?, elements))
}

/// Finds the end of the header: the byte after the `end_header` line.
fn header_end(bytes: &[u8]) -> Option<usize> {
    let marker = b"end_header";
    let at = bytes.windows(marker.len()).position(|w| w == marker)?;
    let newline = bytes[at..].iter().position(|&b| b == b'\n')?;
    Some(at + newline + 1)
}

pub(super) fn read_ply(path: &Path) -> Result<TriangleMesh, MeshError> {
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_ply(&bytes).map_err(|problem| MeshError::Ply {
        path: path.to_path_buf(),
        problem,
    })
}

fn parse_ply(bytes: &[u8]) -> Result<TriangleMesh, String> {
    let end = header_end(bytes).ok_or("no `end_header` line")?;
    let header = std::str::from_utf8(&bytes[..end]).map_err(|_| "the header is not text")?;
    let (encoding, elements) = parse_header(header)?;
    let mut body = Body {
        encoding,
        bytes: &bytes[end..],
        position: 0,
    };
    let mut mesh = TriangleMesh::default();
    let mut saw_vertices = false;
    for element in &elements {
        let find = |name: &str| element.properties.iter().position(|p| p.name == name);
        match element.name.as_str() {
            "vertex" => {
                saw_vertices = true;
                let position = ["x", "y", "z"].map(find);
                let [Some(px), Some(py), Some(pz)] = position else {
                    return Err("element `vertex` lacks one of x, y, z".into());
                };
                let normal = match ["nx", "ny", "nz"].map(find) {
                    [Some(a), Some(b), Some(c)] => Some([a, b, c]),
                    _ => None,
                };
                let capacity = element.count.min(body.remaining());
                mesh.vertices.reserve(capacity);
                if normal.is_some() {
                    mesh.normals.reserve(capacity);
                }
                let mut values = vec![0.0; element.properties.len()];
                for _ in 0..element.count {
                    for (slot, property) in values.iter_mut().zip(&element.properties) {
                        *slot = match property.kind {
                            PropertyKind::Scalar(s) => body.read(s)?,
                            PropertyKind::List { count, item } => {
                                let n = body.read(count)?;
                                for _ in 0..list_length(n, &property.name)? {
                                    body.read(item)?;
                                }
                                0.0
                            }
                        };
                    }
                    mesh.vertices.push([values[px], values[py], values[pz]]);
                    if let Some([a, b, c]) = normal {
                        mesh.normals.push([values[a], values[b], values[c]]);
                    }
                }
            }
            "face" => {
                let indices = find("vertex_indices")
                    .or_else(|| find("vertex_index"))
                    .ok_or("element `face` has no vertex_indices list")?;
                mesh.triangles.reserve(element.count.min(body.remaining()));
                let mut polygon: Vec<u32> = Vec::with_capacity(8);
                for _ in 0..element.count {
                    polygon.clear();
                    for (p, property) in element.properties.iter().enumerate() {
                        match property.kind {
                            PropertyKind::Scalar(s) => {
                                body.read(s)?;
                            }
                            PropertyKind::List { count, item } => {
                                let n = list_length(body.read(count)?, &property.name)?;
                                for _ in 0..n {
                                    let v = body.read(item)?;
                                    if p == indices {
                                        polygon.push(vertex_index(v)?);
                                    }
                                }
                            }
                        }
                    }
                    for k in 1..polygon.len().saturating_sub(1) {
                        mesh.triangles
                            .push([polygon[0], polygon[k], polygon[k + 1]]);
                    }
                }
            }
            _ => {
                for _ in 0..element.count {
                    for property in &element.properties {
                        match property.kind {
                            PropertyKind::Scalar(s) => {
                                body.read(s)?;
                            }
                            PropertyKind::List { count, item } => {
                                for _ in 0..list_length(body.read(count)?, &property.name)? {
                                    body.read(item)?;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    if !saw_vertices {
        return Err("no `vertex` element".into());
    }
    let n = mesh.vertices.len();
    if let Some(bad) = mesh.triangles.iter().flatten().find(|&&i| i as usize >= n) {
        return Err(format!(
            "face refers to vertex {bad} but there are {n} vertices"
        ));
    }
    if mesh
        .vertices
        .iter()
        .chain(&mesh.normals)
        .flatten()
        .any(|v| !v.is_finite())
    {
        return Err("a vertex position or normal is not finite".into());
    }
    Ok(mesh)
}

fn list_length(n: f64, name: &str) -> Result<usize, String> {
    if n >= 0.0 && n.fract() == 0.0 && n < 1e9 {
        Ok(n as usize)
    } else {
        Err(format!("list `{name}` has an invalid length {n}"))
    }
}

fn vertex_index(v: f64) -> Result<u32, String> {
    if v >= 0.0 && v.fract() == 0.0 && v <= u32::MAX as f64 {
        Ok(v as u32)
    } else {
        Err(format!("invalid vertex index {v}"))
    }
}

pub(super) fn write_ply(mesh: &TriangleMesh, path: &Path) -> Result<(), MeshError> {
    let io = |source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    };
    let with_normals = mesh.has_normals();
    let mut header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment phygap triangle mesh\nelement vertex {}\n\
         property float x\nproperty float y\nproperty float z\n",
        mesh.vertices.len()
    );
    if with_normals {
        header.push_str("property float nx\nproperty float ny\nproperty float nz\n");
    }
    header.push_str(&format!(
        "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        mesh.triangles.len()
    ));
    let floats_per_vertex = if with_normals { 6 } else { 3 };
    let mut bytes = Vec::with_capacity(
        header.len() + mesh.vertices.len() * 4 * floats_per_vertex + mesh.triangles.len() * 13,
    );
    bytes.extend_from_slice(header.as_bytes());
    for (i, v) in mesh.vertices.iter().enumerate() {
        for x in v {
            bytes.extend_from_slice(&(*x as f32).to_le_bytes());
        }
        if with_normals {
            for x in &mesh.normals[i] {
                bytes.extend_from_slice(&(*x as f32).to_le_bytes());
            }
        }
    }
    for t in &mesh.triangles {
        bytes.push(3);
        for &i in t {
            let index = i32::try_from(i).map_err(|_| {
                io(std::io::Error::new(
                    std::io::ErrorKind::InvalidInput,
                    format!("vertex index {i} does not fit a PLY int"),
                ))
            })?;
            bytes.extend_from_slice(&index.to_le_bytes());
        }
    }
    let mut file = std::fs::File::create(path).map_err(io)?;
    file.write_all(&bytes).map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn shared_data() -> Option<std::path::PathBuf> {
        let dir = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data"));
        if dir.is_dir() {
            Some(dir.to_path_buf())
        } else {
            println!("skipping: ../shared/data not found");
            None
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
        assert_eq!(back.vertices.len(), mesh.vertices.len());
        for (a, b) in back.vertices.iter().zip(&mesh.vertices) {
            assert!(DVec3::from_array(*a).distance(DVec3::from_array(*b)) < 1e-6);
        }
        for (a, b) in back.normals.iter().zip(&mesh.normals) {
            assert!(DVec3::from_array(*a).distance(DVec3::from_array(*b)) < 1e-6);
        }
    }

    #[test]
    fn ascii_with_reordered_properties_quads_and_extra_elements() {
        let text = "ply\nformat ascii 1.0\ncomment test\nelement material 1\nproperty float shine\n\
                    element vertex 4\nproperty uchar red\nproperty double z\nproperty float x\n\
                    property float y\nproperty list uchar int junk\n\
                    element face 1\nproperty uchar flag\nproperty list uchar uint vertex_index\nend_header\n\
                    0.5\n\
                    255 0.0 0 0 0\n1 0.0 1 0 2 7 8\n2 1.5 1 1 0\n3 0 0 1 1 9\n\
                    1 4 0 1 2 3\n";
        let mesh = parse_ply(text.as_bytes()).unwrap();
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
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
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
        let mesh = parse_ply(&bytes).unwrap();
        assert_eq!(mesh.vertices[2], [-1.0, 0.25, 8.0]);
        assert_eq!(mesh.triangles, vec![[2, 0, 1]]);
    }

    #[test]
    fn bad_files_are_rejected_with_a_reason() {
        let out_of_range = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
                            property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
                            end_header\n0 0 0\n3 0 0 5\n";
        assert!(parse_ply(out_of_range.as_bytes())
            .unwrap_err()
            .contains("vertex 5"));
        let truncated =
            "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n\
                         property float y\nproperty float z\nend_header\n";
        assert!(parse_ply(truncated.as_bytes())
            .unwrap_err()
            .contains("ends"));
        assert!(parse_ply(b"PLY\n").is_err());
    }

    #[test]
    fn reads_the_shared_ground_truth_meshes() {
        let Some(data) = shared_data() else { return };
        for (scene, vertices, faces) in [("knot", 16384, 32768), ("sphere", 10242, 20480)] {
            let mesh = TriangleMesh::read_ply(&data.join(scene).join("mesh.ply")).unwrap();
            assert_eq!(mesh.vertices.len(), vertices, "{scene}");
            assert_eq!(mesh.triangles.len(), faces, "{scene}");
            assert!(mesh.has_normals());
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
            let volume: f64 = (0..mesh.triangles.len())
                .map(|t| {
                    let [a, b, c] = mesh.triangle_corners(t);
                    a.dot(b.cross(c)) / 6.0
                })
                .sum();
            assert!(volume > 0.0, "{scene}: volume {volume}");
            if scene == "sphere" {
                assert!((volume - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.01);
            }
        }
    }
}

//! glTF 2.0 binary (`model.glb`) of the extracted mesh with its learned materials, for Blender,
//! three.js and any other glTF viewer. Written here (serde_json for the JSON chunk, the binary
//! chunk by hand); one mesh, one primitive, one material, in one of two forms.
//!
//! Both forms:
//!
//! - `POSITION` (float, with exact `min`/`max`) and `NORMAL` (float, unit length) in phygap's world
//!   coordinates; the node's `rotation` turns the world's up axis to glTF's +Y, and its (r, f)
//!   lat-long reference axes to −Z and −X, so that `envmap.hdr` used as an equirectangular
//!   environment in three.js (the web page, glTF viewers) lights the object as it was captured.
//! - The IoR in `KHR_materials_ior`: one value per material, the area-weighted median of the
//!   per-vertex IoR ([`area_weighted_median_ior`]); the per-vertex IoR stays in the
//!   application-specific attribute `_IOR` (float) for tools that want it. Metallic 0.
//!
//! **Textured form** ([`textured_glb_bytes`], the default): the mesh cut into a UV atlas
//! ([`crate::core::mesh::uv_atlas`]; seam vertices duplicated) with the materials baked into three
//! square PNG textures ([`super::bake`]), all read through `TEXCOORD_0` (float) with one sampler
//! (linear, trilinear mipmaps, clamp to edge):
//!
//! - `baseColorTexture`: the albedo, sRGB 8-bit;
//! - `metallicRoughnessTexture`: roughness in G, metallic 0 in B (R 255), with both factors 1;
//! - `normalTexture`: the surfels' normals in tangent space against the mesh's interpolated
//!   `NORMAL` and the `TANGENT` attribute written with it (float VEC4, w the handedness), the
//!   frame glTF viewers decode the map in.
//!
//! Attributes `POSITION` 1, `NORMAL` 2, `TANGENT` 3, `TEXCOORD_0` 4, `_IOR` 5 (accessor numbers).
//!
//! **Vertex form** ([`glb_bytes`]): the materials sampled at the vertices ([`super::materials`]),
//! for tools that want plain vertex data:
//!
//! - albedo as per-vertex colour (`COLOR_0`, linear, unsigned short normalized); glTF multiplies
//!   `COLOR_0` into the base colour (factor 1);
//! - roughness through the metallic-roughness texture, which glTF requires for anything that
//!   varies: a 256 × 1 ramp whose texel i holds roughness i/255 in green (metallic 0 in blue),
//!   sampled with linear filtering and no mipmaps at `TEXCOORD_0.u = (0.5 + 255 r) / 256`. Linear
//!   filtering of a linear ramp returns exactly r, and interpolating u over a triangle is
//!   interpolating r, so every viewer shows the per-vertex roughness as a vertex attribute would.
//!
//! Attributes `POSITION` 1, `NORMAL` 2, `COLOR_0` 3, `TEXCOORD_0` 4, `_IOR` 5.
//!
//! Layout: the binary chunk holds the indices (accessor 0; unsigned short below 65 535 vertices,
//! else unsigned int), the attributes one buffer view each (every view and element 4-byte aligned)
//! and the PNGs.

use std::path::{Path, PathBuf};

use glam::{DMat3, DQuat, DVec3};
use serde_json::{json, Value};
use thiserror::Error;

use super::bake::BakedMaps;
use super::materials::{area_weighted_median_ior, VertexMaterial};
use crate::core::envmap::WorldUp;
use crate::core::mesh::{TriangleMesh, UvAtlas};

/// `glTF`, the first word of a GLB file.
pub const GLB_MAGIC: u32 = 0x4654_6C67;
/// Type of the JSON chunk (`JSON`).
pub const CHUNK_JSON: u32 = 0x4E4F_534A;
/// Type of the binary chunk (`BIN\0`).
pub const CHUNK_BIN: u32 = 0x004E_4942;
/// Texels of the roughness ramp.
pub const RAMP_WIDTH: usize = 256;

// glTF enumerations (the WebGL constants).
const UNSIGNED_SHORT: u32 = 5123;
const UNSIGNED_INT: u32 = 5125;
const FLOAT: u32 = 5126;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const LINEAR: u32 = 9729;
const LINEAR_MIPMAP_LINEAR: u32 = 9987;
const CLAMP_TO_EDGE: u32 = 33071;
const TRIANGLES: u32 = 4;

/// Why a mesh could not be written as glTF.
#[derive(Debug, Error)]
pub enum GltfError {
    #[error("the mesh has no triangles with three distinct vertices")]
    EmptyMesh,
    #[error("{what}: {actual} values for {expected} vertices")]
    Count {
        what: &'static str,
        expected: usize,
        actual: usize,
    },
    #[error("triangle {triangle} refers to vertex {index}, but the mesh has {vertices} vertices")]
    Index {
        triangle: usize,
        index: u32,
        vertices: usize,
    },
    #[error("vertex {index}: its {what} is not finite")]
    NonFinite { what: &'static str, index: usize },
    #[error("the GLB would hold {0} bytes, more than the format's 4 GiB")]
    TooLarge(usize),
    #[error("encoding a texture as PNG: {0}")]
    Png(String),
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// What a written GLB holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlbSummary {
    pub vertices: usize,
    pub triangles: usize,
    /// The material's IoR (`KHR_materials_ior`).
    pub ior: f64,
    /// Size of the file.
    pub bytes: usize,
    /// Side of the baked textures (texels); `None` in the vertex form.
    pub texture_size: Option<u32>,
}

/// The rotation from phygap's world into glTF's: up → +Y, the lat-long's r → −Z and f → −X (the
/// frame three.js's equirectangular lookup expects, as the web page's viewer uses).
pub fn world_to_gltf(up: WorldUp) -> DQuat {
    let (r, f, u) = up.basis();
    let target = DMat3::from_cols(DVec3::NEG_Z, DVec3::NEG_X, DVec3::Y);
    let source = DMat3::from_cols(r, f, u);
    DQuat::from_mat3(&(target * source.transpose())).normalize()
}

/// The texture coordinate u that reads roughness `r` from the ramp.
pub fn roughness_to_u(r: f64) -> f64 {
    (0.5 + (RAMP_WIDTH - 1) as f64 * r.clamp(0.0, 1.0)) / RAMP_WIDTH as f64
}

/// The binary chunk under construction and the buffer views into it.
#[derive(Default)]
struct Bin {
    bytes: Vec<u8>,
    views: Vec<Value>,
}

impl Bin {
    /// Appends `data` at the next 4-byte boundary as a new buffer view; returns its index.
    fn view(&mut self, data: &[u8], target: Option<u32>, stride: Option<usize>) -> usize {
        self.pad();
        let mut view = json!({
            "buffer": 0,
            "byteOffset": self.bytes.len(),
            "byteLength": data.len(),
        });
        if let Some(target) = target {
            view["target"] = json!(target);
        }
        if let Some(stride) = stride {
            view["byteStride"] = json!(stride);
        }
        self.bytes.extend_from_slice(data);
        self.views.push(view);
        self.views.len() - 1
    }

    fn pad(&mut self) {
        while !self.bytes.len().is_multiple_of(4) {
            self.bytes.push(0);
        }
    }
}

fn finite(v: DVec3, what: &'static str, index: usize) -> Result<DVec3, GltfError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(GltfError::NonFinite { what, index })
    }
}

/// Unsigned-short normalized encoding of a value in [0, 1].
fn unorm16(v: f64) -> u16 {
    (v.clamp(0.0, 1.0) * 65535.0).round() as u16
}

/// The 256 × 1 RGB texels of the roughness ramp: (occlusion 1, roughness i/255, metallic 0).
fn roughness_ramp() -> Vec<u8> {
    (0..RAMP_WIDTH).flat_map(|i| [255, i as u8, 0]).collect()
}

/// An 8-bit RGB image as PNG (best compression: the textures are most of the file).
fn png(texels: &[u8], width: u32, height: u32) -> Result<Vec<u8>, GltfError> {
    use image::codecs::png::{CompressionType, FilterType, PngEncoder};
    use image::ImageEncoder;
    let mut png = Vec::new();
    PngEncoder::new_with_quality(&mut png, CompressionType::Best, FilterType::Adaptive)
        .write_image(texels, width, height, image::ExtendedColorType::Rgb8)
        .map_err(|e| GltfError::Png(e.to_string()))?;
    Ok(png)
}

/// The triangles of `mesh` that draw something (three distinct vertices), after checking that
/// every triangle refers to an existing vertex.
fn drawn_triangles(mesh: &TriangleMesh) -> Result<Vec<[u32; 3]>, GltfError> {
    let n = mesh.vertices.len();
    let mut triangles = Vec::with_capacity(mesh.triangles.len());
    for (t, triangle) in mesh.triangles.iter().enumerate() {
        if let Some(&index) = triangle.iter().find(|&&i| i as usize >= n) {
            return Err(GltfError::Index {
                triangle: t,
                index,
                vertices: n,
            });
        }
        let [a, b, c] = *triangle;
        if a != b && b != c && a != c {
            triangles.push(*triangle);
        }
    }
    if triangles.is_empty() {
        return Err(GltfError::EmptyMesh);
    }
    Ok(triangles)
}

/// The vertex positions as float32, each finite.
fn float_positions(mesh: &TriangleMesh) -> Result<Vec<glam::Vec3>, GltfError> {
    let mut positions = Vec::with_capacity(mesh.vertices.len());
    for (i, v) in mesh.vertices.iter().enumerate() {
        let v = finite(DVec3::from_array(*v), "position", i)?.as_vec3();
        if !v.is_finite() {
            return Err(GltfError::NonFinite {
                what: "position (as float32)",
                index: i,
            });
        }
        positions.push(v);
    }
    Ok(positions)
}

/// The unit normals of `mesh` (computed from `triangles` when it has none) as float32 bytes.
fn normal_bytes(mesh: &TriangleMesh, triangles: &[[u32; 3]]) -> Result<Vec<u8>, GltfError> {
    let n = mesh.vertices.len();
    if !mesh.normals.is_empty() && mesh.normals.len() != n {
        return Err(GltfError::Count {
            what: "normals",
            expected: n,
            actual: mesh.normals.len(),
        });
    }
    let normals: Vec<DVec3> = if mesh.has_normals() {
        mesh.normals.iter().map(|n| DVec3::from_array(*n)).collect()
    } else {
        let mut copy = mesh.clone();
        copy.triangles = triangles.to_vec();
        copy.compute_vertex_normals();
        copy.normals.iter().map(|n| DVec3::from_array(*n)).collect()
    };
    let mut bytes = Vec::with_capacity(12 * n);
    for (i, normal) in normals.iter().enumerate() {
        let unit = finite(*normal, "normal", i)?
            .try_normalize()
            .unwrap_or(DVec3::Z)
            .as_vec3()
            .normalize();
        for c in unit.to_array() {
            bytes.extend_from_slice(&c.to_le_bytes());
        }
    }
    Ok(bytes)
}

/// The material's IoR: the area-weighted median of the vertices' (their plain median when no
/// triangle has area), at least 1.
fn material_ior(mesh: &TriangleMesh, materials: &[VertexMaterial]) -> f64 {
    area_weighted_median_ior(mesh, materials)
        .unwrap_or_else(|| {
            let mut values: Vec<f64> = materials.iter().map(|m| m.ior).collect();
            values.sort_by(f64::total_cmp);
            values[values.len() / 2]
        })
        .max(1.0)
}

/// Checks that every material value is finite.
fn check_materials(materials: &[VertexMaterial]) -> Result<(), GltfError> {
    for (i, m) in materials.iter().enumerate() {
        finite(m.albedo, "albedo", i)?;
        if !m.roughness.is_finite() {
            return Err(GltfError::NonFinite {
                what: "roughness",
                index: i,
            });
        }
        if !m.ior.is_finite() {
            return Err(GltfError::NonFinite {
                what: "IoR",
                index: i,
            });
        }
    }
    Ok(())
}

/// The parts every form shares: the indices (view and accessor 0), positions (1), normals (2)
/// in `bin`, and the accessors' JSON.
struct Geometry {
    triangles: usize,
    accessors: Vec<Value>,
}

fn write_geometry(
    mesh: &TriangleMesh,
    triangles: &[[u32; 3]],
    bin: &mut Bin,
) -> Result<Geometry, GltfError> {
    let n = mesh.vertices.len();
    let positions = float_positions(mesh)?;
    let normal_bytes = normal_bytes(mesh, triangles)?;
    let (index_type, index_bytes) = if n <= u16::MAX as usize {
        let bytes: Vec<u8> = triangles
            .iter()
            .flatten()
            .flat_map(|&i| (i as u16).to_le_bytes())
            .collect();
        (UNSIGNED_SHORT, bytes)
    } else {
        let bytes: Vec<u8> = triangles
            .iter()
            .flatten()
            .flat_map(|&i| i.to_le_bytes())
            .collect();
        (UNSIGNED_INT, bytes)
    };
    let indices_view = bin.view(&index_bytes, Some(ELEMENT_ARRAY_BUFFER), None);
    let position_bytes: Vec<u8> = positions
        .iter()
        .flat_map(|p| p.to_array())
        .flat_map(f32::to_le_bytes)
        .collect();
    let position_view = bin.view(&position_bytes, Some(ARRAY_BUFFER), None);
    let normal_view = bin.view(&normal_bytes, Some(ARRAY_BUFFER), None);
    let (lo, hi) = positions.iter().skip(1).fold(
        (positions[0], positions[0]),
        |(lo, hi): (glam::Vec3, glam::Vec3), p| (lo.min(*p), hi.max(*p)),
    );
    Ok(Geometry {
        triangles: triangles.len(),
        accessors: vec![
            json!({"bufferView": indices_view, "componentType": index_type,
                   "count": 3 * triangles.len(), "type": "SCALAR"}),
            json!({"bufferView": position_view, "componentType": FLOAT, "count": n,
                   "type": "VEC3", "min": lo.to_array(), "max": hi.to_array()}),
            json!({"bufferView": normal_view, "componentType": FLOAT, "count": n,
                   "type": "VEC3"}),
        ],
    })
}

/// The glTF document around one primitive with `attributes` and `material`.
/// `appearance` holds the `materials`, `textures`, `samplers` and `images` arrays.
fn document(
    up: WorldUp,
    attributes: Value,
    appearance: Value,
    accessors: Vec<Value>,
    bin: &Bin,
) -> Value {
    let rotation = world_to_gltf(up);
    let mut document = json!({
        "asset": {
            "version": "2.0",
            "generator": concat!("phygap ", env!("CARGO_PKG_VERSION")),
        },
        "extensionsUsed": ["KHR_materials_ior"],
        "scene": 0,
        "scenes": [{"name": "phygap reconstruction", "nodes": [0]}],
        "nodes": [{
            "name": "object",
            "mesh": 0,
            "rotation": [rotation.x, rotation.y, rotation.z, rotation.w],
        }],
        "meshes": [{
            "name": "extracted mesh",
            "primitives": [{
                "attributes": attributes,
                "indices": 0,
                "material": 0,
                "mode": TRIANGLES,
            }],
        }],
        "accessors": accessors,
        "bufferViews": bin.views,
        // The chunk as `assemble` pads it.
        "buffers": [{"byteLength": bin.bytes.len().next_multiple_of(4)}],
    });
    if let (Some(document), Value::Object(appearance)) = (document.as_object_mut(), appearance) {
        document.extend(appearance);
    }
    document
}

/// The GLB file of `document` and `bin`.
fn assemble(document: &Value, mut bin: Bin) -> Result<Vec<u8>, GltfError> {
    bin.pad();
    let mut json_chunk =
        serde_json::to_vec(document).expect("a serde_json value always serializes");
    while !json_chunk.len().is_multiple_of(4) {
        json_chunk.push(b' ');
    }
    let total = 12 + 8 + json_chunk.len() + 8 + bin.bytes.len();
    let word = |v: usize| u32::try_from(v).map_err(|_| GltfError::TooLarge(total));
    let mut glb = Vec::with_capacity(total);
    glb.extend_from_slice(&GLB_MAGIC.to_le_bytes());
    glb.extend_from_slice(&2u32.to_le_bytes());
    glb.extend_from_slice(&word(total)?.to_le_bytes());
    glb.extend_from_slice(&word(json_chunk.len())?.to_le_bytes());
    glb.extend_from_slice(&CHUNK_JSON.to_le_bytes());
    glb.extend_from_slice(&json_chunk);
    glb.extend_from_slice(&word(bin.bytes.len())?.to_le_bytes());
    glb.extend_from_slice(&CHUNK_BIN.to_le_bytes());
    glb.extend_from_slice(&bin.bytes);
    Ok(glb)
}

/// The GLB of `mesh` with one material per vertex in `materials`, oriented by `up` (the vertex
/// form, module doc).
pub fn glb_bytes(
    mesh: &TriangleMesh,
    materials: &[VertexMaterial],
    up: WorldUp,
) -> Result<(Vec<u8>, GlbSummary), GltfError> {
    let n = mesh.vertices.len();
    if materials.len() != n {
        return Err(GltfError::Count {
            what: "materials",
            expected: n,
            actual: materials.len(),
        });
    }
    let triangles = drawn_triangles(mesh)?;
    let mut bin = Bin::default();
    let geometry = write_geometry(mesh, &triangles, &mut bin)?;
    check_materials(materials)?;
    let mut color_bytes = Vec::with_capacity(8 * n);
    let mut uv_bytes = Vec::with_capacity(4 * n);
    let mut ior_bytes = Vec::with_capacity(4 * n);
    for m in materials {
        for c in m.albedo.to_array() {
            color_bytes.extend_from_slice(&unorm16(c).to_le_bytes());
        }
        color_bytes.extend_from_slice(&[0, 0]);
        uv_bytes.extend_from_slice(&unorm16(roughness_to_u(m.roughness)).to_le_bytes());
        uv_bytes.extend_from_slice(&unorm16(0.5).to_le_bytes());
        ior_bytes.extend_from_slice(&(m.ior as f32).to_le_bytes());
    }
    let ior = material_ior(mesh, materials);
    let color_view = bin.view(&color_bytes, Some(ARRAY_BUFFER), Some(8));
    let uv_view = bin.view(&uv_bytes, Some(ARRAY_BUFFER), None);
    let ior_view = bin.view(&ior_bytes, Some(ARRAY_BUFFER), None);
    let image_view = bin.view(&png(&roughness_ramp(), RAMP_WIDTH as u32, 1)?, None, None);
    let mut accessors = geometry.accessors;
    accessors.extend([
        json!({"bufferView": color_view, "componentType": UNSIGNED_SHORT, "normalized": true,
               "count": n, "type": "VEC3"}),
        json!({"bufferView": uv_view, "componentType": UNSIGNED_SHORT, "normalized": true,
               "count": n, "type": "VEC2"}),
        json!({"bufferView": ior_view, "componentType": FLOAT, "count": n, "type": "SCALAR"}),
    ]);
    let document = document(
        up,
        json!({"POSITION": 1, "NORMAL": 2, "COLOR_0": 3, "TEXCOORD_0": 4, "_IOR": 5}),
        json!({"materials": [{
            "name": "learned",
            "pbrMetallicRoughness": {
                "baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                "metallicFactor": 0.0,
                "roughnessFactor": 1.0,
                "metallicRoughnessTexture": {"index": 0, "texCoord": 0},
            },
            "extensions": {"KHR_materials_ior": {"ior": ior}},
        }],
        "textures": [{"sampler": 0, "source": 0}],
        "images": [{"name": "roughness ramp", "bufferView": image_view, "mimeType": "image/png"}],
        "samplers": [{
            "magFilter": LINEAR, "minFilter": LINEAR, "wrapS": CLAMP_TO_EDGE,
            "wrapT": CLAMP_TO_EDGE,
        }]}),
        accessors,
        &bin,
    );
    let glb = assemble(&document, bin)?;
    let summary = GlbSummary {
        vertices: n,
        triangles: geometry.triangles,
        ior,
        bytes: glb.len(),
        texture_size: None,
    };
    Ok((glb, summary))
}

/// A mesh laid out in a UV atlas with its baked maps: what the textured form writes.
pub struct TexturedMesh<'a> {
    /// The atlas (its mesh, with seam copies, is the one written).
    pub atlas: &'a UvAtlas,
    /// The atlas's tangents ([`UvAtlas::tangents`]), the frame the normal map was baked in.
    pub tangents: &'a [[f64; 4]],
    /// The material at each vertex of the atlas's mesh: its IoR goes to `_IOR` and, through the
    /// area-weighted median, to `KHR_materials_ior`.
    pub vertex_materials: &'a [VertexMaterial],
    /// The maps baked on the atlas.
    pub maps: &'a BakedMaps,
}

/// The GLB of a textured mesh, oriented by `up` (the textured form, module doc).
pub fn textured_glb_bytes(
    textured: &TexturedMesh,
    up: WorldUp,
) -> Result<(Vec<u8>, GlbSummary), GltfError> {
    let mesh = &textured.atlas.mesh;
    let n = mesh.vertices.len();
    for (what, actual) in [
        ("materials", textured.vertex_materials.len()),
        ("texture coordinates", textured.atlas.uvs.len()),
        ("tangents", textured.tangents.len()),
    ] {
        if actual != n {
            return Err(GltfError::Count {
                what,
                expected: n,
                actual,
            });
        }
    }
    let size = textured.maps.size;
    let texels = 3 * (size as usize).pow(2);
    for (what, map) in [
        ("base colour texels", &textured.maps.base_colour),
        (
            "metallic-roughness texels",
            &textured.maps.metallic_roughness,
        ),
        ("normal texels", &textured.maps.normal),
    ] {
        if map.len() != texels {
            return Err(GltfError::Count {
                what,
                expected: texels,
                actual: map.len(),
            });
        }
    }
    let triangles = drawn_triangles(mesh)?;
    let mut bin = Bin::default();
    let geometry = write_geometry(mesh, &triangles, &mut bin)?;
    check_materials(textured.vertex_materials)?;
    let mut tangent_bytes = Vec::with_capacity(16 * n);
    for (i, t) in textured.tangents.iter().enumerate() {
        let xyz = finite(DVec3::new(t[0], t[1], t[2]), "tangent", i)?
            .try_normalize()
            .unwrap_or(DVec3::X)
            .as_vec3()
            .normalize();
        let w: f32 = if t[3] < 0.0 { -1.0 } else { 1.0 };
        for c in [xyz.x, xyz.y, xyz.z, w] {
            tangent_bytes.extend_from_slice(&c.to_le_bytes());
        }
    }
    let mut uv_bytes = Vec::with_capacity(8 * n);
    for (i, uv) in textured.atlas.uvs.iter().enumerate() {
        if !uv.iter().all(|u| u.is_finite()) {
            return Err(GltfError::NonFinite {
                what: "texture coordinate",
                index: i,
            });
        }
        for &u in uv {
            uv_bytes.extend_from_slice(&(u.clamp(0.0, 1.0) as f32).to_le_bytes());
        }
    }
    let ior_bytes: Vec<u8> = textured
        .vertex_materials
        .iter()
        .flat_map(|m| (m.ior as f32).to_le_bytes())
        .collect();
    let ior = material_ior(mesh, textured.vertex_materials);
    let tangent_view = bin.view(&tangent_bytes, Some(ARRAY_BUFFER), None);
    let uv_view = bin.view(&uv_bytes, Some(ARRAY_BUFFER), None);
    let ior_view = bin.view(&ior_bytes, Some(ARRAY_BUFFER), None);
    let mut image_views = Vec::new();
    for map in [
        &textured.maps.base_colour,
        &textured.maps.metallic_roughness,
        &textured.maps.normal,
    ] {
        image_views.push(bin.view(&png(map, size, size)?, None, None));
    }
    let mut accessors = geometry.accessors;
    accessors.extend([
        json!({"bufferView": tangent_view, "componentType": FLOAT, "count": n, "type": "VEC4"}),
        json!({"bufferView": uv_view, "componentType": FLOAT, "count": n, "type": "VEC2"}),
        json!({"bufferView": ior_view, "componentType": FLOAT, "count": n, "type": "SCALAR"}),
    ]);
    let document = document(
        up,
        json!({"POSITION": 1, "NORMAL": 2, "TANGENT": 3, "TEXCOORD_0": 4, "_IOR": 5}),
        json!({"materials": [{
            "name": "learned",
            "pbrMetallicRoughness": {
                "baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                "baseColorTexture": {"index": 0, "texCoord": 0},
                "metallicFactor": 1.0,
                "roughnessFactor": 1.0,
                "metallicRoughnessTexture": {"index": 1, "texCoord": 0},
            },
            "normalTexture": {"index": 2, "texCoord": 0, "scale": 1.0},
            "extensions": {"KHR_materials_ior": {"ior": ior}},
        }],
        "textures": [
            {"sampler": 0, "source": 0},
            {"sampler": 0, "source": 1},
            {"sampler": 0, "source": 2},
        ],
        "images": [
            {"name": "base colour", "bufferView": image_views[0], "mimeType": "image/png"},
            {"name": "metallic-roughness", "bufferView": image_views[1], "mimeType": "image/png"},
            {"name": "normal", "bufferView": image_views[2], "mimeType": "image/png"},
        ],
        "samplers": [{
            "magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": CLAMP_TO_EDGE,
            "wrapT": CLAMP_TO_EDGE,
        }]}),
        accessors,
        &bin,
    );
    let glb = assemble(&document, bin)?;
    let summary = GlbSummary {
        vertices: n,
        triangles: geometry.triangles,
        ior,
        bytes: glb.len(),
        texture_size: Some(size),
    };
    Ok((glb, summary))
}

/// Writes `bytes` to `path`.
fn write_file(path: &Path, bytes: &[u8]) -> Result<(), GltfError> {
    std::fs::write(path, bytes).map_err(|source| GltfError::Io {
        path: path.to_owned(),
        source,
    })
}

/// Writes [`textured_glb_bytes`] to `path`.
pub fn write_textured_glb(
    path: &Path,
    textured: &TexturedMesh,
    up: WorldUp,
) -> Result<GlbSummary, GltfError> {
    let _span = tracing::info_span!(
        "write_glb",
        vertices = textured.atlas.mesh.vertices.len(),
        texture = textured.maps.size
    )
    .entered();
    let (bytes, summary) = textured_glb_bytes(textured, up)?;
    write_file(path, &bytes)?;
    Ok(summary)
}

/// Writes [`glb_bytes`] to `path`.
pub fn write_glb(
    path: &Path,
    mesh: &TriangleMesh,
    materials: &[VertexMaterial],
    up: WorldUp,
) -> Result<GlbSummary, GltfError> {
    let _span = tracing::info_span!("write_glb", vertices = mesh.vertices.len()).entered();
    let (bytes, summary) = glb_bytes(mesh, materials, up)?;
    write_file(path, &bytes)?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The JSON document and binary chunk of a GLB, after checking its header and chunk headers.
    fn parse_glb(glb: &[u8]) -> (Value, &[u8]) {
        let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap());
        assert_eq!(word(0), GLB_MAGIC);
        assert_eq!(word(4), 2, "version");
        assert_eq!(word(8) as usize, glb.len(), "declared length");
        let json_len = word(12) as usize;
        assert_eq!(word(16), CHUNK_JSON);
        assert_eq!(json_len % 4, 0);
        let json: Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
        let at = 20 + json_len;
        let bin_len = word(at) as usize;
        assert_eq!(word(at + 4), CHUNK_BIN);
        assert_eq!(bin_len % 4, 0);
        assert_eq!(
            at + 8 + bin_len,
            glb.len(),
            "nothing after the binary chunk"
        );
        (json, &glb[at + 8..])
    }

    /// The bytes of accessor `index`'s buffer view and its stride, after checking they fit.
    fn view_of<'a>(json: &'a Value, bin: &'a [u8], accessor: usize) -> (&'a [u8], usize, &'a str) {
        let a = &json["accessors"][accessor];
        let view = &json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let offset = view["byteOffset"].as_u64().unwrap() as usize;
        let length = view["byteLength"].as_u64().unwrap() as usize;
        assert_eq!(offset % 4, 0, "aligned view");
        assert!(offset + length <= bin.len());
        let components = match a["type"].as_str().unwrap() {
            "SCALAR" => 1,
            "VEC2" => 2,
            "VEC3" => 3,
            "VEC4" => 4,
            other => panic!("{other}"),
        };
        let size = match a["componentType"].as_u64().unwrap() as u32 {
            UNSIGNED_SHORT => 2,
            UNSIGNED_INT | FLOAT => 4,
            other => panic!("{other}"),
        };
        let element = components * size;
        let stride = view["byteStride"].as_u64().map_or(element, |s| s as usize);
        if view["target"] == ARRAY_BUFFER {
            assert_eq!(
                stride % 4,
                0,
                "vertex attributes have 4-byte aligned elements"
            );
        }
        let count = a["count"].as_u64().unwrap() as usize;
        assert!(
            (count - 1) * stride + element <= length,
            "accessor {accessor} fits"
        );
        (
            &bin[offset..offset + length],
            stride,
            a["type"].as_str().unwrap(),
        )
    }

    fn f32s(bytes: &[u8]) -> Vec<f32> {
        bytes
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes(b.try_into().unwrap()))
            .collect()
    }

    fn u16_at(bytes: &[u8], at: usize) -> f64 {
        f64::from(u16::from_le_bytes([bytes[at], bytes[at + 1]]))
    }

    fn sphere_with_materials() -> (TriangleMesh, Vec<VertexMaterial>) {
        let centre = DVec3::new(0.5, -0.2, 1.0);
        let mesh = TriangleMesh::icosphere(centre, 0.7, 3);
        let materials = mesh
            .vertices
            .iter()
            .map(|v| {
                let d = (DVec3::from_array(*v) - centre) / 0.7;
                VertexMaterial {
                    albedo: DVec3::new(0.5 + 0.5 * d.x, 0.25, 0.5 - 0.4 * d.y),
                    roughness: 0.5 + 0.45 * d.z,
                    // A quarter of the area (the cap above z = 0.5) has a higher IoR.
                    ior: if d.z > 0.5 { 1.9 } else { 1.45 + 0.01 * d.x },
                }
            })
            .collect();
        (mesh, materials)
    }

    #[test]
    fn a_sphere_round_trips_through_the_glb() {
        let (mesh, materials) = sphere_with_materials();
        let (glb, summary) = glb_bytes(&mesh, &materials, WorldUp::Z).unwrap();
        let (json, bin) = parse_glb(&glb);
        let n = mesh.vertices.len();
        assert_eq!(
            (summary.vertices, summary.triangles, summary.bytes),
            (n, mesh.triangles.len(), glb.len())
        );
        assert_eq!(json["asset"]["version"], "2.0");
        assert_eq!(
            json["buffers"][0]["byteLength"].as_u64().unwrap() as usize,
            bin.len()
        );
        assert_eq!(json["extensionsUsed"], json!(["KHR_materials_ior"]));
        let attributes = &json["meshes"][0]["primitives"][0]["attributes"];
        for (name, accessor) in [
            ("POSITION", 1),
            ("NORMAL", 2),
            ("COLOR_0", 3),
            ("TEXCOORD_0", 4),
            ("_IOR", 5),
        ] {
            assert_eq!(attributes[name], accessor);
            assert_eq!(json["accessors"][accessor]["count"], n);
        }

        // Indices: unsigned short (642 vertices), the mesh's triangles in order.
        assert_eq!(json["accessors"][0]["componentType"], UNSIGNED_SHORT);
        assert_eq!(json["accessors"][0]["count"], 3 * mesh.triangles.len());
        let (indices, _, _) = view_of(&json, bin, 0);
        let read: Vec<u32> = indices
            .chunks_exact(2)
            .map(|b| u32::from(u16::from_le_bytes([b[0], b[1]])))
            .collect();
        assert_eq!(read, mesh.triangles.concat());

        // Positions exactly as float32, bounds equal to their extremes.
        let (positions, _, _) = view_of(&json, bin, 1);
        let positions = f32s(positions);
        for (i, v) in mesh.vertices.iter().enumerate() {
            for c in 0..3 {
                assert_eq!(positions[3 * i + c], v[c] as f32);
            }
        }
        for c in 0..3 {
            let axis = || positions.iter().skip(c).step_by(3).copied();
            let declared = |key: &str| json["accessors"][1][key][c].as_f64().unwrap() as f32;
            assert_eq!(Some(declared("min")), axis().reduce(f32::min), "min[{c}]");
            assert_eq!(Some(declared("max")), axis().reduce(f32::max), "max[{c}]");
        }
        let (lo, hi) = mesh.bounds().unwrap();
        assert!((json["accessors"][1]["min"][2].as_f64().unwrap() - lo.z).abs() < 1e-6);
        assert!((json["accessors"][1]["max"][0].as_f64().unwrap() - hi.x).abs() < 1e-6);

        // Unit normals, the mesh's own.
        let (normals, _, _) = view_of(&json, bin, 2);
        for (i, n) in f32s(normals).chunks_exact(3).enumerate() {
            let n = DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
            assert!((n.length() - 1.0).abs() < 1e-6);
            assert!(n.dot(DVec3::from_array(mesh.normals[i])) > 0.999_999);
        }

        // Albedo as 16-bit linear colour (stride 8).
        let (colors, stride, kind) = view_of(&json, bin, 3);
        assert_eq!((stride, kind), (8, "VEC3"));
        assert_eq!(json["accessors"][3]["normalized"], true);
        for (i, m) in materials.iter().enumerate() {
            for c in 0..3 {
                let value = u16_at(colors, i * stride + 2 * c) / 65535.0;
                assert!((value - m.albedo[c]).abs() <= 0.5 / 65535.0 + 1e-12);
            }
        }

        // Roughness: the texture coordinate read through the ramp (linear filtering, as the
        // sampler says) gives each vertex's roughness back.
        let sampler = &json["samplers"][0];
        assert_eq!(
            (&sampler["magFilter"], &sampler["minFilter"]),
            (&json!(LINEAR), &json!(LINEAR))
        );
        let material = &json["materials"][0];
        let pbr = &material["pbrMetallicRoughness"];
        assert_eq!(pbr["metallicFactor"], 0.0);
        assert_eq!(pbr["roughnessFactor"], 1.0);
        let texture =
            &json["textures"][pbr["metallicRoughnessTexture"]["index"].as_u64().unwrap() as usize];
        let image_json = &json["images"][texture["source"].as_u64().unwrap() as usize];
        assert_eq!(image_json["mimeType"], "image/png");
        let view = &json["bufferViews"][image_json["bufferView"].as_u64().unwrap() as usize];
        let offset = view["byteOffset"].as_u64().unwrap() as usize;
        let png = &bin[offset..offset + view["byteLength"].as_u64().unwrap() as usize];
        let ramp = image::load_from_memory(png).unwrap().to_rgb8();
        assert_eq!(ramp.dimensions(), (RAMP_WIDTH as u32, 1));
        let green = |i: usize| f64::from(ramp.get_pixel(i as u32, 0)[1]) / 255.0;
        assert!(
            (0..RAMP_WIDTH).all(|i| ramp.get_pixel(i as u32, 0)[2] == 0),
            "metallic 0"
        );
        let (uvs, _, _) = view_of(&json, bin, 4);
        let mut worst = 0.0f64;
        for (i, m) in materials.iter().enumerate() {
            let u = u16_at(uvs, 4 * i) / 65535.0;
            let x = (u * RAMP_WIDTH as f64 - 0.5).clamp(0.0, (RAMP_WIDTH - 1) as f64);
            let left = (x.floor() as usize).min(RAMP_WIDTH - 2);
            let t = x - left as f64;
            let read = (1.0 - t) * green(left) + t * green(left + 1);
            worst = worst.max((read - m.roughness).abs());
            assert!((u16_at(uvs, 4 * i + 2) / 65535.0 - 0.5).abs() < 1e-4);
        }
        assert!(worst < 1e-4, "roughness read back within {worst}");

        // The IoR: the area-weighted median (three quarters of the area near 1.45, the cap 1.9),
        // and every vertex's own value in _IOR.
        let ior = material["extensions"]["KHR_materials_ior"]["ior"]
            .as_f64()
            .unwrap();
        assert_eq!(Some(ior), area_weighted_median_ior(&mesh, &materials));
        assert!((ior - 1.45).abs() < 0.011, "{ior}");
        assert_eq!(summary.ior, ior);
        let (iors, _, _) = view_of(&json, bin, 5);
        for (read, m) in f32s(iors).iter().zip(&materials) {
            assert_eq!(*read, m.ior as f32);
        }

        // The node turns world up (+Z) to glTF's +Y.
        let r = &json["nodes"][0]["rotation"];
        let q = DQuat::from_xyzw(
            r[0].as_f64().unwrap(),
            r[1].as_f64().unwrap(),
            r[2].as_f64().unwrap(),
            r[3].as_f64().unwrap(),
        );
        assert!((q.length() - 1.0).abs() < 1e-12);
        assert!((q * DVec3::Z - DVec3::Y).length() < 1e-12);
        assert!((q * DVec3::X - DVec3::NEG_Z).length() < 1e-12);
    }

    #[test]
    fn the_textured_form_carries_the_atlas_the_tangents_and_the_baked_maps() {
        use super::super::bake::{bake, BakeParams, SurfaceSample};
        use crate::core::mesh::AtlasParams;
        let (mesh, materials) = sphere_with_materials();
        let atlas = UvAtlas::build(
            &mesh,
            AtlasParams {
                size: 256,
                ..AtlasParams::default()
            },
        );
        let tangents = atlas.tangents();
        let centre = DVec3::new(0.5, -0.2, 1.0);
        let maps = bake(&atlas, &tangents, BakeParams { dilate: 4 }, |points| {
            points
                .iter()
                .map(|p| {
                    let d = (p.position - centre) / 0.7;
                    SurfaceSample {
                        material: VertexMaterial {
                            albedo: DVec3::new(0.5 + 0.5 * d.x, 0.25, 0.5 - 0.4 * d.y),
                            roughness: 0.5 + 0.45 * d.z,
                            ior: 1.5,
                        },
                        normal: p.normal,
                    }
                })
                .collect()
        });
        let vertex_materials: Vec<VertexMaterial> = atlas
            .source_vertex
            .iter()
            .map(|&v| materials[v as usize])
            .collect();
        let textured = TexturedMesh {
            atlas: &atlas,
            tangents: &tangents,
            vertex_materials: &vertex_materials,
            maps: &maps,
        };
        let (glb, summary) = textured_glb_bytes(&textured, WorldUp::Z).unwrap();
        let (json, bin) = parse_glb(&glb);
        let n = atlas.mesh.vertices.len();
        assert!(n > mesh.vertices.len(), "seam vertices");
        assert_eq!(
            (summary.vertices, summary.triangles, summary.texture_size),
            (n, mesh.triangles.len(), Some(256))
        );
        assert_eq!(
            json["buffers"][0]["byteLength"].as_u64().unwrap() as usize,
            bin.len()
        );
        let attributes = &json["meshes"][0]["primitives"][0]["attributes"];
        for (name, accessor) in [
            ("POSITION", 1),
            ("NORMAL", 2),
            ("TANGENT", 3),
            ("TEXCOORD_0", 4),
            ("_IOR", 5),
        ] {
            assert_eq!(attributes[name], accessor);
            assert_eq!(json["accessors"][accessor]["count"], n);
        }
        assert!(attributes.get("COLOR_0").is_none());
        // Tangents: unit, orthogonal to the normals, w = ±1; the atlas's own.
        let (normals, _, _) = view_of(&json, bin, 2);
        let (tangent_bytes, _, kind) = view_of(&json, bin, 3);
        assert_eq!(kind, "VEC4");
        let normals = f32s(normals);
        for (i, t) in f32s(tangent_bytes).chunks_exact(4).enumerate() {
            let tangent = glam::Vec3::new(t[0], t[1], t[2]);
            let normal = glam::Vec3::from_slice(&normals[3 * i..3 * i + 3]);
            assert!((tangent.length() - 1.0).abs() < 1e-5);
            assert!(tangent.dot(normal).abs() < 1e-5);
            assert!(t[3] == 1.0 || t[3] == -1.0);
            assert_eq!(t[3] as f64, tangents[i][3]);
        }
        // Texture coordinates: the atlas's, in [0, 1].
        let (uvs, _, _) = view_of(&json, bin, 4);
        for (read, uv) in f32s(uvs).chunks_exact(2).zip(&atlas.uvs) {
            assert_eq!(read, [uv[0] as f32, uv[1] as f32]);
        }
        // The material: three textures, each a PNG of the baked map.
        let material = &json["materials"][0];
        let pbr = &material["pbrMetallicRoughness"];
        assert_eq!(json["samplers"][0]["minFilter"], LINEAR_MIPMAP_LINEAR);
        for (reference, map) in [
            (&pbr["baseColorTexture"], &maps.base_colour),
            (&pbr["metallicRoughnessTexture"], &maps.metallic_roughness),
            (&material["normalTexture"], &maps.normal),
        ] {
            assert_eq!(reference["texCoord"], 0);
            let texture = &json["textures"][reference["index"].as_u64().unwrap() as usize];
            let image_json = &json["images"][texture["source"].as_u64().unwrap() as usize];
            assert_eq!(image_json["mimeType"], "image/png");
            let view = &json["bufferViews"][image_json["bufferView"].as_u64().unwrap() as usize];
            let offset = view["byteOffset"].as_u64().unwrap() as usize;
            let png = &bin[offset..offset + view["byteLength"].as_u64().unwrap() as usize];
            let image = image::load_from_memory(png).unwrap().to_rgb8();
            assert_eq!(image.dimensions(), (256, 256));
            assert_eq!(&image.into_raw(), map);
        }
        // Half the sphere's top has roughness above 0.5, read through the map at a vertex's UV.
        let rough_at = |uv: [f64; 2]| {
            let (x, y) = ((uv[0] * 256.0) as usize, (uv[1] * 256.0) as usize);
            f64::from(maps.metallic_roughness[3 * (y.min(255) * 256 + x.min(255)) + 1]) / 255.0
        };
        for (i, uv) in atlas.uvs.iter().enumerate() {
            let expected = vertex_materials[i].roughness;
            assert!((rough_at(*uv) - expected).abs() < 0.05, "vertex {i}");
        }
        let ior = material["extensions"]["KHR_materials_ior"]["ior"]
            .as_f64()
            .unwrap();
        assert!((ior - 1.45).abs() < 0.011, "{ior}");
        assert_eq!(json["extensionsUsed"], json!(["KHR_materials_ior"]));
        // Wrong counts are errors.
        let short = &vertex_materials[1..];
        let broken = TexturedMesh {
            vertex_materials: short,
            ..textured
        };
        assert!(matches!(
            textured_glb_bytes(&broken, WorldUp::Z),
            Err(GltfError::Count {
                what: "materials",
                ..
            })
        ));
    }

    #[test]
    fn orientation_follows_the_world_up_axis() {
        for up in [WorldUp::Z, WorldUp::Y] {
            let q = world_to_gltf(up);
            let (r, f, u) = up.basis();
            assert!((q * u - DVec3::Y).length() < 1e-12, "{up:?}");
            assert!((q * r - DVec3::NEG_Z).length() < 1e-12, "{up:?}");
            assert!((q * f - DVec3::NEG_X).length() < 1e-12, "{up:?}");
        }
        assert_eq!(roughness_to_u(0.0), 0.5 / 256.0);
        assert_eq!(roughness_to_u(1.0), 255.5 / 256.0);
        assert_eq!(roughness_to_u(7.0), roughness_to_u(1.0));
    }

    #[test]
    fn large_meshes_get_32_bit_indices_and_missing_normals_are_computed() {
        // A 300 × 300 grid (90 000 vertices > 65 535) in the plane z = 0.25, without normals.
        let side = 300u32;
        let mut mesh = TriangleMesh::default();
        for y in 0..side {
            for x in 0..side {
                mesh.vertices
                    .push([f64::from(x) / 100.0, f64::from(y) / 100.0, 0.25]);
            }
        }
        for y in 0..side - 1 {
            for x in 0..side - 1 {
                let i = y * side + x;
                mesh.triangles.push([i, i + 1, i + side]);
                mesh.triangles.push([i + 1, i + side + 1, i + side]);
            }
        }
        // A triangle that repeats a vertex is dropped.
        mesh.triangles.push([5, 5, 6]);
        let materials = vec![
            VertexMaterial {
                albedo: DVec3::new(0.2, 0.3, 0.4),
                roughness: 0.6,
                ior: 1.33,
            };
            mesh.vertices.len()
        ];
        let (glb, summary) = glb_bytes(&mesh, &materials, WorldUp::Y).unwrap();
        let (json, bin) = parse_glb(&glb);
        assert_eq!(summary.triangles, mesh.triangles.len() - 1);
        assert_eq!(json["accessors"][0]["componentType"], UNSIGNED_INT);
        assert_eq!(json["accessors"][0]["count"], 3 * summary.triangles);
        let (indices, _, _) = view_of(&json, bin, 0);
        let last = u32::from_le_bytes(indices[indices.len() - 4..].try_into().unwrap());
        assert_eq!(last, side * side - 2);
        let (normals, _, _) = view_of(&json, bin, 2);
        assert!(f32s(normals).chunks_exact(3).all(|n| n == [0.0, 0.0, 1.0]));
        assert_eq!(json["accessors"][1]["min"], json!([0.0, 0.0, 0.25]));
        assert_eq!(
            json["accessors"][1]["max"],
            json!([2.99f32 as f64, 2.99f32 as f64, 0.25])
        );
        let ior = json["materials"][0]["extensions"]["KHR_materials_ior"]["ior"].as_f64();
        assert_eq!(ior, Some(1.33));
    }

    #[test]
    fn bad_meshes_are_errors_not_panics() {
        let (mesh, materials) = sphere_with_materials();
        assert!(matches!(
            glb_bytes(&mesh, &materials[1..], WorldUp::Z),
            Err(GltfError::Count {
                what: "materials",
                ..
            })
        ));
        assert!(matches!(
            glb_bytes(&TriangleMesh::default(), &[], WorldUp::Z),
            Err(GltfError::EmptyMesh)
        ));
        let mut broken = mesh.clone();
        broken.triangles[3][1] = 9999;
        assert!(matches!(
            glb_bytes(&broken, &materials, WorldUp::Z),
            Err(GltfError::Index {
                triangle: 3,
                index: 9999,
                ..
            })
        ));
        let mut broken = mesh.clone();
        broken.vertices[7][0] = f64::NAN;
        assert!(matches!(
            glb_bytes(&broken, &materials, WorldUp::Z),
            Err(GltfError::NonFinite {
                what: "position",
                index: 7
            })
        ));
        let mut broken = mesh.clone();
        broken.vertices[2][1] = 1e300;
        assert!(matches!(
            glb_bytes(&broken, &materials, WorldUp::Z),
            Err(GltfError::NonFinite { index: 2, .. })
        ));
        let mut bad = materials.clone();
        bad[4].ior = f64::INFINITY;
        assert!(matches!(
            glb_bytes(&mesh, &bad, WorldUp::Z),
            Err(GltfError::NonFinite {
                what: "IoR",
                index: 4
            })
        ));
    }
}

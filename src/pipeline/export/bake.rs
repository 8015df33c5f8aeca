//! Baking a surface's materials into the textures of a UV atlas ([`UvAtlas`]): base colour,
//! metallic-roughness and a tangent-space normal map, as glTF's metallic-roughness material reads
//! them.
//!
//! Every texel whose centre lies in a triangle of the atlas (edges included) stands for the
//! surface point at the same barycentric coordinates of the triangle in 3-D; a sampler (the
//! surfels' materials and normals, [`super::materials::SurfelSampler`]) gives its albedo,
//! roughness and normal there. The maps hold:
//!
//! - base colour: the albedo, sRGB-encoded 8-bit RGB (glTF's `baseColorTexture` is sRGB);
//! - metallic-roughness: R 255 (occlusion, unused), G the roughness, B 0 (metallic), linear;
//! - normal: the sampled normal in the frame a viewer rebuilds from the mesh's interpolated
//!   `NORMAL` and `TANGENT` (three.js and the glTF reference viewer: normalize(T x + B y + N z)
//!   with T, N and B = N × T · w each interpolated and normalized), so the map's (x, y, z) solve
//!   that for the sampled normal exactly; encoded (v + 1) / 2 in 8 bits. The mesh's own normal is
//!   (0.5, 0.5, 1).
//!
//! Texels no triangle covers are first dilated from their covered neighbours for
//! [`BakeParams::dilate`] rings (the gutter, so that bilinear filtering and the first mip levels
//! at a chart's edge do not mix in anything but the chart's own values), then filled with the mean
//! of the covered texels (base colour, roughness) or the flat normal.
//!
//! Threading: the texels' surface points and their encoding run in parallel over image rows
//! (rayon); the sampler is called once for all covered texels; rasterization and dilation are
//! sequential.

use glam::{DMat3, DVec2, DVec3};
use rayon::prelude::*;

use super::materials::VertexMaterial;
use crate::core::mesh::UvAtlas;
use crate::formats::image_io::linear_to_srgb;

/// A point of the surface that a texel stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    pub position: DVec3,
    /// The mesh's interpolated normal there (unit).
    pub normal: DVec3,
}

/// What the surface holds at a [`SurfacePoint`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceSample {
    pub material: VertexMaterial,
    /// The surface's normal (unit; the map stores it against the mesh's frame).
    pub normal: DVec3,
}

/// How far the bake fills the empty texels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BakeParams {
    /// Rings of empty texels around the charts that take their neighbours' values.
    pub dilate: u32,
}

/// The baked textures: 8-bit RGB, row-major, `size` × `size`, the first row at v = 0.
#[derive(Clone, Debug, PartialEq)]
pub struct BakedMaps {
    pub size: u32,
    pub base_colour: Vec<u8>,
    pub metallic_roughness: Vec<u8>,
    pub normal: Vec<u8>,
    /// Texels whose centre lies in a triangle.
    pub covered: usize,
}

/// The texel's value of the map's encodings of a unit vector component.
fn signed_level(v: f64) -> u8 {
    ((v.clamp(-1.0, 1.0) * 0.5 + 0.5) * 255.0).round() as u8
}

fn unsigned_level(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn srgb_level(linear: f64) -> u8 {
    (linear_to_srgb(linear.clamp(0.0, 1.0) as f32) * 255.0).round() as u8
}

/// For every texel, the triangle whose surface it stands for and the barycentric coordinates of
/// its centre (`None` outside every triangle); the first triangle wins on shared edges.
fn rasterize(atlas: &UvAtlas) -> Vec<Option<(u32, [f64; 3])>> {
    let size = atlas.size as usize;
    let mut texels = vec![None; size * size];
    for t in 0..atlas.mesh.triangles.len() {
        let [a, b, c] = atlas.texel_triangle(t);
        let twice_area = (b - a).perp_dot(c - a);
        if twice_area.abs() < 1e-12 {
            continue;
        }
        let lo = a.min(b).min(c).floor().max(DVec2::ZERO);
        let hi = a.max(b).max(c).ceil().min(DVec2::splat(size as f64));
        // A texel centre on an edge belongs to both sides: a tolerance of a millionth of a texel.
        let eps = -1e-6 * twice_area.abs();
        for y in lo.y as usize..hi.y as usize {
            for x in lo.x as usize..hi.x as usize {
                let p = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
                let w = [
                    (c - b).perp_dot(p - b) * twice_area.signum(),
                    (a - c).perp_dot(p - c) * twice_area.signum(),
                    (b - a).perp_dot(p - a) * twice_area.signum(),
                ];
                if w.iter().all(|&w| w >= eps) {
                    let slot = &mut texels[y * size + x];
                    if slot.is_none() {
                        let total = twice_area.abs();
                        let bary = w.map(|w| w.max(0.0) / total);
                        let sum: f64 = bary.iter().sum();
                        *slot = Some((t as u32, bary.map(|b| b / sum)));
                    }
                }
            }
        }
    }
    texels
}

/// The frame a viewer decodes the normal map in at barycentric `bary` of triangle `t`: interpolated
/// and normalized tangent, bitangent (N × T · w per vertex) and normal, as the columns.
fn viewer_frame(atlas: &UvAtlas, tangents: &[[f64; 4]], t: usize, bary: [f64; 3]) -> DMat3 {
    let mut normal = DVec3::ZERO;
    let mut tangent = DVec3::ZERO;
    let mut bitangent = DVec3::ZERO;
    for (k, &i) in atlas.mesh.triangles[t].iter().enumerate() {
        let n = DVec3::from_array(atlas.mesh.normals[i as usize]).normalize_or_zero();
        let [x, y, z, w] = tangents[i as usize];
        let tv = DVec3::new(x, y, z);
        normal += bary[k] * n;
        tangent += bary[k] * tv;
        bitangent += bary[k] * (n.cross(tv) * w).normalize_or_zero();
    }
    DMat3::from_cols(
        tangent.normalize_or_zero(),
        bitangent.normalize_or_zero(),
        normal.normalize_or_zero(),
    )
}

/// Bakes the maps of `atlas` (module doc): `tangents` are the atlas's ([`UvAtlas::tangents`]),
/// `sample` gives the surface at a list of points (one sample per point, in order).
pub fn bake(
    atlas: &UvAtlas,
    tangents: &[[f64; 4]],
    params: BakeParams,
    sample: impl Fn(&[SurfacePoint]) -> Vec<SurfaceSample>,
) -> BakedMaps {
    let _span = tracing::info_span!("bake", size = atlas.size).entered();
    let size = atlas.size as usize;
    let texels = rasterize(atlas);
    let covered: Vec<(usize, u32, [f64; 3])> = texels
        .iter()
        .enumerate()
        .filter_map(|(i, t)| t.map(|(t, bary)| (i, t, bary)))
        .collect();
    let points: Vec<(SurfacePoint, DMat3)> = covered
        .par_iter()
        .map(|&(_, t, bary)| {
            let corners = atlas.mesh.triangle_corners(t as usize);
            let position = bary[0] * corners[0] + bary[1] * corners[1] + bary[2] * corners[2];
            let frame = viewer_frame(atlas, tangents, t as usize, bary);
            let normal = frame.z_axis;
            (SurfacePoint { position, normal }, frame)
        })
        .collect();
    let surface: Vec<SurfacePoint> = points.iter().map(|p| p.0).collect();
    let samples = sample(&surface);
    assert_eq!(samples.len(), surface.len(), "one sample per point");

    // Encoded values of the covered texels, then the images.
    let encoded: Vec<[[u8; 3]; 3]> = samples
        .par_iter()
        .zip(&points)
        .map(|(s, (_, frame))| {
            let m = s.material;
            let base = [
                srgb_level(m.albedo.x),
                srgb_level(m.albedo.y),
                srgb_level(m.albedo.z),
            ];
            let mr = [255, unsigned_level(m.roughness), 0];
            // Solve T x + B y + N z ∥ n; a degenerate frame keeps the mesh's normal.
            let inverse = frame.inverse();
            let local = if inverse.is_finite() {
                (inverse * s.normal).try_normalize().unwrap_or(DVec3::Z)
            } else {
                DVec3::Z
            };
            let nm = [
                signed_level(local.x),
                signed_level(local.y),
                signed_level(local.z),
            ];
            [base, mr, nm]
        })
        .collect();
    let mut maps = [
        vec![0u8; 3 * size * size],
        vec![0u8; 3 * size * size],
        vec![0u8; 3 * size * size],
    ];
    let mut filled = vec![false; size * size];
    for (&(i, _, _), values) in covered.iter().zip(&encoded) {
        for (map, value) in maps.iter_mut().zip(values) {
            map[3 * i..3 * i + 3].copy_from_slice(value);
        }
        filled[i] = true;
    }
    dilate(&mut maps, &mut filled, size, params.dilate);
    // The rest: the mean of what was covered (the flat normal for the normal map).
    let mean = |map: &[u8], c: usize| {
        let sum: u64 = covered
            .iter()
            .map(|&(i, _, _)| u64::from(map[3 * i + c]))
            .sum();
        (sum as f64 / covered.len().max(1) as f64).round() as u8
    };
    let fill = [
        [mean(&maps[0], 0), mean(&maps[0], 1), mean(&maps[0], 2)],
        [255, mean(&maps[1], 1), 0],
        [signed_level(0.0), signed_level(0.0), 255],
    ];
    for (i, _) in filled.iter().enumerate().filter(|(_, f)| !**f) {
        for (map, value) in maps.iter_mut().zip(&fill) {
            map[3 * i..3 * i + 3].copy_from_slice(value);
        }
    }
    let [base_colour, metallic_roughness, normal] = maps;
    BakedMaps {
        size: atlas.size,
        base_colour,
        metallic_roughness,
        normal,
        covered: covered.len(),
    }
}

/// `rings` times: every empty texel next to (8-neighbourhood) a filled one takes the mean of those
/// neighbours, in every map.
fn dilate(maps: &mut [Vec<u8>; 3], filled: &mut [bool], size: usize, rings: u32) {
    for _ in 0..rings {
        let mut updates = Vec::new();
        for y in 0..size {
            for x in 0..size {
                if filled[y * size + x] {
                    continue;
                }
                let mut sums = [[0u32; 3]; 3];
                let mut count = 0;
                for dy in -1i64..=1 {
                    for dx in -1i64..=1 {
                        let (nx, ny) = (x as i64 + dx, y as i64 + dy);
                        if nx < 0 || ny < 0 || nx >= size as i64 || ny >= size as i64 {
                            continue;
                        }
                        let j = ny as usize * size + nx as usize;
                        if !filled[j] {
                            continue;
                        }
                        count += 1;
                        for (sum, map) in sums.iter_mut().zip(maps.iter()) {
                            for c in 0..3 {
                                sum[c] += u32::from(map[3 * j + c]);
                            }
                        }
                    }
                }
                if count > 0 {
                    updates.push((
                        y * size + x,
                        sums.map(|s| s.map(|v| ((v + count / 2) / count) as u8)),
                    ));
                }
            }
        }
        if updates.is_empty() {
            break;
        }
        for (i, values) in updates {
            for (map, value) in maps.iter_mut().zip(&values) {
                map[3 * i..3 * i + 3].copy_from_slice(value);
            }
            filled[i] = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::mesh::{AtlasParams, TriangleMesh};

    fn albedo_of(p: DVec3) -> DVec3 {
        DVec3::new(
            0.5 + 0.4 * (2.0 * p.x).sin(),
            0.3 + 0.2 * p.y,
            0.6 - 0.3 * p.z.abs(),
        )
    }

    fn roughness_of(p: DVec3) -> f64 {
        0.5 + 0.35 * (1.5 * p.z + p.x).sin()
    }

    fn srgb_to_linear(level: u8) -> f64 {
        let c = f64::from(level) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    }

    /// The normal of `mesh` at `p`, found independently of the bake: the triangle closest to `p`
    /// (brute force) and its vertex normals interpolated at `p`'s barycentric coordinates.
    fn mesh_normal_at(mesh: &TriangleMesh, p: DVec3) -> DVec3 {
        let mut best = (f64::INFINITY, DVec3::Z);
        for t in 0..mesh.triangles.len() {
            let [a, b, c] = mesh.triangle_corners(t);
            let n = (b - a).cross(c - a);
            let distance = (p - a).dot(n.normalize()).abs();
            let area2 = n.length_squared();
            let w = [
                (c - b).cross(p - b).dot(n) / area2,
                (a - c).cross(p - c).dot(n) / area2,
                (b - a).cross(p - a).dot(n) / area2,
            ];
            if w.iter().all(|&w| w >= -1e-6) && distance < best.0 {
                let normal = mesh.triangles[t]
                    .iter()
                    .zip(w)
                    .map(|(&i, w)| w * DVec3::from_array(mesh.normals[i as usize]))
                    .sum::<DVec3>();
                best = (distance, normal.normalize());
            }
        }
        best.1
    }

    fn known_sampler(points: &[SurfacePoint]) -> Vec<SurfaceSample> {
        points
            .iter()
            .map(|p| SurfaceSample {
                material: VertexMaterial {
                    albedo: albedo_of(p.position),
                    roughness: roughness_of(p.position),
                    ior: 1.5,
                },
                normal: p.normal,
            })
            .collect()
    }

    fn sphere_atlas(size: u32) -> (TriangleMesh, UvAtlas) {
        let mesh = TriangleMesh::icosphere(DVec3::new(0.2, -0.1, 0.3), 0.8, 3);
        let atlas = UvAtlas::build(
            &mesh,
            AtlasParams {
                size,
                ..AtlasParams::default()
            },
        );
        (mesh, atlas)
    }

    #[test]
    fn a_material_given_by_position_is_reproduced_at_the_texel_centres() {
        let (_, atlas) = sphere_atlas(256);
        let tangents = atlas.tangents();
        let maps = bake(&atlas, &tangents, BakeParams { dilate: 2 }, known_sampler);
        let texels = rasterize(&atlas);
        let size = atlas.size as usize;
        assert_eq!(maps.covered, texels.iter().flatten().count());
        assert!(
            maps.covered > size * size / 3,
            "{} texels covered",
            maps.covered
        );
        let mut worst_albedo = 0.0f64;
        let mut worst_roughness = 0.0f64;
        for (i, texel) in texels.iter().enumerate() {
            let Some((t, _)) = texel else { continue };
            // The texel centre's surface point, recomputed from the UVs.
            let (x, y) = (i % size, i / size);
            let p = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
            let [a, b, c] = atlas.texel_triangle(*t as usize);
            let area = (b - a).perp_dot(c - a);
            let w = [
                (c - b).perp_dot(p - b) / area,
                (a - c).perp_dot(p - c) / area,
                (b - a).perp_dot(p - a) / area,
            ];
            let corners = atlas.mesh.triangle_corners(*t as usize);
            let position = w[0] * corners[0] + w[1] * corners[1] + w[2] * corners[2];
            let albedo = albedo_of(position);
            for c in 0..3 {
                let read = srgb_to_linear(maps.base_colour[3 * i + c]);
                // Half an 8-bit sRGB level: at most 0.5/255 times the slope of the sRGB decoding,
                // 2.28 near 1, so 0.0045 in linear terms.
                worst_albedo = worst_albedo.max((read - albedo[c]).abs());
            }
            let read = f64::from(maps.metallic_roughness[3 * i + 1]) / 255.0;
            worst_roughness = worst_roughness.max((read - roughness_of(position)).abs());
            assert_eq!(maps.metallic_roughness[3 * i + 2], 0, "metallic 0");
        }
        assert!(worst_albedo < 0.0046, "albedo off by {worst_albedo}");
        assert!(
            worst_roughness <= 0.5 / 255.0 + 1e-9,
            "roughness off by {worst_roughness}"
        );
    }

    #[test]
    fn a_mesh_baked_against_itself_has_a_flat_normal_map() {
        let (mesh, atlas) = sphere_atlas(128);
        let tangents = atlas.tangents();
        // The normal of the source mesh, found by a search of its own (not the bake's point).
        let maps = bake(&atlas, &tangents, BakeParams { dilate: 2 }, |points| {
            points
                .iter()
                .map(|p| SurfaceSample {
                    material: VertexMaterial {
                        albedo: DVec3::splat(0.5),
                        roughness: 0.5,
                        ior: 1.5,
                    },
                    normal: mesh_normal_at(&mesh, p.position),
                })
                .collect()
        });
        let flat = [128u8, 128, 255];
        let mut off = 0;
        for texel in maps.normal.chunks_exact(3) {
            if texel.iter().zip(flat).any(|(&v, f)| v.abs_diff(f) > 1) {
                off += 1;
            }
        }
        assert_eq!(off, 0, "{off} texels differ from (0.5, 0.5, 1)");
    }

    #[test]
    fn a_tilted_normal_reads_back_through_the_viewers_frame() {
        // The sampled normal leans 30° from the mesh's, toward world +Z where it can: the map,
        // decoded as a viewer does from the interpolated NORMAL and TANGENT, gives it back.
        let (_, atlas) = sphere_atlas(128);
        let tangents = atlas.tangents();
        let lean = |n: DVec3| {
            let side = (DVec3::Z - n * n.z).try_normalize().unwrap_or(DVec3::X);
            (n * 30f64.to_radians().cos() + side * 30f64.to_radians().sin()).normalize()
        };
        let maps = bake(&atlas, &tangents, BakeParams { dilate: 0 }, |points| {
            points
                .iter()
                .map(|p| SurfaceSample {
                    material: VertexMaterial {
                        albedo: DVec3::splat(0.5),
                        roughness: 0.5,
                        ior: 1.5,
                    },
                    normal: lean(p.normal),
                })
                .collect()
        });
        let size = atlas.size as usize;
        let mut worst = 0.0f64;
        let mut tilted = 0;
        for (i, texel) in rasterize(&atlas).iter().enumerate() {
            let Some((t, bary)) = texel else { continue };
            let frame = viewer_frame(&atlas, &tangents, *t as usize, *bary);
            let decode = |c: usize| f64::from(maps.normal[3 * i + c]) / 255.0 * 2.0 - 1.0;
            let read = (frame * DVec3::new(decode(0), decode(1), decode(2))).normalize();
            let expected = lean(frame.z_axis);
            worst = worst.max(read.angle_between(expected).to_degrees());
            if maps.normal[3 * i + 2] < 240 {
                tilted += 1;
            }
        }
        assert!(worst < 0.7, "normal read back {worst}° off");
        assert!(tilted > size * size / 4, "the map leans ({tilted} texels)");
    }

    #[test]
    fn the_gutter_takes_the_neighbouring_values_and_the_rest_the_mean() {
        let (_, atlas) = sphere_atlas(128);
        let tangents = atlas.tangents();
        let maps = bake(&atlas, &tangents, BakeParams { dilate: 2 }, known_sampler);
        let size = atlas.size as usize;
        let texels = rasterize(&atlas);
        // Every texel next to a covered one was filled from covered ones: no black texel there.
        for y in 0..size {
            for x in 0..size {
                let i = y * size + x;
                if texels[i].is_some() {
                    continue;
                }
                let near = (y.saturating_sub(1)..(y + 2).min(size))
                    .flat_map(|ny| (x.saturating_sub(1)..(x + 2).min(size)).map(move |nx| (nx, ny)))
                    .filter(|&(nx, ny)| texels[ny * size + nx].is_some())
                    .count();
                if near > 0 {
                    let neighbours: Vec<usize> = (y.saturating_sub(1)..(y + 2).min(size))
                        .flat_map(|ny| {
                            (x.saturating_sub(1)..(x + 2).min(size)).map(move |nx| ny * size + nx)
                        })
                        .filter(|&j| texels[j].is_some())
                        .collect();
                    for c in 0..3 {
                        let lo = neighbours
                            .iter()
                            .map(|&j| maps.base_colour[3 * j + c])
                            .min()
                            .unwrap();
                        let hi = neighbours
                            .iter()
                            .map(|&j| maps.base_colour[3 * j + c])
                            .max()
                            .unwrap();
                        let v = maps.base_colour[3 * i + c];
                        assert!(
                            lo <= v && v <= hi,
                            "texel ({x}, {y}) channel {c}: {v} outside {lo}..{hi}"
                        );
                    }
                }
            }
        }
        assert!(
            maps.base_colour.chunks_exact(3).all(|t| t != [0, 0, 0]),
            "no black texel"
        );
        assert!(maps
            .metallic_roughness
            .chunks_exact(3)
            .all(|t| t[0] == 255 && t[2] == 0));
    }
}

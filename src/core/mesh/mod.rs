//! Triangle meshes: PLY/OBJ input and output, TSDF fusion of depth maps followed by marching cubes
//! (METHOD.md §8), surface sampling and the unidirectional Chamfer-L1 metric.
//!
//! The submodules split the work: `ply` maps meshes to and from documents of the crate's one PLY
//! parser ([`crate::formats::ply`]), `tsdf` fuses depth maps into a truncated signed distance grid,
//! `marching_cubes` turns that grid into a welded mesh, `holes` closes the holes left where no
//! camera looked (along a `quadric` fitted around each, where one fits), `smooth` filters its
//! normals (bilateral) and fits the surface to them, `simplify` reduces it by quadric-error edge
//! collapses, `uv_atlas` cuts it into charts laid out in a texture (for baking materials), and
//! `chamfer` measures the distance (and the normal error) from one mesh to another. Long stages
//! run inside `tracing` spans and use rayon over independent voxel slabs or sample chunks.

use std::path::{Path, PathBuf};

use glam::DVec3;
use thiserror::Error;

pub mod bench;
pub mod bvh;
mod chamfer;
mod holes;
mod marching_cubes;
mod ply;
mod quadric;
mod simplify;
mod smooth;
mod tsdf;
pub mod uv_atlas;

pub use chamfer::{
    chamfer_l1, chamfer_l1_with, normal_mae_deg, normal_mae_deg_with, sample_surface,
    CHAMFER_SAMPLES,
};
pub use holes::ClosedHoles;
pub use marching_cubes::{marching_cubes, ScalarGrid};
pub use simplify::{Simplification, SimplifyTarget};
pub use smooth::{SmoothParams, NORMAL_SIGMA};
#[cfg(test)]
pub(crate) use tsdf::reference as tsdf_reference;
pub use tsdf::{
    cameras_around, cameras_around_point, depth_spread, extract_mesh, fuse_tsdf, fusion_depth,
    mesh_from_grid, rendered_depth_views, sphere_depth_maps, DepthPixels, DepthView, GridLayout,
    TsdfParams, MARGIN_VOXELS, SURFACE_SPREAD_FOOTPRINTS,
};
pub use uv_atlas::{AtlasParams, UvAtlas};

/// Errors of mesh input/output, extraction and metrics.
#[derive(Debug, Error)]
pub enum MeshError {
    #[error("mesh file {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("PLY file {path}: {source}")]
    Ply {
        path: PathBuf,
        source: crate::formats::ply::PlyError,
    },
    #[error("TSDF fusion needs at least one depth view")]
    NoViews,
    #[error("depth view {view}: {what} has {actual} values but the camera has {expected} pixels")]
    ViewSize {
        view: usize,
        what: &'static str,
        expected: usize,
        actual: usize,
    },
    #[error("TSDF bounds are empty or not finite: min {min}, max {max}")]
    InvalidBounds { min: DVec3, max: DVec3 },
    #[error("TSDF parameter {name} = {value} is out of range ({reason})")]
    InvalidParameter {
        name: &'static str,
        value: f64,
        reason: &'static str,
    },
    #[error("the TSDF has no zero crossing: no surface was observed inside the bounds")]
    NoSurface,
    #[error("mesh `{name}` has no triangles of positive area")]
    EmptyMesh { name: &'static str },
    #[error("none of the {samples} points sampled on the predicted mesh lies inside the GT bounding box")]
    NoSamplesInsideBox { samples: usize },
}

/// An indexed triangle mesh in world coordinates. `normals` is either empty or holds one unit
/// normal per vertex. Triangles are counter-clockwise seen from outside. `material_ids` is either
/// empty or holds one material id per triangle (the GT meshes' 1-based index into scene.json's
/// materials).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    pub vertices: Vec<[f64; 3]>,
    pub normals: Vec<[f64; 3]>,
    pub triangles: Vec<[u32; 3]>,
    pub material_ids: Vec<u8>,
}

impl TriangleMesh {
    /// Reads a PLY file (ASCII or binary, any property order; polygons are fan-triangulated, a
    /// per-face `material_id` is kept on each of its triangles).
    pub fn read_ply(path: &Path) -> Result<Self, MeshError> {
        ply::read_ply(path)
    }

    /// Writes a binary little-endian PLY: float `x y z` (+ `nx ny nz` when normals are present),
    /// faces as `list uchar int vertex_indices` (+ `uchar material_id` when ids are present).
    pub fn write_ply(&self, path: &Path) -> Result<(), MeshError> {
        ply::write_ply(self, path)
    }

    /// Writes a Wavefront OBJ (`v`, `vn` when normals are present, 1-based `f`).
    pub fn write_obj(&self, path: &Path) -> Result<(), MeshError> {
        use std::io::Write;
        let io = |source| MeshError::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = std::fs::File::create(path).map_err(io)?;
        let mut out = std::io::BufWriter::new(file);
        writeln!(
            out,
            "# phygap mesh: {} vertices, {} triangles",
            self.vertices.len(),
            self.triangles.len()
        )
        .map_err(io)?;
        for v in &self.vertices {
            writeln!(out, "v {} {} {}", v[0], v[1], v[2]).map_err(io)?;
        }
        let with_normals = self.has_normals();
        if with_normals {
            for n in &self.normals {
                writeln!(out, "vn {} {} {}", n[0], n[1], n[2]).map_err(io)?;
            }
        }
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| i + 1);
            if with_normals {
                writeln!(out, "f {a}//{a} {b}//{b} {c}//{c}").map_err(io)?;
            } else {
                writeln!(out, "f {a} {b} {c}").map_err(io)?;
            }
        }
        out.flush().map_err(io)
    }

    /// True when there is one normal per vertex.
    pub fn has_normals(&self) -> bool {
        !self.vertices.is_empty() && self.normals.len() == self.vertices.len()
    }

    /// Vertex `i` as a vector.
    pub fn vertex(&self, i: u32) -> DVec3 {
        DVec3::from_array(self.vertices[i as usize])
    }

    /// The three corners of triangle `t`.
    pub fn triangle_corners(&self, t: usize) -> [DVec3; 3] {
        self.triangles[t].map(|i| self.vertex(i))
    }

    /// Axis-aligned bounding box of the vertices referenced by triangles, or `None` without triangles.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let mut it = self.triangles.iter().flatten().map(|&i| self.vertex(i));
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p))))
    }

    /// Total surface area.
    pub fn area(&self) -> f64 {
        (0..self.triangles.len())
            .map(|t| {
                let [a, b, c] = self.triangle_corners(t);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum()
    }

    /// Volume enclosed by a closed mesh, positive when its triangles wind counter-clockwise seen
    /// from outside (the sum of the signed tetrahedra the triangles make with the origin).
    pub fn signed_volume(&self) -> f64 {
        (0..self.triangles.len())
            .map(|t| {
                let [a, b, c] = self.triangle_corners(t);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    /// Recomputes vertex normals as the normalized sum of the (area-weighted) face normals of the
    /// adjacent triangles; the face normal follows the counter-clockwise winding.
    pub fn compute_vertex_normals(&mut self) {
        self.normals = self
            .area_weighted_normal_sums(self.triangles.len())
            .into_iter()
            .map(|s| s.try_normalize().unwrap_or(DVec3::Z).to_array())
            .collect();
    }

    /// Per vertex, the sum of the (twice-)area-weighted normals of the first `triangles`
    /// triangles that use it (zero for a vertex none uses).
    fn area_weighted_normal_sums(&self, triangles: usize) -> Vec<DVec3> {
        let mut sums = vec![DVec3::ZERO; self.vertices.len()];
        for t in 0..triangles {
            let [a, b, c] = self.triangle_corners(t);
            let twice_area_normal = (b - a).cross(c - a);
            for &i in &self.triangles[t] {
                sums[i as usize] += twice_area_normal;
            }
        }
        sums
    }

    /// Keeps the connected component (triangles linked through shared vertices) with the most
    /// triangles and drops the vertices no longer referenced. Normals and material ids are kept
    /// when present.
    pub fn keep_largest_component(&mut self) {
        let n = self.vertices.len();
        let mut parent: Vec<u32> = (0..n as u32).collect();
        fn find(parent: &mut [u32], mut x: u32) -> u32 {
            while parent[x as usize] != x {
                let grand = parent[parent[x as usize] as usize];
                parent[x as usize] = grand;
                x = grand;
            }
            x
        }
        for t in &self.triangles {
            let r0 = find(&mut parent, t[0]);
            for &v in &t[1..] {
                let r = find(&mut parent, v);
                if r != r0 {
                    parent[r as usize] = r0;
                }
            }
        }
        let mut triangles_per_root = vec![0usize; n];
        for t in &self.triangles {
            triangles_per_root[find(&mut parent, t[0]) as usize] += 1;
        }
        let Some(largest) = (0..n).max_by_key(|&r| (triangles_per_root[r], std::cmp::Reverse(r)))
        else {
            return;
        };
        let keep: Vec<bool> = self
            .triangles
            .iter()
            .map(|t| find(&mut parent, t[0]) as usize == largest)
            .collect();
        let mut kept = keep.iter();
        self.triangles
            .retain(|_| *kept.next().expect("one flag per triangle"));
        if self.material_ids.len() == keep.len() {
            let mut kept = keep.iter();
            self.material_ids
                .retain(|_| *kept.next().expect("one flag per triangle"));
        }
        self.drop_unreferenced_vertices();
    }

    /// Removes vertices that no triangle references, renumbering the triangles.
    pub fn drop_unreferenced_vertices(&mut self) {
        let mut new_index = vec![u32::MAX; self.vertices.len()];
        let mut vertices = Vec::new();
        let mut normals = Vec::new();
        let with_normals = self.has_normals();
        for t in &mut self.triangles {
            for i in t.iter_mut() {
                let slot = &mut new_index[*i as usize];
                if *slot == u32::MAX {
                    *slot = vertices.len() as u32;
                    vertices.push(self.vertices[*i as usize]);
                    if with_normals {
                        normals.push(self.normals[*i as usize]);
                    }
                }
                *i = *slot;
            }
        }
        self.vertices = vertices;
        self.normals = normals;
    }

    /// A sphere tessellated by subdividing an icosahedron `subdivisions` times (20·4^s triangles),
    /// vertices exactly on the sphere, outward normals. Handy for tests and benchmarks.
    pub fn icosphere(centre: DVec3, radius: f64, subdivisions: u32) -> Self {
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        let mut dirs: Vec<DVec3> = [
            (-1.0, phi, 0.0),
            (1.0, phi, 0.0),
            (-1.0, -phi, 0.0),
            (1.0, -phi, 0.0),
            (0.0, -1.0, phi),
            (0.0, 1.0, phi),
            (0.0, -1.0, -phi),
            (0.0, 1.0, -phi),
            (phi, 0.0, -1.0),
            (phi, 0.0, 1.0),
            (-phi, 0.0, -1.0),
            (-phi, 0.0, 1.0),
        ]
        .iter()
        .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
        .collect();
        let mut triangles: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..subdivisions {
            let mut midpoints = std::collections::HashMap::new();
            let mut midpoint = |a: u32, b: u32, dirs: &mut Vec<DVec3>| -> u32 {
                *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    dirs.push((dirs[a as usize] + dirs[b as usize]).normalize());
                    dirs.len() as u32 - 1
                })
            };
            triangles = triangles
                .iter()
                .flat_map(|&[a, b, c]| {
                    let ab = midpoint(a, b, &mut dirs);
                    let bc = midpoint(b, c, &mut dirs);
                    let ca = midpoint(c, a, &mut dirs);
                    [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
                })
                .collect();
        }
        TriangleMesh {
            vertices: dirs
                .iter()
                .map(|d| (centre + radius * *d).to_array())
                .collect(),
            normals: dirs.iter().map(|d| d.to_array()).collect(),
            triangles,
            material_ids: Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icosphere_is_closed_and_counter_clockwise_from_outside() {
        let mesh = TriangleMesh::icosphere(DVec3::new(0.5, 0.0, -1.0), 2.0, 2);
        assert_eq!(mesh.triangles.len(), 20 * 16);
        assert_eq!(mesh.vertices.len(), 162);
        for t in 0..mesh.triangles.len() {
            let [a, b, c] = mesh.triangle_corners(t);
            let outward = (a + b + c) / 3.0 - DVec3::new(0.5, 0.0, -1.0);
            assert!(
                (b - a).cross(c - a).dot(outward) > 0.0,
                "triangle {t} winds inward"
            );
        }
        let exact = 4.0 * std::f64::consts::PI * 4.0;
        assert!(mesh.area() < exact && mesh.area() > 0.95 * exact);
    }

    #[test]
    fn largest_component_is_kept_and_vertices_renumbered() {
        let big = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 1);
        let small = TriangleMesh::icosphere(DVec3::new(5.0, 0.0, 0.0), 0.1, 0);
        let mut both = small.clone();
        let offset = both.vertices.len() as u32;
        both.vertices.extend(&big.vertices);
        both.normals.extend(&big.normals);
        both.triangles
            .extend(big.triangles.iter().map(|t| t.map(|i| i + offset)));
        both.material_ids = (0..both.triangles.len())
            .map(|t| if t < small.triangles.len() { 9 } else { 2 })
            .collect();
        both.keep_largest_component();
        assert_eq!(both.triangles.len(), big.triangles.len());
        assert_eq!(both.material_ids, vec![2; big.triangles.len()]);
        assert_eq!(both.vertices.len(), big.vertices.len());
        assert!(both
            .vertices
            .iter()
            .all(|v| DVec3::from_array(*v).length() < 1.0 + 1e-12));
        assert!((both.area() - big.area()).abs() < 1e-12);
    }

    #[test]
    fn vertex_normals_of_a_sphere_point_outward() {
        let mut mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 3);
        let exact = mesh.normals.clone();
        mesh.compute_vertex_normals();
        for (n, e) in mesh.normals.iter().zip(&exact) {
            assert!(DVec3::from_array(*n).dot(DVec3::from_array(*e)) > 0.999);
        }
    }

    #[test]
    fn obj_lists_every_vertex_and_face() {
        let mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 1);
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.obj");
        mesh.write_obj(&path).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(
            text.lines().filter(|l| l.starts_with("v ")).count(),
            mesh.vertices.len()
        );
        assert_eq!(
            text.lines().filter(|l| l.starts_with("vn ")).count(),
            mesh.vertices.len()
        );
        let faces: Vec<&str> = text.lines().filter(|l| l.starts_with("f ")).collect();
        assert_eq!(faces.len(), mesh.triangles.len());
        let [a, b, c] = mesh.triangles[7].map(|i| i + 1);
        assert_eq!(faces[7], format!("f {a}//{a} {b}//{b} {c}//{c}"));
    }
}

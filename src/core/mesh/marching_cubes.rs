//! Marching cubes on a regular scalar grid: the zero level set as a welded, closed triangle mesh.
//!
//! The 256-case triangle table is generated at first use rather than typed in: for every sign
//! configuration of the 8 cube corners, each cube face contributes one directed segment per run of
//! negative corners (walking the face counter-clockwise seen from outside, from the edge where the
//! walk enters the negative run to the edge where it leaves it). Ambiguous faces therefore always
//! separate the negative corners, a rule that depends on the face alone, so neighbouring cubes agree
//! and the surface has no cracks. Chaining the segments gives closed polygons, fan-triangulated;
//! their winding makes `(b − a) × (c − a)` point towards positive values ("outside").
//!
//! Vertices lie on grid edges (linear interpolation of the values) and are welded by a global edge
//! key, so every edge of a closed surface is shared by exactly two triangles. Cells with a corner
//! whose `known` flag is false are skipped. Rayon runs over z-slabs of cells; the welding sorts the
//! keys (deterministic output).

use std::sync::OnceLock;

use glam::DVec3;
use rayon::prelude::*;

use super::TriangleMesh;

/// Corner offsets (x, y, z) of a cell, corner `c` at bit `c` of the case index.
const CORNERS: [[usize; 3]; 8] = [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
];

/// A scalar field sampled at grid points `origin + spacing · (i, j, k)`, x fastest.
#[derive(Clone, Debug)]
pub struct ScalarGrid {
    pub dims: [usize; 3],
    pub origin: DVec3,
    pub spacing: f64,
    /// Values, `dims[0] · dims[1] · dims[2]` of them; negative = inside.
    pub values: Vec<f32>,
    /// Whether each value was observed; cells touching an unknown point produce no triangles.
    pub known: Vec<bool>,
}

impl ScalarGrid {
    fn index(&self, i: usize, j: usize, k: usize) -> usize {
        (k * self.dims[1] + j) * self.dims[0] + i
    }

    fn point(&self, i: usize, j: usize, k: usize) -> DVec3 {
        self.origin + self.spacing * DVec3::new(i as f64, j as f64, k as f64)
    }
}

/// The 12 cell edges as (corner, corner) with the first corner at the lower coordinate.
fn cell_edges() -> Vec<(usize, usize)> {
    let mut edges = Vec::with_capacity(12);
    for (a, ca) in CORNERS.iter().enumerate() {
        for (b, cb) in CORNERS.iter().enumerate() {
            let differing: Vec<usize> = (0..3).filter(|&d| ca[d] != cb[d]).collect();
            if differing.len() == 1 && ca[differing[0]] == 0 {
                edges.push((a, b));
            }
        }
    }
    edges
}

/// The 12 cell edges and, for each of the 256 corner-sign cases (bit set = negative corner), its
/// triangles as triples of edge indices.
type CaseTable = (Vec<(usize, usize)>, Vec<Vec<[u8; 3]>>);

/// The case table, generated on first use.
fn triangle_table() -> &'static CaseTable {
    static TABLE: OnceLock<CaseTable> = OnceLock::new();
    TABLE.get_or_init(|| {
        let edges = cell_edges();
        let edge_of = |a: usize, b: usize| {
            edges
                .iter()
                .position(|&(p, q)| (p, q) == (a, b) || (p, q) == (b, a))
                .expect("adjacent corners share an edge") as u8
        };
        // Faces as corner cycles, counter-clockwise seen from outside the cell.
        let mut faces: Vec<[usize; 4]> = Vec::with_capacity(6);
        #[allow(clippy::needless_range_loop)] // `axis` indexes the corner coordinates
        for axis in 0..3 {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            for side in 0..2 {
                let mut cycle = [0usize; 4];
                // Counter-clockwise around +axis in the (u, v) plane.
                for (slot, (du, dv)) in [(0, 0), (1, 0), (1, 1), (0, 1)].into_iter().enumerate() {
                    cycle[slot] = (0..8)
                        .find(|&c| {
                            CORNERS[c][axis] == side && CORNERS[c][u] == du && CORNERS[c][v] == dv
                        })
                        .expect("every face has 4 corners");
                }
                if side == 0 {
                    cycle.reverse();
                }
                faces.push(cycle);
            }
        }
        let table = (0..256usize)
            .map(|case| {
                let negative = |c: usize| case & (1 << c) != 0;
                // next[e] = the edge the directed segment starting on edge e ends on.
                let mut next = [u8::MAX; 12];
                for face in &faces {
                    let Some(start) = (0..4).find(|&s| !negative(face[s])) else {
                        continue;
                    };
                    let mut entry = None;
                    for step in 0..4 {
                        let a = face[(start + step) % 4];
                        let b = face[(start + step + 1) % 4];
                        match (negative(a), negative(b)) {
                            (false, true) => entry = Some(edge_of(a, b)),
                            (true, false) => {
                                let from = entry.take().expect("a negative run has an entry");
                                next[from as usize] = edge_of(a, b);
                            }
                            _ => {}
                        }
                    }
                }
                let mut triangles = Vec::new();
                let mut visited = [false; 12];
                for first in 0..12 {
                    if next[first] == u8::MAX || visited[first] {
                        continue;
                    }
                    let mut polygon = Vec::new();
                    let mut e = first;
                    while !visited[e] {
                        visited[e] = true;
                        polygon.push(e as u8);
                        e = next[e] as usize;
                    }
                    for k in 1..polygon.len() - 1 {
                        triangles.push([polygon[0], polygon[k], polygon[k + 1]]);
                    }
                }
                triangles
            })
            .collect();
        (edges, table)
    })
}

/// Global key of the grid edge leaving point (i, j, k) along `axis`.
fn edge_key(grid: &ScalarGrid, i: usize, j: usize, k: usize, axis: usize) -> u64 {
    grid.index(i, j, k) as u64 * 3 + axis as u64
}

/// Extracts the zero level set of `grid` (vertices welded, no normals). Faces are oriented so that
/// `(b − a) × (c − a)` points towards positive values.
pub fn marching_cubes(grid: &ScalarGrid) -> TriangleMesh {
    let _span = tracing::info_span!("marching_cubes", dims = ?grid.dims).entered();
    let [nx, ny, nz] = grid.dims;
    if nx < 2 || ny < 2 || nz < 2 {
        return TriangleMesh::default();
    }
    let (edges, table) = triangle_table();
    let edge_axis: Vec<usize> = edges
        .iter()
        .map(|&(a, b)| {
            (0..3)
                .find(|&d| CORNERS[a][d] != CORNERS[b][d])
                .unwrap_or(0)
        })
        .collect();
    let keyed: Vec<[u64; 3]> = (0..nz - 1)
        .into_par_iter()
        .flat_map_iter(|k| {
            let mut out = Vec::new();
            let row = |j: usize, k: usize| {
                let start = grid.index(0, j, k);
                &grid.known[start..start + nx]
            };
            for j in 0..ny - 1 {
                // A cell needs all 8 corners known: skip rows next to an entirely unknown row.
                if [(j, k), (j + 1, k), (j, k + 1), (j + 1, k + 1)]
                    .iter()
                    .any(|&(j, k)| !row(j, k).contains(&true))
                {
                    continue;
                }
                for i in 0..nx - 1 {
                    let mut case = 0usize;
                    let mut known = true;
                    for (c, o) in CORNERS.iter().enumerate() {
                        let idx = grid.index(i + o[0], j + o[1], k + o[2]);
                        known &= grid.known[idx];
                        if grid.values[idx] < 0.0 {
                            case |= 1 << c;
                        }
                    }
                    if !known || case == 0 || case == 255 {
                        continue;
                    }
                    for tri in &table[case] {
                        out.push(tri.map(|e| {
                            let lower = CORNERS[edges[e as usize].0];
                            edge_key(
                                grid,
                                i + lower[0],
                                j + lower[1],
                                k + lower[2],
                                edge_axis[e as usize],
                            )
                        }));
                    }
                }
            }
            out
        })
        .collect();
    let mut keys: Vec<u64> = keyed.iter().flatten().copied().collect();
    keys.par_sort_unstable();
    keys.dedup();
    let plane = nx * ny;
    let vertices: Vec<[f64; 3]> = keys
        .par_iter()
        .map(|&key| {
            let axis = (key % 3) as usize;
            let idx = (key / 3) as usize;
            let (i, j, k) = (idx % nx, (idx / nx) % ny, idx / plane);
            let step = [(1, 0, 0), (0, 1, 0), (0, 0, 1)][axis];
            let (i1, j1, k1) = (i + step.0, j + step.1, k + step.2);
            let v0 = grid.values[idx] as f64;
            let v1 = grid.values[grid.index(i1, j1, k1)] as f64;
            let t = if v0 == v1 {
                0.5
            } else {
                (v0 / (v0 - v1)).clamp(0.0, 1.0)
            };
            grid.point(i, j, k)
                .lerp(grid.point(i1, j1, k1), t)
                .to_array()
        })
        .collect();
    let triangles = keyed
        .par_iter()
        .map(|t| t.map(|key| keys.binary_search(&key).expect("every key was collected") as u32))
        .collect();
    TriangleMesh {
        vertices,
        normals: Vec::new(),
        triangles,
        material_ids: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    fn sampled(
        dims: [usize; 3],
        origin: DVec3,
        spacing: f64,
        f: impl Fn(DVec3) -> f64,
    ) -> ScalarGrid {
        let mut values = Vec::new();
        for k in 0..dims[2] {
            for j in 0..dims[1] {
                for i in 0..dims[0] {
                    let p = origin + spacing * DVec3::new(i as f64, j as f64, k as f64);
                    values.push(f(p) as f32);
                }
            }
        }
        let known = vec![true; values.len()];
        ScalarGrid {
            dims,
            origin,
            spacing,
            values,
            known,
        }
    }

    /// Number of triangles using each undirected edge, and whether each directed edge is unique.
    fn edge_use(mesh: &TriangleMesh) -> (HashMap<(u32, u32), usize>, bool) {
        let mut undirected = HashMap::new();
        let mut directed = std::collections::HashSet::new();
        let mut consistent = true;
        for t in &mesh.triangles {
            for e in 0..3 {
                let (a, b) = (t[e], t[(e + 1) % 3]);
                *undirected.entry((a.min(b), a.max(b))).or_insert(0) += 1;
                consistent &= directed.insert((a, b));
            }
        }
        (undirected, consistent)
    }

    #[test]
    fn every_case_gives_closed_consistently_oriented_patches() {
        // Each single cell case, embedded in a 4×4×4 grid whose border is positive, must give a
        // closed, consistently wound surface enclosing the negative corners.
        for case in 1..255usize {
            let mut grid = sampled([4, 4, 4], DVec3::ZERO, 1.0, |_| 1.0);
            for (c, o) in CORNERS.iter().enumerate() {
                let idx = grid.index(1 + o[0], 1 + o[1], 1 + o[2]);
                grid.values[idx] = if case & (1 << c) != 0 {
                    -1.0
                } else {
                    0.5 + c as f32 * 0.1
                };
            }
            let mesh = marching_cubes(&grid);
            let (use_count, consistent) = edge_use(&mesh);
            assert!(
                use_count.values().all(|&n| n == 2),
                "case {case}: open edge"
            );
            assert!(consistent, "case {case}: inconsistent winding");
            // Signed volume enclosed is positive (normals out of the negative region).
            let volume = mesh.signed_volume();
            assert!(volume > 0.0, "case {case}: enclosed volume {volume}");
        }
    }

    #[test]
    fn sphere_level_set_is_closed_accurate_and_outward() {
        let radius = 0.7;
        let h = 1.0 / 24.0;
        let grid = sampled([57, 57, 57], DVec3::splat(-28.0 * h), h, |p| {
            p.length() - radius
        });
        let mesh = marching_cubes(&grid);
        let (use_count, consistent) = edge_use(&mesh);
        assert!(use_count.values().all(|&n| n == 2) && consistent);
        // Euler characteristic of a sphere.
        let chi = mesh.vertices.len() as i64 - use_count.len() as i64 + mesh.triangles.len() as i64;
        assert_eq!(chi, 2);
        for v in &mesh.vertices {
            let r = DVec3::from_array(*v).length();
            assert!((r - radius).abs() < 0.05 * h, "vertex at radius {r}");
        }
        for t in 0..mesh.triangles.len() {
            let [a, b, c] = mesh.triangle_corners(t);
            let n = (b - a).cross(c - a);
            if n.length() > 1e-12 {
                assert!(n.dot(a + b + c) > 0.0, "triangle {t} faces inward");
            }
        }
    }

    #[test]
    fn unknown_points_block_their_cells() {
        let h = 0.1;
        let mut grid = sampled([21, 21, 21], DVec3::splat(-1.0), h, |p| p.length() - 0.5);
        let full = marching_cubes(&grid).triangles.len();
        for (idx, known) in grid.known.iter_mut().enumerate() {
            let i = idx % 21;
            *known = i < 10; // forget the half-space x > −0.05
        }
        let half = marching_cubes(&grid);
        assert!(half.triangles.len() < full * 6 / 10 && half.triangles.len() > full * 4 / 10);
        assert!(half.vertices.iter().all(|v| v[0] <= -0.1 + 1e-12));
    }
}

//! Closing the holes of a surface where no camera looked: every boundary loop of the mesh (a
//! chain of edges that only one triangle uses) is spanned by a cap, a fan of concentric rings
//! from the loop to its centroid whose inner vertices are then relaxed to the average of their
//! neighbours (a discrete membrane: the smoothest surface through the loop, not a guess at the
//! shape). The caps keep the mesh's winding, so normals stay outward.
//!
//! Single-threaded: a mesh has few holes and a cap costs O(loop length × rings × iterations).

use std::collections::{HashMap, HashSet};

use glam::DVec3;

use super::TriangleMesh;

/// Relaxation sweeps over a cap's inner vertices (Gauss–Seidel); enough for a cap of
/// [`MAX_RINGS`] rings to settle to within a small fraction of its edge length.
const RELAX_SWEEPS: usize = 200;

/// Most concentric rings of one cap.
const MAX_RINGS: usize = 24;

/// What [`TriangleMesh::close_holes`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClosedHoles {
    /// Boundary loops closed.
    pub holes: usize,
    /// Triangles added by the caps.
    pub triangles: usize,
}

impl TriangleMesh {
    /// Edges that only one triangle uses: directed edges whose reverse no triangle uses (0 for a
    /// closed, consistently oriented mesh).
    pub fn boundary_edges(&self) -> usize {
        let directed: HashSet<(u32, u32)> = self
            .triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .collect();
        directed
            .iter()
            .filter(|&&(a, b)| !directed.contains(&(b, a)))
            .count()
    }

    /// Closes every hole of the mesh with a relaxed cap (module doc) and recomputes the normals
    /// when the mesh has them. Boundary chains that do not close into a loop (a non-manifold
    /// boundary) are left open.
    pub fn close_holes(&mut self) -> ClosedHoles {
        let _span = tracing::info_span!("close_holes").entered();
        let loops = boundary_loops(&self.triangles);
        let before = self.triangles.len();
        for boundary in &loops {
            self.cap(boundary);
        }
        if !loops.is_empty() {
            if self.material_ids.len() == before {
                let fill = self.material_ids.first().copied().unwrap_or(0);
                self.material_ids.resize(self.triangles.len(), fill);
            }
            if !self.normals.is_empty() {
                self.compute_vertex_normals();
            }
        }
        ClosedHoles {
            holes: loops.len(),
            triangles: self.triangles.len() - before,
        }
    }

    /// Spans one boundary loop (vertices in the order of the boundary edges `a → b` that the
    /// mesh's triangles use) with rings shrinking to the centroid, then relaxes the inner
    /// vertices.
    fn cap(&mut self, boundary: &[u32]) {
        let n = boundary.len();
        let outer: Vec<DVec3> = boundary.iter().map(|&v| self.vertex(v)).collect();
        let centroid = outer.iter().sum::<DVec3>() / n as f64;
        // About as many rings as the loop is long over its perimeter's "radius" in edges.
        let rings = (((n as f64) / (2.0 * std::f64::consts::PI)).round() as usize).min(MAX_RINGS);
        // ring[r][i]: r = 0 is the boundary, 1..=rings the inner rings; then the centre.
        let mut ring: Vec<Vec<u32>> = vec![boundary.to_vec()];
        for r in 1..=rings {
            let t = r as f64 / (rings + 1) as f64;
            ring.push(
                outer
                    .iter()
                    .map(|&p| self.push_vertex(p + (centroid - p) * t))
                    .collect(),
            );
        }
        let centre = self.push_vertex(centroid);
        // The boundary edge a → b belongs to a mesh triangle; the cap uses b → a.
        for r in 0..rings {
            for i in 0..n {
                let j = (i + 1) % n;
                let (a, b) = (ring[r][i], ring[r][j]);
                let (d, c) = (ring[r + 1][i], ring[r + 1][j]);
                self.triangles.push([b, a, d]);
                self.triangles.push([b, d, c]);
            }
        }
        for i in 0..n {
            let j = (i + 1) % n;
            self.triangles
                .push([ring[rings][j], ring[rings][i], centre]);
        }
        self.relax(&ring, centre);
    }

    fn push_vertex(&mut self, p: DVec3) -> u32 {
        self.vertices.push(p.to_array());
        if !self.normals.is_empty() {
            self.normals.push([0.0; 3]);
        }
        (self.vertices.len() - 1) as u32
    }

    /// Moves each inner vertex of a cap to the mean of its ring neighbours (along its ring and
    /// to the rings inside and outside), the centre to the mean of the innermost ring.
    fn relax(&mut self, ring: &[Vec<u32>], centre: u32) {
        let rings = ring.len() - 1;
        if rings == 0 {
            return;
        }
        let n = ring[0].len();
        for _ in 0..RELAX_SWEEPS {
            for r in 1..=rings {
                for i in 0..n {
                    let inward = if r == rings { centre } else { ring[r + 1][i] };
                    let sum = self.vertex(ring[r][(i + n - 1) % n])
                        + self.vertex(ring[r][(i + 1) % n])
                        + self.vertex(ring[r - 1][i])
                        + self.vertex(inward);
                    self.vertices[ring[r][i] as usize] = (sum / 4.0).to_array();
                }
            }
            let mean = ring[rings].iter().map(|&v| self.vertex(v)).sum::<DVec3>() / n as f64;
            self.vertices[centre as usize] = mean.to_array();
        }
    }
}

/// The mesh's boundary loops: its directed edges whose reverse no triangle uses, chained end to
/// start. Each loop lists its vertices in edge order; a chain that cannot close is dropped.
fn boundary_loops(triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let directed: HashSet<(u32, u32)> = triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
        .collect();
    let mut outgoing: HashMap<u32, Vec<u32>> = HashMap::new();
    let mut edges: Vec<(u32, u32)> = directed
        .iter()
        .filter(|&&(a, b)| !directed.contains(&(b, a)))
        .copied()
        .collect();
    // Deterministic loops whatever the hash order.
    edges.sort_unstable();
    for &(a, b) in &edges {
        outgoing.entry(a).or_default().push(b);
    }
    let mut loops = Vec::new();
    for &(start, _) in &edges {
        while let Some(mut next) = outgoing.get_mut(&start).and_then(Vec::pop) {
            let mut chain = vec![start];
            while next != start {
                chain.push(next);
                match outgoing.get_mut(&next).and_then(Vec::pop) {
                    Some(after) => next = after,
                    None => break,
                }
            }
            if next == start && chain.len() >= 3 {
                loops.push(chain);
            }
        }
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every undirected edge used by exactly two triangles, once in each direction.
    fn is_closed_and_oriented(mesh: &TriangleMesh) -> bool {
        boundary_loops(&mesh.triangles).is_empty() && {
            let mut seen = HashSet::new();
            mesh.triangles
                .iter()
                .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
                .all(|e| seen.insert(e))
        }
    }

    /// An icosphere with the triangles below `z_cut` removed: one hole at the bottom.
    fn sphere_open_below(z_cut: f64) -> TriangleMesh {
        let mut mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 4);
        mesh.triangles.retain(|t| {
            t.iter()
                .map(|&v| mesh.vertices[v as usize][2])
                .fold(f64::INFINITY, f64::min)
                > z_cut
        });
        mesh.drop_unreferenced_vertices();
        mesh.compute_vertex_normals();
        mesh
    }

    #[test]
    fn a_cut_sphere_is_closed_by_a_smooth_outward_cap() {
        let mut mesh = sphere_open_below(-0.6);
        let loops = boundary_loops(&mesh.triangles);
        assert_eq!(loops.len(), 1);
        let rim_z = loops[0]
            .iter()
            .map(|&v| mesh.vertices[v as usize][2])
            .fold(f64::INFINITY, f64::min);
        let old_vertices = mesh.vertices.len();
        let closed = mesh.close_holes();
        assert_eq!(closed.holes, 1);
        assert!(closed.triangles > 0);
        assert!(is_closed_and_oriented(&mesh));
        assert_eq!(mesh.normals.len(), mesh.vertices.len());
        // The cap is a membrane across the rim: no vertex below it or outside the sphere's
        // silhouette, and its normals point down, out of the object.
        for v in old_vertices..mesh.vertices.len() {
            let p = DVec3::from_array(mesh.vertices[v]);
            assert!(p.z > rim_z - 0.05 && p.z < -0.5, "cap vertex {p}");
            assert!(p.x.hypot(p.y) < 0.84, "cap vertex {p} outside the rim");
            assert!(
                mesh.normals[v][2] < -0.9,
                "cap normal {:?}",
                mesh.normals[v]
            );
        }
        // Closed: the enclosed volume is the sphere's minus the cut-off cap segment.
        let volume = mesh.signed_volume();
        let h = 1.0 - 0.6;
        let segment = std::f64::consts::PI * h * h * (3.0 - h) / 3.0;
        let expected = 4.0 / 3.0 * std::f64::consts::PI - segment;
        assert!(
            (volume - expected).abs() < 0.03 * expected,
            "volume {volume}"
        );
    }

    #[test]
    fn closed_meshes_and_several_holes() {
        let mut sphere = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 2);
        let untouched = sphere.clone();
        assert_eq!(sphere.close_holes(), ClosedHoles::default());
        assert_eq!(sphere, untouched);

        let mut band = sphere_open_below(-0.5);
        band.triangles.retain(|t| {
            t.iter()
                .map(|&v| band.vertices[v as usize][2])
                .fold(f64::NEG_INFINITY, f64::max)
                < 0.5
        });
        band.drop_unreferenced_vertices();
        band.material_ids = vec![3; band.triangles.len()];
        let closed = band.close_holes();
        assert_eq!(closed.holes, 2);
        assert!(is_closed_and_oriented(&band));
        assert_eq!(band.material_ids.len(), band.triangles.len());
        assert!(band.material_ids.iter().all(|&m| m == 3));
        // A single triangle has one loop of three: a fan, no rings.
        let mut triangle = TriangleMesh {
            vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            triangles: vec![[0, 1, 2]],
            ..TriangleMesh::default()
        };
        assert_eq!(triangle.close_holes().holes, 1);
        assert!(is_closed_and_oriented(&triangle));
    }
}

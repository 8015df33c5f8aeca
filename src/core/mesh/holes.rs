//! Closing the holes of a surface where no camera looked: every boundary loop of the mesh (a
//! chain of edges that only one triangle uses) is spanned by a cap, concentric rings from the loop
//! to its centroid, each with fewer vertices than the one outside it (in proportion to its
//! distance from the centre, so the triangles stay about as wide as they are deep), stitched ring
//! to ring and closed by a fan around the centre. The caps keep the mesh's winding, so normals
//! stay outward.
//!
//! The caps' vertices are then placed by a biharmonic fair (thin-plate surface): they minimise
//! the sum of the squared umbrella Laplacians (the mean of a vertex's neighbours minus the vertex)
//! over the caps' vertices and the loops' vertices, with everything outside the caps fixed. The
//! loop vertices' Laplacians reach into the observed surface (their neighbours outside the cap),
//! so the cap meets the surface with its slope and goes on with its curvature: a sphere's missing
//! cap comes back as a dome near the sphere, where a membrane (minimal Laplacian, the previous
//! fill) spans the loop flat. The least-squares problem is solved by conjugate gradients on its
//! normal equations, starting from the rings' flat placement.
//!
//! Single-threaded: a mesh has few holes; a cap costs O(loop length × rings) per conjugate-gradient
//! iteration, and the iterations grow with the square of the rings.

use std::collections::{HashMap, HashSet};

use glam::DVec3;

use super::TriangleMesh;

/// Most concentric rings of one cap.
const MAX_RINGS: usize = 32;

/// Most conjugate-gradient iterations of the fair (a cap of [`MAX_RINGS`] rings converges in a
/// few hundred).
const FAIR_MAX_ITERATIONS: usize = 4000;

/// The fair stops when the normal equations' residual has fallen by this factor.
const FAIR_TOLERANCE: f64 = 1e-10;

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

    /// Closes every hole of the mesh with a faired cap (module doc) and recomputes the normals
    /// when the mesh has them. Boundary chains that do not close into a loop (a non-manifold
    /// boundary) are left open.
    pub fn close_holes(&mut self) -> ClosedHoles {
        let _span = tracing::info_span!("close_holes").entered();
        let loops = boundary_loops(&self.triangles);
        let before = self.triangles.len();
        let first_cap_vertex = self.vertices.len();
        for boundary in &loops {
            self.cap(boundary);
        }
        if !loops.is_empty() {
            self.fair_from(first_cap_vertex);
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

    /// The mesh of the triangles before `at` and the mesh of the others (the caps, when `at` is
    /// the triangle count before [`TriangleMesh::close_holes`]), each with all the vertices.
    pub fn split_triangles(&self, at: usize) -> (TriangleMesh, TriangleMesh) {
        let at = at.min(self.triangles.len());
        let part = |range: std::ops::Range<usize>| TriangleMesh {
            vertices: self.vertices.clone(),
            normals: self.normals.clone(),
            triangles: self.triangles[range.clone()].to_vec(),
            material_ids: if self.material_ids.len() == self.triangles.len() {
                self.material_ids[range].to_vec()
            } else {
                Vec::new()
            },
        };
        (part(0..at), part(at..self.triangles.len()))
    }

    /// Spans one boundary loop (vertices in the order of the boundary edges `a → b` that the
    /// mesh's triangles use) with rings shrinking to the centroid, placed flat (each ring a
    /// scaled copy of the loop); [`TriangleMesh::fair_from`] gives them their shape.
    fn cap(&mut self, boundary: &[u32]) {
        let n = boundary.len();
        let outer: Vec<DVec3> = boundary.iter().map(|&v| self.vertex(v)).collect();
        let centroid = outer.iter().sum::<DVec3>() / n as f64;
        // About as many rings as the loop is long over its perimeter's "radius" in edges.
        let rings = (((n as f64) / (2.0 * std::f64::consts::PI)).round() as usize).min(MAX_RINGS);
        // The loop at parameter s ∈ [0, n): its vertices joined by straight edges.
        let along = |s: f64| {
            let i = (s.floor() as usize).min(n - 1);
            let f = s - i as f64;
            outer[i].lerp(outer[(i + 1) % n], f)
        };
        // ring[r]: r = 0 is the boundary, 1..=rings the inner rings, each with vertices in
        // proportion to its distance from the centre; then the centre.
        let mut ring: Vec<Vec<u32>> = vec![boundary.to_vec()];
        for r in 1..=rings {
            let t = r as f64 / (rings + 1) as f64;
            let count = ((n as f64 * (1.0 - t)).round() as usize).max(3);
            ring.push(
                (0..count)
                    .map(|k| {
                        let p = along(n as f64 * k as f64 / count as f64);
                        self.push_vertex(p + (centroid - p) * t)
                    })
                    .collect(),
            );
        }
        let centre = self.push_vertex(centroid);
        for r in 0..rings {
            self.stitch(&ring[r], &ring[r + 1]);
        }
        let inner = &ring[rings];
        for i in 0..inner.len() {
            let j = (i + 1) % inner.len();
            self.triangles.push([inner[j], inner[i], centre]);
        }
    }

    /// Triangles between two closed rings that start at the same angle: the outer one's edges
    /// `a → b` are used by the triangles outside, so the strip uses `b → a`; it advances along
    /// whichever ring's next vertex comes first in the loop's parameter.
    fn stitch(&mut self, outer: &[u32], inner: &[u32]) {
        let (a, b) = (outer.len(), inner.len());
        let (mut i, mut k) = (0, 0);
        while i < a || k < b {
            let advance_outer =
                k == b || (i < a && (i + 1) as f64 / a as f64 <= (k + 1) as f64 / b as f64);
            if advance_outer {
                self.triangles
                    .push([outer[(i + 1) % a], outer[i % a], inner[k % b]]);
                i += 1;
            } else {
                self.triangles
                    .push([outer[i % a], inner[k % b], inner[(k + 1) % b]]);
                k += 1;
            }
        }
    }

    fn push_vertex(&mut self, p: DVec3) -> u32 {
        self.vertices.push(p.to_array());
        if !self.normals.is_empty() {
            self.normals.push([0.0; 3]);
        }
        (self.vertices.len() - 1) as u32
    }

    /// Biharmonic fair of the vertices from `first_free` on (the caps'): minimises
    /// `Σ_v |L_v x|²` over those vertices and their fixed neighbours (the loops), `L_v x` the
    /// umbrella Laplacian (the mean of the neighbours minus `x_v`), by conjugate gradients on the
    /// normal equations `AᵀA y = −Aᵀc` (`A`: the rows' dependence on the free vertices `y`, `c`:
    /// on the fixed ones). The umbrella rather than the cotangent Laplacian: the caps' rings make
    /// its implied parametrisation about right, and the cotangent one, on marching cubes'
    /// slivers around the loops, converged ten times slower to no better caps on the shared
    /// sphere.
    fn fair_from(&mut self, first_free: usize) {
        let free_count = self.vertices.len() - first_free;
        if free_count == 0 {
            return;
        }
        let is_free = |v: u32| v as usize >= first_free;
        // Rows: the free vertices and every vertex sharing a triangle with one.
        let mut row_of: HashMap<u32, usize> = HashMap::new();
        let mut rows: Vec<u32> = Vec::new();
        for v in first_free..self.vertices.len() {
            row_of.insert(v as u32, rows.len());
            rows.push(v as u32);
        }
        for t in &self.triangles {
            if t.iter().any(|&v| is_free(v)) {
                for &v in t {
                    row_of.entry(v).or_insert_with(|| {
                        rows.push(v);
                        rows.len() - 1
                    });
                }
            }
        }
        let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); rows.len()];
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                for (from, to) in [(a, b), (b, a)] {
                    if let Some(&row) = row_of.get(&from) {
                        neighbours[row].push(to);
                    }
                }
            }
        }
        // Each row as (vertex, coefficient) terms, itself included.
        let terms: Vec<Vec<(u32, f64)>> = rows
            .iter()
            .zip(neighbours)
            .map(|(&v, mut list)| {
                list.sort_unstable();
                list.dedup();
                let share = 1.0 / list.len().max(1) as f64;
                let mut terms: Vec<(u32, f64)> = list.into_iter().map(|u| (u, share)).collect();
                terms.push((v, -1.0));
                terms
            })
            .collect();
        let unknown = |v: u32| v as usize - first_free;
        // c: each row from the fixed vertices alone.
        let constant: Vec<DVec3> = terms
            .iter()
            .map(|list| {
                list.iter()
                    .filter(|&&(u, _)| !is_free(u))
                    .map(|&(u, w)| w * self.vertex(u))
                    .sum()
            })
            .collect();
        let apply = |y: &[DVec3]| -> Vec<DVec3> {
            terms
                .iter()
                .map(|list| {
                    list.iter()
                        .filter(|&&(u, _)| is_free(u))
                        .map(|&(u, w)| w * y[unknown(u)])
                        .sum()
                })
                .collect()
        };
        let apply_transposed = |r: &[DVec3]| -> Vec<DVec3> {
            let mut out = vec![DVec3::ZERO; free_count];
            for (list, &value) in terms.iter().zip(r) {
                for &(u, w) in list.iter().filter(|&&(u, _)| is_free(u)) {
                    out[unknown(u)] += w * value;
                }
            }
            out
        };
        let normal_matrix = |y: &[DVec3]| apply_transposed(&apply(y));
        let mut y: Vec<DVec3> = (first_free..self.vertices.len())
            .map(|v| self.vertex(v as u32))
            .collect();
        let rhs: Vec<DVec3> = apply_transposed(&constant)
            .into_iter()
            .map(|c| -c)
            .collect();
        conjugate_gradients(normal_matrix, &rhs, &mut y);
        for (v, p) in y.into_iter().enumerate() {
            self.vertices[first_free + v] = p.to_array();
        }
    }
}

/// Solves `M y = rhs` for a symmetric positive (semi-)definite `M`, each coordinate on its own
/// (three independent conjugate-gradient runs sharing the matrix products), from the given `y`.
fn conjugate_gradients(matrix: impl Fn(&[DVec3]) -> Vec<DVec3>, rhs: &[DVec3], y: &mut [DVec3]) {
    let dot = |a: &[DVec3], b: &[DVec3]| -> DVec3 { a.iter().zip(b).map(|(p, q)| *p * *q).sum() };
    let product = matrix(y);
    let mut residual: Vec<DVec3> = rhs.iter().zip(&product).map(|(b, m)| *b - *m).collect();
    let mut direction = residual.clone();
    let mut energy = dot(&residual, &residual);
    let scale = dot(rhs, rhs).element_sum().max(f64::MIN_POSITIVE);
    let stop = DVec3::splat(FAIR_TOLERANCE * FAIR_TOLERANCE * scale);
    for _ in 0..FAIR_MAX_ITERATIONS {
        if energy.cmple(stop).all() {
            break;
        }
        let product = matrix(&direction);
        let curvature = dot(&direction, &product);
        // A coordinate that has converged (or whose curvature vanished) stops moving.
        let step = DVec3::select(
            energy.cmpgt(stop) & curvature.cmpgt(DVec3::ZERO),
            energy / curvature,
            DVec3::ZERO,
        );
        for ((yi, d), (r, m)) in y
            .iter_mut()
            .zip(&direction)
            .zip(residual.iter_mut().zip(&product))
        {
            *yi += step * *d;
            *r -= step * *m;
        }
        let next = dot(&residual, &residual);
        let beta = DVec3::select(energy.cmpgt(DVec3::ZERO), next / energy, DVec3::ZERO);
        for (d, r) in direction.iter_mut().zip(&residual) {
            *d = *r + beta * *d;
        }
        energy = next;
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

    /// Distances of the vertices from `first` on to the unit sphere: (mean, largest).
    fn off_unit_sphere(mesh: &TriangleMesh, first: usize) -> (f64, f64) {
        let off: Vec<f64> = mesh.vertices[first..]
            .iter()
            .map(|v| (DVec3::from_array(*v).length() - 1.0).abs())
            .collect();
        (
            off.iter().sum::<f64>() / off.len() as f64,
            off.iter().copied().fold(0.0, f64::max),
        )
    }

    /// A unit sphere without its cap below z = −0.6 (a hole 0.8 across and 0.4 deep): a flat
    /// membrane over the rim lies up to 0.4 from the sphere; the faired cap continues the
    /// sphere's curvature, its vertices within a few hundredths of it, its normals outward.
    #[test]
    fn a_cut_sphere_is_closed_by_a_cap_that_continues_it() {
        let mut mesh = sphere_open_below(-0.6);
        let loops = boundary_loops(&mesh.triangles);
        assert_eq!(loops.len(), 1);
        let old_vertices = mesh.vertices.len();
        let closed = mesh.close_holes();
        assert_eq!(closed.holes, 1);
        assert!(closed.triangles > 0);
        assert!(is_closed_and_oriented(&mesh));
        assert_eq!(mesh.normals.len(), mesh.vertices.len());
        let lowest = mesh.vertices[old_vertices..]
            .iter()
            .map(|v| v[2])
            .fold(f64::INFINITY, f64::min);
        let (mean, worst) = off_unit_sphere(&mesh, old_vertices);
        println!(
            "{} cap vertices: {mean:.4} from the sphere on average, {worst:.4} at most, lowest z {lowest:.3}",
            mesh.vertices.len() - old_vertices
        );
        assert!(mean < 0.04 && worst < 0.1, "mean {mean}, worst {worst}");
        assert!(lowest < -0.9, "the cap reaches down to {lowest} only");
        let angles: Vec<f64> = (old_vertices..mesh.vertices.len())
            .map(|v| {
                let p = DVec3::from_array(mesh.vertices[v]).normalize();
                let n = DVec3::from_array(mesh.normals[v]);
                n.dot(p).clamp(-1.0, 1.0).acos().to_degrees()
            })
            .collect();
        let mean_angle = angles.iter().sum::<f64>() / angles.len() as f64;
        let worst_angle = angles.iter().copied().fold(0.0, f64::max);
        println!(
            "cap normals off the radius: {mean_angle:.2}° on average, {worst_angle:.2}° at most"
        );
        assert!(mean_angle < 8.0 && worst_angle < 12.0);
        // Closed: the enclosed volume is nearly the whole sphere's (4.10 of 4.19; the cut-off
        // segment is 9 % of it, which a flat cap would lose).
        let volume = mesh.signed_volume();
        let sphere = 4.0 / 3.0 * std::f64::consts::PI;
        println!("volume {volume:.4} of {sphere:.4}");
        assert!(
            (volume - sphere).abs() < 0.04 * sphere,
            "volume {volume} of {sphere}"
        );
    }

    /// A hole cut out of the flank of a sphere (everything within 0.5 of (1, 0, 0)): the cap
    /// bulges out with the sphere, not flat across.
    #[test]
    fn a_hole_in_the_flank_is_closed_along_the_sphere() {
        let mut mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 4);
        let pole = DVec3::X;
        mesh.triangles.retain(|t| {
            t.iter()
                .all(|&v| DVec3::from_array(mesh.vertices[v as usize]).distance(pole) > 0.5)
        });
        mesh.drop_unreferenced_vertices();
        let old_vertices = mesh.vertices.len();
        assert_eq!(mesh.close_holes().holes, 1);
        assert!(is_closed_and_oriented(&mesh));
        let (mean, worst) = off_unit_sphere(&mesh, old_vertices);
        println!("flank cap: {mean:.4} from the sphere on average, {worst:.4} at most");
        assert!(mean < 0.01 && worst < 0.02, "mean {mean}, worst {worst}");
        let outermost = mesh.vertices[old_vertices..]
            .iter()
            .map(|v| v[0])
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(outermost > 0.97, "the cap reaches x = {outermost} only");
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

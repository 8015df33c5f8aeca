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
//! so the cap meets the surface with its slope. The least-squares problem is solved by conjugate
//! gradients on its normal equations, starting from the rings' flat placement.
//!
//! A thin plate drives the curvature to zero inside the cap, so a sphere's missing cap comes back
//! flatter than the sphere. Where the surface around a hole is a quadric (a sphere, a cylinder, a
//! saddle: [`super::quadric`] fitted to the vertices within a hole's radius of the loop, with
//! their normals, and describing them to within a few percent of that radius; the loop and the
//! two rings next to it are left out of the fit, since where only grazing views saw the
//! surface, its border flares outwards), the cap goes on
//! along it: each cap vertex is projected onto the quadric and moved by the offset of the loop
//! from the quadric, faired over the cap the same way and faded out over its first rings, so the
//! cap meets the loop and lies on the quadric beyond. Where no
//! quadric describes the surround (a crevice, a seam between parts), the thin plate stays.
//!
//! Single-threaded: a mesh has few holes; a cap costs O(loop length × rings) per conjugate-gradient
//! iteration, and the iterations grow with the square of the rings.

use std::collections::{HashMap, HashSet};

use glam::DVec3;

use super::quadric::Quadric;
use super::TriangleMesh;

/// Most concentric rings of one cap.
const MAX_RINGS: usize = 32;

/// Most conjugate-gradient iterations of the fair (a cap of [`MAX_RINGS`] rings converges in a
/// few hundred).
const FAIR_MAX_ITERATIONS: usize = 4000;

/// The fair stops when the normal equations' residual has fallen by this factor.
const FAIR_TOLERANCE: f64 = 1e-10;

/// Rings of vertices next to a hole's loop that its surface is not fitted to: where only
/// grazing views saw the surface, its border flares outwards (by 2 % of the sphere's radius on
/// the sample). A cap laid on the fitted surface leaves the loop's offset from it
/// behind over as many of its own rings.
const FLARE_RINGS: usize = 2;

/// Fewest rings of vertices around a hole that its surface is fitted to (beyond the loop and
/// the [`FLARE_RINGS`], which are not).
const MIN_BAND_RINGS: usize = 3;

/// A quadric describes a vertex around a hole when it passes within this fraction of the hole's
/// radius of it...
const SURFACE_FIT_TOLERANCE: f64 = 0.05;

/// ... with a normal within this angle of the vertex's (degrees)...
const SURFACE_FIT_NORMAL_DEG: f64 = 25.0;

/// ... and it describes the surface around the hole when it describes this fraction of the
/// vertices there (fitted to those it describes, [`Quadric::fit_robust`]).
const SURFACE_DESCRIBED_FRACTION: f64 = 0.8;

/// Largest angle between the quadric's normals and the laid cap's triangles', on average over
/// the triangles (a degenerate one counts as perpendicular), and at the cap's centre between
/// the quadric's normal and the faired cap's, for the cap to be laid on it.
const CAP_NORMAL_AGREEMENT_DEG: f64 = 60.0;

/// What [`TriangleMesh::close_holes`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClosedHoles {
    /// Boundary loops closed.
    pub holes: usize,
    /// Of those, the caps laid on a quadric fitted to the surface around the hole.
    pub continued: usize,
    /// Triangles added by the caps.
    pub triangles: usize,
}

/// One cap spanned by [`TriangleMesh::cap`].
struct Cap {
    /// The loop it closes.
    boundary: Vec<u32>,
    /// Its rings between the loop and the centre.
    rings: usize,
    /// The ring of each of its vertices (1 next to the loop, `rings + 1` the centre).
    ring_of: Vec<usize>,
    /// Its vertices (consecutive, pushed by the cap).
    vertices: std::ops::Range<usize>,
    /// Its triangles (consecutive).
    triangles: std::ops::Range<usize>,
}

/// The surface around a hole, as [`TriangleMesh::surface_around`] found it.
struct FittedSurface {
    quadric: Quadric,
    /// The loop's vertices and their neighbours outside the cap: the fixed vertices the
    /// fairing's rows read.
    near_rim: Vec<u32>,
    /// The loop's mean distance from its centroid.
    hole_radius: f64,
    /// How close to the quadric a projection must come.
    tolerance: f64,
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

    /// Closes every hole of the mesh with a faired cap (module doc), continued along the
    /// surface around it where a quadric describes that surface, and recomputes the normals
    /// when the mesh has them. Boundary chains that do not close into a loop (a non-manifold
    /// boundary) are left open.
    pub fn close_holes(&mut self) -> ClosedHoles {
        let _span = tracing::info_span!("close_holes").entered();
        let loops = boundary_loops(&self.triangles);
        let before = self.triangles.len();
        let first_cap_vertex = self.vertices.len();
        let caps: Vec<Cap> = loops.iter().map(|boundary| self.cap(boundary)).collect();
        let mut continued = 0;
        if !caps.is_empty() {
            let fairing = Fairing::new(&self.triangles, first_cap_vertex, self.vertices.len());
            let flat: Vec<DVec3> = (first_cap_vertex..self.vertices.len())
                .map(|v| self.vertex(v as u32))
                .collect();
            let faired = fairing.solve(|v| self.vertex(v), flat);
            for (v, p) in faired.into_iter().enumerate() {
                self.vertices[first_cap_vertex + v] = p.to_array();
            }
            continued = self.continue_surfaces(&caps, &fairing, before);
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
            continued,
            triangles: self.triangles.len() - before,
        }
    }

    /// Lays each cap on the quadric fitted to the surface around its hole
    /// ([`TriangleMesh::surface_around`]), where one fits: every cap vertex moves to the quadric
    /// (from its faired place, along the quadric's gradient) and then along its normal by the
    /// loop's distance from the quadric, faired over the cap and faded out over its first
    /// [`FLARE_RINGS`] rings, so the cap meets the loop and is on the quadric beyond (a flared
    /// border does not lift the whole cap). Returns how many caps moved.
    fn continue_surfaces(&mut self, caps: &[Cap], fairing: &Fairing, before: usize) -> usize {
        // Unit normals of the observed surface (zero for the caps' vertices).
        let normals: Vec<DVec3> = self
            .area_weighted_normal_sums(before)
            .into_iter()
            .map(DVec3::normalize_or_zero)
            .collect();
        let mut adjacency: Vec<Vec<u32>> = vec![Vec::new(); self.vertices.len()];
        for t in &self.triangles[..before] {
            for k in 0..3 {
                adjacency[t[k] as usize].push(t[(k + 1) % 3]);
                adjacency[t[(k + 1) % 3] as usize].push(t[k]);
            }
        }
        // Each fitted cap's quadric, and the fixed vertices' offsets from it (the rim and the
        // ring outside it, which the fairing's rows read).
        let mut surfaces: Vec<Option<FittedSurface>> = Vec::with_capacity(caps.len());
        // (The fairing smooths 3-vectors; the offsets, signed distances along the quadric's
        // normal, ride in the first coordinate.)
        let mut rim_offsets: HashMap<u32, DVec3> = HashMap::new();
        for cap in caps {
            let surface = self.surface_around(cap, &adjacency, &normals);
            if let Some(surface) = &surface {
                for &v in &surface.near_rim {
                    let (distance, _) = surface.quadric.value_and_gradient(self.vertex(v));
                    rim_offsets.insert(v, DVec3::new(distance, 0.0, 0.0));
                }
            }
            surfaces.push(surface);
        }
        let offsets = fairing.solve(
            |v| rim_offsets.get(&v).copied().unwrap_or(DVec3::ZERO),
            vec![DVec3::ZERO; fairing.free_count],
        );
        let mut continued = 0;
        for (cap, surface) in caps.iter().zip(&surfaces) {
            let Some(surface) = surface else { continue };
            // The loop's offset, faired, fades out over the rings next to it.
            let offset = |v: usize| {
                let ring = cap.ring_of[v - cap.vertices.start] as f64;
                let fade = (1.0 - ring / (FLARE_RINGS + 1) as f64).max(0.0);
                fade * offsets[v - fairing.first_free].x
            };
            if let Some(placed) = self.laid_on(cap, surface, offset) {
                for (v, p) in cap.vertices.clone().zip(placed) {
                    self.vertices[v] = p.to_array();
                }
                continued += 1;
            }
        }
        continued
    }

    /// The places of a cap's vertices laid on `surface`: each projected onto the quadric from
    /// its faired place and moved along the quadric's normal by `offset(vertex)`; `None` where
    /// the quadric is not the surface over the hole: its nearest sheet lies farther than the
    /// hole is wide, or the cap laid on it folds (the end of a tube, whose wall the rings would
    /// be squashed onto), so that the laid triangles turn away from the quadric's normals
    /// (single slivers by the loop may; the cap as a whole must not), or its middle faces
    /// otherwise than it did faired (sideways, on the tube's wall).
    fn laid_on(
        &self,
        cap: &Cap,
        surface: &FittedSurface,
        offset: impl Fn(usize) -> f64,
    ) -> Option<Vec<DVec3>> {
        let quadric = &surface.quadric;
        let normal_at = |p: DVec3| quadric.value_and_gradient(p).1.normalize_or_zero();
        let placed: Vec<DVec3> = cap
            .vertices
            .clone()
            .map(|v| {
                let p = self.vertex(v as u32);
                let on = quadric.project(p, surface.tolerance)?;
                (on.distance(p) <= surface.hole_radius).then(|| on + offset(v) * normal_at(on))
            })
            .collect::<Option<_>>()?;
        let position = |v: u32| match (v as usize).checked_sub(cap.vertices.start) {
            Some(k) if k < placed.len() => placed[k],
            _ => self.vertex(v),
        };
        let facing = |t: &[u32; 3], at: &dyn Fn(u32) -> DVec3| {
            let [a, b, c] = t.map(at);
            (b - a).cross(c - a)
        };
        let triangles = &self.triangles[cap.triangles.clone()];
        let agreement = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(position);
                facing(t, &position)
                    .normalize_or_zero()
                    .dot(normal_at((a + b + c) / 3.0))
            })
            .sum::<f64>()
            / triangles.len().max(1) as f64;
        let centre = (cap.vertices.end - 1) as u32;
        let faired_facing: DVec3 = triangles
            .iter()
            .filter(|t| t.contains(&centre))
            .map(|t| facing(t, &|v| self.vertex(v)))
            .sum();
        let centre_agreement = faired_facing
            .normalize_or_zero()
            .dot(normal_at(position(centre)));
        let min_cos = CAP_NORMAL_AGREEMENT_DEG.to_radians().cos();
        (agreement >= min_cos && centre_agreement >= min_cos).then_some(placed)
    }

    /// The quadric fitted to the surface around one cap's hole (module doc): the vertices more
    /// than [`FLARE_RINGS`] and at most as many edges from the loop as the cap has rings (at
    /// least [`MIN_BAND_RINGS`] beyond the flare),
    /// with their normals; `None` where it describes fewer than [`SURFACE_DESCRIBED_FRACTION`]
    /// of them.
    fn surface_around(
        &self,
        cap: &Cap,
        adjacency: &[Vec<u32>],
        normals: &[DVec3],
    ) -> Option<FittedSurface> {
        let boundary = &cap.boundary;
        let centroid =
            boundary.iter().map(|&v| self.vertex(v)).sum::<DVec3>() / boundary.len() as f64;
        let hole_radius = boundary
            .iter()
            .map(|&v| self.vertex(v).distance(centroid))
            .sum::<f64>()
            / boundary.len() as f64;
        let mut depth: HashMap<u32, usize> = boundary.iter().map(|&v| (v, 0)).collect();
        let mut frontier: Vec<u32> = boundary.to_vec();
        for ring in 1..=cap.rings.max(MIN_BAND_RINGS + FLARE_RINGS) {
            let mut next = Vec::new();
            for &v in &frontier {
                for &u in &adjacency[v as usize] {
                    if let std::collections::hash_map::Entry::Vacant(entry) = depth.entry(u) {
                        entry.insert(ring);
                        next.push(u);
                    }
                }
            }
            frontier = next;
        }
        // The loop and the rings next to it are left out: where only grazing views saw the
        // surface, its border flares outwards.
        let band: Vec<u32> = depth
            .iter()
            .filter(|(_, &ring)| ring > FLARE_RINGS)
            .map(|(&v, _)| v)
            .collect();
        let points: Vec<DVec3> = band.iter().map(|&v| self.vertex(v)).collect();
        let band_normals: Vec<DVec3> = band.iter().map(|&v| normals[v as usize]).collect();
        let (quadric, described) = Quadric::fit_robust(
            &points,
            &band_normals,
            SURFACE_FIT_TOLERANCE * hole_radius,
            SURFACE_FIT_NORMAL_DEG,
        )?;
        tracing::debug!(
            loop_vertices = boundary.len(),
            band = band.len(),
            hole_radius,
            described,
            "surface around a hole"
        );
        (described >= SURFACE_DESCRIBED_FRACTION).then(|| FittedSurface {
            quadric,
            near_rim: depth
                .iter()
                .filter(|(_, &ring)| ring <= 1)
                .map(|(&v, _)| v)
                .collect(),
            hole_radius,
            tolerance: 1e-9 * hole_radius.max(f64::MIN_POSITIVE),
        })
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
    fn cap(&mut self, boundary: &[u32]) -> Cap {
        let first_vertex = self.vertices.len();
        let first_triangle = self.triangles.len();
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
        let ring_of = (1..=rings)
            .flat_map(|r| std::iter::repeat_n(r, ring[r].len()))
            .chain([rings + 1])
            .collect();
        Cap {
            boundary: boundary.to_vec(),
            rings,
            ring_of,
            vertices: first_vertex..self.vertices.len(),
            triangles: first_triangle..self.triangles.len(),
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
}

/// The biharmonic fair of the vertices from `first_free` on (the caps'): the least-squares
/// values that minimise `Σ_v |L_v x|²` over those vertices and their fixed neighbours (the
/// loops), `L_v x` the umbrella Laplacian (the mean of the neighbours minus `x_v`). The system
/// depends on the connectivity alone, so one fairing smooths any field over the caps: their
/// positions, or the offsets of the rims from a fitted surface.
///
/// The umbrella rather than the cotangent Laplacian: the caps' rings make its implied
/// parametrisation about right, and the cotangent one, on marching cubes' slivers around the
/// loops, converged ten times slower to no better caps on the shared sphere.
struct Fairing {
    first_free: usize,
    free_count: usize,
    /// Each row as (vertex, coefficient) terms, itself included.
    terms: Vec<Vec<(u32, f64)>>,
}

impl Fairing {
    fn new(triangles: &[[u32; 3]], first_free: usize, vertex_count: usize) -> Fairing {
        let is_free = |v: u32| v as usize >= first_free;
        // Rows: the free vertices and every vertex sharing a triangle with one.
        let mut row_of: HashMap<u32, usize> = HashMap::new();
        let mut rows: Vec<u32> = Vec::new();
        for v in first_free..vertex_count {
            row_of.insert(v as u32, rows.len());
            rows.push(v as u32);
        }
        for t in triangles {
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
        for t in triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                for (from, to) in [(a, b), (b, a)] {
                    if let Some(&row) = row_of.get(&from) {
                        neighbours[row].push(to);
                    }
                }
            }
        }
        let terms = rows
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
        Fairing {
            first_free,
            free_count: vertex_count.saturating_sub(first_free),
            terms,
        }
    }

    /// The faired values of the free vertices given every fixed vertex's (`fixed`), by
    /// conjugate gradients on the normal equations `AᵀA y = −Aᵀc` (`A`: the rows' dependence on
    /// the free values `y`, `c`: on the fixed ones), starting from `start`.
    fn solve(&self, fixed: impl Fn(u32) -> DVec3, start: Vec<DVec3>) -> Vec<DVec3> {
        let is_free = |v: u32| v as usize >= self.first_free;
        let unknown = |v: u32| v as usize - self.first_free;
        let constant: Vec<DVec3> = self
            .terms
            .iter()
            .map(|list| {
                list.iter()
                    .filter(|&&(u, _)| !is_free(u))
                    .map(|&(u, w)| w * fixed(u))
                    .sum()
            })
            .collect();
        let apply = |y: &[DVec3]| -> Vec<DVec3> {
            self.terms
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
            let mut out = vec![DVec3::ZERO; self.free_count];
            for (list, &value) in self.terms.iter().zip(r) {
                for &(u, w) in list.iter().filter(|&&(u, _)| is_free(u)) {
                    out[unknown(u)] += w * value;
                }
            }
            out
        };
        let normal_matrix = |y: &[DVec3]| apply_transposed(&apply(y));
        let rhs: Vec<DVec3> = apply_transposed(&constant)
            .into_iter()
            .map(|c| -c)
            .collect();
        let mut y = start;
        conjugate_gradients(normal_matrix, &rhs, &mut y);
        y
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

    /// The lowest z of the vertices from `first` on.
    fn lowest_z(mesh: &TriangleMesh, first: usize) -> f64 {
        mesh.vertices[first..]
            .iter()
            .map(|v| v[2])
            .fold(f64::INFINITY, f64::min)
    }

    /// Angles (degrees) between the normals of the vertices from `first` on and the radius of
    /// the sphere about the origin through them: (mean, largest).
    fn normals_off_the_radius(mesh: &TriangleMesh, first: usize) -> (f64, f64) {
        let angles: Vec<f64> = (first..mesh.vertices.len())
            .map(|v| {
                let radial = DVec3::from_array(mesh.vertices[v]).normalize();
                let n = DVec3::from_array(mesh.normals[v]);
                n.dot(radial).clamp(-1.0, 1.0).acos().to_degrees()
            })
            .collect();
        (
            angles.iter().sum::<f64>() / angles.len() as f64,
            angles.iter().copied().fold(0.0, f64::max),
        )
    }

    /// A unit sphere without its cap below z = −0.6 (a hole 0.8 across and 0.4 deep): a flat
    /// membrane over the rim lies up to 0.4 from the sphere, a thin plate a few hundredths
    /// (flatter than the sphere); the cap laid on the quadric around the hole is on the sphere,
    /// its normals outward.
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
        let lowest = lowest_z(&mesh, old_vertices);
        let (mean, worst) = off_unit_sphere(&mesh, old_vertices);
        println!(
            "{} cap vertices: {mean:.4} from the sphere on average, {worst:.4} at most, lowest z {lowest:.3}",
            mesh.vertices.len() - old_vertices
        );
        assert_eq!(closed.continued, 1);
        assert!(mean < 0.002 && worst < 0.005, "mean {mean}, worst {worst}");
        assert!(lowest < -0.99, "the cap reaches down to {lowest} only");
        let (mean_angle, worst_angle) = normals_off_the_radius(&mesh, old_vertices);
        println!(
            "cap normals off the radius: {mean_angle:.2}° on average, {worst_angle:.2}° at most"
        );
        assert!(mean_angle < 3.0 && worst_angle < 8.0);
        // Closed: the enclosed volume is the whole sphere's (the cut-off segment is 9 % of it,
        // which a flat cap would lose).
        let volume = mesh.signed_volume();
        let sphere = 4.0 / 3.0 * std::f64::consts::PI;
        println!("volume {volume:.4} of {sphere:.4}");
        assert!(
            (volume - sphere).abs() < 0.01 * sphere,
            "volume {volume} of {sphere}"
        );
    }

    /// The loop of an extracted mesh flares: where only grazing views saw the surface, its
    /// border lies outside it. With the loop and the ring beyond it pushed out by 0.03, the cap
    /// still starts at the loop, is back on the sphere within a few rings (the fit leaves the
    /// flared rings out), and its normals are the sphere's but where the flare fades.
    #[test]
    fn a_flared_loop_is_met_and_the_cap_returns_to_the_surface() {
        let mut mesh = sphere_open_below(-0.6);
        let loops = boundary_loops(&mesh.triangles);
        let mut flared: HashSet<u32> = loops[0].iter().copied().collect();
        for t in &mesh.triangles {
            if t.iter().any(|v| loops[0].contains(v)) {
                flared.extend(t);
            }
        }
        for &v in &flared {
            let p = DVec3::from_array(mesh.vertices[v as usize]);
            mesh.vertices[v as usize] = (p * 1.03).to_array();
        }
        let rim: Vec<DVec3> = loops[0].iter().map(|&v| mesh.vertex(v)).collect();
        let old_vertices = mesh.vertices.len();
        assert_eq!(mesh.close_holes().continued, 1);
        assert!(is_closed_and_oriented(&mesh));
        assert_eq!(
            rim,
            loops[0].iter().map(|&v| mesh.vertex(v)).collect::<Vec<_>>()
        );
        let lowest = lowest_z(&mesh, old_vertices);
        let (mean_angle, worst_angle) = normals_off_the_radius(&mesh, old_vertices);
        println!(
            "flared loop: the cap reaches z = {lowest:.4}, normals {mean_angle:.2}° off on average, {worst_angle:.2}° at most (where the flare fades)"
        );
        assert!((lowest + 1.0).abs() < 0.002, "lowest {lowest}");
        assert!(
            mean_angle < 4.0 && worst_angle < 15.0,
            "{mean_angle}°, {worst_angle}°"
        );
    }

    /// Around a hole in a bumpy surface no quadric fits, and the thin plate stays: still closed,
    /// the cap within the bumps' reach.
    #[test]
    fn a_surround_no_quadric_fits_keeps_the_thin_plate() {
        let mut mesh = sphere_open_below(-0.6);
        for v in &mut mesh.vertices {
            let p = DVec3::from_array(*v);
            let bump = 1.0 + 0.15 * (9.0 * p.x).sin() * (9.0 * p.y).cos();
            *v = (p * bump).to_array();
        }
        let old_vertices = mesh.vertices.len();
        let closed = mesh.close_holes();
        assert_eq!((closed.holes, closed.continued), (1, 0));
        assert!(is_closed_and_oriented(&mesh));
        let (mean, _) = off_unit_sphere(&mesh, old_vertices);
        assert!(mean < 0.2, "mean {mean}");
    }

    /// An open tube's ends: the surface around each is a cylinder, which turns away from the
    /// cap across the end, so both ends keep their thin plates, flat across the tube.
    #[test]
    fn the_ends_of_a_tube_are_not_laid_on_its_wall() {
        let (around, along) = (48, 24);
        let vertex = |i: usize, k: usize| (k * around + i % around) as u32;
        let mut mesh = TriangleMesh::default();
        for k in 0..along {
            for i in 0..around {
                let angle = std::f64::consts::TAU * i as f64 / around as f64;
                mesh.vertices.push([
                    angle.cos(),
                    angle.sin(),
                    4.0 * k as f64 / (along - 1) as f64,
                ]);
            }
        }
        for k in 0..along - 1 {
            for i in 0..around {
                let (a, b) = (vertex(i, k), vertex(i + 1, k));
                let (c, d) = (vertex(i + 1, k + 1), vertex(i, k + 1));
                mesh.triangles.push([a, b, c]);
                mesh.triangles.push([a, c, d]);
            }
        }
        let old_vertices = mesh.vertices.len();
        let closed = mesh.close_holes();
        assert_eq!((closed.holes, closed.continued), (2, 0));
        assert!(is_closed_and_oriented(&mesh));
        for v in &mesh.vertices[old_vertices..] {
            let radial = (v[0] * v[0] + v[1] * v[1]).sqrt();
            assert!(radial < 1.02, "a cap vertex left the tube: {v:?}");
        }
        assert!(mesh.signed_volume() > 0.0);
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
        assert!(mean < 0.002 && worst < 0.005, "mean {mean}, worst {worst}");
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

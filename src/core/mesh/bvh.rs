//! Bounding volume hierarchy over the triangles of a mesh, in f64: closest hit, any hit
//! (occlusion), inside/outside test and closest point.
//!
//! Built top-down with the binned surface-area heuristic (12 bins per axis, all three axes
//! considered), splitting until a node holds at most 4 triangles. Nodes are flattened in depth-first
//! order (left child follows its parent, the right child index is stored). Traversal is iterative
//! with a fixed 64-entry stack, nearer child first; rays use Möller–Trumbore. Queries are `&self`
//! and allocation-free, so callers parallelize over rays with rayon; the build is single-threaded
//! (tens of milliseconds for 10⁵ triangles).

use glam::DVec3;

use crate::core::mesh::TriangleMesh;

/// Triangles per leaf at most.
const MAX_LEAF: usize = 4;
/// SAH bins per axis.
const BINS: usize = 12;
/// Below this depth nodes split by object median instead of SAH, which bounds the tree depth by
/// `MEDIAN_DEPTH + 32` for any triangle count that fits u32.
const MEDIAN_DEPTH: usize = 48;
/// Traversal stack size: at most one entry per level.
const STACK: usize = MEDIAN_DEPTH + 40;
/// Hits closer than this ray parameter are ignored (self-intersection guard for unit directions).
pub const T_MIN: f64 = 1e-9;

/// A closest-hit record.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter: `position = origin + t · dir`.
    pub t: f64,
    /// Index of the triangle in the mesh.
    pub triangle: u32,
    /// Barycentric `(u, v)` of the hit: weights `(1 − u − v, u, v)` of the triangle's corners.
    pub barycentric: (f64, f64),
    /// Interpolated vertex normal (unit; the geometric normal when the mesh has none).
    pub normal: DVec3,
    pub position: DVec3,
}

#[derive(Clone, Copy, Debug)]
struct Aabb {
    min: DVec3,
    max: DVec3,
}

impl Aabb {
    const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    fn grow(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    fn merge(&mut self, other: &Aabb) {
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
    }

    fn half_area(&self) -> f64 {
        let e = (self.max - self.min).max(DVec3::ZERO);
        e.x * e.y + e.y * e.z + e.z * e.x
    }

    /// Entry distance of the ray into the box if it is hit within `(0, t_max)`.
    fn ray_entry(&self, origin: DVec3, inv_dir: DVec3, t_max: f64) -> Option<f64> {
        let t0 = (self.min - origin) * inv_dir;
        let t1 = (self.max - origin) * inv_dir;
        let near = t0.min(t1).max_element().max(0.0);
        let far = t0.max(t1).min_element().min(t_max);
        (near <= far).then_some(near)
    }

    fn distance_squared(&self, p: DVec3) -> f64 {
        let d = (self.min - p).max(p - self.max).max(DVec3::ZERO);
        d.length_squared()
    }
}

/// A node of [`Bvh::flat_nodes`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatNode {
    pub min: DVec3,
    pub max: DVec3,
    /// Leaf: first triangle slot; interior: index of the right child (the left one follows).
    pub first_or_right: u32,
    /// Triangles in a leaf; 0 for interior nodes.
    pub count: u32,
}

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Leaf: first triangle slot; interior: index of the right child.
    first_or_right: u32,
    /// Triangles in a leaf; 0 for interior nodes.
    count: u32,
}

/// Triangle data in traversal order: one corner and two edges, for Möller–Trumbore.
#[derive(Clone, Copy, Debug)]
struct PreparedTriangle {
    v0: DVec3,
    e1: DVec3,
    e2: DVec3,
}

/// A BVH over one mesh's triangles. It copies what it needs; the mesh can be dropped.
#[derive(Clone, Debug)]
pub struct Bvh {
    nodes: Vec<Node>,
    triangles: Vec<PreparedTriangle>,
    /// Mesh triangle index of each slot.
    original: Vec<u32>,
    /// Vertex normals of each slot's corners.
    normals: Vec<[DVec3; 3]>,
}

/// Builds the BVH of a mesh (an empty mesh gives a BVH that nothing hits).
pub fn build(mesh: &TriangleMesh) -> Bvh {
    Bvh::build(mesh)
}

struct BuildItem {
    bounds: Aabb,
    centroid: DVec3,
    triangle: u32,
}

impl Bvh {
    /// See [`build`].
    pub fn build(mesh: &TriangleMesh) -> Bvh {
        let _span = tracing::info_span!("bvh_build", triangles = mesh.triangles.len()).entered();
        let mut items: Vec<BuildItem> = (0..mesh.triangles.len())
            .map(|t| {
                let corners = mesh.triangle_corners(t);
                let mut bounds = Aabb::EMPTY;
                corners.iter().for_each(|&c| bounds.grow(c));
                BuildItem {
                    bounds,
                    centroid: (corners[0] + corners[1] + corners[2]) / 3.0,
                    triangle: t as u32,
                }
            })
            .collect();
        let mut nodes = Vec::with_capacity(2 * items.len().max(1) / MAX_LEAF + 1);
        if !items.is_empty() {
            build_node(&mut items, 0, 0, &mut nodes);
        }
        let original: Vec<u32> = items.iter().map(|it| it.triangle).collect();
        let triangles = original
            .iter()
            .map(|&t| {
                let [a, b, c] = mesh.triangle_corners(t as usize);
                PreparedTriangle {
                    v0: a,
                    e1: b - a,
                    e2: c - a,
                }
            })
            .collect();
        let with_normals = mesh.has_normals();
        let normals = original
            .iter()
            .map(|&t| {
                let ids = mesh.triangles[t as usize];
                if with_normals {
                    ids.map(|i| DVec3::from_array(mesh.normals[i as usize]))
                } else {
                    let [a, b, c] = mesh.triangle_corners(t as usize);
                    [(b - a).cross(c - a).normalize_or_zero(); 3]
                }
            })
            .collect();
        Bvh {
            nodes,
            triangles,
            original,
            normals,
        }
    }

    /// Number of nodes (for statistics).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The nodes in their flattened depth-first order (a left child follows its parent), for
    /// traversals of the same tree elsewhere (the gpu shading kernels).
    pub fn flat_nodes(&self) -> impl Iterator<Item = FlatNode> + '_ {
        self.nodes.iter().map(|n| FlatNode {
            min: n.bounds.min,
            max: n.bounds.max,
            first_or_right: n.first_or_right,
            count: n.count,
        })
    }

    /// The triangle slots in leaf order: corner `v0`, edges `e1`, `e2` (the triangle is
    /// `v0, v0 + e1, v0 + e2`) and the vertex normals of its corners.
    pub fn slots(&self) -> impl Iterator<Item = ([DVec3; 3], [DVec3; 3])> + '_ {
        self.triangles
            .iter()
            .zip(&self.normals)
            .map(|(t, n)| ([t.v0, t.e1, t.e2], *n))
    }

    /// Bounds of the whole mesh (`None` when empty).
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        self.nodes.first().map(|n| (n.bounds.min, n.bounds.max))
    }

    #[inline]
    fn intersect_triangle(
        &self,
        s: usize,
        origin: DVec3,
        dir: DVec3,
        t_max: f64,
    ) -> Option<(f64, f64, f64)> {
        let tri = &self.triangles[s];
        moller_trumbore(tri.v0, tri.e1, tri.e2, origin, dir, t_max)
    }

    /// Visits leaves whose boxes the ray enters before `t_max` (which `visit` may shrink), nearer
    /// child first. `visit` returns false to stop.
    #[inline]
    fn traverse_ray(
        &self,
        origin: DVec3,
        dir: DVec3,
        mut t_max: f64,
        mut visit: impl FnMut(usize, f64) -> (bool, f64),
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let inv_dir = dir.recip();
        let mut stack = [0u32; STACK];
        let mut top = 0usize;
        let mut node = 0usize;
        if self.nodes[0]
            .bounds
            .ray_entry(origin, inv_dir, t_max)
            .is_none()
        {
            return;
        }
        loop {
            let n = &self.nodes[node];
            if n.count > 0 {
                for s in n.first_or_right as usize..(n.first_or_right + n.count) as usize {
                    let (go_on, new_max) = visit(s, t_max);
                    t_max = new_max;
                    if !go_on {
                        return;
                    }
                }
            } else {
                let (left, right) = (node + 1, n.first_or_right as usize);
                let hit_left = self.nodes[left].bounds.ray_entry(origin, inv_dir, t_max);
                let hit_right = self.nodes[right].bounds.ray_entry(origin, inv_dir, t_max);
                match (hit_left, hit_right) {
                    (Some(a), Some(b)) => {
                        let (near, far) = if a <= b { (left, right) } else { (right, left) };
                        stack[top] = far as u32;
                        top += 1;
                        node = near;
                        continue;
                    }
                    (Some(_), None) => {
                        node = left;
                        continue;
                    }
                    (None, Some(_)) => {
                        node = right;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Pop the next node whose box is still in reach.
            loop {
                if top == 0 {
                    return;
                }
                top -= 1;
                node = stack[top] as usize;
                if self.nodes[node]
                    .bounds
                    .ray_entry(origin, inv_dir, t_max)
                    .is_some()
                {
                    break;
                }
            }
        }
    }

    /// The closest hit of the ray `origin + t · dir` with `T_MIN < t < t_max`. `dir` need not be
    /// unit length (then `t` is in units of `‖dir‖`).
    pub fn intersect(&self, origin: DVec3, dir: DVec3, t_max: f64) -> Option<Hit> {
        let mut best: Option<(usize, f64, f64, f64)> = None;
        self.traverse_ray(origin, dir, t_max, |s, t_max| {
            if let Some((t, u, v)) = self.intersect_triangle(s, origin, dir, t_max) {
                best = Some((s, t, u, v));
                (true, t)
            } else {
                (true, t_max)
            }
        });
        let (s, t, u, v) = best?;
        let [n0, n1, n2] = self.normals[s];
        let tri = &self.triangles[s];
        let normal = ((1.0 - u - v) * n0 + u * n1 + v * n2)
            .try_normalize()
            .unwrap_or_else(|| tri.e1.cross(tri.e2).normalize_or_zero());
        Some(Hit {
            t,
            triangle: self.original[s],
            barycentric: (u, v),
            normal,
            position: origin + t * dir,
        })
    }

    /// Whether anything is hit with `T_MIN < t < t_max` (stops at the first hit found).
    pub fn occluded(&self, origin: DVec3, dir: DVec3, t_max: f64) -> bool {
        let mut hit = false;
        self.traverse_ray(origin, dir, t_max, |s, t_max| {
            hit = self.intersect_triangle(s, origin, dir, t_max).is_some();
            (!hit, t_max)
        });
        hit
    }

    /// Number of surface crossings along the whole ray `t > T_MIN`.
    pub fn count_crossings(&self, origin: DVec3, dir: DVec3) -> usize {
        let mut count = 0;
        self.traverse_ray(origin, dir, f64::INFINITY, |s, t_max| {
            count += self.intersect_triangle(s, origin, dir, t_max).is_some() as usize;
            (true, t_max)
        });
        count
    }

    /// Whether `p` lies inside the (closed) mesh: parity of the crossings along three fixed
    /// directions in general position, majority vote (robust to a ray grazing an edge or vertex).
    pub fn contains(&self, p: DVec3) -> bool {
        // Unnormalized directions with no simple relation to the axes or to each other.
        const DIRECTIONS: [DVec3; 3] = [
            DVec3::new(0.5773, 0.5771, 0.5776),
            DVec3::new(-0.7072, 0.1235, -0.6961),
            DVec3::new(0.2673, -0.8019, 0.5344),
        ];
        let inside_votes = DIRECTIONS
            .iter()
            .filter(|&&d| self.count_crossings(p, d) % 2 == 1)
            .count();
        inside_votes >= 2
    }

    /// The closest point on the mesh to `p` and its distance (`(p, ∞)` for an empty mesh).
    pub fn closest_point(&self, p: DVec3) -> (DVec3, f64) {
        self.closest_triangle(p)
            .map_or((p, f64::INFINITY), |(q, d, _)| (q, d))
    }

    /// The closest point on the mesh to `p`, its distance and the index of the mesh triangle it
    /// lies on (`None` for an empty mesh).
    pub fn closest_triangle(&self, p: DVec3) -> Option<(DVec3, f64, u32)> {
        if self.nodes.is_empty() {
            return None;
        }
        let mut best = (p, 0usize);
        let mut best_sq = f64::INFINITY;
        let mut stack = [0u32; STACK];
        let mut top = 0usize;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.count > 0 {
                for s in n.first_or_right as usize..(n.first_or_right + n.count) as usize {
                    let tri = &self.triangles[s];
                    let q = closest_point_on_triangle(p, tri.v0, tri.v0 + tri.e1, tri.v0 + tri.e2);
                    let d = q.distance_squared(p);
                    if d < best_sq {
                        best_sq = d;
                        best = (q, s);
                    }
                }
            } else {
                let (left, right) = (node + 1, n.first_or_right as usize);
                let dl = self.nodes[left].bounds.distance_squared(p);
                let dr = self.nodes[right].bounds.distance_squared(p);
                let (near, d_near, far, d_far) = if dl <= dr {
                    (left, dl, right, dr)
                } else {
                    (right, dr, left, dl)
                };
                if d_near < best_sq {
                    if d_far < best_sq {
                        stack[top] = far as u32;
                        top += 1;
                    }
                    node = near;
                    continue;
                }
            }
            loop {
                if top == 0 {
                    return Some((best.0, best_sq.sqrt(), self.original[best.1]));
                }
                top -= 1;
                node = stack[top] as usize;
                if self.nodes[node].bounds.distance_squared(p) < best_sq {
                    break;
                }
            }
        }
    }
}

/// Recursively builds the subtree over `items` (whose first slot is `offset`), appending nodes in
/// depth-first order, and returns its node index. Reorders `items`.
fn build_node(
    items: &mut [BuildItem],
    offset: usize,
    depth: usize,
    nodes: &mut Vec<Node>,
) -> usize {
    let mut bounds = Aabb::EMPTY;
    let mut centroids = Aabb::EMPTY;
    for it in items.iter() {
        bounds.merge(&it.bounds);
        centroids.grow(it.centroid);
    }
    let index = nodes.len();
    nodes.push(Node {
        bounds,
        first_or_right: offset as u32,
        count: items.len() as u32,
    });
    if items.len() <= MAX_LEAF {
        return index;
    }
    let split = if depth < MEDIAN_DEPTH {
        sah_split(items, &centroids)
    } else {
        None
    }
    .unwrap_or_else(|| {
        // Object median along the widest centroid axis (halves the count, so depth stays bounded).
        let extent = centroids.max - centroids.min;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let mid = items.len() / 2;
        items.select_nth_unstable_by(mid, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
        mid
    });
    let (left, right) = items.split_at_mut(split);
    build_node(left, offset, depth + 1, nodes);
    let right_index = build_node(right, offset + split, depth + 1, nodes);
    nodes[index].first_or_right = right_index as u32;
    nodes[index].count = 0;
    index
}

/// Partitions `items` by the best binned-SAH plane over the three axes and returns the size of
/// the left part, or `None` when all centroids coincide (the caller splits in the middle).
fn sah_split(items: &mut [BuildItem], centroids: &Aabb) -> Option<usize> {
    let extent = centroids.max - centroids.min;
    let mut best: Option<(f64, usize, usize)> = None; // (cost, axis, bins on the left)
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        let scale = BINS as f64 / extent[axis];
        let bin_of = |c: DVec3| (((c[axis] - centroids.min[axis]) * scale) as usize).min(BINS - 1);
        let mut bin_bounds = [Aabb::EMPTY; BINS];
        let mut bin_count = [0usize; BINS];
        for it in items.iter() {
            let b = bin_of(it.centroid);
            bin_bounds[b].merge(&it.bounds);
            bin_count[b] += 1;
        }
        // Sweep from the right to get suffix areas, then from the left.
        let mut right_area = [0.0; BINS];
        let mut right_count = [0usize; BINS];
        let mut acc = Aabb::EMPTY;
        let mut n = 0;
        for b in (1..BINS).rev() {
            acc.merge(&bin_bounds[b]);
            n += bin_count[b];
            right_area[b] = acc.half_area();
            right_count[b] = n;
        }
        let mut acc = Aabb::EMPTY;
        let mut n = 0;
        for b in 1..BINS {
            acc.merge(&bin_bounds[b - 1]);
            n += bin_count[b - 1];
            if n == 0 || right_count[b] == 0 {
                continue;
            }
            let cost = acc.half_area() * n as f64 + right_area[b] * right_count[b] as f64;
            if best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, axis, b));
            }
        }
    }
    let (_, axis, left_bins) = best?;
    let scale = BINS as f64 / extent[axis];
    let goes_left = |it: &BuildItem| {
        ((((it.centroid[axis] - centroids.min[axis]) * scale) as usize).min(BINS - 1)) < left_bins
    };
    // In-place partition.
    let mut left = 0;
    for i in 0..items.len() {
        if goes_left(&items[i]) {
            items.swap(i, left);
            left += 1;
        }
    }
    Some(left)
}

/// Möller–Trumbore ray–triangle test for the triangle `(v0, v0 + e1, v0 + e2)`: `(t, u, v)` when
/// the ray hits it with `T_MIN < t < t_max` (`u`, `v` = barycentric weights of the 2nd and 3rd corners).
#[inline]
pub fn moller_trumbore(
    v0: DVec3,
    e1: DVec3,
    e2: DVec3,
    origin: DVec3,
    dir: DVec3,
    t_max: f64,
) -> Option<(f64, f64, f64)> {
    let p = dir.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv_det = 1.0 / det;
    let s = origin - v0;
    let u = s.dot(p) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = dir.dot(q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv_det;
    (t > T_MIN && t < t_max).then_some((t, u, v))
}

/// Closest point to `p` on triangle `abc` (Ericson, Real-Time Collision Detection §5.1.5).
pub fn closest_point_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let ab = b - a;
    let ac = c - a;
    let ap = p - a;
    let d1 = ab.dot(ap);
    let d2 = ac.dot(ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let d3 = ab.dot(bp);
    let d4 = ac.dot(bp);
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let d5 = ab.dot(cp);
    let d6 = ac.dot(cp);
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = va + vb + vc;
    if denom == 0.0 {
        // Degenerate (collinear) triangle: the nearest of its three edges.
        return [(a, b), (b, c), (c, a)]
            .into_iter()
            .map(|(s, e)| {
                let d = e - s;
                let len = d.length_squared();
                let t = if len > 0.0 {
                    ((p - s).dot(d) / len).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                s + t * d
            })
            .min_by(|x, y| x.distance_squared(p).total_cmp(&y.distance_squared(p)))
            .unwrap_or(a);
    }
    let v = vb / denom;
    let w = vc / denom;
    a + ab * v + ac * w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::random_unit;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn triangle_soup(seed: u64, count: usize) -> TriangleMesh {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut mesh = TriangleMesh::default();
        for t in 0..count {
            let centre = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let size = rng.random_range(0.02..0.3);
            for _ in 0..3 {
                mesh.vertices
                    .push((centre + size * random_unit(&mut rng)).to_array());
                mesh.normals.push(random_unit(&mut rng).to_array());
            }
            let b = 3 * t as u32;
            mesh.triangles.push([b, b + 1, b + 2]);
        }
        mesh
    }

    fn brute_intersect(mesh: &TriangleMesh, o: DVec3, d: DVec3, t_max: f64) -> Option<(f64, u32)> {
        let mut best: Option<(f64, u32)> = None;
        for t in 0..mesh.triangles.len() {
            let [a, b, c] = mesh.triangle_corners(t);
            if let Some((h, _, _)) = moller_trumbore(a, b - a, c - a, o, d, t_max) {
                if best.is_none_or(|(bt, _)| h < bt) {
                    best = Some((h, t as u32));
                }
            }
        }
        best
    }

    fn brute_closest(mesh: &TriangleMesh, p: DVec3) -> f64 {
        (0..mesh.triangles.len())
            .map(|t| {
                let [a, b, c] = mesh.triangle_corners(t);
                closest_point_on_triangle(p, a, b, c).distance(p)
            })
            .fold(f64::INFINITY, f64::min)
    }

    fn check_rays_against_brute_force(mesh: &TriangleMesh, rays: usize, seed: u64) -> usize {
        let bvh = Bvh::build(mesh);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut hits = 0;
        for r in 0..rays {
            let origin = 2.5 * random_unit(&mut rng);
            let target = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let dir = (target - origin).normalize();
            let t_max = if r % 4 == 0 {
                rng.random_range(0.5..4.0)
            } else {
                f64::INFINITY
            };
            let got = bvh.intersect(origin, dir, t_max);
            let want = brute_intersect(mesh, origin, dir, t_max);
            assert_eq!(bvh.occluded(origin, dir, t_max), want.is_some(), "ray {r}");
            match (got, want) {
                (None, None) => {}
                (Some(h), Some((t, tri))) => {
                    hits += 1;
                    assert!((h.t - t).abs() < 1e-12, "ray {r}: t {} vs {t}", h.t);
                    if h.triangle != tri {
                        // A tie between triangles at the same distance is fine.
                        assert!(
                            (h.t - t).abs() < 1e-14,
                            "ray {r}: triangle {} vs {tri}",
                            h.triangle
                        );
                    }
                    assert!(h.position.distance(origin + t * dir) < 1e-12);
                    let [a, b, c] = mesh.triangle_corners(h.triangle as usize);
                    let (u, v) = h.barycentric;
                    assert!(((1.0 - u - v) * a + u * b + v * c).distance(h.position) < 1e-9);
                    assert!((h.normal.length() - 1.0).abs() < 1e-12);
                }
                (g, w) => panic!("ray {r}: bvh {g:?} vs brute force {w:?}"),
            }
        }
        hits
    }

    #[test]
    fn rays_agree_with_brute_force_on_a_triangle_soup() {
        for seed in 0..3 {
            let mesh = triangle_soup(seed, 400);
            let hits = check_rays_against_brute_force(&mesh, 1500, seed + 100);
            assert!(
                hits > 300,
                "seed {seed}: only {hits} hits — the test would prove little"
            );
        }
    }

    #[test]
    fn hit_normal_interpolates_vertex_normals() {
        let mesh = TriangleMesh {
            vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            normals: vec![[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            triangles: vec![[0, 1, 2]],
            material_ids: Vec::new(),
        };
        let bvh = Bvh::build(&mesh);
        let hit = bvh
            .intersect(DVec3::new(0.25, 0.5, 2.0), DVec3::NEG_Z, f64::INFINITY)
            .unwrap();
        assert!((hit.t - 2.0).abs() < 1e-15);
        assert!(
            (hit.barycentric.0 - 0.25).abs() < 1e-15 && (hit.barycentric.1 - 0.5).abs() < 1e-15
        );
        let expected = DVec3::new(0.25, 0.5, 0.25).normalize();
        assert!(hit.normal.abs_diff_eq(expected, 1e-12));
        assert!(bvh
            .intersect(DVec3::new(0.25, 0.5, 2.0), DVec3::NEG_Z, 1.9)
            .is_none());
        assert!(bvh
            .intersect(DVec3::new(0.8, 0.8, 2.0), DVec3::NEG_Z, 9.0)
            .is_none());
    }

    #[test]
    fn closest_point_agrees_with_brute_force() {
        let mesh = triangle_soup(7, 300);
        let bvh = Bvh::build(&mesh);
        let mut rng = ChaCha8Rng::seed_from_u64(8);
        for _ in 0..2000 {
            let p = 1.6
                * DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
            let (q, d) = bvh.closest_point(p);
            let want = brute_closest(&mesh, p);
            assert!((d - want).abs() < 1e-12, "{d} vs {want}");
            assert!((q.distance(p) - d).abs() < 1e-12);
        }
    }

    #[test]
    fn closest_point_on_triangle_regions() {
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
        let cases = [
            (DVec3::new(0.2, 0.3, 0.7), DVec3::new(0.2, 0.3, 0.0)), // face
            (DVec3::new(-1.0, -1.0, 0.0), a),                       // vertex a
            (DVec3::new(2.0, -0.5, 1.0), b),                        // vertex b
            (DVec3::new(-0.1, 3.0, 0.0), c),                        // vertex c
            (DVec3::new(0.5, -2.0, 0.0), DVec3::new(0.5, 0.0, 0.0)), // edge ab
            (DVec3::new(1.0, 1.0, 5.0), DVec3::new(0.5, 0.5, 0.0)), // edge bc
            (DVec3::new(-3.0, 0.4, 0.0), DVec3::new(0.0, 0.4, 0.0)), // edge ca
        ];
        for (p, want) in cases {
            assert!(
                closest_point_on_triangle(p, a, b, c).abs_diff_eq(want, 1e-15),
                "{p}"
            );
        }
        // Degenerate triangle.
        let q = closest_point_on_triangle(DVec3::new(0.5, 1.0, 0.0), a, b, 2.0 * b);
        assert!(q.abs_diff_eq(DVec3::new(0.5, 0.0, 0.0), 1e-15));
    }

    #[test]
    fn contains_separates_inside_from_outside_of_a_sphere() {
        let mesh = TriangleMesh::icosphere(DVec3::new(0.1, -0.2, 0.3), 1.0, 3);
        let bvh = Bvh::build(&mesh);
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..2000 {
            let p = DVec3::new(0.1, -0.2, 0.3)
                + 1.5 * random_unit(&mut rng) * rng.random_range(0.0..1.0);
            let r = p.distance(DVec3::new(0.1, -0.2, 0.3));
            if (r - 1.0).abs() < 0.02 {
                continue; // within the tessellation error
            }
            assert_eq!(bvh.contains(p), r < 1.0, "point at radius {r}");
        }
    }

    fn tree_depth(bvh: &Bvh, node: usize) -> usize {
        let n = &bvh.nodes[node];
        if n.count > 0 {
            1
        } else {
            1 + tree_depth(bvh, node + 1).max(tree_depth(bvh, n.first_or_right as usize))
        }
    }

    #[test]
    fn geometric_spacing_cannot_overflow_the_traversal_stack() {
        // Triangles at x = 2^-i: binned SAH peels them off one by one, so the depth must be
        // capped by the median fallback.
        let mut mesh = TriangleMesh::default();
        for i in 0..400u32 {
            let x = 0.5f64.powi(i as i32 / 2) * if i % 2 == 0 { 1.0 } else { -1.0 };
            let b = mesh.vertices.len() as u32;
            mesh.vertices
                .extend([[x, -1.0, -1.0], [x, 1.0, -1.0], [x, 0.0, 1.0]]);
            mesh.triangles.push([b, b + 1, b + 2]);
        }
        let bvh = Bvh::build(&mesh);
        let depth = tree_depth(&bvh, 0);
        assert!(depth <= STACK, "depth {depth}");
        assert!(
            depth > 20,
            "depth {depth}: the test no longer exercises deep trees"
        );
        let hits = bvh.count_crossings(DVec3::new(2.0, 0.0, 0.0), DVec3::new(-1.0, 0.001, 0.002));
        assert_eq!(hits, 400);
        let first = bvh
            .intersect(DVec3::new(2.0, 0.0, 0.0), DVec3::NEG_X, 9.0)
            .unwrap();
        assert!((first.t - 1.0).abs() < 1e-15);
        assert!(check_rays_against_brute_force(&mesh, 200, 4) > 50);
    }

    #[test]
    fn empty_mesh_is_never_hit() {
        let bvh = Bvh::build(&TriangleMesh::default());
        assert!(bvh.intersect(DVec3::ZERO, DVec3::X, 1.0).is_none());
        assert!(!bvh.occluded(DVec3::ZERO, DVec3::X, 1.0));
        assert!(!bvh.contains(DVec3::ZERO));
        assert_eq!(bvh.closest_point(DVec3::ONE).1, f64::INFINITY);
    }

    #[test]
    fn leaves_hold_at_most_four_triangles_and_cover_all() {
        let mesh = triangle_soup(11, 1000);
        let bvh = Bvh::build(&mesh);
        let mut seen = vec![false; 1000];
        for n in &bvh.nodes {
            assert!(n.count as usize <= MAX_LEAF);
            for s in n.first_or_right..n.first_or_right + n.count {
                seen[bvh.original[s as usize] as usize] = true;
            }
        }
        assert!(seen.iter().all(|&s| s));
        // Many identical triangles (all centroids equal) still split into small leaves.
        let same = TriangleMesh {
            vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            normals: Vec::new(),
            triangles: vec![[0, 1, 2]; 37],
            material_ids: Vec::new(),
        };
        let bvh = Bvh::build(&same);
        assert!(bvh.nodes.iter().all(|n| n.count as usize <= MAX_LEAF));
        let hit = bvh
            .intersect(DVec3::new(0.2, 0.2, 1.0), DVec3::NEG_Z, 2.0)
            .unwrap();
        assert!((hit.t - 1.0).abs() < 1e-15);
    }

    #[test]
    fn knot_mesh_rays_and_closest_points_agree_with_brute_force() {
        let Some(data) = crate::testing::shared_data_dir() else {
            return;
        };
        let mesh = TriangleMesh::read_ply(&data.join("knot/mesh.ply")).unwrap();
        let hits = check_rays_against_brute_force(&mesh, 300, 5);
        assert!(hits > 50, "only {hits} rays hit the knot");
        let bvh = Bvh::build(&mesh);
        let mut rng = ChaCha8Rng::seed_from_u64(6);
        for _ in 0..200 {
            let p = 1.2 * random_unit(&mut rng) * rng.random_range(0.0..1.0);
            let (_, d) = bvh.closest_point(p);
            assert!((d - brute_closest(&mesh, p)).abs() < 1e-12);
        }
    }
}

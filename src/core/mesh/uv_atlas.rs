//! A UV atlas of a triangle mesh, for baking its materials into textures: the faces are grouped
//! into charts, each chart is projected flat, and the charts are packed side by side into one
//! square texture with a gutter of empty texels around each.
//!
//! - **Charts**: grown breadth-first from a seed face over shared edges, taking a face while its
//!   normal stays within [`AtlasParams::cone_deg`] of the seed's (the chart's axis) and its
//!   projection onto the plane normal to the axis overlaps none of the chart's faces so far. Every
//!   face therefore keeps its orientation in the plane (its normal is less than 90° from the axis),
//!   the stretch of a chart's texels is at most 1 / cos(cone) across it, and a chart never folds
//!   over itself.
//! - **Seams**: a vertex shared by several charts is duplicated, one copy per chart
//!   ([`UvAtlas::source_vertex`] tells which vertex each copy came from).
//! - **Packing**: each chart is turned to the smallest of its bounding boxes over 32 angles, then the
//!   boxes are packed in shelves (tallest first) into a `size` × `size` texture at the largest scale
//!   (texels per scene unit) that fits, found by bisection; boxes are at least
//!   [`AtlasParams::gutter`] texels apart, and half as far from the texture's border. UVs are in
//!   [0, 1], glTF's convention: u to the right, v down the image, (0, 0) the first texel's corner.
//! - **Tangents** ([`UvAtlas::tangents`]): per vertex, the UV gradient of the position (dP/du)
//!   summed over its faces and made orthogonal to the normal, with the handedness glTF's `TANGENT`
//!   carries (the bitangent N × T · w points along −dP/dv, "up" in the image).
//!
//! Single-threaded: the charts grow one after another (a few hundred thousand faces a second).

use std::collections::{HashMap, VecDeque};

use glam::{DVec2, DVec3};

use super::TriangleMesh;

/// How charts are cut and packed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AtlasParams {
    /// Largest angle between a face's normal and its chart's axis (degrees, below 90).
    pub cone_deg: f64,
    /// Side of the square texture (texels).
    pub size: u32,
    /// Empty texels between two charts' boxes (half of it at the texture's border).
    pub gutter: u32,
}

impl Default for AtlasParams {
    fn default() -> Self {
        AtlasParams {
            cone_deg: 50.0,
            size: 1024,
            gutter: 4,
        }
    }
}

/// A mesh cut into charts and laid out in a texture.
#[derive(Clone, Debug, PartialEq)]
pub struct UvAtlas {
    /// The mesh with one vertex per (vertex, chart) pair; same triangles in the same order, normals
    /// copied from the source mesh (computed when it had none).
    pub mesh: TriangleMesh,
    /// Texture coordinates of `mesh`'s vertices, in [0, 1].
    pub uvs: Vec<[f64; 2]>,
    /// For each vertex of `mesh`, the source mesh's vertex it copies.
    pub source_vertex: Vec<u32>,
    /// For each triangle, its chart.
    pub chart_of_triangle: Vec<u32>,
    /// Number of charts.
    pub charts: usize,
    /// Side of the texture the UVs are laid out for (texels).
    pub size: u32,
    /// Texels per scene unit along the charts' planes.
    pub texels_per_unit: f64,
}

/// One chart: its faces, its local 2-D coordinates (scene units) per source vertex, its box.
struct Chart {
    faces: Vec<u32>,
    /// (source vertex, position in the chart's plane, turned to the chart's best angle).
    vertices: Vec<(u32, DVec2)>,
    /// Lower corner and extent of the turned chart's box.
    lo: DVec2,
    extent: DVec2,
}

/// Two vectors spanning the plane normal to `axis` (unit), right-handed with it.
fn plane_basis(axis: DVec3) -> (DVec3, DVec3) {
    let helper = if axis.x.abs() < 0.9 {
        DVec3::X
    } else {
        DVec3::Y
    };
    let e1 = helper.cross(axis).normalize();
    let e2 = axis.cross(e1);
    (e1, e2)
}

/// Whether two 2-D triangles overlap by more than touching (`eps`: tolerance in their units).
/// Separating-axis test over the six edge normals, complete for two convex polygons.
pub fn triangles_overlap(a: &[DVec2; 3], b: &[DVec2; 3], eps: f64) -> bool {
    for tri in [a, b] {
        for k in 0..3 {
            let edge = tri[(k + 1) % 3] - tri[k];
            let axis = edge.perp();
            if axis.length_squared() == 0.0 {
                continue;
            }
            let axis = axis.normalize();
            let range = |t: &[DVec2; 3]| {
                t.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                        let d = p.dot(axis);
                        (lo.min(d), hi.max(d))
                    })
            };
            let (a_lo, a_hi) = range(a);
            let (b_lo, b_hi) = range(b);
            if a_hi <= b_lo + eps || b_hi <= a_lo + eps {
                return false;
            }
        }
    }
    true
}

/// A uniform grid over a chart's plane that lists the faces whose boxes reach each cell.
struct PlaneGrid {
    cell: f64,
    cells: HashMap<(i64, i64), Vec<u32>>,
}

impl PlaneGrid {
    fn cell_range(&self, tri: &[DVec2; 3]) -> ((i64, i64), (i64, i64)) {
        let lo = tri[0].min(tri[1]).min(tri[2]);
        let hi = tri[0].max(tri[1]).max(tri[2]);
        let index = |v: f64| (v / self.cell).floor() as i64;
        ((index(lo.x), index(lo.y)), (index(hi.x), index(hi.y)))
    }

    fn insert(&mut self, face: u32, tri: &[DVec2; 3]) {
        let ((x0, y0), (x1, y1)) = self.cell_range(tri);
        for x in x0..=x1 {
            for y in y0..=y1 {
                self.cells.entry((x, y)).or_default().push(face);
            }
        }
    }

    /// Whether `tri` overlaps any face in the grid (their projections in `projected`).
    fn overlaps(&self, tri: &[DVec2; 3], projected: &HashMap<u32, [DVec2; 3]>, eps: f64) -> bool {
        let ((x0, y0), (x1, y1)) = self.cell_range(tri);
        for x in x0..=x1 {
            for y in y0..=y1 {
                let Some(faces) = self.cells.get(&(x, y)) else {
                    continue;
                };
                if faces
                    .iter()
                    .any(|f| triangles_overlap(tri, &projected[f], eps))
                {
                    return true;
                }
            }
        }
        false
    }
}

/// The charts of `mesh` (module doc), faces with no area joining whichever chart reaches them.
fn grow_charts(mesh: &TriangleMesh, cone_deg: f64) -> Vec<Chart> {
    let faces = mesh.triangles.len();
    let normals: Vec<DVec3> = (0..faces)
        .map(|t| {
            let [a, b, c] = mesh.triangle_corners(t);
            (b - a).cross(c - a).try_normalize().unwrap_or(DVec3::ZERO)
        })
        .collect();
    let mut edge_faces: HashMap<(u32, u32), Vec<u32>> = HashMap::with_capacity(3 * faces / 2);
    let mut edge_length = 0.0;
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            edge_faces
                .entry((a.min(b), a.max(b)))
                .or_default()
                .push(t as u32);
            edge_length += (mesh.vertex(a) - mesh.vertex(b)).length();
        }
    }
    let cell = (edge_length / (3 * faces.max(1)) as f64).max(1e-12);
    let eps = 1e-9 * cell;
    let cos_cone = cone_deg.clamp(1.0, 89.0).to_radians().cos();
    let mut chart_of = vec![u32::MAX; faces];
    let mut charts = Vec::new();
    for seed in 0..faces {
        if chart_of[seed] != u32::MAX {
            continue;
        }
        let id = charts.len() as u32;
        // A face without area has no direction: it seeds a chart facing along +Z.
        let axis = if normals[seed] == DVec3::ZERO {
            DVec3::Z
        } else {
            normals[seed]
        };
        let (e1, e2) = plane_basis(axis);
        let project = |t: usize| {
            mesh.triangle_corners(t)
                .map(|p| DVec2::new(p.dot(e1), p.dot(e2)))
        };
        let mut grid = PlaneGrid {
            cell,
            cells: HashMap::new(),
        };
        let mut projected: HashMap<u32, [DVec2; 3]> = HashMap::new();
        let mut members = vec![seed as u32];
        chart_of[seed] = id;
        let tri = project(seed);
        grid.insert(seed as u32, &tri);
        projected.insert(seed as u32, tri);
        let mut queue = VecDeque::from([seed]);
        while let Some(face) = queue.pop_front() {
            let tri = mesh.triangles[face];
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                for &next in &edge_faces[&(a.min(b), a.max(b))] {
                    let next = next as usize;
                    if chart_of[next] != u32::MAX {
                        continue;
                    }
                    let flat = normals[next] == DVec3::ZERO;
                    if !flat && normals[next].dot(axis) < cos_cone {
                        continue;
                    }
                    let candidate = project(next);
                    if grid.overlaps(&candidate, &projected, eps) {
                        continue;
                    }
                    chart_of[next] = id;
                    members.push(next as u32);
                    grid.insert(next as u32, &candidate);
                    projected.insert(next as u32, candidate);
                    queue.push_back(next);
                }
            }
        }
        // The chart's vertices in its plane.
        let mut local: HashMap<u32, DVec2> = HashMap::new();
        for &f in &members {
            for &v in &mesh.triangles[f as usize] {
                local.entry(v).or_insert_with(|| {
                    let p = mesh.vertex(v);
                    DVec2::new(p.dot(e1), p.dot(e2))
                });
            }
        }
        let mut vertices: Vec<(u32, DVec2)> = local.into_iter().collect();
        vertices.sort_by_key(|v| v.0);
        // The turn (over a quarter circle) with the smallest box.
        let bounds = |turn: DVec2| {
            vertices.iter().fold(
                (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
                |(lo, hi), (_, p)| {
                    let q = turn.rotate(*p);
                    (lo.min(q), hi.max(q))
                },
            )
        };
        let best = (0..32)
            .map(|k| DVec2::from_angle(k as f64 * std::f64::consts::FRAC_PI_2 / 32.0))
            .min_by(|a, b| {
                let area = |t: &DVec2| {
                    let (lo, hi) = bounds(*t);
                    (hi - lo).x * (hi - lo).y
                };
                area(a).total_cmp(&area(b))
            })
            .expect("32 angles");
        let (lo, hi) = bounds(best);
        for (_, p) in &mut vertices {
            *p = best.rotate(*p);
        }
        charts.push(Chart {
            faces: members,
            vertices,
            lo,
            extent: hi - lo,
        });
    }
    charts
}

/// The texel corner of each chart's box at `scale` texels per unit, or `None` when they do not
/// fit. `order`: the charts, tallest first.
fn shelf_pack(
    charts: &[Chart],
    order: &[usize],
    scale: f64,
    size: u32,
    gutter: u32,
) -> Option<Vec<DVec2>> {
    let size = f64::from(size);
    let gutter = f64::from(gutter);
    let mut corners = vec![DVec2::ZERO; charts.len()];
    let (mut x, mut y, mut shelf) = (0.0, 0.0, 0.0);
    for &c in order {
        let w = (charts[c].extent.x * scale).ceil() + gutter;
        let h = (charts[c].extent.y * scale).ceil() + gutter;
        if w > size {
            return None;
        }
        if x + w > size {
            x = 0.0;
            y += shelf;
            shelf = 0.0;
        }
        if y + h > size {
            return None;
        }
        corners[c] = DVec2::new(x, y);
        x += w;
        shelf = f64::max(shelf, h);
    }
    Some(corners)
}

impl UvAtlas {
    /// The atlas of `mesh` (module doc). A mesh without triangles gives an empty atlas.
    pub fn build(mesh: &TriangleMesh, params: AtlasParams) -> UvAtlas {
        let _span = tracing::info_span!(
            "uv_atlas",
            triangles = mesh.triangles.len(),
            size = params.size
        )
        .entered();
        let size = params.size.max(1);
        let gutter = params.gutter.min(size / 4);
        let charts = grow_charts(mesh, params.cone_deg);
        let mut order: Vec<usize> = (0..charts.len()).collect();
        order.sort_by(|&a, &b| charts[b].extent.y.total_cmp(&charts[a].extent.y));
        // Bisection on the scale: the area bound is an upper limit (the boxes cover at least the
        // charts' area), halving from it until the charts fit.
        let area: f64 = charts
            .iter()
            .map(|c| c.extent.x.max(1e-12) * c.extent.y.max(1e-12))
            .sum();
        let mut high = f64::from(size) / area.sqrt().max(1e-12);
        let mut low = high;
        let mut placed = None;
        for _ in 0..200 {
            if let Some(corners) = shelf_pack(&charts, &order, low, size, gutter) {
                placed = Some(corners);
                break;
            }
            high = low;
            low *= 0.5;
        }
        let mut corners = placed.unwrap_or_else(|| vec![DVec2::ZERO; charts.len()]);
        for _ in 0..40 {
            let mid = 0.5 * (low + high);
            match shelf_pack(&charts, &order, mid, size, gutter) {
                Some(fit) => {
                    low = mid;
                    corners = fit;
                }
                None => high = mid,
            }
        }
        let scale = low;

        let mut source_mesh_normals = mesh.normals.clone();
        if !mesh.has_normals() {
            let mut copy = mesh.clone();
            copy.compute_vertex_normals();
            source_mesh_normals = copy.normals;
        }
        let mut out = TriangleMesh {
            triangles: mesh.triangles.clone(),
            material_ids: mesh.material_ids.clone(),
            ..TriangleMesh::default()
        };
        let mut uvs = Vec::new();
        let mut source_vertex = Vec::new();
        let mut chart_of_triangle = vec![0u32; mesh.triangles.len()];
        let half_gutter = f64::from(gutter / 2);
        for (id, chart) in charts.iter().enumerate() {
            let mut new_index: HashMap<u32, u32> = HashMap::with_capacity(chart.vertices.len());
            let origin = corners[id] + DVec2::splat(half_gutter);
            for &(v, p) in &chart.vertices {
                new_index.insert(v, out.vertices.len() as u32);
                out.vertices.push(mesh.vertices[v as usize]);
                out.normals.push(source_mesh_normals[v as usize]);
                let texel = origin + (p - chart.lo) * scale;
                uvs.push(
                    (texel / f64::from(size))
                        .clamp(DVec2::ZERO, DVec2::ONE)
                        .to_array(),
                );
                source_vertex.push(v);
            }
            for &f in &chart.faces {
                chart_of_triangle[f as usize] = id as u32;
                let t = &mut out.triangles[f as usize];
                *t = t.map(|v| new_index[&v]);
            }
        }
        UvAtlas {
            mesh: out,
            uvs,
            source_vertex,
            chart_of_triangle,
            charts: charts.len(),
            size,
            texels_per_unit: scale,
        }
    }

    /// Triangle `t`'s corners in texels (UV × size).
    pub fn texel_triangle(&self, t: usize) -> [DVec2; 3] {
        self.mesh.triangles[t]
            .map(|i| DVec2::from_array(self.uvs[i as usize]) * f64::from(self.size))
    }

    /// Per-vertex tangents `[x, y, z, w]` (module doc): unit, orthogonal to the vertex normal,
    /// w = ±1 the handedness. A vertex whose faces have no UV gradient gets any unit vector
    /// orthogonal to its normal.
    pub fn tangents(&self) -> Vec<[f64; 4]> {
        let n = self.mesh.vertices.len();
        let mut du = vec![DVec3::ZERO; n];
        let mut dv = vec![DVec3::ZERO; n];
        for (t, tri) in self.mesh.triangles.iter().enumerate() {
            let [p0, p1, p2] = self.mesh.triangle_corners(t);
            let [a, b, c] = tri.map(|i| DVec2::from_array(self.uvs[i as usize]));
            let (e1, e2) = (p1 - p0, p2 - p0);
            let (d1, d2) = (b - a, c - a);
            let det = d1.x * d2.y - d2.x * d1.y;
            if det.abs() < 1e-300 {
                continue;
            }
            // dP/du and dP/dv from the two edges; weighted by the face's UV area (|det|/2) through
            // the 1/det, so larger faces count more, as the area-weighted normals do.
            let sign = det.signum();
            let tu = (e1 * d2.y - e2 * d1.y) * sign;
            let tv = (e2 * d1.x - e1 * d2.x) * sign;
            for &i in tri {
                du[i as usize] += tu;
                dv[i as usize] += tv;
            }
        }
        (0..n)
            .map(|i| {
                let normal = DVec3::from_array(self.mesh.normals[i])
                    .try_normalize()
                    .unwrap_or(DVec3::Z);
                let tangent = (du[i] - normal * normal.dot(du[i]))
                    .try_normalize()
                    .unwrap_or_else(|| plane_basis(normal).0);
                let w = if normal.cross(tangent).dot(-dv[i]) < 0.0 {
                    -1.0
                } else {
                    1.0
                };
                [tangent.x, tangent.y, tangent.z, w]
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A torus (major radius 1, minor 0.35) of `rings` × `sides` quads: curved both ways, with a
    /// hole, so that no single projection covers it.
    fn torus(rings: u32, sides: u32) -> TriangleMesh {
        let mut mesh = TriangleMesh::default();
        for i in 0..rings {
            for j in 0..sides {
                let (a, b) = (
                    std::f64::consts::TAU * f64::from(i) / f64::from(rings),
                    std::f64::consts::TAU * f64::from(j) / f64::from(sides),
                );
                let r = 1.0 + 0.35 * b.cos();
                mesh.vertices
                    .push([r * a.cos(), r * a.sin(), 0.35 * b.sin()]);
            }
        }
        let index = |i: u32, j: u32| (i % rings) * sides + (j % sides);
        for i in 0..rings {
            for j in 0..sides {
                let (a, b, c, d) = (
                    index(i, j),
                    index(i + 1, j),
                    index(i + 1, j + 1),
                    index(i, j + 1),
                );
                mesh.triangles.push([a, b, c]);
                mesh.triangles.push([a, c, d]);
            }
        }
        mesh.compute_vertex_normals();
        mesh
    }

    /// Texels whose centre lies inside (or on the edge of) each triangle, by chart.
    fn covered_texels(atlas: &UvAtlas) -> HashMap<(u32, u32), u32> {
        let mut owner: HashMap<(u32, u32), u32> = HashMap::new();
        for t in 0..atlas.mesh.triangles.len() {
            let [a, b, c] = atlas.texel_triangle(t);
            let lo = a.min(b).min(c).floor();
            let hi = a.max(b).max(c).ceil();
            for y in lo.y as u32..hi.y as u32 {
                for x in lo.x as u32..hi.x as u32 {
                    let p = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                    let edge = |p0: DVec2, p1: DVec2| (p1 - p0).perp_dot(p - p0);
                    let (w0, w1, w2) = (edge(b, c), edge(c, a), edge(a, b));
                    let inside = (w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0)
                        || (w0 <= 0.0 && w1 <= 0.0 && w2 <= 0.0);
                    if inside {
                        let chart = atlas.chart_of_triangle[t];
                        let previous = owner.insert((x, y), chart);
                        assert!(
                            previous.is_none_or(|p| p == chart),
                            "texel ({x}, {y}) in charts {previous:?} and {chart}"
                        );
                    }
                }
            }
        }
        owner
    }

    #[test]
    fn charts_cover_every_triangle_without_overlapping() {
        let mesh = torus(48, 24);
        let params = AtlasParams {
            size: 512,
            ..AtlasParams::default()
        };
        let atlas = UvAtlas::build(&mesh, params);
        assert_eq!(atlas.mesh.triangles.len(), mesh.triangles.len());
        assert!(
            atlas.charts > 4 && atlas.charts < mesh.triangles.len() / 10,
            "{}",
            atlas.charts
        );
        // Every triangle is a copy of the source's, through the seam copies.
        for (t, tri) in atlas.mesh.triangles.iter().enumerate() {
            let back = tri.map(|i| atlas.source_vertex[i as usize]);
            assert_eq!(back, mesh.triangles[t]);
            for &i in tri {
                assert_eq!(
                    atlas.mesh.vertices[i as usize],
                    mesh.vertices[atlas.source_vertex[i as usize] as usize]
                );
            }
        }
        // A vertex copy belongs to one chart only.
        let mut chart_of_vertex = vec![u32::MAX; atlas.mesh.vertices.len()];
        for (t, tri) in atlas.mesh.triangles.iter().enumerate() {
            for &i in tri {
                let c = &mut chart_of_vertex[i as usize];
                assert!(*c == u32::MAX || *c == atlas.chart_of_triangle[t]);
                *c = atlas.chart_of_triangle[t];
            }
        }
        assert!(
            atlas.mesh.vertices.len() > mesh.vertices.len(),
            "seams duplicate vertices"
        );
        // UVs in [0, 1]; every triangle keeps its orientation and has area in the texture.
        assert!(atlas
            .uvs
            .iter()
            .flatten()
            .all(|&u| (0.0..=1.0).contains(&u)));
        for t in 0..atlas.mesh.triangles.len() {
            let [a, b, c] = atlas.texel_triangle(t);
            assert!(
                (b - a).perp_dot(c - a) > 0.0,
                "triangle {t} flipped or flat"
            );
        }
        // No two triangles overlap in UV (all pairs, by box first).
        let boxes: Vec<_> = (0..atlas.mesh.triangles.len())
            .map(|t| {
                let tri = atlas.texel_triangle(t);
                (
                    tri,
                    tri[0].min(tri[1]).min(tri[2]),
                    tri[0].max(tri[1]).max(tri[2]),
                )
            })
            .collect();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                let (a, alo, ahi) = &boxes[i];
                let (b, blo, bhi) = &boxes[j];
                if alo.cmpgt(*bhi).any() || blo.cmpgt(*ahi).any() {
                    continue;
                }
                assert!(
                    !triangles_overlap(a, b, 1e-9),
                    "triangles {i} and {j} overlap"
                );
            }
        }
        // Charts' texels are apart by the gutter: the texels of two charts never touch.
        let owner = covered_texels(&atlas);
        for (&(x, y), &chart) in &owner {
            for dy in -2i64..=2 {
                for dx in -2i64..=2 {
                    let neighbour = ((i64::from(x) + dx) as u32, (i64::from(y) + dy) as u32);
                    if let Some(&other) = owner.get(&neighbour) {
                        assert_eq!(other, chart, "charts {chart} and {other} within 2 texels");
                    }
                }
            }
        }
        // The packing uses the texture: the charts' texels cover a good part of it.
        let fill = owner.len() as f64 / f64::from(params.size * params.size);
        assert!(fill > 0.35, "fill {fill}");
        // Texel density: each texel covers about 1/scale² of the surface (the stretch of the
        // cone aside).
        let surface_texels = mesh.area() * atlas.texels_per_unit.powi(2);
        let ratio = owner.len() as f64 / surface_texels;
        assert!(
            ratio > 0.6 && ratio <= 1.05,
            "texels {} for {surface_texels}",
            owner.len()
        );
    }

    #[test]
    fn tangents_follow_the_texture_and_stay_orthogonal_to_the_normal() {
        let mesh = TriangleMesh::icosphere(DVec3::new(0.3, 0.0, -1.0), 2.0, 3);
        let atlas = UvAtlas::build(&mesh, AtlasParams::default());
        let tangents = atlas.tangents();
        assert_eq!(tangents.len(), atlas.mesh.vertices.len());
        for (t, tri) in atlas.mesh.triangles.iter().enumerate() {
            let [p0, p1, p2] = atlas.mesh.triangle_corners(t);
            let [a, b, c] = tri.map(|i| DVec2::from_array(atlas.uvs[i as usize]));
            // dP/du of this face from its own edges.
            let m = glam::DMat2::from_cols(b - a, c - a).inverse();
            let grad_u = (p1 - p0) * m.col(0).x + (p2 - p0) * m.col(0).y;
            let grad_v = (p1 - p0) * m.col(1).x + (p2 - p0) * m.col(1).y;
            for &i in tri {
                let [x, y, z, w] = tangents[i as usize];
                let tangent = DVec3::new(x, y, z);
                let normal = DVec3::from_array(atlas.mesh.normals[i as usize]);
                assert!((tangent.length() - 1.0).abs() < 1e-9);
                assert!(tangent.dot(normal).abs() < 1e-9);
                assert!(tangent.dot(grad_u.normalize()) > 0.9, "face {t}");
                // The bitangent points up the image (against v).
                let bitangent = normal.cross(tangent) * w;
                assert!(bitangent.dot(-grad_v.normalize()) > 0.9, "face {t}");
            }
        }
    }

    #[test]
    fn overlap_test_tells_touching_from_overlapping() {
        let a = [DVec2::ZERO, DVec2::X, DVec2::Y];
        let shared_edge = [DVec2::X, DVec2::ONE, DVec2::Y];
        let shared_corner = [DVec2::X, DVec2::new(2.0, 0.0), DVec2::new(2.0, 1.0)];
        let inside = [
            DVec2::splat(0.1),
            DVec2::new(0.3, 0.1),
            DVec2::new(0.1, 0.3),
        ];
        let crossing = [
            DVec2::new(0.4, -0.5),
            DVec2::new(0.6, -0.5),
            DVec2::new(0.5, 2.0),
        ];
        assert!(!triangles_overlap(&a, &shared_edge, 1e-12));
        assert!(!triangles_overlap(&a, &shared_corner, 1e-12));
        assert!(triangles_overlap(&a, &inside, 1e-12));
        assert!(triangles_overlap(&inside, &a, 1e-12));
        assert!(triangles_overlap(&a, &crossing, 1e-12));
    }
}

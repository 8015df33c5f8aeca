//! A UV atlas of a triangle mesh, for baking its materials into textures: the faces are grouped
//! into charts, each chart is projected flat, and the charts are packed side by side into one
//! square texture with a gutter of empty texels around each.
//!
//! - **Charts**: grown breadth-first from a seed face over shared edges, taking a face while its
//!   normal stays within [`AtlasParams::cone_deg`] of the seed's (the chart's axis) and its
//!   projection onto the plane normal to the axis overlaps none of the chart's faces so far. Every
//!   face therefore keeps its orientation in the plane (its normal is less than 90° from the axis),
//!   the stretch of a chart's texels is at most 1 / cos(cone) across it, and a chart never folds
//!   over itself. A chart whose faces cover less than half of its smallest box (a curved band,
//!   such as a tube's side seen from one direction) is cut across its longer side where that
//!   halves its area, each side's edge-connected parts becoming charts, until every chart covers
//!   half its box or has fewer than 8 faces: short pieces of a band pack closer than the band.
//! - **Seams**: a vertex shared by several charts is duplicated, one copy per chart
//!   ([`UvAtlas::source_vertex`] tells which vertex each copy came from).
//! - **Packing**: each chart is turned to the smallest of its bounding boxes over 32 angles and
//!   packed by its shape, not its box: its footprint is rasterized on a grid of texels (cells of
//!   2, 4, ... texels above 1024² textures) as the cells that come within half a gutter of its
//!   faces along both axes, and the footprints go, longest first, each in the best of its four
//!   quarter turns, to the first place from the texture's top-left corner (lowest row, then
//!   column) where they meet no cell taken before: charts interlock, and small ones fill the
//!   hollows of large ones. The scale (texels per scene unit) is the largest at which all fit,
//!   found by bisection. Two charts' faces are therefore at least [`AtlasParams::gutter`] texels
//!   apart along one axis or the other, and half as far from the texture's border. UVs are in
//!   [0, 1], glTF's convention: u to the right, v down the image, (0, 0) the first texel's corner.
//! - **Tangents** ([`UvAtlas::tangents`]): per vertex, the UV gradient of the position (dP/du)
//!   summed over its faces and made orthogonal to the normal, with the handedness glTF's `TANGENT`
//!   carries (the bitangent N × T · w points along −dP/dv, "up" in the image).
//!
//! Single-threaded: the charts grow one after another (a few hundred thousand faces a second); the
//! packing, about ten passes over the charts' footprints (one per scale tried), takes a few tenths
//! of a second for 7,000 faces on a 512² texture.

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
    /// Empty texels between two charts' faces (half of it at the texture's border).
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
    /// The faces' corners in the chart's plane, from the box's lower corner (scene units).
    triangles: Vec<[DVec2; 3]>,
    /// The faces' area in the chart's plane (scene units²).
    area: f64,
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

/// Charts that cover less than this share of their box are cut in two ([`split_chart`]).
const SPLIT_FILL: f64 = 0.5;

/// Charts of fewer faces are never cut.
const SPLIT_FACES: usize = 8;

/// The chart of faces `members` projected on the plane of `basis`, turned to its smallest box.
fn flatten(mesh: &TriangleMesh, members: Vec<u32>, (e1, e2): (DVec3, DVec3)) -> Chart {
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
    let at: HashMap<u32, DVec2> = vertices.iter().copied().collect();
    let triangles: Vec<[DVec2; 3]> = members
        .iter()
        .map(|&f| mesh.triangles[f as usize].map(|v| at[&v] - lo))
        .collect();
    let area = triangles
        .iter()
        .map(|[a, b, c]| 0.5 * (*b - *a).perp_dot(*c - *a).abs())
        .sum();
    Chart {
        faces: members,
        vertices,
        lo,
        extent: hi - lo,
        triangles,
        area,
    }
}

/// Adds the chart of faces `members` (on the plane of `basis`) to `charts`, cut first while it
/// covers less than [`SPLIT_FILL`] of its box: a curved band (a tube's side seen from one
/// direction) leaves most of its box empty, and its pieces pack closer. A cut runs across the
/// box's longer side where it halves the area, and each side's edge-connected parts go on as
/// charts of their own.
fn split_chart(
    mesh: &TriangleMesh,
    members: Vec<u32>,
    basis: (DVec3, DVec3),
    edge_faces: &HashMap<(u32, u32), Vec<u32>>,
    charts: &mut Vec<Chart>,
) {
    let chart = flatten(mesh, members, basis);
    let box_area = chart.extent.x * chart.extent.y;
    if chart.faces.len() < SPLIT_FACES || chart.area >= SPLIT_FILL * box_area {
        charts.push(chart);
        return;
    }
    let along = usize::from(chart.extent.y > chart.extent.x);
    let mut by_position: Vec<(f64, f64, u32)> = chart
        .triangles
        .iter()
        .zip(&chart.faces)
        .map(|(t, &f)| {
            let centre = (t[0] + t[1] + t[2]) / 3.0;
            let area = 0.5 * (t[1] - t[0]).perp_dot(t[2] - t[0]).abs();
            (centre[along], area, f)
        })
        .collect();
    by_position.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.2.cmp(&b.2)));
    let mut before = 0.0;
    let cut = by_position
        .iter()
        .position(|&(_, area, _)| {
            before += area;
            before >= 0.5 * chart.area
        })
        .unwrap_or(0)
        .clamp(1, by_position.len() - 1);
    for side in [&by_position[..cut], &by_position[cut..]] {
        let mut left: Vec<u32> = side.iter().map(|p| p.2).collect();
        left.sort_unstable();
        // Its edge-connected parts, each from its lowest face.
        while let Some(&seed) = left.first() {
            let mut part = vec![seed];
            let mut queue = VecDeque::from([seed]);
            left.remove(0);
            while let Some(face) = queue.pop_front() {
                let tri = mesh.triangles[face as usize];
                for k in 0..3 {
                    let (a, b) = (tri[k], tri[(k + 1) % 3]);
                    for next in &edge_faces[&(a.min(b), a.max(b))] {
                        if let Ok(i) = left.binary_search(next) {
                            left.remove(i);
                            part.push(*next);
                            queue.push_back(*next);
                        }
                    }
                }
            }
            split_chart(mesh, part, basis, edge_faces, charts);
        }
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
        let id = seed as u32;
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
        split_chart(mesh, members, (e1, e2), &edge_faces, &mut charts);
    }
    charts
}

/// Cells of the packing grid across the texture at most: a cell is one texel up to this size of
/// texture, and 2, 4, ... texels above it.
const PACK_GRID: u32 = 1024;

/// The range of y over the part of `tri` whose x lies in [`a`, `b`] (`None` when none does).
fn slice_range(tri: &[DVec2; 3], a: f64, b: f64) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..3 {
        let (p, q) = (tri[k], tri[(k + 1) % 3]);
        if (a..=b).contains(&p.x) {
            (lo, hi) = (lo.min(p.y), hi.max(p.y));
        }
        for line in [a, b] {
            if (p.x - line) * (q.x - line) < 0.0 {
                let y = p.y + (line - p.x) / (q.x - p.x) * (q.y - p.y);
                (lo, hi) = (lo.min(y), hi.max(y));
            }
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// A chart's footprint on the packing grid at one scale: the cells that come within half a gutter
/// of its faces along both axes (the faces grown by a square of that half-side), row by row.
struct Footprint {
    /// Its box (cells).
    width: u32,
    height: u32,
    /// Row-major, `width` × `height`.
    cells: Vec<bool>,
}

/// A footprint turned for packing: its box and, per row, its runs of cells (first, past the last).
struct Turned {
    width: u32,
    height: u32,
    runs: Vec<Vec<(u32, u32)>>,
    /// The row with the longest run, and that run's length.
    widest: (u32, u32),
    /// Every run as (row, first, past the last), longest first: the order to test them in.
    checks: Vec<(u32, u32, u32)>,
}

impl Footprint {
    /// The footprint of `chart` at `scale` texels per unit, its faces `margin` texels in from its
    /// box's corner (the texel coordinates [`Footprint::texel`] turns), on cells of `cell`
    /// texels; `None` when its box exceeds `grid` cells. A column of cells [x0, x1] meets a face
    /// grown by `margin` over the rows that the face's slice over [x0 − margin, x1 + margin]
    /// reaches, widened by `margin`.
    fn of(chart: &Chart, scale: f64, margin: f64, cell: f64, grid: u32) -> Option<Footprint> {
        let cells = |extent: f64| ((extent * scale + 2.0 * margin) / cell).ceil().max(1.0);
        let (width, height) = (cells(chart.extent.x), cells(chart.extent.y));
        if width > f64::from(grid) || height > f64::from(grid) {
            return None;
        }
        let (width, height) = (width as u32, height as u32);
        let mut occupied = vec![false; (width * height) as usize];
        for tri in &chart.triangles {
            let t = tri.map(|p| p * scale + DVec2::splat(margin));
            let lo = t[0].x.min(t[1].x).min(t[2].x);
            let hi = t[0].x.max(t[1].x).max(t[2].x);
            let first = ((lo - margin) / cell).floor().max(0.0) as u32;
            let last = (((hi + margin) / cell).ceil().max(0.0) as u32).min(width);
            for c in first..last {
                let x0 = f64::from(c) * cell - margin;
                if let Some((y0, y1)) = slice_range(&t, x0, x0 + cell + 2.0 * margin) {
                    let r0 = (((y0 - margin) / cell).floor().max(0.0) as u32).min(height - 1);
                    let r1 = (((y1 + margin) / cell).ceil().max(0.0) as u32).clamp(r0 + 1, height);
                    for r in r0..r1 {
                        occupied[(r * width + c) as usize] = true;
                    }
                }
            }
        }
        Some(Footprint {
            width,
            height,
            cells: occupied,
        })
    }

    /// The footprint turned by `turn` quarter turns ((x, y) to (−y, x) each, shifted back into the
    /// box; as [`Footprint::texel`] turns a point).
    fn turned(&self, turn: u8) -> Turned {
        let (w, h) = (self.width, self.height);
        let (tw, th) = if turn.is_multiple_of(2) {
            (w, h)
        } else {
            (h, w)
        };
        // The unturned cell under turned cell (x, y).
        let source = |x: u32, y: u32| match turn % 4 {
            0 => (x, y),
            1 => (y, h - 1 - x),
            2 => (w - 1 - x, h - 1 - y),
            _ => (w - 1 - y, x),
        };
        let runs = (0..th)
            .map(|y| {
                let mut runs: Vec<(u32, u32)> = Vec::new();
                for x in 0..tw {
                    let (sx, sy) = source(x, y);
                    if !self.cells[(sy * w + sx) as usize] {
                        continue;
                    }
                    match runs.last_mut() {
                        Some(run) if run.1 == x => run.1 = x + 1,
                        _ => runs.push((x, x + 1)),
                    }
                }
                runs
            })
            .collect::<Vec<_>>();
        let widest = runs
            .iter()
            .enumerate()
            .map(|(y, r)| (y as u32, r.iter().map(|(a, b)| b - a).max().unwrap_or(0)))
            .fold((0, 0), |best, row| if row.1 > best.1 { row } else { best });
        let mut checks: Vec<(u32, u32, u32)> = runs
            .iter()
            .enumerate()
            .flat_map(|(y, r)| r.iter().map(move |&(a, b)| (y as u32, a, b)))
            .collect();
        checks.sort_by_key(|&(y, a, b)| (std::cmp::Reverse(b - a), y, a));
        Turned {
            width: tw,
            height: th,
            runs,
            widest,
            checks,
        }
    }

    /// A point `q` of the unturned footprint (texels from its box's corner) once turned by `turn`
    /// quarter turns; `cell`: the side of a cell (texels).
    fn texel(&self, q: DVec2, turn: u8, cell: f64) -> DVec2 {
        let (w, h) = (f64::from(self.width) * cell, f64::from(self.height) * cell);
        match turn % 4 {
            0 => q,
            1 => DVec2::new(h - q.y, q.x),
            2 => DVec2::new(w - q.x, h - q.y),
            _ => DVec2::new(q.y, w - q.x),
        }
    }
}

/// The packing grid's cells, per row: for a free cell the number of free cells from it to the
/// next taken one (or the row's end), for a taken cell minus the number of taken ones likewise.
struct Occupancy {
    side: u32,
    runs: Vec<i32>,
    /// Per row, its longest free run.
    longest: Vec<u32>,
}

impl Occupancy {
    fn new(side: u32) -> Occupancy {
        let mut grid = Occupancy {
            side,
            runs: vec![0; (side * side) as usize],
            longest: vec![0; side as usize],
        };
        for y in 0..side {
            grid.recount(y);
        }
        grid
    }

    fn row(&mut self, y: u32) -> &mut [i32] {
        let side = self.side as usize;
        &mut self.runs[y as usize * side..(y as usize + 1) * side]
    }

    /// Recounts row `y`'s runs from which of its cells are taken (negative) or free.
    fn recount(&mut self, y: u32) {
        let row = self.row(y);
        let (mut next, mut longest) = (0i32, 0i32);
        for v in row.iter_mut().rev() {
            let taken = *v < 0;
            next = match (taken, next) {
                (false, n) if n > 0 => n + 1,
                (false, _) => 1,
                (true, n) if n < 0 => n - 1,
                (true, _) => -1,
            };
            *v = next;
            longest = longest.max(next);
        }
        self.longest[y as usize] = longest as u32;
    }

    /// Where the first cell of `shape` at column `x`, row `y` that is taken or lacks room lies,
    /// as the columns to move right before it can fit (0: it fits).
    fn shift_to_fit(&self, shape: &Turned, x: u32, y: u32) -> u32 {
        let side = self.side as usize;
        for &(i, a, b) in &shape.checks {
            let row = (y + i) as usize * side;
            let at = (x + a) as usize;
            let v = self.runs[row + at];
            if v >= (b - a) as i32 {
                continue;
            }
            // The run must start past the taken cells that end or start here.
            let free = v.max(0) as usize;
            let taken = at + free;
            let skip = if taken < side {
                (-self.runs[row + taken]).max(1) as usize
            } else {
                1
            };
            return (free + skip) as u32;
        }
        0
    }

    /// The first place (lowest row, then leftmost column) where `shape` fits, in rows up to
    /// `rows` (exclusive).
    fn first_fit(&self, shape: &Turned, rows: u32) -> Option<(u32, u32)> {
        if shape.width > self.side || shape.height > self.side {
            return None;
        }
        let (widest_row, widest) = shape.widest;
        for y in 0..rows.min(self.side - shape.height + 1) {
            if self.longest[(y + widest_row) as usize] < widest {
                continue;
            }
            let mut x = 0;
            while x + shape.width <= self.side {
                match self.shift_to_fit(shape, x, y) {
                    0 => return Some((x, y)),
                    shift => x += shift,
                }
            }
        }
        None
    }

    fn take(&mut self, shape: &Turned, x: u32, y: u32) {
        for (i, runs) in shape.runs.iter().enumerate() {
            let row_y = y + i as u32;
            let row = self.row(row_y);
            for &(a, b) in runs {
                for v in &mut row[(x + a) as usize..(x + b) as usize] {
                    *v = -1;
                }
            }
            self.recount(row_y);
        }
    }
}

/// Where a chart goes: the corner of its turned footprint (cells), its quarter turns, its
/// footprint.
struct Placement {
    corner: (u32, u32),
    turn: u8,
    footprint: Footprint,
}

/// The placement of each chart at `scale` texels per unit on a `grid` × `grid` grid of cells of
/// `cell` texels, charts `2 margin` texels apart and `margin` from the border, or `None` when they
/// do not fit. `order`: the charts, largest first. Each chart's footprint (its faces grown by
/// `margin`, rasterized), in each of its four quarter turns, goes to the first place from the
/// top-left (lowest row, then column) where it meets no cell taken so far: charts interlock by
/// their shapes, and small ones fill the hollows of large ones.
fn pack(
    charts: &[Chart],
    order: &[usize],
    scale: f64,
    grid: u32,
    cell: f64,
    margin: f64,
) -> Option<Vec<Placement>> {
    let mut occupancy = Occupancy::new(grid);
    let mut placements: Vec<Option<Placement>> = (0..charts.len()).map(|_| None).collect();
    for &c in order {
        let footprint = Footprint::of(&charts[c], scale, margin, cell, grid)?;
        let mut best: Option<((u32, u32), u8, Turned)> = None;
        for turn in 0..4u8 {
            let shape = footprint.turned(turn);
            let rows = best.as_ref().map_or(grid, |b| b.0 .1 + 1);
            if let Some((x, y)) = occupancy.first_fit(&shape, rows) {
                if best.as_ref().is_none_or(|b| (y, x) < (b.0 .1, b.0 .0)) {
                    best = Some(((x, y), turn, shape));
                }
            }
        }
        let (corner, turn, shape) = best?;
        occupancy.take(&shape, corner.0, corner.1);
        placements[c] = Some(Placement {
            corner,
            turn,
            footprint,
        });
    }
    Some(placements.into_iter().map(|p| p.expect("placed")).collect())
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
        let cell = (size / PACK_GRID).max(1);
        let grid = size / cell;
        let cell = f64::from(cell);
        let margin = f64::from(gutter) / 2.0;
        // Largest first: by the longer side of the box, then by area.
        let mut order: Vec<usize> = (0..charts.len()).collect();
        order.sort_by(|&a, &b| {
            let key = |c: &Chart| (c.extent.max_element(), c.area);
            let (ka, kb) = (key(&charts[a]), key(&charts[b]));
            kb.0.total_cmp(&ka.0).then(kb.1.total_cmp(&ka.1))
        });
        // The scale: at most the one at which the charts' faces alone would fill the texture;
        // from three quarters of it, lowered by 0.85 until the charts fit, then bisected to 0.4 %
        // (a packing that fits at one scale almost always fits at any smaller one).
        let area: f64 = charts.iter().map(|c| c.area).sum();
        let mut high = f64::from(size) / area.sqrt().max(1e-12);
        let mut low = high * 0.75;
        let mut placed = None;
        for _ in 0..400 {
            if let Some(fit) = pack(&charts, &order, low, grid, cell, margin) {
                placed = Some(fit);
                break;
            }
            high = low;
            low *= 0.85;
        }
        while placed.is_some() && high > low * 1.004 {
            let mid = 0.5 * (low + high);
            match pack(&charts, &order, mid, grid, cell, margin) {
                Some(fit) => {
                    low = mid;
                    placed = Some(fit);
                }
                None => high = mid,
            }
        }
        let scale = low;
        tracing::debug!(
            charts = charts.len(),
            texels_per_unit = scale,
            faces_share = area * scale * scale / f64::from(size).powi(2),
            "charts packed"
        );

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
        for (id, chart) in charts.iter().enumerate() {
            let mut new_index: HashMap<u32, u32> = HashMap::with_capacity(chart.vertices.len());
            let place = placed.as_ref().map(|p| &p[id]);
            for &(v, p) in &chart.vertices {
                new_index.insert(v, out.vertices.len() as u32);
                out.vertices.push(mesh.vertices[v as usize]);
                out.normals.push(source_mesh_normals[v as usize]);
                let q = (p - chart.lo) * scale + DVec2::splat(margin);
                let texel = place.map_or(q, |place| {
                    let (x, y) = place.corner;
                    DVec2::new(f64::from(x), f64::from(y)) * cell
                        + place.footprint.texel(q, place.turn, cell)
                });
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

    /// Two triangles per quad of `mesh`'s vertices laid out as `rings` rings of `sides`, closed
    /// both ways (the last ring joins the first, the last side each ring's first), then normals.
    fn close_ring_grid(mesh: &mut TriangleMesh, rings: u32, sides: u32) {
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
    }

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
        close_ring_grid(&mut mesh, rings, sides);
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

    /// A tube of radius 0.3 around a (2, 3) torus knot, `rings` × `sides` quads: a long band that
    /// curls through space, like the shared `knot` capture.
    fn torus_knot(rings: u32, sides: u32) -> TriangleMesh {
        let centre = |t: f64| {
            let r = 2.0 + (3.0 * t).cos();
            DVec3::new(r * (2.0 * t).cos(), r * (2.0 * t).sin(), -(3.0 * t).sin())
        };
        let mut mesh = TriangleMesh::default();
        for i in 0..rings {
            let t = std::f64::consts::TAU * f64::from(i) / f64::from(rings);
            let h = 1e-4;
            let tangent = (centre(t + h) - centre(t - h)).normalize();
            let bend = centre(t + h) + centre(t - h) - 2.0 * centre(t);
            let normal = (bend - tangent * tangent.dot(bend)).normalize();
            let binormal = tangent.cross(normal);
            for j in 0..sides {
                let a = std::f64::consts::TAU * f64::from(j) / f64::from(sides);
                let p = centre(t) + 0.3 * (normal * a.cos() + binormal * a.sin());
                mesh.vertices.push(p.to_array());
            }
        }
        close_ring_grid(&mut mesh, rings, sides);
        mesh
    }

    /// The share of the texture whose texels lie in a triangle, after checking that no texel
    /// lies in two charts and that no two charts' texels come closer than `gutter` texels along
    /// both axes.
    fn checked_fill(atlas: &UvAtlas, gutter: u32) -> f64 {
        let owner = covered_texels(atlas);
        let size = i64::from(atlas.size);
        let mut chart_at = vec![u32::MAX; (size * size) as usize];
        for (&(x, y), &chart) in &owner {
            chart_at[(i64::from(y) * size + i64::from(x)) as usize] = chart;
        }
        let reach = i64::from(gutter) - 1;
        for (&(x, y), &chart) in &owner {
            let (x, y) = (i64::from(x), i64::from(y));
            for ny in (y - reach).max(0)..=(y + reach).min(size - 1) {
                for nx in (x - reach).max(0)..=(x + reach).min(size - 1) {
                    let other = chart_at[(ny * size + nx) as usize];
                    assert!(
                        other == u32::MAX || other == chart,
                        "charts {chart} and {other} at ({x}, {y}) and ({nx}, {ny})"
                    );
                }
            }
        }
        owner.len() as f64 / (size * size) as f64
    }

    #[test]
    fn charts_packed_by_their_shape_cover_half_the_texture() {
        // A knot's charts are curved bands: cut into shorter pieces and interlocked by their
        // shapes, their faces cover half the texture.
        let knot = torus_knot(240, 12);
        let atlas = UvAtlas::build(
            &knot,
            AtlasParams {
                size: 512,
                gutter: 4,
                ..AtlasParams::default()
            },
        );
        let fill = checked_fill(&atlas, 4);
        assert!(fill > 0.45, "knot fill {fill}");
        for (mesh, size, gutter, least) in [
            (torus(48, 24), 512, 4, 0.55),
            (TriangleMesh::icosphere(DVec3::ZERO, 1.0, 3), 256, 4, 0.5),
            (TriangleMesh::icosphere(DVec3::ZERO, 1.0, 4), 1024, 8, 0.55),
        ] {
            let atlas = UvAtlas::build(
                &mesh,
                AtlasParams {
                    size,
                    gutter,
                    ..AtlasParams::default()
                },
            );
            let fill = checked_fill(&atlas, gutter);
            assert!(fill > least, "fill {fill} at {size}");
        }
    }

    #[test]
    fn a_turned_footprint_holds_its_turned_chart() {
        // An L of two triangles: every turn of its footprint holds the faces turned the same way.
        let corners = [
            DVec2::new(0.0, 0.0),
            DVec2::new(3.0, 0.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(0.0, 3.0),
        ];
        let chart = Chart {
            faces: vec![0, 1],
            vertices: Vec::new(),
            lo: DVec2::ZERO,
            extent: DVec2::splat(3.0),
            triangles: vec![
                [corners[0], corners[1], corners[2]],
                [corners[0], corners[2], corners[3]],
            ],
            area: 3.0,
        };
        let (scale, margin, cell) = (5.0, 1.5, 2.0);
        let footprint = Footprint::of(&chart, scale, margin, cell, 64).unwrap();
        let count = |shape: &Turned| shape.runs.iter().flatten().map(|r| r.1 - r.0).sum::<u32>();
        let unturned = count(&footprint.turned(0));
        assert!(
            unturned < footprint.width * footprint.height,
            "an L, not its box"
        );
        for turn in 0..4 {
            let shape = footprint.turned(turn);
            assert_eq!(count(&shape), unturned, "turn {turn}");
            let taken = |x: f64, y: f64| {
                let (cx, cy) = ((x / cell).floor() as u32, (y / cell).floor() as u32);
                shape.runs[cy as usize]
                    .iter()
                    .any(|&(a, b)| (a..b).contains(&cx))
            };
            // Points of the faces, and points half a gutter off them, lie in taken cells.
            for tri in &chart.triangles {
                for (u, v) in [
                    (0.2, 0.2),
                    (0.6, 0.2),
                    (0.2, 0.6),
                    (0.33, 0.33),
                    (0.01, 0.01),
                ] {
                    let p = tri[0] + (tri[1] - tri[0]) * u + (tri[2] - tri[0]) * v;
                    let q = p * scale + DVec2::splat(margin);
                    for d in [
                        DVec2::ZERO,
                        DVec2::splat(0.99 * margin),
                        -DVec2::splat(0.99 * margin),
                    ] {
                        let t = footprint.texel(q + d, turn, cell);
                        assert!(taken(t.x, t.y), "turn {turn}: {p} + {d} at {t}");
                    }
                }
            }
        }
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

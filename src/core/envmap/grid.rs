//! Geometry of one cube resolution: texel directions, exact texel solid angles, a border table that
//! makes bilinear lookups seamless across faces, and 8×8 texel blocks with bounding cones used to
//! cull lobe convolutions. Built once per resolution and shared (read-only) between threads.

use glam::DVec3;

use super::{dir_to_face_uv_with_grad, face_uv_to_dir, texel_dir, texel_solid_angle, NUM_FACES};

/// Edge length of the culling blocks, in texels.
const BLOCK: usize = 8;

/// A square block of texels of one face, with a cone bounding their directions.
#[derive(Clone, Debug)]
pub struct TexelBlock {
    /// Unit axis of the bounding cone.
    pub center: DVec3,
    /// Half-angle of the bounding cone, radians.
    pub radius: f64,
    /// Range into [`CubeGrid::block_texels`] / [`CubeGrid::block_dirs`].
    pub start: usize,
    pub end: usize,
}

/// One bilinear tap: flat texel index and its weight.
pub type Tap = (usize, f64);

/// The derivatives of one RGB lookup of a (prefiltered) map in its inputs: a direction (or
/// normal) and one scalar (roughness or IoR).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LookupJacobian {
    /// `d_dir[i]` = ∂value/∂dir_i (one RGB vector per input component).
    pub d_dir: [DVec3; 3],
    /// ∂value/∂scalar.
    pub d_scalar: DVec3,
}

impl LookupJacobian {
    /// (dL/d dir, dL/d scalar) for an upstream dL/d value.
    pub fn backward(&self, grad_out: DVec3) -> (DVec3, f64) {
        let [x, y, z] = self.d_dir;
        (
            DVec3::new(x.dot(grad_out), y.dot(grad_out), z.dot(grad_out)),
            self.d_scalar.dot(grad_out),
        )
    }
}

/// Texel geometry of a D×D cube map.
#[derive(Clone, Debug)]
pub struct CubeGrid {
    pub size: usize,
    /// Unit direction of each texel centre (flat texel index = (face · D + y) · D + x).
    pub dirs: Vec<DVec3>,
    /// Solid angle of each texel, steradians.
    pub solid_angle: Vec<f64>,
    /// For padded coordinates (x, y) ∈ [−1, D]² of each face, the flat index of the texel that
    /// continues the face across its border (the nearest texel centre of the neighbouring face).
    border: Vec<u32>,
    pub blocks: Vec<TexelBlock>,
    /// Texel indices, grouped by block.
    pub block_texels: Vec<u32>,
    /// Directions of `block_texels` (contiguous, for cache-friendly convolution loops).
    pub block_dirs: Vec<DVec3>,
}

impl CubeGrid {
    /// Builds the geometry of a D×D cube (D ≥ 1).
    pub fn new(size: usize) -> Self {
        assert!(size >= 1, "cube size must be positive");
        let n = NUM_FACES * size * size;
        let mut dirs = Vec::with_capacity(n);
        let mut solid_angle = Vec::with_capacity(n);
        for face in 0..NUM_FACES {
            for y in 0..size {
                for x in 0..size {
                    dirs.push(texel_dir(size, face, x, y));
                    solid_angle.push(texel_solid_angle(size, x, y));
                }
            }
        }
        let padded = size + 2;
        let mut border = Vec::with_capacity(NUM_FACES * padded * padded);
        for face in 0..NUM_FACES {
            for py in 0..padded {
                for px in 0..padded {
                    let (x, y) = (px as isize - 1, py as isize - 1);
                    let inside = |c: isize| (0..size as isize).contains(&c);
                    let index = if inside(x) && inside(y) {
                        (face * size + y as usize) * size + x as usize
                    } else {
                        let u = 2.0 * (x as f64 + 0.5) / size as f64 - 1.0;
                        let v = 2.0 * (y as f64 + 0.5) / size as f64 - 1.0;
                        nearest_texel(size, face_uv_to_dir(face, u, v))
                    };
                    border.push(index as u32);
                }
            }
        }
        let mut blocks = Vec::new();
        let mut block_texels = Vec::with_capacity(n);
        let mut block_dirs = Vec::with_capacity(n);
        for face in 0..NUM_FACES {
            for by in (0..size).step_by(BLOCK) {
                for bx in (0..size).step_by(BLOCK) {
                    let start = block_texels.len();
                    let mut sum = DVec3::ZERO;
                    for y in by..(by + BLOCK).min(size) {
                        for x in bx..(bx + BLOCK).min(size) {
                            let t = (face * size + y) * size + x;
                            block_texels.push(t as u32);
                            block_dirs.push(dirs[t]);
                            sum += dirs[t];
                        }
                    }
                    let end = block_texels.len();
                    let center = sum.normalize();
                    let min_cos = block_dirs[start..end]
                        .iter()
                        .map(|d| d.dot(center))
                        .fold(1.0f64, f64::min);
                    // Slack for rounding so no texel is ever culled wrongly.
                    let radius = min_cos.clamp(-1.0, 1.0).acos() + 1e-9;
                    blocks.push(TexelBlock {
                        center,
                        radius,
                        start,
                        end,
                    });
                }
            }
        }
        CubeGrid {
            size,
            dirs,
            solid_angle,
            border,
            blocks,
            block_texels,
            block_dirs,
        }
    }

    /// Number of texels (6 · D²).
    pub fn num_texels(&self) -> usize {
        self.dirs.len()
    }

    /// The border table: for each face and padded coordinates (x, y) ∈ [−1, D]², at
    /// `(face · (D + 2) + y + 1) · (D + 2) + x + 1`, the flat index of the texel there (across a
    /// face edge, the nearest texel of the neighbouring face). The gpu shader's lookups read it.
    pub fn border_table(&self) -> &[u32] {
        &self.border
    }

    fn padded_index(&self, face: usize, x: isize, y: isize) -> usize {
        let p = self.size + 2;
        self.border[(face * p + (y + 1) as usize) * p + (x + 1) as usize] as usize
    }

    /// The four bilinear taps of a lookup along `dir` (non-zero, need not be unit), plus the
    /// gradient of each tap weight with respect to `dir`.
    pub fn taps_with_grad(&self, dir: DVec3) -> ([Tap; 4], [DVec3; 4]) {
        self.taps_at(&CubePoint::of(dir))
    }

    /// [`Self::taps_with_grad`] at a direction already placed on the cube (for lookups of one
    /// direction in several grids: the levels of a mip chain).
    #[inline]
    pub fn taps_at(&self, point: &CubePoint) -> ([Tap; 4], [DVec3; 4]) {
        let CubePoint { face, u, v, du, dv } = *point;
        let s = self.size as f64;
        // Continuous texel coordinates; texel x has its centre at x.
        let cx = (u + 1.0) * 0.5 * s - 0.5;
        let cy = (v + 1.0) * 0.5 * s - 0.5;
        let (dcx, dcy) = (du * 0.5 * s, dv * 0.5 * s);
        let max = self.size as f64 - 0.5;
        let cx = cx.clamp(-0.5, max);
        let cy = cy.clamp(-0.5, max);
        let x0 = (cx.floor() as isize).min(self.size as isize - 1);
        let y0 = (cy.floor() as isize).min(self.size as isize - 1);
        let fx = cx - x0 as f64;
        let fy = cy - y0 as f64;
        let taps = [
            (self.padded_index(face, x0, y0), (1.0 - fx) * (1.0 - fy)),
            (self.padded_index(face, x0 + 1, y0), fx * (1.0 - fy)),
            (self.padded_index(face, x0, y0 + 1), (1.0 - fx) * fy),
            (self.padded_index(face, x0 + 1, y0 + 1), fx * fy),
        ];
        let grads = [
            -dcx * (1.0 - fy) - dcy * (1.0 - fx),
            dcx * (1.0 - fy) - dcy * fx,
            -dcx * fy + dcy * (1.0 - fx),
            dcx * fy + dcy * fx,
        ];
        (taps, grads)
    }

    /// Bilinear lookup of an RGB texel buffer (`values[t · 3 + c]`).
    pub fn sample(&self, values: &[f64], dir: DVec3) -> DVec3 {
        self.sample_at(values, &CubePoint::of(dir))
    }

    /// [`Self::sample`] at a direction already placed on the cube.
    #[inline]
    pub fn sample_at(&self, values: &[f64], point: &CubePoint) -> DVec3 {
        // Inlined, so the tap gradients nobody reads are not computed.
        self.taps_at(point)
            .0
            .iter()
            .map(|&(t, w)| w * rgb(values, t))
            .sum()
    }
}

/// Where a direction meets the cube: its face and face coordinates `(u, v)` ∈ [−1, 1]², with
/// their gradients in the direction ([`dir_to_face_uv_with_grad`]); the same for every face size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CubePoint {
    pub face: usize,
    pub u: f64,
    pub v: f64,
    pub du: DVec3,
    pub dv: DVec3,
}

impl CubePoint {
    /// The point of `dir` (non-zero, need not be unit).
    #[inline]
    pub fn of(dir: DVec3) -> Self {
        let (face, du, dv, u, v) = dir_to_face_uv_with_grad(dir);
        CubePoint { face, u, v, du, dv }
    }
}

/// RGB triple of texel `t` in an interleaved buffer.
pub fn rgb(values: &[f64], t: usize) -> DVec3 {
    DVec3::new(values[t * 3], values[t * 3 + 1], values[t * 3 + 2])
}

/// Adds `v` into texel `t` of an interleaved RGB buffer.
pub fn add_rgb(values: &mut [f64], t: usize, v: DVec3) {
    values[t * 3] += v.x;
    values[t * 3 + 1] += v.y;
    values[t * 3 + 2] += v.z;
}

/// Flat index of the texel whose centre is nearest to where `dir` hits the cube.
fn nearest_texel(size: usize, dir: DVec3) -> usize {
    let (face, _, _, u, v) = dir_to_face_uv_with_grad(dir);
    let s = size as f64;
    let clamp = |c: f64| ((c + 1.0) * 0.5 * s).floor().clamp(0.0, s - 1.0) as usize;
    (face * size + clamp(v)) * size + clamp(u)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_dir(rng: &mut ChaCha8Rng) -> DVec3 {
        DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
    }

    #[test]
    fn bilinear_reproduces_texel_centres_and_is_seamless() {
        let grid = CubeGrid::new(8);
        // A linear function of the direction sampled at texel centres.
        let f = |d: DVec3| DVec3::new(1.0 + d.x, 2.0 + d.y, 3.0 + d.z);
        let values: Vec<f64> = grid.dirs.iter().flat_map(|&d| f(d).to_array()).collect();
        for t in [0, 17, 100, 383] {
            assert!(grid
                .sample(&values, grid.dirs[t])
                .abs_diff_eq(f(grid.dirs[t]), 1e-12));
        }
        // Across a face edge the lookup is continuous.
        let edge = DVec3::new(1.0, 0.3, 1.0);
        let a = grid.sample(&values, edge + DVec3::new(1e-9, 0.0, 0.0));
        let b = grid.sample(&values, edge + DVec3::new(0.0, 0.0, 1e-9));
        assert!(a.abs_diff_eq(b, 1e-6), "{a} vs {b}");
        // Everywhere, the interpolant stays close to the smooth function.
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for _ in 0..500 {
            let d = random_dir(&mut rng).normalize();
            let err = (grid.sample(&values, d) - f(d)).abs().max_element();
            assert!(err < 0.03, "{d}: {err}");
        }
    }

    #[test]
    fn tap_weight_gradients_match_finite_differences() {
        let grid = CubeGrid::new(6);
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let values: Vec<f64> = (0..grid.num_texels() * 3).map(|_| rng.random()).collect();
        for _ in 0..40 {
            let d = random_dir(&mut rng);
            let g = DVec3::new(0.3, -1.0, 0.7);
            let (taps, grads) = grid.taps_with_grad(d);
            let analytic: DVec3 = taps
                .iter()
                .zip(grads)
                .map(|(&(t, _), dw)| dw * rgb(&values, t).dot(g))
                .sum();
            let mut f = |x: &[f64]| grid.sample(&values, DVec3::from_slice(x)).dot(g);
            crate::core::gradcheck::assert_gradient(
                "cube lookup d/ddir",
                &mut f,
                &d.to_array(),
                &analytic.to_array(),
                1e-7,
                1e-5,
                1e-6,
            );
        }
    }

    #[test]
    fn blocks_bound_their_texels() {
        let grid = CubeGrid::new(20);
        assert_eq!(grid.block_texels.len(), grid.num_texels());
        for b in &grid.blocks {
            for d in &grid.block_dirs[b.start..b.end] {
                assert!(d.dot(b.center).clamp(-1.0, 1.0).acos() <= b.radius);
            }
        }
    }
}

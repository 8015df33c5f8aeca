//! The 48 symmetries of the cube (the signed permutations of the axes) acting on the texels of a
//! D×D cube grid, and the orbits they split the texels into.
//!
//! A symmetry g maps every texel centre onto a texel centre: on face coordinates the centres are
//! the odd multiples of 1/D, so in units of 1/D a texel of face f is the integer vector with ±D on
//! f's major axis and odd values in (−D, D) on the other two, and a signed permutation of that
//! vector is again such a vector. The action is computed on those integers, exactly.
//!
//! A kernel that depends only on the angle between two directions is invariant under all of them:
//! `k(g·o, t) = k(o, g⁻¹·t)`. One row of weights per orbit, the row of its representative, is
//! then the whole kernel (a 48th of it): [`OrbitKernel`] in the prefilter uses this.
//!
//! Threading: none; built once per grid size (a few milliseconds at D = 64) and read-only after.

use super::{FACES, NUM_FACES};

/// Number of symmetries of the cube: 3! axis permutations × 2³ signs.
pub const NUM_SYMMETRIES: usize = 48;

/// The symmetries' action on the texels of one cube size, with one representative per orbit.
#[derive(Clone, Debug)]
pub struct CubeSymmetry {
    /// `image[g · n + t]`: the texel g maps texel t onto (n texels).
    image: Vec<u32>,
    /// The representative of each orbit: its smallest texel index, ascending.
    pub representatives: Vec<u32>,
    /// Per texel: the index into `representatives` of its orbit and the first symmetry g (lowest
    /// index) that maps that representative onto it.
    pub owner: Vec<(u32, u8)>,
}

impl CubeSymmetry {
    /// The action on a D×D cube's texels (flat index `(face · D + y) · D + x`).
    pub fn new(size: usize) -> Self {
        let n = NUM_FACES * size * size;
        let mut image = Vec::with_capacity(NUM_SYMMETRIES * n);
        for g in 0..NUM_SYMMETRIES {
            image.extend((0..n).map(|t| apply(g, size, t) as u32));
        }
        let mut representatives = Vec::new();
        let mut owner = vec![(0u32, 0u8); n];
        let mut assigned = vec![false; n];
        for t in 0..n {
            if assigned[t] {
                continue;
            }
            // Texels are visited in ascending order, so `t` is the smallest of its orbit.
            let orbit = representatives.len() as u32;
            representatives.push(t as u32);
            for g in 0..NUM_SYMMETRIES {
                let o = image[g * n + t] as usize;
                if !assigned[o] {
                    assigned[o] = true;
                    owner[o] = (orbit, g as u8);
                }
            }
        }
        CubeSymmetry {
            image,
            representatives,
            owner,
        }
    }

    /// The texel that symmetry `g` maps texel `t` onto.
    pub fn image(&self, g: usize, t: usize) -> usize {
        self.image[g * self.owner.len() + t] as usize
    }
}

/// Symmetry `g`: the axis permutation `g / 8` (of the six) and the sign flips in the bits of `g % 8`.
fn signed_permutation(g: usize) -> ([usize; 3], [i64; 3]) {
    const PERMUTATIONS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let signs = std::array::from_fn(|i| if g & (1 << i) == 0 { 1 } else { -1 });
    (PERMUTATIONS[g / 8], signs)
}

/// Texel `t`'s centre as an integer vector in units of 1/D (see the module docs).
fn texel_vector(size: usize, t: usize) -> [i64; 3] {
    let d = size as i64;
    let (face, rest) = (t / (size * size), t % (size * size));
    let (x, y) = ((rest % size) as i64, (rest / size) as i64);
    let axes = FACES[face];
    let mut v = [0i64; 3];
    v[axes.major] = axes.major_sign as i64 * d;
    v[axes.u_axis] = axes.u_sign as i64 * (2 * x + 1 - d);
    v[axes.v_axis] = axes.v_sign as i64 * (2 * y + 1 - d);
    v
}

/// The texel whose centre is the integer vector `v` (one component ±D, the others odd in (−D, D)).
fn texel_of_vector(size: usize, v: [i64; 3]) -> usize {
    let d = size as i64;
    let face = (0..NUM_FACES)
        .find(|&f| v[FACES[f].major] == FACES[f].major_sign as i64 * d)
        .expect("a texel centre lies on exactly one face");
    let axes = FACES[face];
    let x = (axes.u_sign as i64 * v[axes.u_axis] + d - 1) / 2;
    let y = (axes.v_sign as i64 * v[axes.v_axis] + d - 1) / 2;
    (face * size + y as usize) * size + x as usize
}

/// The texel symmetry `g` maps texel `t` of a D×D cube onto.
fn apply(g: usize, size: usize, t: usize) -> usize {
    let (perm, signs) = signed_permutation(g);
    let v = texel_vector(size, t);
    let w = std::array::from_fn(|i| signs[i] * v[perm[i]]);
    texel_of_vector(size, w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::envmap::texel_dir;
    use glam::DVec3;

    /// The signed permutation `g` applied to a direction.
    fn rotate(g: usize, d: DVec3) -> DVec3 {
        let (perm, signs) = signed_permutation(g);
        let a = d.to_array();
        DVec3::from_array(std::array::from_fn(|i| signs[i] as f64 * a[perm[i]]))
    }

    #[test]
    fn every_symmetry_maps_texel_centres_onto_texel_centres() {
        for size in [1, 2, 3, 8] {
            let sym = CubeSymmetry::new(size);
            let n = NUM_FACES * size * size;
            let dir = |t: usize| {
                let (face, rest) = (t / (size * size), t % (size * size));
                texel_dir(size, face, rest % size, rest / size)
            };
            for g in 0..NUM_SYMMETRIES {
                let mut hit = vec![false; n];
                for t in 0..n {
                    let o = sym.image(g, t);
                    assert!(
                        rotate(g, dir(t)).abs_diff_eq(dir(o), 1e-12),
                        "size {size}, g {g}, texel {t} -> {o}"
                    );
                    hit[o] = true;
                }
                assert!(
                    hit.iter().all(|&h| h),
                    "g {g} is a permutation of the texels"
                );
            }
        }
    }

    #[test]
    fn the_orbits_partition_the_texels_and_owners_map_back() {
        for size in [2, 3, 16] {
            let sym = CubeSymmetry::new(size);
            let n = NUM_FACES * size * size;
            for t in 0..n {
                let (orbit, g) = sym.owner[t];
                let rep = sym.representatives[orbit as usize] as usize;
                assert_eq!(sym.image(g as usize, rep), t);
                assert!(rep <= t, "the representative is the orbit's smallest texel");
            }
            // An even size has no texel on a symmetry plane through a face's centre line, so
            // its orbits are of 48 texels or, on the face diagonals, of 24.
            if size % 2 == 0 {
                let half = size / 2;
                let expected = half * (half + 1) / 2;
                assert_eq!(sym.representatives.len(), expected, "size {size}");
            }
        }
    }
}

//! A static k-d tree over 3D points for k-nearest-neighbour queries (GridMap's albedo lookup at
//! the k = 3 nearest surfel centres, METHOD.md §5).
//!
//! Implicit balanced layout: the points are permuted so that every subrange `[lo, hi)` has its
//! median at `(lo + hi) / 2`, split along the axis of largest extent (stored per median). Ranges of
//! at most `BUCKET` points are scanned linearly. Queries are `&self`; callers parallelize over
//! query points with rayon. Building is O(n log n) with `select_nth_unstable`.

use glam::DVec3;

/// Ranges this small are scanned instead of split.
const BUCKET: usize = 8;

/// k-d tree over a point set; query results refer to indices of the input slice.
#[derive(Clone, Debug)]
pub struct KdTree {
    points: Vec<DVec3>,
    /// Input index of each permuted point.
    indices: Vec<usize>,
    /// Split axis of the range whose median sits at this slot (unused inside buckets).
    axes: Vec<u8>,
}

impl KdTree {
    /// Builds the tree. Points with NaN coordinates are never returned.
    pub fn build(points: &[DVec3]) -> Self {
        let _span = tracing::info_span!("kdtree_build", points = points.len()).entered();
        let mut order: Vec<(DVec3, usize)> = points.iter().copied().zip(0..).collect();
        let mut axes = vec![0u8; points.len()];
        split(&mut order, 0, &mut axes);
        KdTree {
            points: order.iter().map(|p| p.0).collect(),
            indices: order.iter().map(|p| p.1).collect(),
            axes,
        }
    }

    pub fn len(&self) -> usize {
        self.points.len()
    }

    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The `k` nearest points to `p` as `(input index, squared distance)`, nearest first
    /// (fewer when the tree holds fewer than `k` points). Ties keep an arbitrary but deterministic order.
    pub fn k_nearest(&self, p: DVec3, k: usize) -> Vec<(usize, f64)> {
        let mut best: Vec<(usize, f64)> = Vec::with_capacity(k + 1);
        if k > 0 {
            self.search(p, k, 0, self.points.len(), &mut best);
        }
        best.iter()
            .map(|&(slot, d)| (self.indices[slot], d))
            .collect()
    }

    /// Inserts `(slot, d)` into the sorted list of at most `k` best.
    fn offer(best: &mut Vec<(usize, f64)>, k: usize, slot: usize, d: f64) {
        if d.is_nan() || (best.len() == k && best.last().is_some_and(|w| d >= w.1)) {
            return;
        }
        let at = best.partition_point(|b| b.1 <= d);
        best.insert(at, (slot, d));
        best.truncate(k);
    }

    fn search(&self, p: DVec3, k: usize, lo: usize, hi: usize, best: &mut Vec<(usize, f64)>) {
        if hi - lo <= BUCKET {
            for slot in lo..hi {
                Self::offer(best, k, slot, self.points[slot].distance_squared(p));
            }
            return;
        }
        let mid = (lo + hi) / 2;
        let axis = self.axes[mid] as usize;
        Self::offer(best, k, mid, self.points[mid].distance_squared(p));
        let diff = p[axis] - self.points[mid][axis];
        let (near, far) = if diff < 0.0 {
            ((lo, mid), (mid + 1, hi))
        } else {
            ((mid + 1, hi), (lo, mid))
        };
        self.search(p, k, near.0, near.1, best);
        let worst = if best.len() < k {
            f64::INFINITY
        } else {
            best[k - 1].1
        };
        if diff * diff < worst {
            self.search(p, k, far.0, far.1, best);
        }
    }
}

fn split(items: &mut [(DVec3, usize)], offset: usize, axes: &mut [u8]) {
    if items.len() <= BUCKET {
        return;
    }
    let (lo, hi) = items.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), (p, _)| (lo.min(*p), hi.max(*p)),
    );
    let extent = hi - lo;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| a.0[axis].total_cmp(&b.0[axis]));
    axes[offset + mid] = axis as u8;
    let (left, rest) = items.split_at_mut(mid);
    split(left, offset, axes);
    split(&mut rest[1..], offset + mid + 1, axes);
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn brute(points: &[DVec3], p: DVec3, k: usize) -> Vec<f64> {
        let mut d: Vec<f64> = points.iter().map(|q| q.distance_squared(p)).collect();
        d.sort_by(f64::total_cmp);
        d.truncate(k);
        d
    }

    #[test]
    fn k_nearest_agrees_with_brute_force() {
        for seed in 0..4u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let n = [1, 7, 300, 5000][seed as usize];
            // Anisotropic cloud with duplicated points, like surfels on a thin shell.
            let mut points: Vec<DVec3> = (0..n)
                .map(|_| {
                    DVec3::new(
                        rng.random_range(-2.0..2.0),
                        rng.random_range(-0.5..0.5),
                        rng.random_range(-0.05..0.05),
                    )
                })
                .collect();
            if n > 10 {
                points[3] = points[4];
            }
            let tree = KdTree::build(&points);
            assert_eq!(tree.len(), n);
            for _ in 0..500 {
                let p = DVec3::new(
                    rng.random_range(-2.5..2.5),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-0.5..0.5),
                );
                for k in [1, 3, 10] {
                    let got = tree.k_nearest(p, k);
                    let want = brute(&points, p, k);
                    assert_eq!(got.len(), want.len());
                    for ((i, d), w) in got.iter().zip(&want) {
                        assert_eq!(*d, *w, "seed {seed}, k {k}");
                        assert_eq!(
                            points[*i].distance_squared(p),
                            *d,
                            "index points to the wrong point"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn empty_tree_and_zero_k_return_nothing() {
        let tree = KdTree::build(&[]);
        assert!(tree.is_empty());
        assert!(tree.k_nearest(DVec3::ZERO, 3).is_empty());
        let tree = KdTree::build(&[DVec3::ONE]);
        assert!(tree.k_nearest(DVec3::ZERO, 0).is_empty());
        assert_eq!(tree.k_nearest(DVec3::ZERO, 3), vec![(0, 3.0)]);
    }
}

//! Vectors of one repeated value, written by rayon's threads.
//!
//! A step allocates its per-pixel buffers and gradients afresh (G-buffers, loss gradients, the
//! per-surfel gradient) and most start at zero. `vec![0.0; n]` fills them on the calling thread,
//! while the pool's other threads wait: on the 2-core machine of issue 29 that serial `memset`
//! was the largest piece of the step's serial work. [`filled`] writes the same values in
//! parallel chunks instead.
//!
//! Threading: chunks of at least [`PARALLEL_MIN_LEN`] elements on rayon's pool; shorter vectors
//! are filled on the calling thread.

use rayon::prelude::*;

/// Elements below which a vector is filled on the calling thread (waking the pool would cost
/// more than the fill).
pub const PARALLEL_MIN_LEN: usize = 1 << 14;

/// `len` copies of `value`: the same vector as `vec![value; len]`.
pub fn filled<T: Copy + Send + Sync>(len: usize, value: T) -> Vec<T> {
    if len < 2 * PARALLEL_MIN_LEN {
        return vec![value; len];
    }
    let mut out = Vec::with_capacity(len);
    out.par_extend(rayon::iter::repeat_n(value, len).with_min_len(PARALLEL_MIN_LEN));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equals_the_serial_fill_at_every_length_around_the_threshold() {
        for len in [
            0,
            1,
            PARALLEL_MIN_LEN,
            2 * PARALLEL_MIN_LEN - 1,
            2 * PARALLEL_MIN_LEN,
            5 * PARALLEL_MIN_LEN + 3,
        ] {
            assert_eq!(filled(len, 1.5f64), vec![1.5f64; len], "len {len}");
            assert_eq!(filled(len, [0u32; 3]), vec![[0u32; 3]; len], "len {len}");
        }
    }
}

//! Eight f32 lanes as plain arrays, and a lane-wise `exp`: the vector type of the fast engine's
//! per-pixel loops ([`super::tile`]).
//!
//! Every operation is an `#[inline(always)]` loop over the 8 lanes with no branches, so LLVM's
//! vectorizers turn it into SIMD instructions for whatever target features the *calling*
//! function is compiled with: SSE2 (two 4-lane registers) in the portable build, one 256-bit
//! register where the tile kernels are compiled a second time with `#[target_feature(enable =
//! "avx2")]` and picked at run time ([`super::SimdPath`]), NEON on aarch64. (A SIMD crate such as
//! `wide` fixes its register width at compile time from the target features, i.e. SSE2 for the
//! baseline x86-64 build, so it cannot serve the runtime-dispatched AVX2 copy.)
//!
//! No operation is fused (Rust never contracts `a * b + c`), so every path computes the same
//! IEEE-754 results bit for bit.
//!
//! Masks are lanes of `u32`, all ones (true) or zero (false).
//!
//! Nothing here (nor in the kernels) goes through `array::map`: LLVM may keep `map`'s closure
//! out of line, and an out-of-line function is compiled without the calling kernel's target
//! features, so the AVX2 kernels spilled their vectors around SSE calls (where it happened, it
//! cost a knot training step 13–17% of its time). `objdump -d` of `forward_tile_avx2` and
//! `backward_tile_avx2` shows no call in their loops.
//!
//! The lane loops index their arrays with the lane number on purpose (clippy's
//! `needless_range_loop` is off here): several arrays advance in step, one lane per iteration,
//! which is the shape the vectorizer turns into one vector instruction.
#![allow(clippy::needless_range_loop)]

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// Lanes per vector.
pub const LANES: usize = 8;

/// Eight f32 lanes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(32))]
pub struct F32x8(pub [f32; LANES]);

/// Eight lane masks: `u32::MAX` where true, 0 where false.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C, align(32))]
pub struct Mask8(pub [u32; LANES]);

macro_rules! lanewise_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl $trait for F32x8 {
            type Output = F32x8;
            #[inline(always)]
            fn $method(self, rhs: F32x8) -> F32x8 {
                let mut out = [0.0; LANES];
                for l in 0..LANES {
                    out[l] = self.0[l] $op rhs.0[l];
                }
                F32x8(out)
            }
        }
        impl $trait<f32> for F32x8 {
            type Output = F32x8;
            #[inline(always)]
            fn $method(self, rhs: f32) -> F32x8 {
                self $op F32x8::splat(rhs)
            }
        }
    };
}

lanewise_op!(Add, add, +);
lanewise_op!(Sub, sub, -);
lanewise_op!(Mul, mul, *);
lanewise_op!(Div, div, /);

impl AddAssign for F32x8 {
    #[inline(always)]
    fn add_assign(&mut self, rhs: F32x8) {
        *self = *self + rhs;
    }
}

impl Neg for F32x8 {
    type Output = F32x8;
    #[inline(always)]
    fn neg(self) -> F32x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = -self.0[l];
        }
        F32x8(out)
    }
}

macro_rules! lanewise_cmp {
    ($method:ident, $op:tt) => {
        #[inline(always)]
        pub fn $method(self, rhs: F32x8) -> Mask8 {
            let mut out = [0; LANES];
            for l in 0..LANES {
                out[l] = if self.0[l] $op rhs.0[l] { u32::MAX } else { 0 };
            }
            Mask8(out)
        }
    };
}

impl F32x8 {
    #[inline(always)]
    pub fn splat(v: f32) -> Self {
        F32x8([v; LANES])
    }

    /// [`Self::splat`] of each value.
    #[inline(always)]
    pub fn splat_each<const N: usize>(values: &[f32; N]) -> [Self; N] {
        std::array::from_fn(|i| Self::splat(values[i]))
    }

    /// `start, start + 1, …, start + 7`.
    #[inline(always)]
    pub fn ramp(start: f32) -> Self {
        let mut out = [0.0; LANES];
        for (l, o) in out.iter_mut().enumerate() {
            *o = start + l as f32;
        }
        F32x8(out)
    }

    lanewise_cmp!(lt, <);
    lanewise_cmp!(le, <=);
    lanewise_cmp!(gt, >);

    /// `self` where `mask`, else 0 (also where `self` is NaN or infinite).
    #[inline(always)]
    pub fn and(self, mask: Mask8) -> Self {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = f32::from_bits(self.0[l].to_bits() & mask.0[l]);
        }
        F32x8(out)
    }

    /// Sum of the lanes, in lane order (a fixed order: deterministic).
    #[inline(always)]
    pub fn sum(self) -> f32 {
        let v = self.0;
        ((v[0] + v[1]) + (v[2] + v[3])) + ((v[4] + v[5]) + (v[6] + v[7]))
    }
}

impl Mask8 {
    /// Lanes `l < n`.
    #[inline(always)]
    pub fn first(n: usize) -> Self {
        let mut out = [0; LANES];
        for (l, o) in out.iter_mut().enumerate() {
            *o = if l < n { u32::MAX } else { 0 };
        }
        Mask8(out)
    }

    /// Lanes where `values[l] > k` (for the per-pixel counts of composited entries).
    #[inline(always)]
    pub fn greater(values: &[u32], k: u32) -> Self {
        let v = &values[..LANES];
        let mut out = [0; LANES];
        for l in 0..LANES {
            out[l] = if v[l] > k { u32::MAX } else { 0 };
        }
        Mask8(out)
    }

    #[inline(always)]
    pub fn and(self, rhs: Mask8) -> Self {
        let mut out = [0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] & rhs.0[l];
        }
        Mask8(out)
    }

    #[inline(always)]
    pub fn or(self, rhs: Mask8) -> Self {
        let mut out = [0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] | rhs.0[l];
        }
        Mask8(out)
    }

    /// `self && !rhs`.
    #[inline(always)]
    pub fn and_not(self, rhs: Mask8) -> Self {
        let mut out = [0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] & !rhs.0[l];
        }
        Mask8(out)
    }

    /// One bit per lane, bit `l` set where lane `l` is true.
    ///
    /// On x86-64 two SSE2 `movmskps` (LLVM turns the portable loop below into per-lane word
    /// extractions: 18% of the forward kernel in a knot geometry step).
    #[inline(always)]
    pub fn bits(self) -> u32 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::{__m128i, _mm_castsi128_ps, _mm_loadu_si128, _mm_movemask_ps};
            let lanes = self.0.as_ptr().cast::<__m128i>();
            // SAFETY: SSE2 is part of the x86-64 baseline, so the intrinsics exist on every CPU
            // this binary runs on; the two unaligned 16-byte loads read lanes 0–3 and 4–7 of
            // `self.0` (32 bytes), in bounds.
            unsafe {
                let lo = _mm_movemask_ps(_mm_castsi128_ps(_mm_loadu_si128(lanes)));
                let hi = _mm_movemask_ps(_mm_castsi128_ps(_mm_loadu_si128(lanes.add(1))));
                (lo | (hi << 4)) as u32
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let mut bits = 0;
            for l in 0..LANES {
                bits |= (self.0[l] >> 31) << l;
            }
            bits
        }
    }

    #[inline(always)]
    pub fn any(self) -> bool {
        self.bits() != 0
    }

    /// Number of true lanes.
    #[inline(always)]
    pub fn count(self) -> u32 {
        self.bits().count_ones()
    }

    /// `a` where true, else `b`.
    #[inline(always)]
    pub fn select(self, a: F32x8, b: F32x8) -> F32x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            let m = self.0[l];
            out[l] = f32::from_bits((a.0[l].to_bits() & m) | (b.0[l].to_bits() & !m));
        }
        F32x8(out)
    }

    /// `a` where true, else `b`, for f64 lanes.
    #[inline(always)]
    pub fn select_f64(self, a: F64x8, b: F64x8) -> F64x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            let m = u64::from(self.0[l]) * 0x1_0000_0001;
            out[l] = f64::from_bits((a.0[l].to_bits() & m) | (b.0[l].to_bits() & !m));
        }
        F64x8(out)
    }

    /// `a` where true, else `b`, for `u32` lanes.
    #[inline(always)]
    pub fn select_u32(self, a: [u32; LANES], b: &[u32]) -> [u32; LANES] {
        let b = &b[..LANES];
        let mut out = [0; LANES];
        for l in 0..LANES {
            let m = self.0[l];
            out[l] = (a[l] & m) | (b[l] & !m);
        }
        out
    }
}

/// Eight f64 lanes: the per-pixel transmittance, whose products are compared with
/// `transmittance_min` (in f32 two `alpha_max`-clamped surfels in a row land on the other side of
/// the default threshold `(1 − 0.99)² = 1e-4` than in the f64 reference).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(64))]
pub struct F64x8(pub [f64; LANES]);

impl F64x8 {
    #[inline(always)]
    pub fn splat(v: f64) -> Self {
        F64x8([v; LANES])
    }

    #[inline(always)]
    pub fn from_f32(v: F32x8) -> Self {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = f64::from(v.0[l]);
        }
        F64x8(out)
    }

    #[inline(always)]
    pub fn to_f32(self) -> F32x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] as f32;
        }
        F32x8(out)
    }

    #[inline(always)]
    pub fn lt(self, rhs: F64x8) -> Mask8 {
        let mut out = [0; LANES];
        for l in 0..LANES {
            out[l] = if self.0[l] < rhs.0[l] { u32::MAX } else { 0 };
        }
        Mask8(out)
    }
}

impl Mul for F64x8 {
    type Output = F64x8;
    #[inline(always)]
    fn mul(self, rhs: F64x8) -> F64x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] * rhs.0[l];
        }
        F64x8(out)
    }
}

impl Div for F64x8 {
    type Output = F64x8;
    #[inline(always)]
    fn div(self, rhs: F64x8) -> F64x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] / rhs.0[l];
        }
        F64x8(out)
    }
}

impl Sub for F64x8 {
    type Output = F64x8;
    #[inline(always)]
    fn sub(self, rhs: F64x8) -> F64x8 {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            out[l] = self.0[l] - rhs.0[l];
        }
        F64x8(out)
    }
}

/// `ln(f32::MIN_POSITIVE)`: below it [`exp`] returns 0 (no subnormal results).
const EXP_MIN_ARG: f32 = -87.336_55;

/// Lane-wise `e^x` for `x ≤ 0` (the Gaussian weights `exp(−ρ/2)`), branch-free.
///
/// Cephes' `expf` scheme: `x = n ln 2 + r` with `n = round(x / ln 2)` (rounded by adding and
/// subtracting `1.5 · 2²³`), `ln 2` split in two so `r ∈ [−ln2/2, ln2/2]` is exact to f32, a
/// degree-6 polynomial for `e^r`, and `2ⁿ` built in the exponent bits. Relative error ≤ 2 ulp
/// (≤ 2.4e-7) for `x ∈ [−87.3, 0]`, checked against f64 `exp` on a dense grid by
/// `exp_matches_f64_to_two_ulp`; 0 below `EXP_MIN_ARG` (where `e^x` is subnormal) and for NaN.
/// Positive `x` up to 88 is also accurate, though the rasterizer never asks for it.
#[inline(always)]
pub fn exp(x: F32x8) -> F32x8 {
    const LOG2E: f32 = std::f32::consts::LOG2_E;
    const ROUND: f32 = 12_582_912.0; // 1.5 · 2²³
    const LN2_HI: f32 = 0.693_359_4;
    const LN2_LO: f32 = -2.121_944_4e-4;
    const P: [f32; 6] = [
        1.987_569_1e-4,
        1.398_199_9e-3,
        8.333_452e-3,
        4.166_579_6e-2,
        1.666_666_5e-1,
        0.5,
    ];
    let mut out = [0.0; LANES];
    for l in 0..LANES {
        let v = x.0[l];
        // NaN and tiny arguments give 0 (the comparison is false for NaN).
        let underflow = (v < EXP_MIN_ARG) | v.is_nan();
        let v = if underflow { 0.0 } else { v };
        let t = v * LOG2E + ROUND;
        let n = t - ROUND;
        let r = (v - n * LN2_HI) - n * LN2_LO;
        let mut p = P[0];
        p = p * r + P[1];
        p = p * r + P[2];
        p = p * r + P[3];
        p = p * r + P[4];
        p = p * r + P[5];
        let e = (p * (r * r) + r) + 1.0;
        // The low bits of t hold n + 2²²; n ∈ [−126, 127] here.
        let n_int = (t.to_bits() as i32).wrapping_sub(0x4B40_0000);
        let scale = f32::from_bits(((n_int + 127) as u32) << 23);
        let result = e * scale;
        out[l] = if underflow { 0.0 } else { result };
    }
    F32x8(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_matches_f64_to_two_ulp() {
        let mut worst = 0.0f64;
        let n = 2_000_000;
        for i in 0..=n {
            let x = EXP_MIN_ARG * (i as f32 / n as f32);
            let got = exp(F32x8::splat(x)).0[0] as f64;
            let want = (x as f64).exp();
            worst = worst.max((got - want).abs() / want);
        }
        println!("worst relative error of exp on [{EXP_MIN_ARG}, 0]: {worst:.3e}");
        assert!(worst <= 2.4e-7, "{worst:e}");
        assert_eq!(exp(F32x8::splat(0.0)).0[0], 1.0);
        assert_eq!(exp(F32x8::splat(-100.0)).0[0], 0.0);
        assert_eq!(exp(F32x8::splat(f32::NAN)).0[0], 0.0);
        assert_eq!(exp(F32x8::splat(f32::NEG_INFINITY)).0[0], 0.0);
    }

    #[test]
    fn masks_select_and_count_lanes() {
        let a = F32x8::ramp(0.0);
        let m = a.lt(F32x8::splat(3.0));
        assert_eq!(m.count(), 3);
        assert!(m.any());
        assert!(!Mask8([0; LANES]).any());
        let s = m.select(a, F32x8::splat(-1.0));
        assert_eq!(s.0, [0.0, 1.0, 2.0, -1.0, -1.0, -1.0, -1.0, -1.0]);
        assert_eq!(
            F32x8::splat(f32::NAN).and(Mask8([0; LANES])).0,
            [0.0; LANES]
        );
        assert_eq!(Mask8::first(5).and_not(m).count(), 2);
        assert_eq!(m.bits(), 0b111);
        assert_eq!(
            Mask8::greater(&[0, 9, 0, 9, 0, 0, 0, 9], 1).bits(),
            0b1000_1010
        );
        assert_eq!(a.sum(), 28.0);
        let counts = [0u32, 1, 2, 3, 4, 5, 6, 7];
        assert_eq!(Mask8::greater(&counts, 4).count(), 3);
        assert_eq!(m.select_u32([9; LANES], &counts), [9, 9, 9, 3, 4, 5, 6, 7]);
    }
}

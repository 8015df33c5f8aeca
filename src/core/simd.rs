//! Runtime choice of the wider SIMD path for host loops written as plain lane arithmetic.
//!
//! Loops that LLVM vectorizes (fixed-width lane loops, or slices walked in step) are compiled for
//! the build's baseline target (SSE2 on x86-64) unless the function holding them is compiled with
//! more target features. Such a loop is written once as an `#[inline(always)]` function and called
//! through a `#[target_feature(enable = "avx2")]` copy where [`avx2_available`] says the CPU has
//! it. As Rust never fuses `a * b + c`, both copies compute the same bits; the fast rasterizer has
//! its own switch (`raster::fast::SimdPath`) so that tests can force either path.

/// Whether this CPU runs AVX2 (cached by the standard library after the first call).
pub fn avx2_available() -> bool {
    #[cfg(target_arch = "x86_64")]
    return is_x86_feature_detected!("avx2");
    #[cfg(not(target_arch = "x86_64"))]
    false
}

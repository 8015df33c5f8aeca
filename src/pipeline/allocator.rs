//! Keeps the C allocator from handing large buffers back to the kernel after every use.
//!
//! A training step allocates and frees G-buffers, gradient images and per-tile gradient slots of
//! a few MiB each. glibc serves such blocks with `mmap` and returns them with `munmap`, so every
//! step page-faults its buffers in again and every `munmap` flushes the TLB of all worker
//! threads (measured: ~28% of a geometry-stage step in the kernel, 4.5 s of 68 s system time on a
//! 300-iteration knot run). Raising the mmap threshold to its maximum (32 MiB) and the trim
//! threshold keeps freed blocks in the heap for the next step (0.6 s system time on the same run).
//!
//! Other platforms and C libraries keep their defaults; the call changes speed, never results.

/// Applies the tuning once, at the start of a binary's `main`, before worker threads start.
pub fn keep_large_buffers() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        /// glibc's ceiling for `M_MMAP_THRESHOLD` on 64-bit targets (`HEAP_MAX_SIZE / 2`).
        const MMAP_THRESHOLD: libc::c_int = 32 << 20;
        /// Free memory above this at the top of the heap is returned to the kernel.
        const TRIM_THRESHOLD: libc::c_int = 512 << 20;
        // SAFETY: `mallopt` takes two plain integers and only updates the allocator's tunables
        // under its own arena lock; it touches no memory of ours and is called before any
        // thread of this program allocates concurrently. A rejected value (return 0) leaves the
        // default in place, which is still correct, so the result is ignored on purpose.
        unsafe {
            libc::mallopt(libc::M_MMAP_THRESHOLD, MMAP_THRESHOLD);
            libc::mallopt(libc::M_TRIM_THRESHOLD, TRIM_THRESHOLD);
        }
    }
}

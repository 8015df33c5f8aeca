//! Mappable buffers that bring results back from the device, kept between submissions.
//!
//! wgpu's Vulkan allocator (gpu-alloc) hands a block of memory back to the driver as soon as the
//! last buffer in it is freed, and the read-back buffers are the only ones of their memory type
//! (host-visible, cached). A read-back buffer created and dropped at every step therefore made
//! every step allocate host memory from the driver again. The pool keeps each buffer once its
//! bytes are read and gives it to the next read-back of the same size class.
//!
//! Threading: the pool is a mutex around a list; a buffer is held by one read-back at a time.

use std::sync::{Mutex, PoisonError};

/// Buffers are made in sizes of powers of two from this up, so a read-back of a size seen before
/// finds one.
const SMALLEST_BYTES: u64 = 256;

/// The most bytes the pool keeps while they are not in use; a buffer returned beyond it is freed
/// (read-backs of whole images are rare and large, the per-step ones are a few bytes).
const KEPT_BYTES: u64 = 64 << 20;

/// The free read-back buffers of one device.
#[derive(Default)]
pub(super) struct ReadbackPool {
    free: Mutex<Vec<wgpu::Buffer>>,
}

impl ReadbackPool {
    /// An unmapped `MAP_READ | COPY_DST` buffer of at least `bytes` bytes: a kept one of the size
    /// class of `bytes`, else a new one.
    pub(super) fn take(&self, device: &wgpu::Device, bytes: u64) -> wgpu::Buffer {
        let size = size_class(bytes);
        let mut free = self.free.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(i) = free.iter().position(|b| b.size() == size) {
            return free.swap_remove(i);
        }
        drop(free);
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    /// Keeps `buffer` (unmapped by the caller) for a later read-back, unless the pool already
    /// holds [`KEPT_BYTES`].
    pub(super) fn give_back(&self, buffer: wgpu::Buffer) {
        let mut free = self.free.lock().unwrap_or_else(PoisonError::into_inner);
        let kept: u64 = free.iter().map(wgpu::Buffer::size).sum();
        if kept + buffer.size() <= KEPT_BYTES {
            free.push(buffer);
        }
    }

    /// Number of buffers kept now.
    #[cfg(test)]
    pub(super) fn kept(&self) -> usize {
        self.free
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .len()
    }
}

/// The size a read-back of `bytes` gets: the next power of two, at least [`SMALLEST_BYTES`].
fn size_class(bytes: u64) -> u64 {
    bytes.max(SMALLEST_BYTES).next_power_of_two()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn size_classes_are_powers_of_two_from_the_smallest() {
        assert_eq!(size_class(0), 256);
        assert_eq!(size_class(4), 256);
        assert_eq!(size_class(256), 256);
        assert_eq!(size_class(257), 512);
        assert_eq!(size_class(3 << 20), 4 << 20);
    }
}

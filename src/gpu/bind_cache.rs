//! Bind groups kept from one training step to the next. A resident run dispatches the same
//! kernels on the same buffers every step, so the bind groups of a step are looked up by what
//! they bind (the kernel's layout and each binding's buffer, offset and size) instead of being
//! created again: creating one costs wgpu a validation and a descriptor-set write each.
//!
//! Eviction is by generation: [`BindCache::end_step`] keeps only the groups the step just encoded.
//! A group also holds its buffers alive, so groups of buffers that were replaced (the surfels after
//! densification, a grown entry buffer, a new GridMap) go at the end of the next step and never
//! keep old buffers past it.
//!
//! Threading: the map sits behind a mutex; encoding is one step at a time anyway.

use std::collections::HashMap;
use std::sync::{Mutex, PoisonError};

use super::device::{Device, Kernel};

/// What a bind group binds: the layout it was made for and, per binding number, the buffer range.
#[derive(Clone, PartialEq, Eq, Hash)]
struct BindKey {
    layout: wgpu::BindGroupLayout,
    entries: Vec<(u32, wgpu::Buffer, u64, Option<wgpu::BufferSize>)>,
}

#[derive(Default)]
struct Generations {
    /// Groups used since the last [`BindCache::end_step`].
    current: HashMap<BindKey, wgpu::BindGroup>,
    /// Groups of the step before, moved to `current` when used again.
    previous: HashMap<BindKey, wgpu::BindGroup>,
    created: u64,
    reused: u64,
}

/// Bind groups of the previous and the current step (see the module doc).
#[derive(Default)]
pub(super) struct BindCache {
    state: Mutex<Generations>,
}

/// How many bind groups a cache created and how many lookups found one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BindCounts {
    pub created: u64,
    pub reused: u64,
}

impl BindCache {
    /// The bind group of `kernel` with each named buffer range bound, from the cache when the
    /// current or the previous step made the same one. Resources other than buffers are not
    /// cached.
    pub(super) fn bind_resources<'a>(
        &self,
        device: &Device,
        kernel: &Kernel,
        resources: impl IntoIterator<Item = (&'a str, wgpu::BindingResource<'a>)>,
    ) -> wgpu::BindGroup {
        let resources: Vec<(&str, wgpu::BindingResource)> = resources.into_iter().collect();
        let entries: Option<Vec<_>> = resources
            .iter()
            .map(|(name, resource)| match resource {
                wgpu::BindingResource::Buffer(b) => Some((
                    kernel.spec().number_of(name),
                    b.buffer.clone(),
                    b.offset,
                    b.size,
                )),
                _ => None,
            })
            .collect();
        let Some(mut entries) = entries else {
            return device.bind_resources(kernel, resources);
        };
        entries.sort_by_key(|e| e.0);
        let key = BindKey {
            layout: kernel.layout().clone(),
            entries,
        };
        let mut state = self.state.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(group) = state.current.get(&key) {
            let group = group.clone();
            state.reused += 1;
            return group;
        }
        let group = match state.previous.remove(&key) {
            Some(group) => {
                state.reused += 1;
                group
            }
            None => {
                state.created += 1;
                device.bind_resources(kernel, resources)
            }
        };
        state.current.insert(key, group.clone());
        group
    }

    /// [`Self::bind_resources`] with each buffer bound whole.
    pub(super) fn bind(
        &self,
        device: &Device,
        kernel: &Kernel,
        buffers: &[(&str, &wgpu::Buffer)],
    ) -> wgpu::BindGroup {
        self.bind_resources(
            device,
            kernel,
            buffers
                .iter()
                .map(|&(name, buffer)| (name, buffer.as_entire_binding())),
        )
    }

    /// Ends a step: the groups it did not use are dropped (with their hold on their buffers).
    pub(super) fn end_step(&self) {
        let mut state = self.state.lock().unwrap_or_else(PoisonError::into_inner);
        state.previous = std::mem::take(&mut state.current);
    }

    /// Groups created and reused since the cache was made.
    pub(super) fn counts(&self) -> BindCounts {
        let state = self.state.lock().unwrap_or_else(PoisonError::into_inner);
        BindCounts {
            created: state.created,
            reused: state.reused,
        }
    }

    /// Groups held now (the current and the previous step's).
    pub(super) fn len(&self) -> usize {
        let state = self.state.lock().unwrap_or_else(PoisonError::into_inner);
        state.current.len() + state.previous.len()
    }
}

/// Where a dispatch's bind groups come from: made afresh (per-call work, whose buffers live for
/// one call), or a step's [`BindCache`].
#[derive(Clone, Copy)]
pub(super) enum Binder<'a> {
    Fresh(&'a Device),
    Cached(&'a Device, &'a BindCache),
}

impl<'a> Binder<'a> {
    pub(super) fn device(self) -> &'a Device {
        match self {
            Binder::Fresh(device) | Binder::Cached(device, _) => device,
        }
    }

    /// A bind group of `kernel` with each `(name, buffer)` bound whole ([`Device::bind`]).
    pub(super) fn bind(
        self,
        kernel: &Kernel,
        buffers: &[(&str, &wgpu::Buffer)],
    ) -> wgpu::BindGroup {
        match self {
            Binder::Fresh(device) => device.bind(kernel, buffers),
            Binder::Cached(device, cache) => cache.bind(device, kernel, buffers),
        }
    }

    /// [`Self::bind`] with any resources ([`Device::bind_resources`]).
    pub(super) fn bind_resources<'r>(
        self,
        kernel: &Kernel,
        resources: impl IntoIterator<Item = (&'r str, wgpu::BindingResource<'r>)>,
    ) -> wgpu::BindGroup {
        match self {
            Binder::Fresh(device) => device.bind_resources(kernel, resources),
            Binder::Cached(device, cache) => cache.bind_resources(device, kernel, resources),
        }
    }
}

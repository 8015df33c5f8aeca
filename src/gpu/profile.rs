//! Where a device run's time goes. [`PassProfiler`]: device time of each compute pass, from
//! timestamp queries (`GpuOptions::profile`, where the adapter has `TIMESTAMP_QUERY`):
//! `phygap bench raster --backend gpu --stages` prints them. [`HostClock`]: the host's side of a
//! resident training step (encoding, finishing the command buffer, submitting, waiting for the
//! device), always measured: `phygap bench train --backend gpu` prints it.
//!
//! Each pass gets a begin and an end timestamp in a query set; before a submission is read back
//! the query set is resolved into a buffer that is read back with it, and the durations are added
//! to per-label totals until [`PassProfiler::take`] drains them. Threading: the pending labels and
//! totals sit behind a mutex (calls on the backend are serialized anyway).

use std::sync::{Mutex, PoisonError};
use std::time::Duration;

use crate::core::raster::StageTime;

/// Passes timed per submission; later passes of the same submission go untimed.
const MAX_PASSES: u32 = 64;

pub(super) struct PassProfiler {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    /// Nanoseconds per timestamp tick.
    period_ns: f64,
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    /// Labels of the passes of the submission being encoded, in query order.
    pending: Vec<&'static str>,
    totals: Totals,
}

/// Calls and nanoseconds per label, in order of first appearance.
#[derive(Default)]
struct Totals(Vec<(&'static str, usize, f64)>);

impl Totals {
    fn add(&mut self, label: &'static str, ns: f64) {
        match self.0.iter_mut().find(|(l, _, _)| *l == label) {
            Some((_, calls, total)) => {
                *calls += 1;
                *total += ns;
            }
            None => self.0.push((label, 1, ns)),
        }
    }

    /// The totals, which are reset.
    fn take(&mut self) -> Vec<StageTime> {
        std::mem::take(&mut self.0)
            .into_iter()
            .map(|(name, calls, ns)| StageTime {
                name: name.to_string(),
                calls,
                total_ms: ns * 1e-6,
            })
            .collect()
    }
}

/// Host time per labelled phase of the resident trainer's steps.
#[derive(Default)]
pub(super) struct HostClock {
    totals: Mutex<Totals>,
}

impl HostClock {
    pub(super) fn record(&self, label: &'static str, elapsed: Duration) {
        self.totals
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .add(label, elapsed.as_secs_f64() * 1e9);
    }

    /// The totals since the last call, which are reset.
    pub(super) fn take(&self) -> Vec<StageTime> {
        self.totals
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .take()
    }
}

impl PassProfiler {
    /// A profiler, or `None` where the device was opened without `TIMESTAMP_QUERY`.
    pub(super) fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Option<Self> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        Some(PassProfiler {
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("pass timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: 2 * MAX_PASSES,
            }),
            resolved: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("resolved timestamps"),
                size: u64::from(2 * MAX_PASSES) * 8,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            }),
            period_ns: f64::from(queue.get_timestamp_period()),
            state: Mutex::new(State::default()),
        })
    }

    fn state(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The timestamp writes of the next pass, labelled `label` (none once the set is full).
    pub(super) fn writes(
        &self,
        label: &'static str,
    ) -> Option<wgpu::ComputePassTimestampWrites<'_>> {
        let mut state = self.state();
        let index = state.pending.len() as u32;
        if index >= MAX_PASSES {
            return None;
        }
        state.pending.push(label);
        Some(wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * index),
            end_of_pass_write_index: Some(2 * index + 1),
        })
    }

    /// Resolves this submission's timestamps at the end of `encoder`; returns the buffer to read
    /// back with it and its length in bytes (none when no pass was timed).
    pub(super) fn resolve(
        &self,
        encoder: &mut wgpu::CommandEncoder,
    ) -> Option<(&wgpu::Buffer, u64)> {
        let passes = self.state().pending.len() as u32;
        if passes == 0 {
            return None;
        }
        encoder.resolve_query_set(&self.queries, 0..2 * passes, &self.resolved, 0);
        Some((&self.resolved, u64::from(passes) * 16))
    }

    /// Adds the durations in `bytes` (read back from [`PassProfiler::resolve`]'s buffer) to the
    /// totals of their passes' labels.
    pub(super) fn record(&self, bytes: &[u8]) {
        let ticks: Vec<u64> = bytemuck::pod_collect_to_vec(bytes);
        let mut state = self.state();
        let pending = std::mem::take(&mut state.pending);
        for (label, pair) in pending.iter().zip(ticks.chunks_exact(2)) {
            let ns = pair[1].saturating_sub(pair[0]) as f64 * self.period_ns;
            state.totals.add(label, ns);
        }
    }

    /// The totals since the last call, which are reset.
    pub(super) fn take(&self) -> Vec<StageTime> {
        self.state().totals.take()
    }
}

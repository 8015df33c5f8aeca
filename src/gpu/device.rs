//! The device the gpu kernels run on, and what every kernel module does with it: compile a
//! kernel of the table in [`super::shaders`] (its bind group layout built from the table), create
//! storage buffers checked against the device's binding limit, bind them by their WGSL names,
//! size 1-D dispatch grids, encode (optionally timed) compute passes, submit and read buffers
//! back, and turn the device's validation and out-of-memory errors into [`GpuError`]s.
//!
//! Threading: work on one [`Device`] is serialized by [`Device::scoped`] (wgpu's error scopes are
//! one stack per device, so two threads inside it at once would pop each other's scopes).

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;

use wgpu::util::DeviceExt;

use super::profile::{HostClock, PassProfiler};
use super::readback::ReadbackPool;
use super::shaders::{KernelSpec, Variant};
use super::{GpuContext, GpuError};
use crate::core::raster::StageTime;

/// Threads per workgroup of the 1-D kernels (`@workgroup_size(256)`, `linear_index`).
pub(super) const GROUP: u32 = 256;

/// Smallest storage buffer: a binding must hold at least one element of its array, and the
/// largest element of any kernel is a projected surfel (7 × vec4).
pub(super) const MIN_BINDING_BYTES: u64 = 112;

/// A compiled kernel: its pipeline, the layout of its bind group and its entry in the table.
pub(super) struct Kernel {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    spec: &'static KernelSpec,
}

impl Kernel {
    pub(super) fn pipeline(&self) -> &wgpu::ComputePipeline {
        &self.pipeline
    }

    pub(super) fn layout(&self) -> &wgpu::BindGroupLayout {
        &self.layout
    }

    /// The kernel's entry in the table of [`super::shaders`].
    pub(super) fn spec(&self) -> &'static KernelSpec {
        self.spec
    }
}

/// An opened adapter with its limits, the kernel variant its features choose, the pass profiler
/// and the lock that serializes work.
pub struct Device {
    ctx: GpuContext,
    variant: Variant,
    /// The largest buffer a binding may hold: the device's limit, or less (to test splitting).
    binding_limit: u64,
    profiler: Option<PassProfiler>,
    host_clock: HostClock,
    /// The most buffer memory seen in use at a submission, in bytes.
    peak_buffer_bytes: AtomicU64,
    readbacks: ReadbackPool,
    exclusive: Mutex<()>,
}

/// Device memory held in buffers (wgpu's allocation counters: what the driver was asked for,
/// after alignment; the driver's own overhead is not included).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DeviceMemory {
    pub in_use_bytes: u64,
    /// The most in use at any submission since the device was opened.
    pub peak_bytes: u64,
}

impl Device {
    /// Kernels are compiled as `variant`; with `max_binding_bytes`, buffers above it count as
    /// beyond the binding limit; with `profile`, every pass is timed where the adapter has
    /// `TIMESTAMP_QUERY`.
    pub(super) fn new(
        ctx: GpuContext,
        variant: Variant,
        max_binding_bytes: Option<u64>,
        profile: bool,
    ) -> Self {
        let limits = ctx.device.limits();
        let device_limit =
            u64::from(limits.max_storage_buffer_binding_size).min(limits.max_buffer_size);
        let profiler = if profile {
            PassProfiler::new(&ctx.device, &ctx.queue)
        } else {
            None
        };
        Device {
            binding_limit: max_binding_bytes.map_or(device_limit, |m| m.min(device_limit)),
            profiler,
            host_clock: HostClock::default(),
            peak_buffer_bytes: AtomicU64::new(0),
            readbacks: ReadbackPool::default(),
            ctx,
            variant,
            exclusive: Mutex::new(()),
        }
    }

    pub fn context(&self) -> &GpuContext {
        &self.ctx
    }

    /// The kernel variant the adapter's features chose.
    pub(super) fn variant(&self) -> Variant {
        self.variant
    }

    pub(super) fn wgpu(&self) -> &wgpu::Device {
        &self.ctx.device
    }

    pub(super) fn queue(&self) -> &wgpu::Queue {
        &self.ctx.queue
    }

    /// The largest buffer a binding may hold.
    pub(super) fn binding_limit(&self) -> u64 {
        self.binding_limit
    }

    /// Compiles `spec` (its files as this device's variant chooses them) into a compute pipeline
    /// whose bind group layout holds the table's bindings. Errors surface in the caller's error
    /// scope (see [`Device::compile_all`]): a WGSL error, or a binding the table and the WGSL
    /// disagree on.
    pub(super) fn kernel(&self, spec: &'static KernelSpec) -> Kernel {
        let device = self.wgpu();
        let entries: Vec<wgpu::BindGroupLayoutEntry> =
            spec.all_bindings().map(|b| b.layout_entry()).collect();
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(spec.name),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(spec.name),
            bind_group_layouts: &[&layout],
            push_constant_ranges: &[],
        });
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(spec.name),
            source: wgpu::ShaderSource::Wgsl(spec.source(self.variant).into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(spec.name),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some(spec.entry),
            compilation_options: Default::default(),
            cache: None,
        });
        Kernel {
            pipeline,
            layout,
            spec,
        }
    }

    /// Runs `build` (which compiles pipelines with [`Device::pipeline`]) inside a validation
    /// scope, so a kernel that fails to compile becomes [`GpuError::Shader`].
    pub(super) fn compile_all<T>(&self, build: impl FnOnce(&Self) -> T) -> Result<T, GpuError> {
        self.wgpu().push_error_scope(wgpu::ErrorFilter::Validation);
        let built = build(self);
        match pollster::block_on(self.wgpu().pop_error_scope()) {
            Some(e) => Err(GpuError::Shader {
                adapter: self.ctx.adapter_summary().name.clone(),
                message: e.to_string(),
            }),
            None => Ok(built),
        }
    }

    /// Fails with a message naming the buffer when `bytes` exceeds the device's limits.
    pub(super) fn check_size(&self, name: &str, bytes: u64) -> Result<(), GpuError> {
        if bytes > self.binding_limit {
            return Err(self.too_large(name, bytes));
        }
        Ok(())
    }

    /// The error of a buffer `name` of `bytes` that exceeds the binding limit.
    pub(super) fn too_large(&self, name: &str, bytes: u64) -> GpuError {
        GpuError::BufferTooLarge {
            name: name.to_owned(),
            bytes,
            limit: self.binding_limit,
        }
    }

    /// A zeroed storage buffer of `bytes` (checked against the binding limit).
    pub(super) fn storage(
        &self,
        name: &str,
        bytes: u64,
        extra: wgpu::BufferUsages,
    ) -> Result<wgpu::Buffer, GpuError> {
        self.check_size(name, bytes)?;
        Ok(self.wgpu().create_buffer(&wgpu::BufferDescriptor {
            label: Some(name),
            size: bytes.max(MIN_BINDING_BYTES).next_multiple_of(4),
            usage: wgpu::BufferUsages::STORAGE | extra,
            mapped_at_creation: false,
        }))
    }

    /// A storage buffer holding `contents` (checked against the binding limit); it can be
    /// rewritten with `queue.write_buffer` and copied from.
    pub(super) fn storage_init(
        &self,
        name: &str,
        contents: &[u8],
    ) -> Result<wgpu::Buffer, GpuError> {
        self.check_size(name, contents.len() as u64)?;
        let mut padded;
        let data = if (contents.len() as u64) < MIN_BINDING_BYTES {
            padded = contents.to_vec();
            padded.resize(MIN_BINDING_BYTES as usize, 0);
            &padded[..]
        } else {
            contents
        };
        Ok(self
            .wgpu()
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(name),
                contents: data,
                usage: wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_DST
                    | wgpu::BufferUsages::COPY_SRC,
            }))
    }

    /// Submits the uploads queued so far and waits for them. wgpu keeps the contents of a buffer
    /// created with them in a staging buffer of its own (host memory on a discrete GPU) until the
    /// queue's next submission completes; this frees those copies now.
    pub(super) fn flush_uploads(&self) -> Result<(), GpuError> {
        self.queue().submit([]);
        self.wait_for_queue()
    }

    /// Waits until the device has finished everything submitted.
    fn wait_for_queue(&self) -> Result<(), GpuError> {
        self.wgpu()
            .poll(wgpu::PollType::Wait)
            .map(drop)
            .map_err(|e| GpuError::Device(e.to_string()))
    }

    /// A uniform buffer holding `contents`, rewritable with `queue.write_buffer`.
    pub(super) fn uniform(&self, label: &str, contents: &[u8]) -> wgpu::Buffer {
        self.wgpu()
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            })
    }

    /// A bind group of `kernel` with each `(name, buffer)` bound whole at the binding of that
    /// WGSL name.
    ///
    /// # Panics
    /// When a name is not one of the kernel's bindings, or a binding is left out or given twice
    /// (a call site disagrees with the table in [`super::shaders`]).
    pub(super) fn bind(
        &self,
        kernel: &Kernel,
        buffers: &[(&str, &wgpu::Buffer)],
    ) -> wgpu::BindGroup {
        self.bind_resources(
            kernel,
            buffers
                .iter()
                .map(|&(name, buffer)| (name, buffer.as_entire_binding())),
        )
    }

    /// [`Device::bind`] with any resources (e.g. a slice of a buffer).
    pub(super) fn bind_resources<'a>(
        &self,
        kernel: &Kernel,
        resources: impl IntoIterator<Item = (&'a str, wgpu::BindingResource<'a>)>,
    ) -> wgpu::BindGroup {
        let spec = kernel.spec;
        let entries: Vec<wgpu::BindGroupEntry> = resources
            .into_iter()
            .map(|(name, resource)| wgpu::BindGroupEntry {
                binding: spec.number_of(name),
                resource,
            })
            .collect();
        for binding in spec.all_bindings() {
            let given = entries
                .iter()
                .filter(|e| e.binding == binding.number)
                .count();
            assert!(
                given == 1,
                "kernel `{}`: binding `{}` given {given} times",
                spec.name,
                binding.name
            );
        }
        self.wgpu().create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(spec.name),
            layout: &kernel.layout,
            entries: &entries,
        })
    }

    /// Workgroup grid for `threads` invocations of a 256-thread 1-D kernel (`linear_index`).
    pub(super) fn grid(&self, threads: u64) -> Result<(u32, u32), GpuError> {
        self.workgroup_grid(threads.div_ceil(u64::from(GROUP)))
    }

    /// A 2-D grid of at least `groups` workgroups within the device's per-dimension limit.
    pub(super) fn workgroup_grid(&self, groups: u64) -> Result<(u32, u32), GpuError> {
        let max = u64::from(self.wgpu().limits().max_compute_workgroups_per_dimension);
        let x = groups.min(max);
        let y = groups.div_ceil(x.max(1));
        if y > max {
            return Err(GpuError::Device(format!(
                "{groups} workgroups exceed the device's dispatch limit"
            )));
        }
        Ok((x as u32, y as u32))
    }

    /// A compute pass labelled `label`, timed when profiling.
    pub(super) fn begin_pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        label: &'static str,
    ) -> wgpu::ComputePass<'e> {
        encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(label),
            timestamp_writes: self.profiler.as_ref().and_then(|p| p.writes(label)),
        })
    }

    /// One pass running `kernel` over `threads` invocations of a 1-D kernel (none for 0).
    pub(super) fn dispatch_1d(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        label: &'static str,
        kernel: &Kernel,
        group: &wgpu::BindGroup,
        threads: u64,
    ) -> Result<(), GpuError> {
        if threads == 0 {
            return Ok(());
        }
        let (x, y) = self.grid(threads)?;
        let mut pass = self.begin_pass(encoder, label);
        pass.set_pipeline(&kernel.pipeline);
        pass.set_bind_group(0, group, &[]);
        pass.dispatch_workgroups(x, y, 1);
        Ok(())
    }

    /// Copies each `(buffer, bytes)` into a mappable buffer after `encoder`'s work, submits, waits
    /// and returns the bytes. The pass timestamps (when profiling) come back with them and go to
    /// the profiler.
    pub(super) fn submit_and_read(
        &self,
        encoder: wgpu::CommandEncoder,
        sources: &[(&wgpu::Buffer, u64)],
    ) -> Result<Vec<Vec<u8>>, GpuError> {
        self.submit_and_read_with(encoder, sources, false)
    }

    /// [`Self::submit_and_read`] of a training step, whose host phases go to the
    /// [`HostClock`] as "read-back" (taking the read-back buffers and recording their copies),
    /// "finish", "submit" and "wait" ([`Self::take_host_times`]).
    pub(super) fn submit_step_and_read(
        &self,
        encoder: wgpu::CommandEncoder,
        sources: &[(&wgpu::Buffer, u64)],
    ) -> Result<Vec<Vec<u8>>, GpuError> {
        self.submit_and_read_with(encoder, sources, true)
    }

    /// Records a phase of a training step on the host.
    pub(super) fn record_host_time(&self, label: &'static str, since: Instant) {
        self.host_clock.record(label, since.elapsed());
    }

    fn submit_and_read_with(
        &self,
        mut encoder: wgpu::CommandEncoder,
        sources: &[(&wgpu::Buffer, u64)],
        timed: bool,
    ) -> Result<Vec<Vec<u8>>, GpuError> {
        let mut clock = Instant::now();
        let mut lap = |label: &'static str| {
            if timed {
                self.host_clock.record(label, clock.elapsed());
                clock = Instant::now();
            }
        };
        let timestamps = self.profiler.as_ref().and_then(|p| p.resolve(&mut encoder));
        // Each read-back: its buffer, the bytes copied (a multiple of 4) and the bytes asked for.
        let staging: Vec<(wgpu::Buffer, u64, u64)> = sources
            .iter()
            .chain(&timestamps)
            .map(|&(src, bytes)| {
                let size = bytes.max(4).next_multiple_of(4);
                let dst = self.readbacks.take(self.wgpu(), size);
                if bytes > 0 {
                    encoder.copy_buffer_to_buffer(src, 0, &dst, 0, size);
                }
                (dst, size, bytes)
            })
            .collect();
        lap("read-back");
        let commands = encoder.finish();
        lap("finish");
        self.queue().submit([commands]);
        lap("submit");
        self.note_buffer_memory();
        let (tx, rx) = std::sync::mpsc::channel();
        for (i, (buf, size, _)) in staging.iter().enumerate() {
            let tx = tx.clone();
            buf.slice(..*size)
                .map_async(wgpu::MapMode::Read, move |r| drop(tx.send((i, r))));
        }
        drop(tx);
        self.wait_for_queue()?;
        for (_, r) in rx.iter() {
            r.map_err(|e| GpuError::Device(format!("reading back a buffer failed: {e}")))?;
        }
        let mut data: Vec<Vec<u8>> = staging
            .into_iter()
            .map(|(buf, size, bytes)| {
                let data = buf.slice(..size).get_mapped_range()[..bytes as usize].to_vec();
                buf.unmap();
                self.readbacks.give_back(buf);
                data
            })
            .collect();
        if let (Some(profiler), Some(_)) = (&self.profiler, timestamps) {
            profiler.record(&data.pop().unwrap_or_default());
        }
        lap("wait");
        Ok(data)
    }

    /// Raises the peak of buffer memory to what is in use now.
    fn note_buffer_memory(&self) {
        let in_use = self.buffer_memory().in_use_bytes;
        self.peak_buffer_bytes.fetch_max(in_use, Ordering::Relaxed);
    }

    /// Buffer memory in use now and at its peak.
    pub(super) fn buffer_memory(&self) -> DeviceMemory {
        let counters = self.wgpu().get_internal_counters();
        let in_use_bytes = counters.hal.buffer_memory.read().max(0) as u64;
        DeviceMemory {
            in_use_bytes,
            peak_bytes: self
                .peak_buffer_bytes
                .load(Ordering::Relaxed)
                .max(in_use_bytes),
        }
    }

    /// Host time of the training steps' phases since the last call.
    pub(super) fn take_host_times(&self) -> Vec<StageTime> {
        self.host_clock.take()
    }

    /// Runs `f` alone on this device, inside out-of-memory and validation error scopes; a device
    /// error becomes [`GpuError::Device`] naming `stage`.
    pub(super) fn scoped<T, E: From<GpuError>>(
        &self,
        stage: &str,
        f: impl FnOnce() -> Result<T, E>,
    ) -> Result<T, E> {
        // A panic inside another call leaves no state behind that this one depends on.
        let _exclusive = self
            .exclusive
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        let device = self.wgpu();
        device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        device.push_error_scope(wgpu::ErrorFilter::Validation);
        let result = f();
        let validation = pollster::block_on(device.pop_error_scope());
        let oom = pollster::block_on(device.pop_error_scope());
        if let Some(e) = oom.or(validation) {
            return Err(GpuError::Device(format!("{stage}: {e}")).into());
        }
        result
    }

    /// Device times of the passes since the last call (empty unless profiling).
    pub(super) fn take_stage_times(&self) -> Vec<StageTime> {
        self.profiler
            .as_ref()
            .map_or_else(Vec::new, PassProfiler::take)
    }
}

#[cfg(test)]
mod tests {
    use wgpu::util::DeviceExt;

    use crate::gpu::test_backend;

    /// Read-backs reuse their mappable buffers (two of the smallest size class serve both rounds
    /// here), and a reused buffer returns the new bytes, cut to the length asked for.
    #[test]
    fn read_backs_reuse_their_buffers_and_return_fresh_bytes() {
        let Some(gpu) = test_backend() else { return };
        let device = gpu.device();
        for value in [7u32, 11] {
            let words: Vec<u32> = (0..10).map(|i| value * 100 + i).collect();
            let buffer = device
                .wgpu()
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("words"),
                    contents: bytemuck::cast_slice(&words),
                    usage: wgpu::BufferUsages::COPY_SRC,
                });
            let encoder = device.wgpu().create_command_encoder(&Default::default());
            let data = device
                .submit_and_read(encoder, &[(&buffer, 40), (&buffer, 8)])
                .unwrap();
            assert_eq!(bytemuck::pod_collect_to_vec::<u8, u32>(&data[0]), words);
            assert_eq!(
                bytemuck::pod_collect_to_vec::<u8, u32>(&data[1]),
                words[..2]
            );
            assert_eq!(device.readbacks.kept(), 2);
        }
    }

    /// A buffer's bytes count as in use while it lives and stay in the peak after it is freed.
    #[test]
    fn buffer_memory_follows_allocations_and_keeps_the_peak() {
        let Some(gpu) = test_backend() else { return };
        let device = gpu.device();
        let before = device.buffer_memory();
        let bytes = 24 << 20;
        let buffer = device
            .storage("big", bytes, wgpu::BufferUsages::COPY_SRC)
            .unwrap();
        let encoder = device.wgpu().create_command_encoder(&Default::default());
        device.submit_and_read(encoder, &[(&buffer, 4)]).unwrap();
        let held = device.buffer_memory();
        assert!(
            held.in_use_bytes >= before.in_use_bytes + bytes,
            "{held:?} after {before:?}"
        );
        drop(buffer);
        device.wgpu().poll(wgpu::PollType::Wait).unwrap();
        let after = device.buffer_memory();
        assert!(
            after.in_use_bytes + bytes <= held.in_use_bytes,
            "{after:?} after {held:?}"
        );
        assert!(after.peak_bytes >= held.in_use_bytes, "{after:?}");
    }
}

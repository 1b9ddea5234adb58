//! GPU timestamps around each pass, where the device has `TIMESTAMP_QUERY`.

use crate::gpu::{GpuError, map_for_reading};

/// Most passes one frame can time; aokit's longest chain (`msvo`: its nine passes, the depth
/// MIP chain's four and the filters) stays well below this.
const MAX_PASSES: u32 = 32;

/// GPU time of one pass.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &mut aokit::AoPipeline)
/// #     -> Result<(), aokit::GpuError> {
/// if pipeline.enable_timing(device, queue) {
///     // ... encode and submit a frame ...
///     if let Some(times) = pipeline.last_pass_times(device) {
///         for aokit::PassTime { name, ms } in times? {
///             println!("{name:>20} {ms:7.3} ms");
///         }
///     }
/// }
/// # Ok(()) }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PassTime {
    /// The pass, as its shader is named (`gtao`, `linear_depth`, ...).
    pub name: &'static str,
    /// Milliseconds between the pass's start and end timestamps.
    pub ms: f64,
}

/// A query set with two timestamps per pass, resolved once per frame. [`AoPipeline`]
/// owns one once [`enable_timing`] succeeds and hands it to its passes; read the times with
/// [`last_pass_times`] (see [`PassTime`]). Public so that passes outside aokit (a tool's peer
/// implementation, timed beside aokit's) are timed the same way.
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, pipeline: &wgpu::ComputePipeline,
/// #      bind_group: &wgpu::BindGroup) -> Result<(), aokit::GpuError> {
/// use aokit::timing::PassTimer;
/// let Some(mut timer) = PassTimer::new(device, queue) else {
///     return Ok(()); // no TIMESTAMP_QUERY on this device
/// };
/// timer.begin_frame();
/// let mut encoder = device.create_command_encoder(&Default::default());
/// {
///     let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
///         label: Some("my_pass"),
///         timestamp_writes: timer.pass("my_pass"),
///     });
///     pass.set_pipeline(pipeline);
///     pass.set_bind_group(0, bind_group, &[]);
///     pass.dispatch_workgroups(240, 135, 1);
/// }
/// timer.resolve(&mut encoder);
/// queue.submit([encoder.finish()]);
/// for time in timer.read(device)? {
///     println!("{}: {:.3} ms", time.name, time.ms);
/// }
/// # Ok(()) }
/// ```
///
/// [`AoPipeline`]: crate::AoPipeline
/// [`enable_timing`]: crate::AoPipeline::enable_timing
/// [`last_pass_times`]: crate::AoPipeline::last_pass_times
pub struct PassTimer {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    readback: wgpu::Buffer,
    names: Vec<&'static str>,
    period_ns: f32,
}

impl PassTimer {
    /// A timer, or `None` when the device lacks `TIMESTAMP_QUERY`.
    ///
    /// ```no_run
    /// # fn f(gpu: &aokit::GpuContext) {
    /// let timed = aokit::timing::PassTimer::new(&gpu.device, &gpu.queue).is_some();
    /// # }
    /// ```
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Option<Self> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        let count = 2 * MAX_PASSES;
        let bytes = u64::from(count) * 8;
        let buffer = |label, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: bytes,
                usage,
                mapped_at_creation: false,
            })
        };
        Some(Self {
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("aokit pass timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count,
            }),
            resolved: buffer(
                "aokit timestamps resolved",
                wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            ),
            readback: buffer(
                "aokit timestamps readback",
                wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            ),
            names: Vec::new(),
            period_ns: queue.get_timestamp_period(),
        })
    }

    /// Forgets the passes of the previous frame.
    ///
    /// ```no_run
    /// # fn f(timer: &mut aokit::timing::PassTimer) {
    /// // At the start of each frame's recording, before its first `pass`.
    /// timer.begin_frame();
    /// # }
    /// ```
    pub fn begin_frame(&mut self) {
        self.names.clear();
    }

    /// Timestamp writes for the next pass, or `None` once the set is full.
    ///
    /// ```no_run
    /// # fn f(timer: &mut aokit::timing::PassTimer, encoder: &mut wgpu::CommandEncoder) {
    /// let pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
    ///     label: Some("blur"),
    ///     timestamp_writes: timer.pass("blur"),
    /// });
    /// # }
    /// ```
    pub fn pass(&mut self, name: &'static str) -> Option<wgpu::ComputePassTimestampWrites<'_>> {
        let index = self.names.len() as u32;
        if index >= MAX_PASSES {
            return None;
        }
        self.names.push(name);
        Some(wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * index),
            end_of_pass_write_index: Some(2 * index + 1),
        })
    }

    /// Records the copy of this frame's timestamps to the read-back buffer.
    ///
    /// ```no_run
    /// # fn f(timer: &aokit::timing::PassTimer, encoder: &mut wgpu::CommandEncoder) {
    /// // After the frame's last timed pass, into the same encoder.
    /// timer.resolve(encoder);
    /// # }
    /// ```
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        let count = 2 * self.names.len() as u32;
        if count == 0 {
            return;
        }
        encoder.resolve_query_set(&self.queries, 0..count, &self.resolved, 0);
        encoder.copy_buffer_to_buffer(&self.resolved, 0, &self.readback, 0, u64::from(count) * 8);
    }

    /// Reads the last resolved frame's pass times; call after its commands were submitted.
    /// Blocks until the GPU has finished them.
    ///
    /// ```no_run
    /// # fn f(timer: &aokit::timing::PassTimer, device: &wgpu::Device) -> Result<(), aokit::GpuError> {
    /// let total_ms: f64 = timer.read(device)?.iter().map(|time| time.ms).sum();
    /// # Ok(()) }
    /// ```
    pub fn read(&self, device: &wgpu::Device) -> Result<Vec<PassTime>, GpuError> {
        let count = 2 * self.names.len() as u64;
        if count == 0 {
            return Ok(Vec::new());
        }
        let slice = self.readback.slice(..count * 8);
        map_for_reading(device, &slice, None)?;
        let ticks: Vec<u64> = {
            let mapped = slice
                .get_mapped_range()
                .map_err(|e| GpuError::Readback(e.to_string()))?;
            bytemuck::pod_collect_to_vec(&mapped)
        };
        self.readback.unmap();
        Ok(self
            .names
            .iter()
            .zip(ticks.chunks_exact(2))
            .map(|(&name, pair)| PassTime {
                name,
                ms: pair[1].saturating_sub(pair[0]) as f64 * f64::from(self.period_ns) * 1e-6,
            })
            .collect())
    }
}

//! Command recording and submission. Every command is followed by a full compute/transfer/host
//! memory barrier, so kernels recorded in sequence see each other's writes.
use super::buffer::Buffer;
use super::context::{Context, Shared};
use super::error::{vk_err, GpuError, Result};
use super::kernel::{BindingKind, Kernel};
use ash::vk;
use std::sync::Arc;

/// The largest workgroup count in one dimension that every Vulkan device accepts.
const MAX_GROUPS_X: u32 = 65_535;

/// Workgroup counts covering `n_groups` linear groups: kernels combine them as
/// `gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x` (see `glsl/common.glsl`).
pub fn groups_for(n_groups: u32) -> [u32; 3] {
    if n_groups <= MAX_GROUPS_X {
        [n_groups.max(1), 1, 1]
    } else {
        [MAX_GROUPS_X, n_groups.div_ceil(MAX_GROUPS_X), 1]
    }
}

/// Per-dispatch GPU time from timestamp queries, in recording order.
#[derive(Debug, Default, Clone)]
pub struct Timings {
    pub entries: Vec<(&'static str, f64)>,
}

impl Timings {
    /// Total milliseconds spent in kernels named `name`.
    pub fn ms(&self, name: &str) -> f64 {
        self.entries
            .iter()
            .filter(|e| e.0 == name)
            .map(|e| e.1)
            .sum()
    }
    /// Total milliseconds of all timed commands.
    pub fn total_ms(&self) -> f64 {
        self.entries.iter().map(|e| e.1).sum()
    }

    /// One line: each kernel's total time in name order, then the sum.
    pub fn summary(&self) -> String {
        let mut names: Vec<&str> = self.entries.iter().map(|e| e.0).collect();
        names.sort();
        names.dedup();
        let mut line = String::new();
        for name in names {
            line.push_str(&format!("{name} {:.2} ms  ", self.ms(name)));
        }
        line + &format!("| total {:.2} ms", self.total_ms())
    }
}

/// A command buffer being recorded. Dropping it without `submit` discards the work.
pub struct Stream {
    shared: Arc<Shared>,
    pool: vk::CommandPool,
    cb: vk::CommandBuffer,
    labels: Vec<&'static str>,
    queries: Option<(vk::QueryPool, u32)>,
    timed: Vec<&'static str>,
}

impl Stream {
    /// Starts recording.
    pub fn new(ctx: &Context) -> Result<Stream> {
        Self::create(ctx, 0)
    }

    /// Starts recording with room for `max_commands` timed commands (timestamps around each).
    pub fn timed(ctx: &Context, max_commands: u32) -> Result<Stream> {
        Self::create(ctx, max_commands)
    }

    fn create(ctx: &Context, max_timed: u32) -> Result<Stream> {
        let shared = ctx.shared.clone();
        let dev = &shared.device;
        // SAFETY: valid create infos on a live device; freed in Drop.
        unsafe {
            let pool = dev
                .create_command_pool(
                    &vk::CommandPoolCreateInfo::default()
                        .queue_family_index(shared.queue_family)
                        .flags(vk::CommandPoolCreateFlags::TRANSIENT),
                    None,
                )
                .map_err(vk_err("vkCreateCommandPool"))?;
            let cb = match dev.allocate_command_buffers(
                &vk::CommandBufferAllocateInfo::default()
                    .command_pool(pool)
                    .level(vk::CommandBufferLevel::PRIMARY)
                    .command_buffer_count(1),
            ) {
                Ok(v) => v[0],
                Err(e) => {
                    dev.destroy_command_pool(pool, None);
                    return Err(vk_err("vkAllocateCommandBuffers")(e));
                }
            };
            dev.begin_command_buffer(
                cb,
                &vk::CommandBufferBeginInfo::default()
                    .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
            )
            .map_err(vk_err("vkBeginCommandBuffer"))?;
            let queries = if max_timed > 0 && shared.info.timestamp_period_ns > 0.0 {
                let qp = dev
                    .create_query_pool(
                        &vk::QueryPoolCreateInfo::default()
                            .query_type(vk::QueryType::TIMESTAMP)
                            .query_count(2 * max_timed),
                        None,
                    )
                    .map_err(vk_err("vkCreateQueryPool"))?;
                dev.cmd_reset_query_pool(cb, qp, 0, 2 * max_timed);
                Some((qp, max_timed))
            } else {
                None
            };
            Ok(Stream {
                shared,
                pool,
                cb,
                labels: Vec::new(),
                queries,
                timed: Vec::new(),
            })
        }
    }

    fn barrier(&self) {
        let all = vk::AccessFlags::SHADER_READ
            | vk::AccessFlags::SHADER_WRITE
            | vk::AccessFlags::TRANSFER_READ
            | vk::AccessFlags::TRANSFER_WRITE
            | vk::AccessFlags::HOST_READ
            | vk::AccessFlags::HOST_WRITE;
        let b = [vk::MemoryBarrier::default()
            .src_access_mask(
                vk::AccessFlags::SHADER_WRITE
                    | vk::AccessFlags::TRANSFER_WRITE
                    | vk::AccessFlags::SHADER_READ
                    | vk::AccessFlags::TRANSFER_READ,
            )
            .dst_access_mask(all)];
        let stages = vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER;
        // SAFETY: recording into our command buffer.
        unsafe {
            self.shared.device.cmd_pipeline_barrier(
                self.cb,
                stages,
                stages | vk::PipelineStageFlags::HOST,
                vk::DependencyFlags::empty(),
                &b,
                &[],
                &[],
            )
        };
    }

    fn stamp(&mut self, label: &'static str, end: bool) {
        if let Some((qp, max)) = self.queries {
            let i = self.timed.len() as u32;
            if i < max {
                let stage = if end {
                    vk::PipelineStageFlags::BOTTOM_OF_PIPE
                } else {
                    vk::PipelineStageFlags::TOP_OF_PIPE
                };
                // SAFETY: query index within the pool.
                unsafe {
                    self.shared
                        .device
                        .cmd_write_timestamp(self.cb, stage, qp, 2 * i + end as u32)
                };
                if end {
                    self.timed.push(label);
                }
            }
        }
    }

    /// Records `kernel` over `groups` workgroups, binding each named buffer to the binding of that
    /// name in the kernel; `push` must be exactly the kernel's push-constant size.
    pub fn dispatch(
        &mut self,
        kernel: &Kernel,
        buffers: &[(&str, &Buffer)],
        push: &[u8],
        groups: [u32; 3],
    ) -> Result<()> {
        let kerr = |msg: String| GpuError::Kernel {
            kernel: kernel.name.to_string(),
            msg,
        };
        if push.len() as u32 != kernel.push_size {
            return Err(kerr(format!(
                "push constants are {} bytes, the kernel declares {}",
                push.len(),
                kernel.push_size
            )));
        }
        if buffers.len() != kernel.bindings.len() {
            let want: Vec<&str> = kernel.bindings.iter().map(|b| b.0.as_str()).collect();
            let got: Vec<&str> = buffers.iter().map(|b| b.0).collect();
            return Err(kerr(format!("binds {got:?}, the kernel declares {want:?}")));
        }
        let mut infos = Vec::with_capacity(buffers.len());
        let mut views = Vec::with_capacity(buffers.len());
        for (name, _, kind) in &kernel.bindings {
            let buf = buffers
                .iter()
                .find(|b| b.0 == name)
                .ok_or_else(|| kerr(format!("buffer `{name}` not bound")))?
                .1;
            infos.push(vk::DescriptorBufferInfo {
                buffer: buf.raw,
                offset: 0,
                range: vk::WHOLE_SIZE,
            });
            views.push(match kind {
                BindingKind::Storage => vk::BufferView::null(),
                BindingKind::Texels => buf.texel_view()?,
            });
        }
        let writes: Vec<vk::WriteDescriptorSet> = kernel
            .bindings
            .iter()
            .zip(infos.iter().zip(&views))
            .map(|((_, binding, kind), (info, view))| {
                let w = vk::WriteDescriptorSet::default()
                    .dst_binding(*binding)
                    .descriptor_type(kind.descriptor_type());
                match kind {
                    BindingKind::Storage => w.buffer_info(std::slice::from_ref(info)),
                    BindingKind::Texels => w.texel_buffer_view(std::slice::from_ref(view)),
                }
            })
            .collect();
        if groups.contains(&0) {
            return Ok(());
        }
        self.labels.push(kernel.name);
        self.stamp(kernel.name, false);
        let dev = &self.shared.device;
        // SAFETY: the pipeline, layout and buffers are live; push size checked above.
        unsafe {
            dev.cmd_bind_pipeline(self.cb, vk::PipelineBindPoint::COMPUTE, kernel.pipeline);
            if !writes.is_empty() {
                self.shared.push_descriptor.cmd_push_descriptor_set(
                    self.cb,
                    vk::PipelineBindPoint::COMPUTE,
                    kernel.layout,
                    0,
                    &writes,
                );
            }
            if !push.is_empty() {
                dev.cmd_push_constants(
                    self.cb,
                    kernel.layout,
                    vk::ShaderStageFlags::COMPUTE,
                    0,
                    push,
                );
            }
            dev.cmd_dispatch(self.cb, groups[0], groups[1], groups[2]);
        }
        self.stamp(kernel.name, true);
        self.barrier();
        Ok(())
    }

    /// Copies `bytes` from the start of `src` to the start of `dst`.
    pub fn copy(&mut self, src: &Buffer, dst: &Buffer, bytes: u64) {
        self.copy_region(src, 0, dst, 0, bytes)
    }

    /// Copies `bytes` from `src` at byte `src_offset` to `dst` at byte `dst_offset`.
    pub fn copy_region(
        &mut self,
        src: &Buffer,
        src_offset: u64,
        dst: &Buffer,
        dst_offset: u64,
        bytes: u64,
    ) {
        if bytes == 0 {
            return;
        }
        self.labels.push("copy");
        let region = [vk::BufferCopy {
            src_offset,
            dst_offset,
            size: bytes,
        }];
        // SAFETY: both buffers are live and at least `bytes` long (callers check).
        unsafe {
            self.shared
                .device
                .cmd_copy_buffer(self.cb, src.raw, dst.raw, &region)
        };
        self.barrier();
    }

    /// Fills the whole buffer with the 32-bit word `value`.
    pub fn fill(&mut self, buf: &Buffer, value: u32) {
        self.labels.push("fill");
        // SAFETY: live buffer; whole-size fill of a 4-byte-multiple allocation.
        unsafe {
            self.shared
                .device
                .cmd_fill_buffer(self.cb, buf.raw, 0, vk::WHOLE_SIZE, value)
        };
        self.barrier();
    }

    /// Fills `size` bytes of `buf` from byte `offset` (both multiples of 4) with `value`.
    pub fn fill_region(&mut self, buf: &Buffer, offset: u64, size: u64, value: u32) {
        if size == 0 {
            return;
        }
        self.labels.push("fill");
        // SAFETY: live buffer; the caller keeps offset + size inside it, in whole words.
        unsafe {
            self.shared
                .device
                .cmd_fill_buffer(self.cb, buf.raw, offset, size, value)
        };
        self.barrier();
    }

    /// Submits, waits for completion, and returns per-dispatch timings (empty unless `timed`).
    /// Any validation message raised meanwhile turns into an error.
    pub fn submit(self) -> Result<Timings> {
        let dev = &self.shared.device;
        // SAFETY: the command buffer is in the recording state; the fence is waited on before return.
        unsafe {
            dev.end_command_buffer(self.cb)
                .map_err(vk_err("vkEndCommandBuffer"))?;
            let fence = dev
                .create_fence(&vk::FenceCreateInfo::default(), None)
                .map_err(vk_err("vkCreateFence"))?;
            let cbs = [self.cb];
            let submit = [vk::SubmitInfo::default().command_buffers(&cbs)];
            let res = {
                let q = self.shared.queue.lock().unwrap_or_else(|e| e.into_inner());
                dev.queue_submit(*q, &submit, fence)
            }
            .and_then(|_| dev.wait_for_fences(&[fence], true, u64::MAX));
            dev.destroy_fence(fence, None);
            if let Err(e) = res {
                return Err(match e {
                    vk::Result::ERROR_DEVICE_LOST => GpuError::DeviceLost {
                        kernels: self.labels.join(", "),
                    },
                    other => vk_err("vkQueueSubmit")(other),
                });
            }
        }
        let mut timings = Timings::default();
        if let Some((qp, _)) = self.queries {
            let n = self.timed.len();
            if n > 0 {
                let mut data = vec![0u64; 2 * n];
                // SAFETY: the queries were written by the completed submission.
                unsafe {
                    dev.get_query_pool_results(
                        qp,
                        0,
                        &mut data,
                        vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
                    )
                }
                .map_err(vk_err("vkGetQueryPoolResults"))?;
                let period = self.shared.info.timestamp_period_ns as f64;
                for (i, label) in self.timed.iter().enumerate() {
                    let dt = data[2 * i + 1].saturating_sub(data[2 * i]) as f64 * period * 1e-6;
                    timings.entries.push((label, dt));
                }
            }
        }
        let msgs = self.shared.take_messages();
        if !msgs.is_empty() {
            return Err(GpuError::Validation(msgs));
        }
        Ok(timings)
    }
}

impl Drop for Stream {
    fn drop(&mut self) {
        // SAFETY: the submission (if any) completed; nothing references the pool or queries.
        unsafe {
            if let Some((qp, _)) = self.queries {
                self.shared.device.destroy_query_pool(qp, None);
            }
            self.shared.device.destroy_command_pool(self.pool, None);
        }
    }
}

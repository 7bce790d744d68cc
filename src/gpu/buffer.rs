//! Named storage buffers allocated through gpu-allocator and freed on drop.
use super::context::{Context, Shared};
use super::error::{vk_err, GpuError, Result};
use ash::vk;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme};
use gpu_allocator::MemoryLocation;
use std::sync::{Arc, Mutex};

/// The word fresh device buffers hold in debug builds: a quiet NaN as f32, huge as u32.
pub const GARBAGE: u32 = 0x7fc0_dead;

/// Where a buffer lives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BufferUsage {
    /// Device-local storage; host access goes through a staging copy unless the memory is mappable.
    Device,
    /// Host-visible staging memory written by the CPU.
    Upload,
    /// Host-visible memory read back by the CPU.
    Readback,
}

/// A storage buffer. Owns its allocation; dropping it frees both (submission is synchronous, so
/// the device is never still using a buffer the host can drop).
pub struct Buffer {
    pub(crate) shared: Arc<Shared>,
    pub(crate) raw: vk::Buffer,
    alloc: Option<Allocation>,
    size: u64,
    /// Bytes actually allocated: `size` rounded up to 16.
    alloc_size: u64,
    name: String,
    /// The `R32G32B32A32_UINT` view used by texel-buffer bindings, made on first use.
    view: Mutex<Option<vk::BufferView>>,
}

impl std::fmt::Debug for Buffer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Buffer({:?}, {} bytes)", self.name, self.size)
    }
}

impl Buffer {
    /// Allocates `size` bytes named `name` (the name appears in validation and leak reports).
    /// Refuses sizes above the device's storage-buffer range (128 MiB on lavapipe).
    pub fn new(ctx: &Context, name: &str, size: u64, usage: BufferUsage) -> Result<Buffer> {
        let shared = ctx.shared.clone();
        let limit = shared.info.max_storage_buffer_range;
        if size > limit {
            return Err(GpuError::BufferTooLarge {
                name: name.to_string(),
                size,
                limit,
            });
        }
        // Vulkan forbids empty buffers; an empty one still gets 16 bytes of backing. Sizes are
        // rounded up to 16 bytes so kernels may read whole `uvec4`s up to the end of the data.
        let alloc_size = size.max(16).next_multiple_of(16);
        let info = vk::BufferCreateInfo::default()
            .size(alloc_size)
            .usage(
                vk::BufferUsageFlags::STORAGE_BUFFER
                    | vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER
                    | vk::BufferUsageFlags::TRANSFER_SRC
                    | vk::BufferUsageFlags::TRANSFER_DST,
            )
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: valid create info on a live device.
        let raw = unsafe { shared.device.create_buffer(&info, None) }
            .map_err(vk_err("vkCreateBuffer"))?;
        // SAFETY: `raw` was just created on this device.
        let requirements = unsafe { shared.device.get_buffer_memory_requirements(raw) };
        let location = match usage {
            BufferUsage::Device => MemoryLocation::GpuOnly,
            BufferUsage::Upload => MemoryLocation::CpuToGpu,
            BufferUsage::Readback => MemoryLocation::GpuToCpu,
        };
        let alloc = {
            let mut guard = shared.allocator.lock().unwrap_or_else(|e| e.into_inner());
            let allocator = guard
                .as_mut()
                .expect("allocator lives as long as the device");
            allocator.allocate(&AllocationCreateDesc {
                name,
                requirements,
                location,
                linear: true,
                allocation_scheme: AllocationScheme::GpuAllocatorManaged,
            })
        };
        let alloc = match alloc {
            Ok(a) => a,
            Err(e) => {
                // SAFETY: the buffer has no memory bound and is unused.
                unsafe { shared.device.destroy_buffer(raw, None) };
                return Err(GpuError::OutOfMemory {
                    name: name.to_string(),
                    size,
                    detail: e.to_string(),
                });
            }
        };
        // SAFETY: memory from the allocator satisfies the buffer's requirements.
        if let Err(e) = unsafe {
            shared
                .device
                .bind_buffer_memory(raw, alloc.memory(), alloc.offset())
        } {
            // SAFETY: as above.
            unsafe { shared.device.destroy_buffer(raw, None) };
            if let Some(a) = shared
                .allocator
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .as_mut()
            {
                let _ = a.free(alloc);
            }
            return Err(vk_err("vkBindBufferMemory")(e));
        }
        shared.name_object(raw, name);
        let buf = Buffer {
            shared,
            raw,
            alloc: Some(alloc),
            size,
            alloc_size,
            name: name.to_string(),
            view: Mutex::new(None),
        };
        if cfg!(debug_assertions) && usage == BufferUsage::Device {
            // Debug builds and tests fill fresh device buffers with a NaN pattern, so a kernel
            // that forgets to write its output fails the comparison with the CPU reference.
            buf.fill_words(GARBAGE)?;
        }
        Ok(buf)
    }

    /// A device buffer holding `data`.
    pub fn from_slice<T: bytemuck::Pod>(ctx: &Context, name: &str, data: &[T]) -> Result<Buffer> {
        let b = Buffer::new(
            ctx,
            name,
            std::mem::size_of_val(data) as u64,
            BufferUsage::Device,
        )?;
        b.write(data)?;
        Ok(b)
    }

    /// Fills the whole buffer with the 32-bit word `word`.
    pub fn fill_words(&self, word: u32) -> Result<()> {
        let ctx = Context {
            shared: self.shared.clone(),
        };
        let mut s = super::Stream::new(&ctx)?;
        s.fill(self, word);
        s.submit().map(|_| ())
    }

    /// A device buffer of `len` zeroed elements of `T`.
    pub fn zeroed<T: bytemuck::Pod>(ctx: &Context, name: &str, len: usize) -> Result<Buffer> {
        let b = Buffer::new(
            ctx,
            name,
            (len * std::mem::size_of::<T>()) as u64,
            BufferUsage::Device,
        )?;
        b.write(&vec![0u8; len * std::mem::size_of::<T>()])?;
        Ok(b)
    }

    /// The buffer seen as `uvec4` texels (for `usamplerBuffer` bindings), created on first use
    /// and destroyed with the buffer.
    pub(crate) fn texel_view(&self) -> Result<vk::BufferView> {
        let mut guard = self.view.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(v) = *guard {
            return Ok(v);
        }
        let texels = self.alloc_size / 16;
        let limit = self.shared.info.max_texel_buffer_elements as u64;
        if texels > limit {
            return Err(GpuError::Kernel {
                kernel: "texel view".into(),
                msg: format!(
                    "buffer `{}` holds {texels} 16-byte texels; the device allows {limit} per view",
                    self.name
                ),
            });
        }
        let info = vk::BufferViewCreateInfo::default()
            .buffer(self.raw)
            .format(vk::Format::R32G32B32A32_UINT)
            .offset(0)
            .range(vk::WHOLE_SIZE);
        // SAFETY: the buffer is live and was created with UNIFORM_TEXEL_BUFFER usage.
        let v = unsafe { self.shared.device.create_buffer_view(&info, None) }
            .map_err(vk_err("vkCreateBufferView"))?;
        *guard = Some(v);
        Ok(v)
    }

    /// Size in bytes as requested.
    pub fn size(&self) -> u64 {
        self.size
    }

    /// The name given at creation.
    pub fn name(&self) -> &str {
        &self.name
    }

    fn mapped(&self) -> Option<std::ptr::NonNull<std::ffi::c_void>> {
        self.alloc.as_ref().and_then(|a| a.mapped_ptr())
    }

    /// Copies `data` to the start of the buffer.
    pub fn write<T: bytemuck::Pod>(&self, data: &[T]) -> Result<()> {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        if bytes.len() as u64 > self.size {
            return Err(GpuError::Kernel {
                kernel: "upload".into(),
                msg: format!(
                    "{} bytes do not fit buffer `{}` of {} bytes",
                    bytes.len(),
                    self.name,
                    self.size
                ),
            });
        }
        if bytes.is_empty() {
            return Ok(());
        }
        if let Some(ptr) = self.mapped() {
            // SAFETY: the mapping covers `size` bytes and no submission is in flight (synchronous model).
            unsafe {
                std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr.as_ptr() as *mut u8, bytes.len())
            };
            return Ok(());
        }
        let ctx = Context {
            shared: self.shared.clone(),
        };
        let staging = Buffer::new(
            &ctx,
            &format!("{} (upload)", self.name),
            bytes.len() as u64,
            BufferUsage::Upload,
        )?;
        staging.write(bytes)?;
        let mut s = super::Stream::new(&ctx)?;
        s.copy(&staging, self, bytes.len() as u64);
        s.submit()?;
        Ok(())
    }

    /// Reads the first `len` elements of `T` back to the host.
    pub fn read<T: bytemuck::Pod>(&self, len: usize) -> Result<Vec<T>> {
        self.read_at(0, len)
    }

    /// Reads `len` elements of `T` starting at element `first`.
    pub fn read_at<T: bytemuck::Pod>(&self, first: usize, len: usize) -> Result<Vec<T>> {
        let elem = std::mem::size_of::<T>();
        let start = (first * elem) as u64;
        let nbytes = len * elem;
        if start + nbytes as u64 > self.size {
            return Err(GpuError::Kernel {
                kernel: "readback".into(),
                msg: format!(
                    "{nbytes} bytes asked of buffer `{}` of {} bytes",
                    self.name, self.size
                ),
            });
        }
        let mut out = vec![T::zeroed(); len];
        if nbytes == 0 {
            return Ok(out);
        }
        if let Some(ptr) = self.mapped() {
            // SAFETY: the mapping covers `size` bytes; the device is idle for this buffer.
            unsafe {
                std::ptr::copy_nonoverlapping(
                    (ptr.as_ptr() as *const u8).add(start as usize),
                    bytemuck::cast_slice_mut::<T, u8>(&mut out).as_mut_ptr(),
                    nbytes,
                )
            };
            return Ok(out);
        }
        let ctx = Context {
            shared: self.shared.clone(),
        };
        let staging = Buffer::new(
            &ctx,
            &format!("{} (readback)", self.name),
            nbytes as u64,
            BufferUsage::Readback,
        )?;
        let mut s = super::Stream::new(&ctx)?;
        s.copy_region(self, start, &staging, 0, nbytes as u64);
        s.submit()?;
        staging.read(len)
    }

    /// Reads the whole buffer as `T`s.
    pub fn read_all<T: bytemuck::Pod>(&self) -> Result<Vec<T>> {
        self.read(self.size as usize / std::mem::size_of::<T>())
    }
}

impl Drop for Buffer {
    fn drop(&mut self) {
        // SAFETY: synchronous submission means the device no longer uses this buffer or its view.
        unsafe {
            if let Some(v) = self.view.lock().unwrap_or_else(|e| e.into_inner()).take() {
                self.shared.device.destroy_buffer_view(v, None);
            }
            self.shared.device.destroy_buffer(self.raw, None)
        };
        if let Some(a) = self.alloc.take() {
            if let Some(al) = self
                .shared
                .allocator
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .as_mut()
            {
                let _ = al.free(a);
            }
        }
    }
}

//! Errors of the GPU layer: every `vk::Result` is mapped at its call into a few meaningful cases.
use ash::vk;

/// Result alias of the GPU layer.
pub type Result<T, E = GpuError> = std::result::Result<T, E>;

/// What can go wrong talking to a Vulkan device.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error("cannot load the Vulkan loader ({0}); install libvulkan1 and a driver (e.g. mesa-vulkan-drivers)")]
    Loader(String),
    #[error("no usable Vulkan device: {0}")]
    NoDevice(String),
    #[error("out of memory allocating `{name}` ({size} bytes): {detail}")]
    OutOfMemory {
        name: String,
        size: u64,
        detail: String,
    },
    #[error("buffer `{name}` needs {size} bytes, over the device's {limit}-byte storage-buffer limit; split the work")]
    BufferTooLarge { name: String, size: u64, limit: u64 },
    #[error("{n} Gaussians to train at once, more than the {most} this device's {} MiB storage-buffer limit holds; stopped before training (a scene this large is refined or edited on a device with a larger limit)", .limit >> 20)]
    TooManyToTrain { n: usize, most: usize, limit: u64 },
    #[error("device lost while running [{kernels}]")]
    DeviceLost { kernels: String },
    #[error("Vulkan validation reported {} message(s):\n{}", .0.len(), .0.join("\n"))]
    Validation(Vec<String>),
    #[error("kernel `{kernel}`: {msg}")]
    Kernel { kernel: String, msg: String },
    #[error("{call} failed: {result}")]
    Vk {
        call: &'static str,
        result: vk::Result,
    },
}

/// Maps a raw `vk::Result` of `call` to a [`GpuError`].
pub(crate) fn vk_err(call: &'static str) -> impl Fn(vk::Result) -> GpuError {
    move |result| match result {
        vk::Result::ERROR_OUT_OF_DEVICE_MEMORY | vk::Result::ERROR_OUT_OF_HOST_MEMORY => {
            GpuError::OutOfMemory {
                name: call.to_string(),
                size: 0,
                detail: result.to_string(),
            }
        }
        vk::Result::ERROR_DEVICE_LOST => GpuError::DeviceLost {
            kernels: call.to_string(),
        },
        _ => GpuError::Vk { call, result },
    }
}

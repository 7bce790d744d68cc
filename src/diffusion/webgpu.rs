//! ONNX Runtime's WebGPU execution provider (a plugin library on Dawn; Vulkan on Linux): found
//! beside libonnxruntime (scripts/setup.sh puts it there) or at `$DREAMSCENE_WEBGPU_EP`,
//! registered once with the environment, and reached through its EP devices. Appending it by name
//! (`ort::ep::WebGPU`) is refused by the PyPI library, hence the device path.
use ort::environment::Environment;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The plugin's EP name.
pub const EP: &str = "WebGpuExecutionProvider";
const LIBRARY: &str = "libonnxruntime_providers_webgpu.so";

/// Where the plugin library is: `$DREAMSCENE_WEBGPU_EP`, else beside the ONNX Runtime library.
pub fn library(ort_library: &Path) -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("DREAMSCENE_WEBGPU_EP").filter(|v| !v.is_empty()) {
        return Some(PathBuf::from(p));
    }
    let p = ort_library.parent()?.join(LIBRARY);
    p.is_file().then_some(p)
}

/// Whether Linux shows a GPU to ONNX Runtime's device discovery (a DRM card).
pub fn drm_card() -> bool {
    std::fs::read_dir("/sys/class/drm").is_ok_and(|d| {
        d.flatten().any(|e| {
            let n = e.file_name();
            let n = n.to_string_lossy();
            n.starts_with("card") && !n.contains('-')
        })
    })
}

static REGISTERED: OnceLock<Result<(), String>> = OnceLock::new();

/// Registers the plugin with `env` (once per process). Without a DRM card (containers, CPU
/// Vulkan such as lavapipe) the factory offers no device unless
/// `ORT_WEBGPU_EP_ALLOW_SOFTWARE_ADAPTER=1` is set before registration; it is set then, and
/// Dawn chooses the adapter itself.
pub fn register(env: &Environment, ort_library: &Path) -> Result<(), String> {
    REGISTERED
        .get_or_init(|| {
            let lib = library(ort_library).ok_or_else(|| {
                format!(
                    "--provider webgpu: {LIBRARY} is not beside {} (run `bash scripts/setup.sh`, \
                     or set DREAMSCENE_WEBGPU_EP to its full path)",
                    ort_library.display()
                )
            })?;
            if !drm_card() && std::env::var_os("ORT_WEBGPU_EP_ALLOW_SOFTWARE_ADAPTER").is_none() {
                // Read by the factory at registration; set before any session exists.
                std::env::set_var("ORT_WEBGPU_EP_ALLOW_SOFTWARE_ADAPTER", "1");
            }
            env.register_ep_library("webgpu", &lib).map_err(|e| {
                format!(
                    "{}: cannot register the WebGPU provider: {e}",
                    lib.display()
                )
            })
        })
        .clone()
}

/// The WebGPU EP's devices of `env` (after [`register`]); an error when there is none.
pub fn devices(env: &Environment) -> Result<Vec<ort::device::Device<'_>>, String> {
    let devs: Vec<_> = env.devices().filter(|d| d.ep().ok() == Some(EP)).collect();
    if devs.is_empty() {
        return Err(
            "--provider webgpu: the WebGPU provider offers no device (Dawn found no usable \
             Vulkan adapter; on lavapipe it needs Mesa 25, see scripts/setup.sh)"
                .into(),
        );
    }
    Ok(devs)
}

/// The session options of the provider: Dawn on Vulkan.
pub fn options() -> Vec<(String, String)> {
    vec![(format!("{EP}.dawnBackendType"), "Vulkan".to_string())]
}

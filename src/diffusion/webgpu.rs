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

/// The session options of the provider: Dawn on Vulkan, then the `KEY=VALUE` pairs of
/// `$DREAMSCENE_WEBGPU_OPTIONS` (comma-separated, e.g. `validationMode=disabled,preferredLayout=NCHW`),
/// which override the defaults: the provider's settings can be measured without a rebuild.
pub fn options() -> Vec<(String, String)> {
    let extra = std::env::var("DREAMSCENE_WEBGPU_OPTIONS").unwrap_or_default();
    let (options, bad) = with_overrides(&extra);
    for b in bad {
        eprintln!("warning: DREAMSCENE_WEBGPU_OPTIONS: `{b}` is not KEY=VALUE; ignored");
    }
    options
}

/// The default options with `extra`'s pairs over them, each key prefixed by the EP's name,
/// and the pairs that are not `KEY=VALUE`.
fn with_overrides(extra: &str) -> (Vec<(String, String)>, Vec<String>) {
    let (options, bad) = super::runtime::merge_options(&[("dawnBackendType", "Vulkan")], extra);
    let options = options
        .into_iter()
        .map(|(k, v)| (format!("{EP}.{k}"), v))
        .collect();
    (options, bad)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overrides_replace_defaults_and_add_keys() {
        let (o, bad) = with_overrides(" validationMode=disabled, dawnBackendType=D3D12,oops,,=x");
        assert_eq!(
            o,
            vec![
                (format!("{EP}.dawnBackendType"), "D3D12".to_string()),
                (format!("{EP}.validationMode"), "disabled".to_string()),
            ],
            "an override replaces the default and a new key is added"
        );
        assert_eq!(
            bad,
            vec!["oops".to_string(), "=x".to_string()],
            "bad pairs are reported"
        );
        let (o, bad) = with_overrides("");
        assert_eq!(
            o,
            vec![(format!("{EP}.dawnBackendType"), "Vulkan".to_string())],
            "defaults"
        );
        assert!(bad.is_empty(), "nothing to report");
    }
}

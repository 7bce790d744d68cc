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

const NO_ADAPTER: &str = "--provider webgpu: Dawn accepts no Vulkan adapter here (on lavapipe \
     it needs Mesa 25, which scripts/setup.sh installs; --provider cpu runs everywhere)";

fn refused_adapter(e: &str) -> bool {
    e.contains("Failed to get a WebGPU adapter") || e.starts_with(NO_ADAPTER)
}

/// Runs `f` (a first WebGPU session: Dawn asks the Vulkan drivers for adapters) with the
/// process's native standard error sent to a file, and writes what it caught back to standard
/// error unless `f` failed only because no adapter was accepted: that failure is then the one
/// line of [`load_error`], without Dawn's and the Vulkan loader's warnings around it. Called
/// before any other thread of the program writes.
pub fn quiet_adapter_search<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    use std::io::{Read as _, Seek as _, Write as _};
    use std::os::fd::AsRawFd as _;
    let path = std::env::temp_dir().join(format!("dreamscene-stderr-{}", std::process::id()));
    let file = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(true)
        .open(&path);
    // Unlinked at once: the descriptor keeps it until dropped.
    let _ = std::fs::remove_file(&path);
    let Ok(mut file) = file else {
        return f();
    };
    let _ = std::io::stderr().flush();
    // SAFETY: dup of descriptor 2, which is open for the whole process; the copy is restored
    // and closed before returning, whatever `f` does short of aborting.
    let saved = unsafe { libc::dup(2) };
    // SAFETY: dup2 of a file this function owns onto descriptor 2, which the saved copy restores.
    let moved = saved >= 0 && unsafe { libc::dup2(file.as_raw_fd(), 2) } >= 0;
    if !moved {
        if saved >= 0 {
            // SAFETY: closing the descriptor dup returned above, used nowhere else.
            unsafe { libc::close(saved) };
        }
        return f();
    }
    let r = f();
    let _ = std::io::stderr().flush();
    // SAFETY: putting back the descriptor saved above, then closing the copy.
    unsafe {
        libc::dup2(saved, 2);
        libc::close(saved);
    }
    let mut caught = String::new();
    let _ = file.rewind().and_then(|_| file.read_to_string(&mut caught));
    if !matches!(&r, Err(e) if refused_adapter(e)) {
        eprint!("{caught}");
    }
    r
}

/// `shown`'s load error `e` in one line a user can act on: Dawn's refusal of every Vulkan
/// adapter (a driver without `shaderUniform*ArrayDynamicIndexing`, such as Debian 12's Mesa 22.3
/// lavapipe) says so and what to do instead of ONNX Runtime's stack of source locations.
pub fn load_error(shown: &str, e: &str) -> String {
    if refused_adapter(e) {
        NO_ADAPTER.to_string()
    } else {
        format!("{shown}: ONNX Runtime cannot load the model: {e}")
    }
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
    fn a_refused_adapter_is_one_line_with_what_to_do() {
        let ort = "/onnxruntime_src/x.cc:71 CreateProvider Error creating execution provider: \
                   [ONNXRuntimeError] : 11 : EP_FAIL : /onnxruntime_src/webgpu_context.cc:136 \
                   adapter_result.status == wgpu::RequestAdapterStatus::Success was false. \
                   Failed to get a WebGPU adapter: No supported adapters";
        let m = load_error("unet/model.onnx", ort);
        assert!(
            m.starts_with("--provider webgpu: Dawn accepts no Vulkan adapter")
                && m.contains("Mesa 25")
                && m.contains("--provider cpu")
                && !m.contains("onnxruntime_src")
                && !m.contains('\n'),
            "{m}"
        );
        assert!(refused_adapter(&m), "its own line is recognised again");
        let other = load_error("vae/model.onnx", "Protobuf parsing failed");
        assert_eq!(
            other,
            "vae/model.onnx: ONNX Runtime cannot load the model: Protobuf parsing failed"
        );
    }

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

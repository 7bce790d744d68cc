//! ONNX Runtime through `ort`, loaded dynamically by full path, and checked model sessions.
//!
//! The library is searched in this order: `$DREAMSCENE_ORT_LIB`, `$ORT_DYLIB_PATH`, then
//! `libonnxruntime.so*` in `$XDG_DATA_HOME/dreamscene/onnxruntime/` (default
//! `~/.local/share/dreamscene/onnxruntime/`, where `scripts/setup.sh` puts the library of the PyPI
//! `onnxruntime` wheel), and beside the executable (`./` and `lib/`).
use ort::ep::{ExecutionProvider as _, ExecutionProviderDispatch};
use ort::session::{Session, SessionInputValue};
use ort::value::{PrimitiveTensorElementType, Tensor, TensorElementType, TensorRef, ValueType};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The ONNX Runtime version the bindings were built for (`api-31`).
pub const EXPECTED_VERSION: &str = "1.31";

/// Execution provider for the diffusion models.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Provider {
    /// ONNX Runtime's CPU provider.
    #[default]
    Cpu,
    /// CUDA (needs a library built with it, e.g. from the `onnxruntime-gpu` wheel).
    Cuda,
    /// WebGPU on Vulkan (the `onnxruntime-ep-webgpu` plugin library beside ONNX Runtime).
    Webgpu,
    /// A GPU provider on a real GPU, else the CPU (`doctor` says which and why).
    Auto,
}

/// What [`choose_auto`] looks at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GpuFacts {
    /// Linux shows a GPU (a DRM card under /sys/class/drm, or NVIDIA's /dev/nvidiactl).
    pub real_gpu: bool,
    /// The loaded ONNX Runtime library has the CUDA provider, and a graph loads on it (its CUDA
    /// and cuDNN libraries and a device are found).
    pub cuda: bool,
    /// The WebGPU plugin library is installed beside ONNX Runtime.
    pub webgpu: bool,
}

/// The provider `auto` takes and why: on a real GPU, CUDA when the library has it, else WebGPU
/// when its plugin is installed; otherwise the CPU (a software Vulkan device such as lavapipe is
/// no faster than the CPU provider).
pub fn choose_auto(f: GpuFacts) -> (Provider, &'static str) {
    match f {
        GpuFacts {
            real_gpu: false, ..
        } => (
            Provider::Cpu,
            "no GPU (no DRM card in /sys/class/drm, no /dev/nvidiactl)",
        ),
        GpuFacts { cuda: true, .. } => (
            Provider::Cuda,
            "a GPU, and the CUDA provider of the ONNX Runtime library loads",
        ),
        GpuFacts { webgpu: true, .. } => (
            Provider::Webgpu,
            "a GPU, and the WebGPU provider is installed beside ONNX Runtime",
        ),
        _ => (
            Provider::Cpu,
            "a GPU, but neither the CUDA nor the WebGPU provider is installed \
             (`bash scripts/setup.sh` installs WebGPU, `--cuda` the CUDA build)",
        ),
    }
}

/// The facts of this machine and library (the library is loaded if it can be).
pub fn gpu_facts() -> GpuFacts {
    let real_gpu = super::webgpu::drm_card() || Path::new("/dev/nvidiactl").exists();
    let lib = loaded().ok();
    GpuFacts {
        real_gpu,
        cuda: real_gpu && lib.is_some() && cuda_loads(),
        webgpu: lib
            .is_some_and(|l| super::webgpu::library(&l.library).is_some_and(|p| p.is_file())),
    }
}

/// Whether the CUDA provider loads here, asked once per process (it loads CUDA itself).
fn cuda_loads() -> bool {
    static LOADS: OnceLock<bool> = OnceLock::new();
    *LOADS.get_or_init(|| {
        ort::ep::CUDA::is_available().unwrap_or(false) && check_provider(Provider::Cuda).is_ok()
    })
}

impl Provider {
    /// The concrete provider: `auto` chosen for this machine, others as they are.
    pub fn resolved(self) -> Provider {
        match self {
            Provider::Auto => choose_auto(gpu_facts()).0,
            p => p,
        }
    }
}

/// Where the library may be, in search order, each with how it was found.
pub fn library_candidates() -> Vec<(PathBuf, &'static str)> {
    let mut out = vec![];
    for var in ["DREAMSCENE_ORT_LIB", "ORT_DYLIB_PATH"] {
        if let Some(p) = crate::util::env_path(var) {
            out.push((p, var));
        }
    }
    let mut dirs: Vec<PathBuf> = vec![];
    if let Some(d) = crate::util::env_path("XDG_DATA_HOME") {
        dirs.push(d.join("dreamscene/onnxruntime"));
    }
    if let Some(h) = crate::util::env_path("HOME") {
        dirs.push(h.join(".local/share/dreamscene/onnxruntime"));
    }
    if let Some(exe_dir) = std::env::current_exe()
        .ok()
        .and_then(|e| e.parent().map(Path::to_path_buf))
    {
        dirs.push(exe_dir.join("lib"));
        dirs.push(exe_dir);
    }
    for d in dirs {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        let mut libs: Vec<PathBuf> = entries
            .flatten()
            .map(|e| e.path())
            .filter(|p| {
                p.file_name()
                    .and_then(|n| n.to_str())
                    .is_some_and(|n| n.starts_with("libonnxruntime.so"))
            })
            .collect();
        // Prefer the fully versioned name (libonnxruntime.so.1.31.1) over symlinks.
        libs.sort_by_key(|p| std::cmp::Reverse(p.as_os_str().len()));
        out.extend(libs.into_iter().map(|p| (p, "search path")));
    }
    out
}

struct Loaded {
    env: ort::environment::Environment,
    library: PathBuf,
}

static RUNTIME: OnceLock<Result<Loaded, String>> = OnceLock::new();

fn load() -> Result<Loaded, String> {
    let candidates = library_candidates();
    // A path named explicitly must exist; it is not silently skipped.
    if let Some((p, how)) = candidates
        .iter()
        .find(|(p, how)| *how != "search path" && !p.is_file())
    {
        return Err(format!(
            "{how}={}: no such file (it must be the full path of libonnxruntime.so.{EXPECTED_VERSION}.x)",
            p.display()
        ));
    }
    let Some((path, how)) = candidates.into_iter().find(|(p, _)| p.is_file()) else {
        return Err(format!(
            "ONNX Runtime {EXPECTED_VERSION} library not found (looked at $DREAMSCENE_ORT_LIB, \
             $ORT_DYLIB_PATH, ~/.local/share/dreamscene/onnxruntime/ and beside the executable); \
             run `bash scripts/setup.sh`, or set DREAMSCENE_ORT_LIB to the full path of \
             libonnxruntime.so.{EXPECTED_VERSION}.x"
        ));
    };
    let path = path.canonicalize().unwrap_or(path);
    let shown = path.display().to_string();
    let builder = std::panic::catch_unwind(|| ort::init_from(&path))
        .map_err(|_| format!("{shown} (from {how}): ONNX Runtime panicked while loading"))?
        .map_err(|e| {
            format!("{shown} (from {how}): cannot load ONNX Runtime: {e} (this build needs {EXPECTED_VERSION}.x)")
        })?;
    let env = builder
        .with_name("dreamscene")
        .build()
        .map_err(|e| format!("{shown}: cannot create the ONNX Runtime environment: {e}"))?;
    Ok(Loaded { env, library: path })
}

fn loaded() -> Result<&'static Loaded, String> {
    RUNTIME.get_or_init(load).as_ref().map_err(Clone::clone)
}

/// What `doctor` reports.
#[derive(Debug, Clone)]
pub struct RuntimeInfo {
    pub library: PathBuf,
    /// The version, from the library's build information (or its file name).
    pub version: String,
    pub build_info: String,
    pub providers: Vec<String>,
}

/// Loads the library if needed and describes it.
pub fn info() -> Result<RuntimeInfo, String> {
    let l = loaded()?;
    let build_info = ort::info().to_string();
    let version = build_info
        .split(|c: char| c == ',' || c.is_whitespace())
        .find_map(|f| f.strip_prefix("git-branch=rel-"))
        .map(str::to_string)
        .or_else(|| {
            l.library
                .file_name()
                .and_then(|n| n.to_str())
                .and_then(|n| n.strip_prefix("libonnxruntime.so."))
                .map(str::to_string)
        })
        .unwrap_or_else(|| "unknown".into());
    Ok(RuntimeInfo {
        library: l.library.clone(),
        version,
        build_info,
        providers: available_providers()?,
    })
}

/// The execution providers this library was built with.
pub fn available_providers() -> Result<Vec<String>, String> {
    loaded()?;
    let api = ort::api();
    let mut list: *mut *mut std::ffi::c_char = std::ptr::null_mut();
    let mut n: std::ffi::c_int = 0;
    // SAFETY: the library is loaded; the API fills `list` with `n` C strings that are released
    // with the matching call below.
    unsafe {
        let status = (api.GetAvailableProviders)(&mut list, &mut n);
        if !status.0.is_null() {
            (api.ReleaseStatus)(status.0);
            return Err("ONNX Runtime could not list its execution providers".into());
        }
        let mut out = vec![];
        for i in 0..n.max(0) as usize {
            let p = *list.add(i);
            if !p.is_null() {
                out.push(std::ffi::CStr::from_ptr(p).to_string_lossy().into_owned());
            }
        }
        let status = (api.ReleaseAvailableProviders)(list, n);
        if !status.0.is_null() {
            (api.ReleaseStatus)(status.0);
        }
        Ok(out)
    }
}

/// Whether the loaded ONNX Runtime library can run `p`; the error says why not and what to do.
/// The CUDA provider is a library of its own, loaded with its CUDA and cuDNN libraries only when
/// a session asks for it, and the WebGPU provider asks Dawn for an adapter only then: each counts
/// as runnable once a small graph loads on it.
pub fn check_provider(p: Provider) -> Result<(), String> {
    provider_dispatch(p)?;
    match p.resolved() {
        Provider::Cuda => super::probe::loads(p)?,
        Provider::Webgpu => super::webgpu::quiet_adapter_search(|| super::probe::loads(p))?,
        _ => {}
    }
    Ok(())
}

fn provider_dispatch(p: Provider) -> Result<Vec<ExecutionProviderDispatch>, String> {
    match p.resolved() {
        Provider::Auto => Ok(vec![ort::ep::CPU::default().build()]),
        Provider::Cpu => Ok(vec![ort::ep::CPU::default().build()]),
        Provider::Webgpu => {
            // Reached through its devices (OnnxModel::load), not appended by name.
            let l = loaded()?;
            super::webgpu::register(&l.env, &l.library)?;
            super::webgpu::devices(&l.env)?;
            Ok(vec![])
        }
        Provider::Cuda => {
            // The project's library is loaded first: asking ort before would make it load its own.
            let library = &loaded()?.library;
            if !ort::ep::CUDA::is_available().unwrap_or(false) {
                return Err(format!(
                    "--provider cuda: the ONNX Runtime library at {} has no CUDA provider (it has: \
                     {}); install the library of the `onnxruntime-gpu` wheel and point \
                     DREAMSCENE_ORT_LIB at it",
                    library.display(),
                    available_providers()?.join(", ")
                ));
            }
            Ok(vec![cuda_ep().build().error_on_failure()])
        }
    }
}

/// `defaults` with the `KEY=VALUE` pairs of a comma-separated option string over them (a pair
/// replaces the default of its key, or is added), and the parts that are not such a pair. The
/// strings are `DREAMSCENE_WEBGPU_OPTIONS` and `DREAMSCENE_CUDA_OPTIONS`.
pub(crate) fn merge_options(
    defaults: &[(&str, &str)],
    extra: &str,
) -> (Vec<(String, String)>, Vec<String>) {
    let mut options: Vec<(String, String)> = defaults
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let mut bad = vec![];
    for pair in extra.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        match pair.split_once('=') {
            Some((k, v)) if !k.trim().is_empty() => {
                let (k, v) = (k.trim().to_string(), v.trim().to_string());
                match options.iter_mut().find(|(key, _)| *key == k) {
                    Some(o) => o.1 = v,
                    None => options.push((k, v)),
                }
            }
            _ => bad.push(pair.to_string()),
        }
    }
    (options, bad)
}

/// The CUDA provider's settings that differ from ONNX Runtime's defaults: cuDNN's heuristic
/// choice of convolution algorithm. The default, an exhaustive benchmark of every algorithm, runs
/// again for each new input shape, and the UNet's runs change shape within every iteration (the
/// null prompt's run, then the chain points'); ONNX Runtime's issue tracker reports 0.3–1.3 s per
/// new shape for it and no loss in steady state for the heuristic.
const CUDA_DEFAULTS: [(&str, &str); 1] = [("cudnn_conv_algo_search", "HEURISTIC")];

/// The CUDA provider with [`CUDA_DEFAULTS`] and the `KEY=VALUE` pairs of
/// `$DREAMSCENE_CUDA_OPTIONS` over them (the provider's own option names, e.g.
/// `cudnn_conv_algo_search=EXHAUSTIVE,prefer_nhwc=1`): its settings can be measured without a
/// rebuild.
fn cuda_ep() -> ort::ep::CUDA {
    use ort::ep::ArbitrarilyConfigurableExecutionProvider as _;
    let extra = std::env::var("DREAMSCENE_CUDA_OPTIONS").unwrap_or_default();
    let (pairs, bad) = merge_options(&CUDA_DEFAULTS, &extra);
    for b in bad {
        eprintln!("warning: DREAMSCENE_CUDA_OPTIONS: `{b}` is not KEY=VALUE; ignored");
    }
    pairs
        .into_iter()
        .fold(ort::ep::CUDA::default(), |ep, (k, v)| {
            ep.with_arbitrary_config(k, v)
        })
}

/// A session builder on `provider` with `threads` intra-op threads; errors name `shown`.
fn builder(
    provider: Provider,
    threads: Option<usize>,
    shown: &str,
) -> Result<ort::session::builder::SessionBuilder, String> {
    let env = &loaded()?.env;
    let provider = provider.resolved();
    let eps = provider_dispatch(provider)?;
    let mut b = if provider == Provider::Webgpu {
        let devs = super::webgpu::devices(env)?;
        Session::builder(env)
            .and_then(|b| {
                b.with_devices(devs, Some(&super::webgpu::options()))
                    .map_err(|e| e.into())
            })
            .map_err(|e| format!("{shown}: {e}"))?
    } else {
        Session::builder(env)
            .and_then(|b| b.with_execution_providers(eps).map_err(|e| e.into()))
            .map_err(|e| format!("{shown}: {e}"))?
    };
    if let Some(n) = threads {
        b = b
            .with_intra_threads(n)
            .map_err(|e| format!("{shown}: {e}"))?;
    }
    Ok(b)
}

/// A tensor's element type and rank as a model declares them.
#[derive(Debug, Clone, PartialEq)]
pub struct Port {
    pub name: String,
    pub ty: TensorElementType,
    /// Dimensions, −1 where dynamic.
    pub dims: Vec<i64>,
}

/// What a model must declare for one input or output: one of `names`, one of `ranks`, one of
/// `types`.
pub struct PortSpec<'a> {
    pub names: &'a [&'a str],
    pub ranks: &'a [usize],
    pub types: &'a [TensorElementType],
}

/// A loaded ONNX model with its declared inputs and outputs.
pub struct OnnxModel {
    pub path: PathBuf,
    session: Session,
    pub inputs: Vec<Port>,
    pub outputs: Vec<Port>,
    /// Seconds the last [`Self::run`] spent inside ONNX Runtime's `session.run` (the rest of
    /// the call is the host's conversion of inputs and outputs).
    last_session: f64,
    /// A delay added to every run's input conversion (a test hook: see
    /// [`Self::plant_slow_conversion`]).
    slow_conversion: std::time::Duration,
}

fn port(name: &str, t: &ValueType) -> Option<Port> {
    match t {
        ValueType::Tensor { ty, shape, .. } => Some(Port {
            name: name.to_string(),
            ty: *ty,
            dims: shape.to_vec(),
        }),
        _ => None,
    }
}

fn type_name(t: TensorElementType) -> &'static str {
    match t {
        TensorElementType::Float32 => "float32",
        TensorElementType::Float16 => "float16",
        TensorElementType::Float64 => "float64",
        TensorElementType::Int32 => "int32",
        TensorElementType::Int64 => "int64",
        TensorElementType::Bfloat16 => "bfloat16",
        _ => "another type",
    }
}

/// A host tensor of `shape` from `values`, as a session input.
fn tensor<T: PrimitiveTensorElementType + std::fmt::Debug + Clone + 'static>(
    shape: Vec<i64>,
    values: Vec<T>,
) -> ort::Result<SessionInputValue<'static>> {
    Ok(Tensor::from_array((shape, values))?.into())
}

/// `data` as a session input of element type `ty`, converted once and straight to it: f32
/// latents and images are lent to ONNX Runtime as they are for an f32 model, rounded to f16
/// in one pass for an f16 one. Every value the pipeline feeds (latents, timesteps, token ids
/// < 2^24) converts exactly, or rounds as its one conversion would. `None` for a type
/// dreamscene cannot feed.
fn input_value<'a>(
    shape: Vec<i64>,
    data: &Data<'a>,
    ty: TensorElementType,
) -> ort::Result<Option<SessionInputValue<'a>>> {
    use TensorElementType as E;
    let v = match (data, ty) {
        (Data::F32(d), E::Float32) => TensorRef::from_array_view((shape, *d))?.into(),
        (Data::F32(d), E::Float16) => tensor(shape, super::convert::f32_to_f16(d))?,
        (Data::F32(d), E::Int64) => tensor(shape, d.iter().map(|v| v.round() as i64).collect())?,
        (Data::F32(d), E::Int32) => tensor(shape, d.iter().map(|v| v.round() as i32).collect())?,
        (Data::I64(d), E::Int64) => TensorRef::from_array_view((shape, *d))?.into(),
        (Data::I64(d), E::Int32) => tensor(shape, d.iter().map(|v| *v as i32).collect())?,
        (Data::I64(d), E::Float32) => tensor(shape, d.iter().map(|v| *v as f32).collect())?,
        (Data::I64(d), E::Float16) => tensor(
            shape,
            d.iter().map(|v| half::f16::from_f64(*v as f64)).collect(),
        )?,
        _ => return Ok(None),
    };
    Ok(Some(v))
}

/// One output tensor: its shape and its values as f32.
pub type Output = (Vec<i64>, Vec<f32>);

/// Host data for one input; converted to the model's declared element type.
pub enum Data<'a> {
    F32(&'a [f32]),
    I64(&'a [i64]),
}

impl OnnxModel {
    /// Loads `path` on `provider`, then checks the declared inputs and outputs against `inputs` /
    /// `outputs` (in order). Errors name the file.
    pub fn load(
        path: &Path,
        provider: Provider,
        threads: Option<usize>,
        inputs: &[PortSpec],
        outputs: &[PortSpec],
    ) -> Result<OnnxModel, String> {
        let shown = path.display().to_string();
        if !path.is_file() {
            return Err(format!("{shown}: model file missing"));
        }
        let session = builder(provider, threads, &shown)?
            .commit_from_file(path)
            .map_err(|e| super::webgpu::load_error(&shown, &e.to_string()))?;
        Self::checked(path, session, inputs, outputs)
    }

    /// Loads an in-memory model (named `name` in errors) on `provider`, checked as [`Self::load`].
    pub fn load_bytes(
        name: &str,
        bytes: &[u8],
        provider: Provider,
        threads: Option<usize>,
        inputs: &[PortSpec],
        outputs: &[PortSpec],
    ) -> Result<OnnxModel, String> {
        let session = builder(provider, threads, name)?
            .commit_from_memory(bytes)
            .map_err(|e| super::webgpu::load_error(name, &e.to_string()))?;
        Self::checked(Path::new(name), session, inputs, outputs)
    }

    fn checked(
        path: &Path,
        session: Session,
        inputs: &[PortSpec],
        outputs: &[PortSpec],
    ) -> Result<OnnxModel, String> {
        let shown = path.display().to_string();
        let collect = |list: &[ort::value::Outlet], what: &str| -> Result<Vec<Port>, String> {
            list.iter()
                .map(|o| {
                    port(o.name(), o.dtype())
                        .ok_or_else(|| format!("{shown}: {what} {:?} is not a tensor", o.name()))
                })
                .collect()
        };
        let model = OnnxModel {
            inputs: collect(session.inputs(), "input")?,
            outputs: collect(session.outputs(), "output")?,
            path: path.to_path_buf(),
            session,
            last_session: 0.0,
            slow_conversion: std::time::Duration::ZERO,
        };
        // Every input must be fed; extra outputs (e.g. pooler_output) are allowed.
        check_ports(&shown, "input", &model.inputs, inputs, true)?;
        check_ports(&shown, "output", &model.outputs, outputs, false)?;
        Ok(model)
    }

    /// Seconds the last [`Self::run`] spent in ONNX Runtime's `session.run`, without the
    /// conversion of its inputs and outputs.
    pub fn last_session_seconds(&self) -> f64 {
        self.last_session
    }

    /// Makes every later run's input conversion take `delay` longer: a test hook that shows
    /// where timings count the conversions (never inside the model's own time).
    pub fn plant_slow_conversion(&mut self, delay: std::time::Duration) {
        self.slow_conversion = delay;
    }

    /// Checks a declared dimension where it is static: `axis` of input (or output) `port` must be
    /// one of `allowed`. Dynamic dimensions (−1) pass.
    pub fn expect_dim(
        &self,
        input: bool,
        port: usize,
        axis: usize,
        allowed: &[i64],
        why: &str,
    ) -> Result<(), String> {
        let p = if input {
            &self.inputs[port]
        } else {
            &self.outputs[port]
        };
        match p.dims.get(axis) {
            Some(&d) if d >= 0 && !allowed.contains(&d) => Err(format!(
                "{}: {} {:?} has {d} at axis {axis}, expected {} ({why})",
                self.path.display(),
                if input { "input" } else { "output" },
                p.name,
                allowed
                    .iter()
                    .map(|a| a.to_string())
                    .collect::<Vec<_>>()
                    .join(" or ")
            )),
            _ => Ok(()),
        }
    }

    /// Runs the model on `inputs` (one per declared input, in order) and returns every output as
    /// f32 with its shape.
    ///
    /// [`Self::last_session_seconds`] tells afterwards how much of the call ONNX Runtime took.
    pub fn run(&mut self, inputs: &[(Vec<i64>, Data)]) -> Result<Vec<Output>, String> {
        let shown = self.path.display().to_string();
        if inputs.len() != self.inputs.len() {
            return Err(format!(
                "{shown}: {} inputs given, the model has {}",
                inputs.len(),
                self.inputs.len()
            ));
        }
        let mut values: Vec<(String, SessionInputValue)> = vec![];
        for ((shape, data), p) in inputs.iter().zip(&self.inputs) {
            if p.dims.len() != shape.len()
                || p.dims.iter().zip(shape).any(|(d, s)| *d >= 0 && d != s)
            {
                return Err(format!(
                    "{shown}: input {:?} has shape {:?}, the model declares {:?}",
                    p.name, shape, p.dims
                ));
            }
            let err = |e: ort::Error| format!("{shown}: input {:?}: {e}", p.name);
            let v = input_value(shape.clone(), data, p.ty)
                .map_err(err)?
                .ok_or_else(|| {
                    format!(
                        "{shown}: input {:?} is {}, which dreamscene cannot feed",
                        p.name,
                        type_name(p.ty)
                    )
                })?;
            values.push((p.name.clone(), v));
        }
        std::thread::sleep(self.slow_conversion);
        let t0 = std::time::Instant::now();
        let outputs = self.session.run(values);
        self.last_session = t0.elapsed().as_secs_f64();
        let outputs = outputs.map_err(|e| format!("{shown}: run failed: {e}"))?;
        let mut out = vec![];
        for p in &self.outputs {
            let v = &outputs[p.name.as_str()];
            let r = match p.ty {
                TensorElementType::Float16 => v
                    .try_extract_tensor::<half::f16>()
                    .map(|(s, d)| (s.to_vec(), super::convert::f16_to_f32(d))),
                _ => v
                    .try_extract_tensor::<f32>()
                    .map(|(s, d)| (s.to_vec(), d.to_vec())),
            };
            let (shape, data) = r.map_err(|e| format!("{shown}: output {:?}: {e}", p.name))?;
            if !super::convert::all_finite(&data) {
                return Err(format!(
                    "{shown}: output {:?} has non-finite values (NaN/Inf)",
                    p.name
                ));
            }
            out.push((shape, data));
        }
        Ok(out)
    }
}

fn check_ports(
    shown: &str,
    what: &str,
    have: &[Port],
    want: &[PortSpec],
    exact: bool,
) -> Result<(), String> {
    let describe = |ports: &[Port]| {
        ports
            .iter()
            .map(|p| format!("{} ({}, rank {})", p.name, type_name(p.ty), p.dims.len()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if have.len() < want.len() || (exact && have.len() != want.len()) {
        return Err(format!(
            "{shown}: expected {} {what}s ({}), the model has {}: {}",
            want.len(),
            want.iter()
                .map(|w| w.names.join("|"))
                .collect::<Vec<_>>()
                .join(", "),
            have.len(),
            describe(have)
        ));
    }
    for (h, w) in have.iter().zip(want) {
        if !w.names.contains(&h.name.as_str()) {
            return Err(format!(
                "{shown}: {what} {:?} where {} was expected (the model's {what}s: {})",
                h.name,
                w.names.join(" or "),
                describe(have)
            ));
        }
        if !w.ranks.contains(&h.dims.len()) {
            return Err(format!(
                "{shown}: {what} {:?} has rank {}, expected {}",
                h.name,
                h.dims.len(),
                w.ranks
                    .iter()
                    .map(|r| r.to_string())
                    .collect::<Vec<_>>()
                    .join(" or ")
            ));
        }
        if !w.types.contains(&h.ty) {
            return Err(format!(
                "{shown}: {what} {:?} is {}, expected {}",
                h.name,
                type_name(h.ty),
                w.types
                    .iter()
                    .map(|t| type_name(*t))
                    .collect::<Vec<_>>()
                    .join(" or ")
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cuda_options_override_the_heuristic_default() {
        let (o, bad) = merge_options(
            &CUDA_DEFAULTS,
            " cudnn_conv_algo_search = EXHAUSTIVE ,prefer_nhwc=1,x,,=2",
        );
        assert_eq!(
            o,
            vec![
                (
                    "cudnn_conv_algo_search".to_string(),
                    "EXHAUSTIVE".to_string()
                ),
                ("prefer_nhwc".to_string(), "1".to_string()),
            ]
        );
        assert_eq!(bad, vec!["x".to_string(), "=2".to_string()]);
        let (o, bad) = merge_options(&CUDA_DEFAULTS, "");
        assert_eq!(
            o,
            vec![(
                "cudnn_conv_algo_search".to_string(),
                "HEURISTIC".to_string()
            )]
        );
        assert!(bad.is_empty());
    }

    #[test]
    fn auto_takes_a_gpu_provider_only_on_a_real_gpu() {
        let f = |real_gpu, cuda, webgpu| {
            choose_auto(GpuFacts {
                real_gpu,
                cuda,
                webgpu,
            })
            .0
        };
        // No real GPU: the CPU, whatever is installed (lavapipe is no faster).
        for (c, w) in [(false, false), (true, false), (false, true), (true, true)] {
            assert_eq!(f(false, c, w), Provider::Cpu);
        }
        assert_eq!(f(true, true, true), Provider::Cuda);
        assert_eq!(f(true, true, false), Provider::Cuda);
        assert_eq!(f(true, false, true), Provider::Webgpu);
        let (p, why) = choose_auto(GpuFacts {
            real_gpu: true,
            cuda: false,
            webgpu: false,
        });
        assert_eq!(p, Provider::Cpu);
        assert!(why.contains("setup.sh"), "{why}");
        assert_eq!(Provider::Webgpu.resolved(), Provider::Webgpu);
    }
}

//! One loaded Stable Diffusion pipeline per model directory and provider for the whole process.
//! Opening a pipeline builds an ONNX Runtime session per model (and, on a GPU provider, probes
//! it); an `edit` that adds an object and then re-optimises the environment around it would
//! otherwise pay that again for every prior it makes, as would any caller making priors in turn.
//! [`super::prior_spec::open_sd`] takes a pipeline from here when one was given back, and an
//! [`super::prior::SdPrior`] gives its pipeline back when it is dropped. Nothing else is shared:
//! prompts and their embeddings stay with each prior.
use crate::diffusion::model::StableDiffusion;
use crate::diffusion::runtime::Provider;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// Which pipeline: the model directory and the provider asked for.
pub type PoolKey = (PathBuf, Provider);

static IDLE: Mutex<Vec<(PoolKey, StableDiffusion)>> = Mutex::new(Vec::new());
static OPENED: AtomicUsize = AtomicUsize::new(0);

/// The key of `dir` (made absolute where it can be) on `provider`.
pub fn key(dir: &Path, provider: Provider) -> PoolKey {
    (
        dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf()),
        provider,
    )
}

/// An idle pipeline of `key`, if one was given back.
pub fn take(key: &PoolKey) -> Option<StableDiffusion> {
    let mut idle = IDLE.lock().unwrap_or_else(|e| e.into_inner());
    let at = idle.iter().position(|(k, _)| k == key)?;
    Some(idle.swap_remove(at).1)
}

/// Records that a pipeline was opened (not taken from the pool).
pub fn opened() {
    OPENED.fetch_add(1, Ordering::Relaxed);
}

/// Pipelines opened by this process so far.
pub fn pipelines_opened() -> usize {
    OPENED.load(Ordering::Relaxed)
}

/// Gives a pipeline back for the next prior of `key`: its batch cap and time counters are reset;
/// what its provider probe learned is kept.
pub fn give_back(key: PoolKey, mut sd: StableDiffusion) {
    sd.set_unet_max_batch(None);
    sd.take_times();
    IDLE.lock()
        .unwrap_or_else(|e| e.into_inner())
        .push((key, sd));
}

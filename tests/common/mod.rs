//! Helpers shared by the GPU tests.
#![allow(dead_code)]
use dreamscene::gpu::Context;
use rand::SeedableRng;

/// Opens the Vulkan device. A GPU test never passes without one: no device is a failure, with
/// the reason (install mesa-vulkan-drivers for lavapipe).
pub fn gpu() -> Context {
    let ctx = Context::new()
        .unwrap_or_else(|e| panic!("GPU test needs a Vulkan device and found none: {e}"));
    if std::env::var("DREAMSCENE_REQUIRE_VALIDATION").is_ok_and(|v| v == "1") {
        assert!(
            ctx.info().validation,
            "validation layer required but not active"
        );
    }
    ctx
}

/// Deterministic RNG for a test.
pub fn rng(seed: u64) -> rand_chacha::ChaCha8Rng {
    rand_chacha::ChaCha8Rng::seed_from_u64(seed)
}

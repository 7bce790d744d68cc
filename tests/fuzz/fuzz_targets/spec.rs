//! The spec.json reader: any bytes, no panic; an accepted spec validates.
#![no_main]
use dreamscene::plan::spec::SceneSpec;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(spec) = SceneSpec::parse(data) {
        assert!(spec.validate().is_ok());
    }
});

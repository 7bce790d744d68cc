//! The layout.json reader: any bytes, no panic; an accepted layout holds finite numbers.
#![no_main]
use dreamscene::plan::spec::Layout;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(l) = Layout::parse(data) {
        assert!(l.room.size.iter().all(|v| v.is_finite()));
    }
});

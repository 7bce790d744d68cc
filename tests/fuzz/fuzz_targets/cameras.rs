//! The cameras.json reader: any bytes, no panic; accepted cameras have sizes, focal lengths and
//! names that stay inside the output directory.
#![no_main]
use dreamscene::camera::parse_cameras;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(cams) = parse_cameras(data) {
        assert!(!cams.is_empty());
        for c in &cams {
            assert!(c.width > 0 && c.height > 0 && c.fx > 0.0 && c.fy > 0.0);
            assert!(!std::path::Path::new(&c.img_name).is_absolute());
        }
    }
});

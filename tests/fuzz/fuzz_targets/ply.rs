//! The splat PLY reader: any bytes, no panic, no hang, no allocation sized by the header; what it
//! accepts is a consistent cloud of finite values.
#![no_main]
use dreamscene::splat::ply::{parse_ply, Invalid};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for invalid in [Invalid::Refuse, Invalid::Drop] {
        if let Ok(r) = parse_ply(&mut &data[..], invalid) {
            let g = &r.gaussians;
            assert!(g.check().is_ok());
            let flat = g.means.iter().flatten().chain(g.scales.iter().flatten());
            let flat = flat.chain(g.rotations.iter().flatten()).chain(&g.opacities);
            assert!(flat.chain(&g.sh).all(|v| v.is_finite()));
        }
    }
});

//! Property tests of every reader of untrusted input, on a fixed budget: random bytes, and valid
//! files with random bytes changed, cut short or spliced. No reader may panic or hang, and what
//! a reader accepts must hold its promises (a consistent, finite cloud; validated cameras).
//! The longer-running cargo-fuzz targets for the same readers live in `tests/fuzz/`.
use super::{cam, cams_json, foreign_ply, Enc};
use dreamscene::camera::parse_cameras;
use dreamscene::plan::llm::parse_loose_json;
use dreamscene::plan::spec::{Layout, SceneSpec};
use dreamscene::splat::ply::{parse_ply, Invalid};
use dreamscene::splat::Gaussians;
use proptest::prelude::*;
use std::sync::OnceLock;

/// Cases per property: about a second in a debug build all together.
const CASES: u32 = 200;

/// Valid inputs to mutate: PLYs in each encoding, cameras, a spec and a layout.
struct Seeds {
    plys: Vec<Vec<u8>>,
    cameras: Vec<u8>,
    spec: Vec<u8>,
    layout: Vec<u8>,
}

fn seeds() -> &'static Seeds {
    static S: OnceLock<Seeds> = OnceLock::new();
    S.get_or_init(|| {
        let g = Gaussians::random(&mut crate::common::rng(50), 3, [-1.0; 3], [1.0; 3], 0.1, 1);
        let plys = [
            (Enc::Ascii, "float"),
            (Enc::Little, "float"),
            (Enc::Big, "double"),
        ]
        .map(|(e, t)| foreign_ply(&g, e, t))
        .to_vec();
        let spec_text = include_str!("../data/living_room.json");
        let spec = SceneSpec::parse(spec_text.as_bytes()).expect("fixture spec");
        let layout =
            dreamscene::plan::gcp::layout(&spec, dreamscene::plan::gcp::LayoutOptions::seeded(3))
                .expect("fixture layout");
        Seeds {
            plys,
            cameras: cams_json(&[cam(0, "a"), cam(1, "sub/b")]),
            spec: spec_text.as_bytes().to_vec(),
            layout: serde_json::to_vec_pretty(&layout).expect("layout serialises"),
        }
    })
}

/// An edit of a valid file: bytes overwritten, a cut, or a span repeated (counts and lists that
/// disagree with the data).
#[derive(Debug, Clone)]
enum Edit {
    Set(usize, u8),
    Cut(usize),
    Repeat(usize, usize),
    Digits(usize, String),
}

fn edits() -> impl Strategy<Value = Vec<Edit>> {
    prop::collection::vec(
        prop_oneof![
            4 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Set(i, b)),
            1 => any::<usize>().prop_map(Edit::Cut),
            1 => (any::<usize>(), 1usize..64).prop_map(|(i, n)| Edit::Repeat(i, n)),
            2 => (any::<usize>(), "[0-9]{1,20}|-[0-9]{1,3}|nan|inf|1e999").prop_map(|(i, s)| Edit::Digits(i, s)),
        ],
        1..6,
    )
}

fn apply(seed: &[u8], edits: &[Edit]) -> Vec<u8> {
    let mut b = seed.to_vec();
    for e in edits {
        if b.is_empty() {
            break;
        }
        match e {
            Edit::Set(i, v) => {
                let i = i % b.len();
                b[i] = *v;
            }
            Edit::Cut(i) => b.truncate(i % b.len()),
            Edit::Repeat(i, n) => {
                let i = i % b.len();
                let span = b[i..(i + n).min(b.len())].to_vec();
                b.splice(i..i, span);
            }
            Edit::Digits(i, s) => {
                // Replace the number (or word) at a position: a count, a length, a value.
                let i = i % b.len();
                let end = b[i..]
                    .iter()
                    .position(|c| !c.is_ascii_alphanumeric() && *c != b'.' && *c != b'-')
                    .map_or(b.len(), |k| i + k);
                b.splice(i..end, s.bytes());
            }
        }
    }
    b
}

fn check_ply(bytes: &[u8]) {
    for invalid in [Invalid::Refuse, Invalid::Drop] {
        if let Ok(r) = parse_ply(&mut &bytes[..], invalid) {
            let g = &r.gaussians;
            g.check().expect("an accepted cloud is consistent");
            let values = g.means.iter().flatten().chain(g.scales.iter().flatten());
            let values = values
                .chain(g.rotations.iter().flatten())
                .chain(&g.opacities);
            assert!(
                values.chain(&g.sh).all(|v| v.is_finite()),
                "an accepted cloud has finite values"
            );
            assert!(
                g.rotations.iter().all(|q| q.iter().any(|v| *v != 0.0)),
                "an accepted cloud has no zero quaternion"
            );
            if invalid == Invalid::Refuse {
                assert_eq!(r.dropped, 0, "refusing mode drops nothing");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: CASES, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn ply_reader_survives_random_bytes(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        check_ply(&bytes);
        let mut with_magic = b"ply\n".to_vec();
        with_magic.extend(&bytes);
        check_ply(&with_magic);
    }

    #[test]
    fn ply_reader_survives_edited_files(which in 0usize..3, e in edits()) {
        check_ply(&apply(&seeds().plys[which], &e));
    }

    #[test]
    fn cameras_reader_survives_edited_and_random_input(
        e in edits(),
        bytes in prop::collection::vec(any::<u8>(), 0..256),
    ) {
        for input in [apply(&seeds().cameras, &e), bytes] {
            if let Ok(cams) = parse_cameras(&input) {
                prop_assert!(!cams.is_empty());
                for c in &cams {
                    prop_assert!(c.width > 0 && c.fx.is_finite() && c.fx > 0.0);
                    prop_assert!(!c.img_name.contains(".."));
                }
            }
        }
    }

    #[test]
    fn spec_and_layout_readers_survive_edited_and_random_input(
        e in edits(),
        bytes in prop::collection::vec(any::<u8>(), 0..256),
    ) {
        let s = seeds();
        for input in [apply(&s.spec, &e), apply(&s.layout, &e), bytes] {
            if let Ok(spec) = SceneSpec::parse(&input) {
                prop_assert!(spec.validate().is_ok());
            }
            if let Ok(l) = Layout::parse(&input) {
                prop_assert!(l.objects.iter().all(|o| o.position.iter().all(|v| v.is_finite())));
            }
        }
    }

    #[test]
    fn llm_answer_repair_survives_any_text(
        text in ".{0,200}",
        fence in prop::bool::ANY,
        e in edits(),
    ) {
        let _ = parse_loose_json(&text);
        let answer = if fence {
            format!("Sure! ```json\n{text}\n``` hope it helps")
        } else {
            text.clone()
        };
        let _ = parse_loose_json(&answer);
        let edited = apply(&seeds().spec, &e);
        let _ = parse_loose_json(&String::from_utf8_lossy(&edited));
    }
}

/// Deep nesting is where recursive parsers overflow their stack.
#[test]
fn readers_refuse_deep_nesting_without_overflowing() {
    for depth in [1_000, 100_000] {
        let open = "[".repeat(depth);
        let obj = format!("{{\"a\": {open}");
        assert!(parse_cameras(open.as_bytes()).is_err());
        assert!(SceneSpec::parse(obj.as_bytes()).is_err());
        assert!(Layout::parse(obj.as_bytes()).is_err());
        let closed = format!("{{\"a\": {open}{}}}", "]".repeat(depth));
        let _ = parse_loose_json(&closed);
    }
}

//! One loaded Stable Diffusion pipeline per process: the priors an `edit` (or any caller)
//! make one after another share the pipeline (its ONNX Runtime sessions and what its provider
//! probe learned) instead of opening the models again. Needs the ONNX Runtime library
//! (scripts/setup.sh installs it). One test in this binary: the counter is the process's.
use dreamscene::diffusion::model::ModelTimes;
use dreamscene::diffusion::runtime::Provider;
use dreamscene::generate::prior_spec::open_sd;
use dreamscene::generate::sd_pool::pipelines_opened;
use std::path::Path;

#[test]
fn priors_made_one_after_another_share_one_pipeline() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tiny-sd");
    assert_eq!(pipelines_opened(), 0);
    let mut first = open_sd(&dir, Provider::Cpu, "a chair", None).unwrap();
    first.sd.set_unet_max_batch(Some(3));
    first.sd.encode_text(&["a chair"]).unwrap();
    assert_eq!(pipelines_opened(), 1);
    drop(first);
    // The next object's prior (another prompt, with an edit prompt) takes the same pipeline,
    // reset: no cap left from the first, no time counted.
    let mut second = open_sd(&dir, Provider::Cpu, "a table", Some("a red table")).unwrap();
    assert_eq!(pipelines_opened(), 1);
    assert_eq!(second.sd.unet_cap(), None);
    assert_eq!(second.sd.take_times(), ModelTimes::default());
    // Two priors alive at once need two pipelines; both are kept for later priors.
    let third = open_sd(&dir, Provider::Cpu, "a lamp", None).unwrap();
    assert_eq!(pipelines_opened(), 2);
    drop((second, third));
    let _a = open_sd(&dir, Provider::Cpu, "a bed", None).unwrap();
    let _b = open_sd(&dir.join("."), Provider::Cpu, "a rug", None).unwrap();
    assert_eq!(
        pipelines_opened(),
        2,
        "the same directory, however it is written"
    );
    // Another model directory is another pipeline.
    let other = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/exported-sd/fp32");
    let _c = open_sd(&other, Provider::Cpu, "a bed", None).unwrap();
    assert_eq!(pipelines_opened(), 3);
}

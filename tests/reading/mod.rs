//! What the reader tests share: the offline plan of a prompt, failing the test with the prompt
//! and the reader's one-line error when it cannot be planned.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;

/// The spec the offline planner makes of `prompt`.
pub fn plan(prompt: &str) -> SceneSpec {
    match plan_prompt(prompt) {
        Ok(p) => p.spec,
        Err(e) => panic!("{prompt}: {e}"),
    }
}

//! What the reader tests share: the offline plan of a prompt, failing the test with the prompt
//! and the reader's one-line error when it cannot be planned, and counts of what a plan holds.
#![allow(dead_code, reason = "each reader test uses some of the shared helpers")]
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;

/// The spec the offline planner makes of `prompt`.
pub fn plan(prompt: &str) -> SceneSpec {
    match plan_prompt(prompt) {
        Ok(p) => p.spec,
        Err(e) => panic!("{prompt}: {e}"),
    }
}

/// How many instances the plan holds of categories whose name contains `word`.
pub fn number(spec: &SceneSpec, word: &str) -> u32 {
    spec.objects
        .iter()
        .filter(|(c, _)| c.contains(word))
        .map(|(_, o)| o.number)
        .sum()
}

/// The plan's categories with their counts, `category:n`, for failure messages.
pub fn keys(s: &SceneSpec) -> Vec<String> {
    s.objects
        .iter()
        .map(|(c, o)| format!("{c}:{}", o.number))
        .collect()
}

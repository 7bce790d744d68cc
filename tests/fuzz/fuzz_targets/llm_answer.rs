//! The LLM-answer repair (fences, prose, comments, trailing commas, bare words): any text, no
//! panic, no hang.
#![no_main]
use dreamscene::plan::llm::parse_loose_json;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let _ = parse_loose_json(&String::from_utf8_lossy(data));
});

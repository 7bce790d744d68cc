//! The LLM planner against a local HTTP server on loopback that replays recorded answers, good
//! and malformed. No network.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::plan::llm::{parse_loose_json, plan_llm, LlmConfig};
use dreamscene::plan::spec::{Anchor, RelationKind};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// (Authorization header, body) of each request the server saw.
type Log = Arc<Mutex<Vec<(String, String)>>>;

/// Serves `answers` in order as chat completions; records each request.
fn server(answers: Vec<String>) -> (String, Log) {
    let s = tiny_http::Server::http("127.0.0.1:0").unwrap();
    let url = format!("http://{}/v1", s.server_addr().to_ip().unwrap());
    let log = Arc::new(Mutex::new(vec![]));
    let log2 = log.clone();
    std::thread::spawn(move || {
        let mut answers = answers.into_iter();
        for mut req in s.incoming_requests() {
            let mut body = String::new();
            req.as_reader().read_to_string(&mut body).unwrap();
            let auth = req
                .headers()
                .iter()
                .find(|h| h.field.equiv("Authorization"))
                .map(|h| h.value.to_string())
                .unwrap_or_default();
            log2.lock().unwrap().push((auth, body));
            let reply = match answers.next() {
                Some(a) => serde_json::json!({"choices": [{"message": {"role": "assistant", "content": a}}]}).to_string(),
                None => "{\"error\": \"no more answers\"}".into(),
            };
            let code = if reply.contains("no more answers") {
                500
            } else {
                200
            };
            req.respond(tiny_http::Response::from_string(reply).with_status_code(code))
                .ok();
        }
    });
    (url, log)
}

fn config(url: String) -> LlmConfig {
    LlmConfig {
        url,
        model: "test-model".into(),
        api_key: Some("sk-secret-123".into()),
        timeout: Duration::from_secs(10),
        retries: 1,
    }
}

#[test]
fn loose_json_is_repaired() {
    let v = parse_loose_json("Sure! Here you go:\n```json\n{\"sofa1\": SIDE, 'tv1': \"OPPOSITE\", // a comment\n \"rug1\": CENTER,}\n```\nEnjoy.").unwrap();
    assert_eq!(v["sofa1"], "SIDE");
    assert_eq!(v["tv1"], "OPPOSITE");
    assert_eq!(v["rug1"], "CENTER");
    let v =
        parse_loose_json("{\"a\": {\"number\": 2, \"ok\": true, \"size\": [1, 2, 3],}}").unwrap();
    assert_eq!(v["a"]["ok"], true);
    assert!(parse_loose_json("I cannot help with that.").is_err());
}

#[test]
fn a_good_conversation_becomes_a_spec() {
    let answers = vec![
        // objects: fenced, a synonym (couch), centimetres, a missing prefix
        "```json\n{\"couch\": {\"number\": 1, \"size\": [210, 95, 85], \"description\": \"A DSLR photo of a green velvet couch\"},\n \"coffee table\": {\"number\": 1, \"size\": [1.1, 0.6, 0.45], \"description\": \"a marble coffee table\"},\n \"armchair\": {\"number\": 2, \"size\": [0.8, 0.8, 0.9], \"description\": \"A DSLR photo of a rattan armchair\"},}\n```".to_string(),
        // anchors: bare words, a key with different case
        "{\"sofa1\": SIDE, \"Coffee Table1\": CENTER, \"armchair1\": OTHERS, \"armchair2\": OTHERS}".to_string(),
        // relations, one answer per category (armchair, coffee table, sofa)
        "{\"coffee table1\": NEXT}".to_string(),
        "{\"sofa1\": 'FRONT'}".to_string(),
        "{\"armchair2\": \"NEXT\", \"nonexistent9\": \"LEFT\", \"armchair1\": \"SIDEWAYS\"}".to_string(),
    ];
    let (url, log) = server(answers);
    let (spec, report) = plan_llm(&config(url), "a living room with a green velvet couch");
    assert!(!report.offline_fallback, "{:?}", report.warnings);
    assert_eq!(
        spec.objects["sofa"].size,
        [2.1, 0.95, 0.85],
        "synonym mapped, centimetres fixed"
    );
    assert!(spec.objects["coffee table"]
        .description
        .starts_with("A DSLR photo of"));
    assert_eq!(spec.anchors["coffee table1"], Anchor::Center);
    assert!(spec.relations.iter().any(|r| r.subject == "coffee table1"
        && r.relation == RelationKind::Front
        && r.object == "sofa1"));
    spec.validate().unwrap();
    let log = log.lock().unwrap();
    assert_eq!(log.len(), 5);
    assert!(log.iter().all(|(auth, _)| auth == "Bearer sk-secret-123"));
    assert!(log[0].1.contains("test-model") && log[0].1.contains("A DSLR photo of"));
    assert!(log[0]
        .1
        .contains("You are a professional scene designer. Based on the user requirements"));
    assert!(!format!("{report:?}").contains("sk-secret"));
}

#[test]
fn a_malformed_answer_is_retried_with_the_error() {
    let answers = vec![
        "I think a bedroom needs a bed.".to_string(),
        "{\"bed\": {\"number\": 1, \"size\": [1.6, 2.1, 1.0], \"description\": \"A DSLR photo of a bed\"}}".to_string(),
        "{\"bed1\": SIDE}".to_string(),
        "{}".to_string(),
    ];
    let (url, log) = server(answers);
    let (spec, report) = plan_llm(&config(url), "a bedroom");
    assert!(!report.offline_fallback, "{:?}", report.warnings);
    assert_eq!(spec.anchors["bed1"], Anchor::Side);
    let log = log.lock().unwrap();
    assert!(
        log[1].1.contains("could not be used"),
        "the error is fed back"
    );
    assert!(report.warnings.iter().any(|w| w.contains("unusable")));
}

#[test]
fn hopeless_answers_or_a_dead_server_fall_back_offline() {
    let answers = vec!["no".to_string(), "still no".to_string()];
    let (url, _) = server(answers);
    let (spec, report) = plan_llm(&config(url), "a cozy living room");
    assert!(report.offline_fallback);
    assert!(spec.objects.contains_key("sofa"));
    // Nothing listens on this port: a connection error, then the offline plan.
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    drop(listener);
    let mut cfg = config(format!("http://127.0.0.1:{port}/v1"));
    cfg.timeout = Duration::from_secs(2);
    let (spec, report) = plan_llm(&cfg, "a kitchen");
    assert!(report.offline_fallback);
    assert!(spec.objects.contains_key("refrigerator"));
    let all = format!("{:?} {cfg:?}", report.warnings);
    assert!(!all.contains("sk-secret"), "the key never appears: {all}");
}

/// The verb: warnings on stderr, the offline fallback, and the key nowhere in the output.
#[test]
fn plan_verb_with_an_llm_never_prints_the_key() {
    let (url, log) = server(vec![
        "garbage".into(),
        "more garbage".into(),
        "and more".into(),
    ]);
    let dir = std::env::temp_dir().join(format!("dreamscene-llm-{}", std::process::id()));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args([
            "plan",
            "a cozy living room",
            "--llm-url",
            &url,
            "--llm-model",
            "m",
            "--out",
        ])
        .arg(&dir)
        .env("OPENAI_API_KEY", "sk-secret-456")
        .output()
        .unwrap();
    let all = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "{all}");
    assert!(all.contains("planning offline instead"), "{all}");
    assert!(!all.contains("sk-secret"), "{all}");
    assert!(log
        .lock()
        .unwrap()
        .iter()
        .all(|(a, _)| a == "Bearer sk-secret-456"));
    assert!(dir.join("layout.png").is_file());
    std::fs::remove_dir_all(&dir).ok();
}

/// An LLM plan goes through the same functional groups and capacity as the offline one: the
/// chairs it lists get seats round the table, an object the prompt names that the answer left
/// out is added, and default furniture is trimmed to the stated room.
#[test]
fn llm_plans_get_functional_groups_and_capacity() {
    let answers = vec![
        "{\"dining table\": {\"number\": 1, \"size\": [1.8, 0.9, 0.75], \"description\": \"A DSLR photo of an oak table\"}, \"dining chair\": {\"number\": 6, \"size\": [0.45, 0.5, 0.9], \"description\": \"A DSLR photo of a chair\"}, \"sideboard\": {\"number\": 1, \"size\": [1.6, 0.45, 0.8], \"description\": \"A DSLR photo of a sideboard\"}, \"china cabinet\": {\"number\": 1, \"size\": [1.2, 0.45, 1.9], \"description\": \"A DSLR photo of a cabinet\"}}".to_string(),
        "{\"dining table1\": CENTER}".to_string(),
        "{}".to_string(),
        "{}".to_string(),
        "{}".to_string(),
        "{}".to_string(),
    ];
    let (url, _) = server(answers);
    let (spec, report) = plan_llm(&config(url), "a dining room, 3.5m x 3m, with a piano");
    assert!(!report.offline_fallback, "{:?}", report.warnings);
    assert!(
        spec.objects.contains_key("piano"),
        "named, added: {:?}",
        spec.objects.keys()
    );
    assert!(report.warnings.iter().any(|w| w.contains("piano")));
    assert!(
        report
            .warnings
            .iter()
            .any(|w| w.contains("left out to fit")),
        "defaults trimmed: {:?}",
        report.warnings
    );
    let around = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Around && r.object == "dining table1")
        .count();
    let chairs = spec
        .objects
        .get("dining chair")
        .map(|o| o.number)
        .unwrap_or(0);
    assert!(
        chairs > 0 && around as u32 == chairs,
        "{around} of {chairs} chairs round the table"
    );
    let l = dreamscene::plan::gcp::layout(&spec, dreamscene::plan::gcp::LayoutOptions::seeded(0))
        .unwrap();
    assert!(dreamscene::plan::check::validity_problems(&l, &spec).is_empty());
}

/// An LLM answer goes through the same reading as the offline plan: the counts the text sets,
/// nothing it excludes, and a named object in place of the default of its role.
#[test]
fn llm_answers_keep_the_texts_counts_negations_and_roles() {
    let answers = vec![
        "{\"bed\": {\"number\": 1, \"size\": [1.6, 2.1, 1.0], \"description\": \"A DSLR photo of a bed\"}, \"single bed\": {\"number\": 1, \"size\": [1.0, 2.0, 0.9], \"description\": \"A DSLR photo of a single bed\"}, \"nightstand\": {\"number\": 1, \"size\": [0.5, 0.4, 0.55], \"description\": \"A DSLR photo of a nightstand\"}, \"tv\": {\"number\": 1, \"size\": [1.3, 0.08, 0.75], \"description\": \"A DSLR photo of a tv\"}}".to_string(),
        "{\"bed1\": SIDE, \"single bed1\": SIDE}".to_string(),
        "{}".to_string(),
        "{}".to_string(),
        "{}".to_string(),
        "{}".to_string(),
    ];
    let (url, _) = server(answers);
    let (spec, report) = plan_llm(
        &config(url),
        "a guest room with a single bed, two nightstands and no tv",
    );
    assert!(!report.offline_fallback, "{:?}", report.warnings);
    let n = |c: &str| spec.objects.get(c).map(|o| o.number).unwrap_or(0);
    assert_eq!(n("tv"), 0, "excluded: {:?}", report.warnings);
    assert_eq!(
        n("nightstand"),
        2,
        "the text's count: {:?}",
        report.warnings
    );
    assert_eq!(n("single bed"), 1);
    assert_eq!(n("bed"), 0, "the single bed is the sleeping place");
    assert!(spec.anchors.contains_key("nightstand2") && !spec.anchors.contains_key("tv1"));
    assert!(spec
        .relations
        .iter()
        .all(|r| r.subject != "bed1" && r.object != "bed1"));
    spec.validate().unwrap();
}

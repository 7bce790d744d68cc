//! The LLM planner: any OpenAI-compatible chat-completions endpoint (OpenAI, Ollama, llama.cpp's
//! server, vLLM) asked the paper's three questions (objects, anchors, relations) with the user
//! constraint prefix. LLM output is untrusted: code fences, comments, trailing commas, single
//! quotes and bare enum words (`"sofa1": SIDE`) are tolerated, answers are validated against the
//! schema with synonyms mapped and counts and sizes clamped, a failed answer is retried with the
//! error fed back, and if that fails too the offline planner takes over with a warning. The API
//! key is sent only in the Authorization header: it is never printed or logged.
use super::gcp::choose_room;
use super::kb::{parse_anchor, parse_relation, KnowledgeBase};
use super::offline::{parse_room_size, plan_offline, plan_prompt};
use super::spec::{Anchor, ObjectSpec, Relation, Room, SceneSpec, SceneType, MAX_NUMBER};
use regex::Regex;
use serde_json::{json, Value};
use std::collections::{BTreeMap, BTreeSet};
use std::time::Duration;

/// Where and how to ask.
#[derive(Clone)]
pub struct LlmConfig {
    /// Base URL, e.g. `https://api.openai.com/v1` or `http://localhost:11434/v1`; the client
    /// posts to `<url>/chat/completions` (a URL already ending in that is used as is).
    pub url: String,
    pub model: String,
    /// Bearer token (from OPENAI_API_KEY); never printed.
    pub api_key: Option<String>,
    pub timeout: Duration,
    /// Extra attempts per question after an unusable answer.
    pub retries: u32,
}

impl std::fmt::Debug for LlmConfig {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LlmConfig")
            .field("url", &self.url)
            .field("model", &self.model)
            .field("api_key", &self.api_key.as_ref().map(|_| "<set>"))
            .field("timeout", &self.timeout)
            .field("retries", &self.retries)
            .finish()
    }
}

/// Why the LLM could not plan.
#[derive(Debug, thiserror::Error)]
pub enum LlmError {
    #[error("LLM request to {url} failed: {msg}")]
    Http { url: String, msg: String },
    #[error("unusable LLM answer to the {question} question: {msg}")]
    Answer { question: &'static str, msg: String },
}

/// What one planning run did, for the user.
#[derive(Debug, Default, Clone)]
pub struct PlanReport {
    /// Warnings (answers repaired or retried, entries dropped, the offline fallback).
    pub warnings: Vec<String>,
    /// True when the offline planner produced the spec.
    pub offline_fallback: bool,
}

const SYSTEM: &str = "You are a professional scene designer. Reply with JSON only.";

fn prefix(constraint: &str) -> String {
    format!(
        "You are a professional scene designer. Based on the user requirements \"{constraint}\", and your domain knowledge, "
    )
}

fn objects_prompt(constraint: &str, scene_text: &str) -> String {
    format!(
        "{}your task is to generate a list of objects commonly found in the described scene. For each object, please include its frequency of appearance, typical dimensions ([x, y, z] in meters), and a brief description starting with \"A DSLR photo of\". Ensure that the object descriptions are consistent with the scene's style and reflect common human understanding. Output should be formatted as follows in JSON:\nInput: a living room\nOutput: {{\"sofa\": {{\"number\": 2, \"size\": [2.0, 1.0, 0.8], \"description\": \"A DSLR photo of a plush grey sectional sofa with deep cushions\"}}, \"coffee table\": {{\"number\": 1, \"size\": [1.2, 0.6, 0.45], \"description\": \"A DSLR photo of a low oak coffee table\"}}}}\nNow, let's design the scene: {scene_text}.",
        prefix(constraint)
    )
}

fn anchors_prompt(constraint: &str, scene: SceneType, scene_text: &str, ids: &[String]) -> String {
    let zones = match scene {
        SceneType::Indoor => "There are four relationships to choose from: 1. CENTER, the object is in the center of the scene 2. SIDE, the object is at the boundary of the scene 3. CORNER, the object is in the corner of the scene 4. OTHERS, the object is in other places.",
        SceneType::Outdoor => "There are three relationships to choose from: 1. CENTER, the object is in the center of the scene 2. SIDE, the object is at the boundary of the scene 3. OTHERS, the object is in other places.",
    };
    let input =
        json!({"scene_type": scene_word(scene), "scene_text": scene_text, "objects_list": ids});
    format!(
        "{}your task is to determine the spatial relationship between an object and its environment based on the object's name and common human understanding. {zones} When dealing with multiple similar objects, arrange their positions reasonably to prevent conflicts. Please return in the following example format in JSON format.\nInput: {{\"scene_type\": \"indoor scene\", \"scene_text\": \"a living room\", \"objects_list\": [\"sofa1\", \"sofa2\", \"coffee table1\", \"potted plant1\"]}}\nOutput: {{\"sofa1\": \"SIDE\", \"sofa2\": \"SIDE\", \"coffee table1\": \"CENTER\", \"potted plant1\": \"CORNER\"}}\nNow, I need select for {input}.",
        prefix(constraint)
    )
}

fn relations_prompt(
    constraint: &str,
    scene: SceneType,
    scene_text: &str,
    current: &str,
    others: &[String],
) -> String {
    let input = json!({"scene_type": scene_word(scene), "scene_text": scene_text, "current_object": current, "objects_list": others});
    format!(
        "{}the given environment, your task is to select objects from the provided list that are relevant to the current object based on common human usage, and describe their spatial or functional relationships. The possible relationships include: 1. LEFT, the current object is at the left of the selected object. 2. RIGHT, the current object is at the right of the selected object. 3. FRONT, the current object is at the front of the selected object. 4. BEHIND, the current object is behind the selected object. 5. OVER, the current object is above the selected object. 6. UNDER, the current object is below the selected object. 7. NEXT, the current object is near the selected object. 8. OPPOSITE, the current object is opposite the selected object. Output the selected objects and their relationship in JSON format. For example:\nInput: {{\"scene_type\": \"indoor scene\", \"scene_text\": \"a living room\", \"current_object\": \"sofa1\", \"objects_list\": [\"sofa2\", \"coffee table1\", \"TV1\"]}}\nOutput: {{\"sofa2\": \"NEXT\", \"TV1\": \"OPPOSITE\"}}\nNow, I need design for {input}.",
        prefix(constraint)
    )
}

fn scene_word(s: SceneType) -> &'static str {
    match s {
        SceneType::Indoor => "indoor scene",
        SceneType::Outdoor => "outdoor scene",
    }
}

/// Extracts and parses the JSON object of an LLM answer, tolerating code fences, prose around
/// it, comments, trailing commas, single quotes and bare enum words as values.
pub fn parse_loose_json(text: &str) -> Result<Value, String> {
    static FENCE: std::sync::OnceLock<Regex> = std::sync::OnceLock::new();
    static BARE: std::sync::OnceLock<Regex> = std::sync::OnceLock::new();
    let fence = FENCE.get_or_init(|| {
        Regex::new(r"(?s)```(?:json|JSON|json5)?\s*(.*?)```").expect("valid regex")
    });
    let body = fence
        .captures(text)
        .map(|c| c[1].to_string())
        .unwrap_or_else(|| text.to_string());
    let start = body.find('{').ok_or("no JSON object in the answer")?;
    let end = body.rfind('}').ok_or("unterminated JSON object")?;
    if end < start {
        return Err("no JSON object in the answer".into());
    }
    let obj = &body[start..=end];
    // Bare words as values (`"sofa1": SIDE`) become strings; true/false/null stay.
    let bare = BARE.get_or_init(|| {
        Regex::new(r#":\s*([A-Za-z_][A-Za-z_ ]*[A-Za-z_])\s*([,}\]\n])"#).expect("valid regex")
    });
    let quoted = bare.replace_all(obj, |c: &regex::Captures| {
        let w = &c[1];
        if ["true", "false", "null"].contains(&w) {
            c[0].to_string()
        } else {
            format!(": \"{w}\"{}", &c[2])
        }
    });
    json5::from_str::<Value>(&quoted).map_err(|e| format!("not JSON: {e}"))
}

/// One chat completion: returns the assistant's text.
fn chat(cfg: &LlmConfig, messages: &[Value]) -> Result<String, LlmError> {
    let url = if cfg.url.trim_end_matches('/').ends_with("/chat/completions") {
        cfg.url.clone()
    } else {
        format!("{}/chat/completions", cfg.url.trim_end_matches('/'))
    };
    let agent = ureq::AgentBuilder::new().timeout(cfg.timeout).build();
    let mut req = agent.post(&url).set("Content-Type", "application/json");
    if let Some(k) = &cfg.api_key {
        req = req.set("Authorization", &format!("Bearer {k}"));
    }
    let body = json!({"model": cfg.model, "messages": messages, "temperature": 0.2});
    let http = |msg: String| LlmError::Http {
        url: url.clone(),
        msg,
    };
    let resp = match req.send_json(body) {
        Ok(r) => r,
        Err(ureq::Error::Status(code, r)) => {
            let text = r.into_string().unwrap_or_default();
            let snippet: String = text.chars().take(200).collect();
            return Err(http(format!("HTTP {code}: {}", snippet.replace('\n', " "))));
        }
        Err(e) => return Err(http(e.to_string())),
    };
    let v: Value = resp
        .into_json()
        .map_err(|e| http(format!("response is not JSON: {e}")))?;
    v["choices"][0]["message"]["content"]
        .as_str()
        .map(str::to_string)
        .ok_or_else(|| http("response has no choices[0].message.content".into()))
}

/// Asks `prompt`, parses with `parse`, and on an unusable answer asks again with the error
/// appended, up to `cfg.retries` more times.
fn ask<T>(
    cfg: &LlmConfig,
    question: &'static str,
    prompt: &str,
    report: &mut PlanReport,
    parse: impl Fn(&Value) -> Result<T, String>,
) -> Result<T, LlmError> {
    let mut messages = vec![
        json!({"role": "system", "content": SYSTEM}),
        json!({"role": "user", "content": prompt}),
    ];
    let mut last = String::new();
    for attempt in 0..=cfg.retries {
        let answer = chat(cfg, &messages)?;
        match parse_loose_json(&answer).and_then(|v| parse(&v)) {
            Ok(t) => return Ok(t),
            Err(e) => {
                report
                    .warnings
                    .push(format!("{question} answer {} unusable: {e}", attempt + 1));
                messages.push(json!({"role": "assistant", "content": answer}));
                messages.push(json!({"role": "user", "content": format!(
                    "Your answer could not be used: {e}. Reply again with only the JSON object in the format shown."
                )}));
                last = e;
            }
        }
    }
    Err(LlmError::Answer {
        question,
        msg: last,
    })
}

/// Lower-case, trimmed, synonyms mapped to the knowledge base's category, digits stripped.
fn category_name(kb: &KnowledgeBase, raw: &str) -> String {
    let n = raw
        .trim()
        .to_lowercase()
        .replace('_', " ")
        .trim_end_matches(|c: char| c.is_ascii_digit())
        .trim()
        .to_string();
    kb.object(&n).map(|o| o.category.clone()).unwrap_or(n)
}

fn parse_objects(
    kb: &KnowledgeBase,
    v: &Value,
    warnings: &mut Vec<String>,
) -> Result<BTreeMap<String, ObjectSpec>, String> {
    let map = v.as_object().ok_or("expected an object of objects")?;
    let mut out: BTreeMap<String, ObjectSpec> = BTreeMap::new();
    for (name, o) in map {
        let cat = category_name(kb, name);
        if cat.is_empty() {
            continue;
        }
        let known = kb.object(&cat);
        let number = o["number"]
            .as_f64()
            .or_else(|| o["number"].as_str().and_then(|s| s.trim().parse().ok()))
            .unwrap_or(1.0);
        let number = (number.round() as i64).clamp(1, MAX_NUMBER as i64) as u32;
        let size: Option<Vec<f64>> = o["size"]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect());
        let size = match (size, known) {
            (Some(s), _) if s.len() == 3 && s.iter().all(|v| v.is_finite() && *v > 0.0) => {
                // Centimetres slip in: a sofa of 200 x 90 x 80.
                let s: Vec<f64> = if s.iter().any(|v| *v > 30.0) {
                    s.iter().map(|v| v / 100.0).collect()
                } else {
                    s
                };
                [0, 1, 2].map(|k| s[k].clamp(0.005, 20.0))
            }
            (_, Some(k)) => {
                warnings.push(format!(
                    "`{name}`: size missing or invalid, using {:?}",
                    k.size
                ));
                k.size
            }
            _ => {
                warnings.push(format!("`{name}`: size missing or invalid, dropped"));
                continue;
            }
        };
        let mut description = o["description"].as_str().unwrap_or("").trim().to_string();
        if !description.starts_with("A DSLR photo of") {
            let body = if description.is_empty() {
                cat.clone()
            } else {
                description.clone()
            };
            description = format!("A DSLR photo of {body}");
        }
        out.insert(
            cat,
            ObjectSpec {
                number,
                size,
                description,
                rows: 0,
                sizes: vec![],
                on_wall: None,
            },
        );
    }
    if out.is_empty() {
        return Err("no usable objects".into());
    }
    Ok(out)
}

/// Plans with the LLM; on any failure falls back to the offline planner (with a warning).
pub fn plan_llm(cfg: &LlmConfig, constraint: &str) -> (SceneSpec, PlanReport) {
    let mut report = PlanReport::default();
    match plan_llm_strict(cfg, constraint, &mut report) {
        Ok(spec) => (spec, report),
        Err(e) => {
            report
                .warnings
                .push(format!("{e}; planning offline instead"));
            report.offline_fallback = true;
            (plan_offline(constraint), report)
        }
    }
}

/// Plans with the LLM, or the error.
pub fn plan_llm_strict(
    cfg: &LlmConfig,
    constraint: &str,
    report: &mut PlanReport,
) -> Result<SceneSpec, LlmError> {
    let kb = KnowledgeBase::builtin();
    // The scene type and room size the text states; the offline reading decides indoor/outdoor.
    let offline = plan_offline(constraint);
    let scene_type = offline.scene_type;
    let scene_text = constraint.trim().to_string();
    let mut warnings = vec![];
    let objects = ask(
        cfg,
        "objects",
        &objects_prompt(constraint, &scene_text),
        report,
        |v| {
            let mut w = vec![];
            let r = parse_objects(kb, v, &mut w);
            r.map(|o| (o, w))
        },
    )
    .map(|(o, w)| {
        warnings.extend(w);
        o
    })?;
    let mut spec = SceneSpec {
        scene_type,
        scene_text: scene_text.clone(),
        room: None,
        objects,
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    let ids: Vec<String> = spec.instances().into_iter().map(|i| i.id).collect();
    let lookup = |raw: &str| -> Option<String> {
        let r = raw.trim().to_lowercase().replace('_', " ");
        if ids.contains(&r) {
            return Some(r);
        }
        // "couch1" -> "sofa1"; a bare category means its first instance.
        let digits = &r[r.trim_end_matches(|c: char| c.is_ascii_digit()).len()..];
        let index = if digits.is_empty() { "1" } else { digits };
        let id = format!("{}{index}", category_name(kb, &r));
        ids.contains(&id).then_some(id)
    };
    let anchors = ask(
        cfg,
        "anchors",
        &anchors_prompt(constraint, scene_type, &scene_text, &ids),
        report,
        |v| {
            let map = v.as_object().ok_or("expected an object of anchors")?;
            let mut out = BTreeMap::new();
            for (k, a) in map {
                let (Some(id), Some(anchor)) = (lookup(k), a.as_str().and_then(parse_anchor))
                else {
                    continue;
                };
                out.insert(id, anchor);
            }
            if out.is_empty() {
                return Err("no usable anchors (keys must be the listed instances, values CENTER, SIDE, CORNER or OTHERS)".to_string());
            }
            Ok(out)
        },
    )?;
    for id in &ids {
        let cat = id.trim_end_matches(|c: char| c.is_ascii_digit());
        let mut a = anchors
            .get(id)
            .copied()
            .or_else(|| kb.object(cat).map(|o| o.anchor))
            .unwrap_or(Anchor::Others);
        if scene_type == SceneType::Outdoor && a == Anchor::Corner {
            a = Anchor::Side;
        }
        spec.anchors.insert(id.clone(), a);
    }
    // Relations: one question per category's first instance (the paper asks per object).
    let mut seen = std::collections::BTreeSet::new();
    for cat in spec.objects.keys().cloned().collect::<Vec<_>>() {
        let current = format!("{cat}1");
        let others: Vec<String> = ids.iter().filter(|i| **i != current).cloned().collect();
        if others.is_empty() {
            continue;
        }
        let rels = ask(
            cfg,
            "relations",
            &relations_prompt(constraint, scene_type, &scene_text, &current, &others),
            report,
            |v| {
                let map = v.as_object().ok_or("expected an object of relations")?;
                let mut out = vec![];
                for (k, r) in map {
                    if let (Some(id), Some(rel)) = (lookup(k), r.as_str().and_then(parse_relation))
                    {
                        out.push((id, rel));
                    }
                }
                Ok(out)
            },
        )?;
        for (other, rel) in rels {
            if other == current {
                continue;
            }
            let key = (
                current.clone().min(other.clone()),
                current.clone().max(other.clone()),
            );
            if seen.insert(key) {
                spec.relations.push(Relation {
                    subject: current.clone(),
                    relation: rel,
                    object: other,
                });
            }
        }
    }
    report.warnings.extend(warnings);
    // The same reading, functional groups and capacity as the offline planner: counts the
    // text sets, no excluded thing, roles filled once; objects the text names (as the offline
    // reading finds them) are never dropped; defaults are trimmed to the room.
    let named: BTreeSet<String> = match plan_prompt(constraint) {
        Ok(p) => {
            report
                .warnings
                .extend(super::conform::conform(&mut spec, &p));
            for c in &p.named {
                if !spec.objects.contains_key(c) {
                    if let Some(o) = p.spec.objects.get(c) {
                        report.warnings.push(format!(
                            "the answer left out `{c}`, which the prompt names: added"
                        ));
                        spec.objects.insert(c.clone(), o.clone());
                        for k in 1..=o.number {
                            let id = format!("{c}{k}");
                            let a = p.spec.anchors.get(&id).copied().unwrap_or(Anchor::Others);
                            spec.anchors.insert(id, a);
                        }
                    }
                }
            }
            p.named
        }
        Err(_) => BTreeSet::new(),
    };
    super::groups::apply(&mut spec, &BTreeSet::new());
    let stated = parse_room_size(constraint);
    let chosen = choose_room(&spec.instances(), scene_type);
    spec.room = Some(match stated {
        Some([w, d]) => Room {
            size: [w, d, chosen.size[2]],
        },
        None => chosen,
    });
    let notes = super::capacity::fit(&mut spec, &named, &BTreeSet::new(), stated.is_some())
        .map_err(|e| LlmError::Answer {
            question: "objects",
            msg: e.to_string(),
        })?;
    report.warnings.extend(notes);
    spec.validate().map_err(|e| LlmError::Answer {
        question: "objects",
        msg: e.to_string(),
    })?;
    Ok(spec)
}

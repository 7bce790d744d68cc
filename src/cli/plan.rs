//! `dreamscene plan`: a sentence or a dialogue to a SceneSpec and its layout.
use super::write_png;
use anyhow::{bail, Context as _, Result};
use dreamscene::plan::gcp::{layout, layout_growing, LayoutOptions};
use dreamscene::plan::spec::SceneSpec;
use dreamscene::plan::understood::{Because, Understood};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// What to build, e.g. "a cozy living room".
    /// A prompt may start with a hyphen ("- a kitchen", a dialogue's first line).
    #[arg(allow_hyphen_values = true)]
    pub prompt: Option<String>,
    /// A dialogue instead: a JSON list of {"role", "content"}; the user turns are planned.
    #[arg(long)]
    pub dialogue: Option<PathBuf>,
    #[command(flatten)]
    pub llm: LlmArgs,
    /// Ask about style and constraints before planning.
    #[arg(long)]
    pub interactive: bool,
    /// Seed of the layout.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Output directory.
    #[arg(long)]
    pub out: PathBuf,
    /// Replace the scene already in --out (generated or edited), whole, with the plan.
    #[arg(long)]
    pub force: bool,
}

pub fn run(a: Args) -> Result<()> {
    let llm = a.llm.config();
    if a.out.is_dir() {
        if let Some(what) = holds_scene(&a.out) {
            if !a.force {
                bail!(
                    "{} holds {what}, whose spec.json and layout.json a plan would overwrite; give \
                     another --out, or --force to replace the scene with the plan",
                    a.out.display()
                );
            }
            let found = super::generate::contents(&a.out)?;
            super::generate::empty_out(&a.out, &found)?;
        }
    }
    plan(a.prompt, a.dialogue, llm, a.interactive, a.seed, &a.out)
}

/// Entries only `generate` (and `edit` after it) writes into a scene directory: a plan's own
/// three files beside none of them are a plan that may be planned again.
const SCENE_ENTRIES: [&str; 6] = [
    "scene.json",
    "objects",
    "checkpoints",
    "renders",
    "scene.ply",
    "environment.ply",
];

/// What of a scene `dir` holds ("a scene with 2 edits", "a scene", "an unfinished scene"), if
/// anything: a plan written there would lose it.
fn holds_scene(dir: &Path) -> Option<String> {
    if !SCENE_ENTRIES.iter().any(|e| dir.join(e).exists()) {
        return None;
    }
    Some(match dreamscene::scene::dir::read_scene(dir) {
        Ok(s) if !s.history.is_empty() => format!("a scene with {} edits", s.history.len()),
        Ok(_) => "a scene".to_string(),
        Err(_) => "an unfinished scene".to_string(),
    })
}

/// The planner's LLM endpoint, shared by `plan` and `generate`.
#[derive(clap::Args)]
pub struct LlmArgs {
    /// Plan with an OpenAI-compatible chat endpoint instead (OpenAI, Ollama, llama.cpp, vLLM),
    /// e.g. https://api.openai.com/v1 or http://localhost:11434/v1. The key comes from
    /// OPENAI_API_KEY. Unusable answers are retried, then the offline planner takes over.
    #[arg(long, env = "DREAMSCENE_LLM_URL")]
    pub llm_url: Option<String>,
    /// Model name for the endpoint.
    #[arg(long, env = "DREAMSCENE_LLM_MODEL", default_value = "gpt-4o")]
    pub llm_model: String,
    /// Seconds to wait for each LLM answer.
    #[arg(long, default_value_t = 120)]
    pub llm_timeout: u64,
}

impl LlmArgs {
    /// The endpoint's settings when `--llm-url` is given (key from OPENAI_API_KEY).
    pub fn config(self) -> Option<dreamscene::plan::llm::LlmConfig> {
        let (model, timeout) = (self.llm_model, self.llm_timeout);
        self.llm_url.map(|url| dreamscene::plan::llm::LlmConfig {
            url,
            model,
            api_key: dreamscene::util::env_var("OPENAI_API_KEY"),
            timeout: std::time::Duration::from_secs(timeout.max(1)),
            retries: 2,
        })
    }
}

fn plan(
    prompt: Option<String>,
    dialogue: Option<PathBuf>,
    llm: Option<dreamscene::plan::llm::LlmConfig>,
    interactive: bool,
    seed: u64,
    out: &Path,
) -> Result<()> {
    let text = plan_text(prompt, dialogue, interactive)?;
    let (spec, l) = plan_to_dir(&text, llm.as_ref(), seed, out)?;
    println!(
        "{} scene: {}{}",
        match spec.scene_type {
            dreamscene::plan::spec::SceneType::Indoor => "indoor",
            dreamscene::plan::spec::SceneType::Outdoor => "outdoor",
        },
        l.summary(&spec),
        unsatisfied_note(&l)
    );
    println!(
        "wrote {0}/spec.json, {0}/layout.json, {0}/layout.png",
        out.display()
    );
    Ok(())
}

/// Asks about style and constraints on the terminal; the answers join the user constraint.
fn interview(text: &str) -> Result<String> {
    use std::io::{BufRead, Write};
    let mut out = text.to_string();
    let stdin = std::io::stdin();
    for q in [
        "What style should it have (e.g. minimalist, rustic, beach-inspired)? ",
        "Any constraints: room size, objects it must have, where things go? ",
    ] {
        eprint!("{q}");
        std::io::stderr().flush().ok();
        let mut line = String::new();
        stdin
            .lock()
            .read_line(&mut line)
            .context("reading the answer")?;
        let a = line.trim();
        if !a.is_empty() {
            out = if out.is_empty() {
                a.to_string()
            } else {
                format!("{out}. {a}")
            };
        }
    }
    Ok(out)
}

/// The text to plan: the prompt, or the user turns of a dialogue file joined, after the
/// interview when `interactive`. Never empty.
pub fn plan_text(
    prompt: Option<String>,
    dialogue: Option<PathBuf>,
    interactive: bool,
) -> Result<String> {
    let text = match (prompt, dialogue) {
        (Some(p), None) => p,
        (None, Some(f)) => {
            let raw =
                std::fs::read_to_string(&f).with_context(|| format!("reading {}", f.display()))?;
            let turns: Vec<dreamscene::plan::dialogue::Turn> = serde_json::from_str(&raw)
                .with_context(|| {
                    format!("{}: expected a JSON list of {{role, content}}", f.display())
                })?;
            match dreamscene::plan::dialogue::user_text(&turns) {
                Some(t) => t,
                None => bail!("{}: the dialogue has no user turns", f.display()),
            }
        }
        (Some(_), Some(_)) => bail!("give a prompt or --dialogue, not both"),
        (None, None) if interactive => String::new(),
        (None, None) => {
            bail!("give a prompt (or --dialogue FILE), e.g. \"a cozy living room\"")
        }
    };
    let text = if interactive {
        if text.is_empty() {
            eprint!("What scene would you like? ");
            let mut line = String::new();
            std::io::stdin()
                .read_line(&mut line)
                .context("reading the answer")?;
            interview(line.trim())?
        } else {
            interview(&text)?
        }
    } else {
        text
    };
    if text.trim().is_empty() {
        bail!("the prompt is empty");
    }
    Ok(text)
}

/// Plans `text` (offline, or with the LLM endpoint) and lays it out: writes spec.json,
/// layout.json and layout.png into `out` (created); returns the spec and the layout.
pub fn plan_to_dir(
    text: &str,
    llm: Option<&dreamscene::plan::llm::LlmConfig>,
    seed: u64,
    out: &Path,
) -> Result<(SceneSpec, dreamscene::plan::spec::Layout)> {
    let (mut spec, understood, room_stated) = match llm {
        None => {
            let p = dreamscene::plan::offline::plan_prompt(text)?;
            for n in &p.notes {
                eprintln!("note: {n}");
            }
            (p.spec, p.understood, p.room_stated)
        }
        Some(cfg) => {
            eprintln!("asking {} ({})", cfg.url, cfg.model);
            let (spec, report) = dreamscene::plan::llm::plan_llm(cfg, text);
            for w in &report.warnings {
                eprintln!("warning: {w}");
            }
            let understood = Understood {
                objects: spec
                    .objects
                    .iter()
                    .map(|(c, o)| Because {
                        category: c.clone(),
                        count: o.number,
                        why: "from the language model's answer".into(),
                    })
                    .collect(),
                unused: vec![],
            };
            (spec, understood, true)
        }
    };
    println!("understood:");
    for line in understood.lines() {
        println!("  {line}");
    }
    // a room the text gave no size is the planner's choice: it grows to take everything
    let l = if room_stated {
        layout(&spec, LayoutOptions::seeded(seed))?
    } else {
        let planned = spec.room;
        let l = layout_growing(&mut spec, LayoutOptions::seeded(seed))?;
        match (planned, spec.room) {
            (Some(a), Some(b)) if a != b => eprintln!(
                "note: the {} x {} m room grew to {} x {} m to take everything",
                a.size[0], a.size[1], b.size[0], b.size[1]
            ),
            _ => {}
        }
        l
    };
    super::create_dir(out)?;
    // spec.json records what was understood and what the layout could not satisfy (added keys).
    let mut json = serde_json::to_value(&spec)?;
    if let Some(map) = json.as_object_mut() {
        map.insert("understood".into(), serde_json::to_value(&understood)?);
        // (the anchors it could not meet too: "desk1 WINDOW")
        let unsatisfied: Vec<String> = l
            .unsatisfied
            .iter()
            .map(|r| r.to_string())
            .chain(l.unsatisfied_anchors.iter().map(|a| a.to_string()))
            .collect();
        map.insert("unsatisfied".into(), serde_json::to_value(unsatisfied)?);
    }
    let spec_json = serde_json::to_string_pretty(&json)?;
    dreamscene::util::write_atomic(&out.join("spec.json"), spec_json.as_bytes())
        .with_context(|| format!("writing {}/spec.json", out.display()))?;
    l.write(&out.join("layout.json"))
        .with_context(|| format!("writing {}/layout.json", out.display()))?;
    write_png(
        &dreamscene::plan::draw::draw_layout(&l),
        &out.join("layout.png"),
    )?;
    Ok((spec, l))
}

/// "; 1 relation unsatisfied: chair1 faces table1" (each named), then "; 1 anchor unmet: desk1
/// WINDOW", or nothing when all hold.
pub fn unsatisfied_note(l: &dreamscene::plan::spec::Layout) -> String {
    let listed = |what: &str, v: Vec<String>| match v.len() {
        0 => String::new(),
        n => format!(
            "; {n} {what}{} {}: {}",
            if n == 1 { "" } else { "s" },
            if what == "relation" {
                "unsatisfied"
            } else {
                "unmet"
            },
            v.join(", ")
        ),
    };
    let relations: Vec<String> = l.unsatisfied.iter().map(|r| r.to_string()).collect();
    let anchors: Vec<String> = l
        .unsatisfied_anchors
        .iter()
        .map(|a| a.to_string())
        .collect();
    listed("relation", relations) + &listed("anchor", anchors)
}

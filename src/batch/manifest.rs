//! The batch manifest: one prompt a line, or JSONL of `{"id", "prompt", "seed", ...generate
//! flags}`. Every scene gets an id that names its directory (`DIR/<id>/`) and decides its shard.
use super::BatchError;
use serde::Deserialize;
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// One scene of a manifest: its id, prompt, and the generate flags its line sets (unset flags
/// take the batch command's values).
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    /// Directory name under the batch's output; from a text manifest the prompt's ordinal,
    /// zero-padded to four digits (`0001`, `0002`, ...).
    #[serde(default)]
    pub id: String,
    pub prompt: String,
    pub seed: Option<u64>,
    pub draft: Option<bool>,
    pub prior: Option<String>,
    pub models: Option<PathBuf>,
    pub resolution: Option<u32>,
    pub renders: Option<usize>,
    pub iterations: Option<u32>,
    pub object_iterations: Option<u32>,
    pub recon_passes: Option<u32>,
    pub object_recon_passes: Option<u32>,
    pub object_gaussians: Option<usize>,
    pub env_density: Option<f64>,
}

/// Reads a manifest file (see [`parse`]).
pub fn read(path: &Path) -> Result<Vec<Entry>, BatchError> {
    let text = std::fs::read_to_string(path).map_err(|e| BatchError::Io {
        path: path.display().to_string(),
        msg: e.to_string(),
    })?;
    let jsonl = path
        .extension()
        .is_some_and(|e| e == "jsonl" || e == "ndjson");
    parse(&text, jsonl).map_err(|m| BatchError::Manifest {
        path: path.display().to_string(),
        msg: m,
    })
}

/// Parses a manifest. It is JSONL when `jsonl` is set or its first line that is neither blank
/// nor a `#` comment starts with `{`; otherwise every such line is one prompt. Errors name the
/// line.
pub fn parse(text: &str, jsonl: bool) -> Result<Vec<Entry>, String> {
    let lines: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
        .collect();
    let jsonl = jsonl || lines.first().is_some_and(|(_, l)| l.starts_with('{'));
    let mut out = Vec::with_capacity(lines.len());
    for (k, (line, l)) in lines.iter().enumerate() {
        let e = if jsonl {
            let mut e: Entry =
                serde_json::from_str(l).map_err(|err| format!("line {line}: {err}"))?;
            if e.id.is_empty() {
                e.id = format!("{:04}", k + 1);
            }
            e
        } else {
            Entry {
                id: format!("{:04}", k + 1),
                prompt: l.to_string(),
                ..Entry::default()
            }
        };
        check_id(&e.id).map_err(|m| format!("line {line}: {m}"))?;
        if e.prompt.trim().is_empty() {
            return Err(format!("line {line}: the prompt is empty"));
        }
        out.push(e);
    }
    let mut seen = HashSet::new();
    for e in &out {
        if !seen.insert(e.id.as_str()) {
            return Err(format!("the id `{}` appears twice", e.id));
        }
    }
    if out.is_empty() {
        return Err("no prompts (one a line, or JSONL objects with \"prompt\")".into());
    }
    Ok(out)
}

/// An id must be usable as one directory name on any file system.
fn check_id(id: &str) -> Result<(), String> {
    let ok = !id.is_empty()
        && id.len() <= 100
        && !id.starts_with('.')
        && id
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-'));
    if ok {
        Ok(())
    } else {
        Err(format!(
            "id `{id}`: use 1 to 100 letters, digits, '.', '_' or '-', not starting with '.'"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_lines_are_numbered_prompts_without_blanks_or_comments() {
        let m = parse(
            "a bedroom\n\n# not this\n  a kitchen with two stools  \n",
            false,
        )
        .unwrap();
        assert_eq!(m.len(), 2);
        assert_eq!(
            (m[0].id.as_str(), m[0].prompt.as_str()),
            ("0001", "a bedroom")
        );
        assert_eq!(
            (m[1].id.as_str(), m[1].prompt.as_str()),
            ("0002", "a kitchen with two stools")
        );
        assert_eq!(m[1].seed, None);
    }

    #[test]
    fn jsonl_lines_carry_ids_seeds_and_flags() {
        let t = r#"{"id": "room-a", "prompt": "a bedroom", "seed": 7, "resolution": 64}
{"prompt": "a garden", "draft": true}"#;
        let m = parse(t, false).unwrap();
        assert_eq!(m[0].id, "room-a");
        assert_eq!((m[0].seed, m[0].resolution), (Some(7), Some(64)));
        assert_eq!((m[1].id.as_str(), m[1].draft), ("0002", Some(true)));
    }

    #[test]
    fn bad_lines_are_named() {
        let unknown = parse(r#"{"prompt": "x", "colour": 1}"#, true).unwrap_err();
        assert!(
            unknown.contains("line 1") && unknown.contains("colour"),
            "{unknown}"
        );
        let dup = parse(
            "{\"id\":\"a\",\"prompt\":\"x\"}\n{\"id\":\"a\",\"prompt\":\"y\"}",
            true,
        )
        .unwrap_err();
        assert!(dup.contains("`a` appears twice"), "{dup}");
        let path = parse(r#"{"id": "../up", "prompt": "x"}"#, true).unwrap_err();
        assert!(path.contains("../up"), "{path}");
        assert!(parse("# only a comment\n", false).is_err());
        let empty = parse(r#"{"prompt": " "}"#, true).unwrap_err();
        assert!(empty.contains("empty"), "{empty}");
    }
}

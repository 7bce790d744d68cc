//! The CLIP BPE tokenizer, read from a model directory's `tokenizer/` (`vocab.json`, `merges.txt`,
//! and the special tokens and maximum length from `special_tokens_map.json` /
//! `tokenizer_config.json`).
//!
//! Text is cleaned as CLIP does (HTML entities decoded, whitespace collapsed, lower-cased; ftfy's
//! mojibake repair is not reproduced), split by CLIP's pattern, each piece mapped byte-wise to the
//! GPT-2 byte alphabet with `</w>` marking the end of the word, and merged by rank. The output is
//! `<|startoftext|>` + at most `max_length − 2` tokens + `<|endoftext|>`, padded to `max_length`.
//! No crate covers this layout without pulling a large tokenizer framework, and the algorithm is
//! short.
use regex::Regex;
use serde_json::Value;
use std::collections::HashMap;
use std::path::Path;
use std::sync::{Mutex, OnceLock, PoisonError};

/// A loaded CLIP tokenizer.
pub struct ClipTokenizer {
    vocab: HashMap<String, i64>,
    ranks: HashMap<(String, String), usize>,
    byte_chars: Vec<char>,
    pattern: Regex,
    cache: Mutex<HashMap<String, Vec<i64>>>,
    pub bos: i64,
    pub eos: i64,
    pub pad: i64,
    pub unk: i64,
    pub max_length: usize,
}

/// GPT-2's reversible byte → printable character table.
fn byte_chars() -> Vec<char> {
    let printable: Vec<u32> = (b'!' as u32..=b'~' as u32)
        .chain(0xA1..=0xAC)
        .chain(0xAE..=0xFF)
        .collect();
    let mut map = vec!['\0'; 256];
    for &b in &printable {
        map[b as usize] = char::from_u32(b).expect("Latin-1 code points are chars");
    }
    let mut n = 0;
    for b in 0..256u32 {
        if !printable.contains(&b) {
            map[b as usize] = char::from_u32(256 + n).expect("code points below 512 are chars");
            n += 1;
        }
    }
    map
}

/// The token string of a special-token entry: either a plain string or `{"content": …}`.
fn token_content(v: &Value) -> Option<String> {
    match v {
        Value::String(s) => Some(s.clone()),
        Value::Object(o) => o
            .get("content")
            .and_then(|c| c.as_str())
            .map(str::to_string),
        _ => None,
    }
}

/// Decodes the HTML entities CLIP's cleaning undoes (named basics and numeric references).
fn html_unescape(s: &str) -> String {
    if !s.contains('&') {
        return s.to_string();
    }
    static ENTITY: OnceLock<Regex> = OnceLock::new();
    let re = ENTITY.get_or_init(|| {
        Regex::new(r"&(#[0-9]+|#[xX][0-9a-fA-F]+|amp|lt|gt|quot|apos|nbsp);")
            .expect("the entity pattern is a valid regex")
    });
    re.replace_all(s, |c: &regex::Captures| {
        let e = &c[1];
        let ch = match e {
            "amp" => Some('&'),
            "lt" => Some('<'),
            "gt" => Some('>'),
            "quot" => Some('"'),
            "apos" => Some('\''),
            "nbsp" => Some('\u{a0}'),
            _ if e.starts_with("#x") || e.starts_with("#X") => u32::from_str_radix(&e[2..], 16)
                .ok()
                .and_then(char::from_u32),
            _ => e[1..].parse::<u32>().ok().and_then(char::from_u32),
        };
        ch.map(String::from).unwrap_or_else(|| c[0].to_string())
    })
    .into_owned()
}

impl ClipTokenizer {
    /// Loads `dir/vocab.json`, `dir/merges.txt` and the optional special-token files.
    pub fn load(dir: &Path) -> Result<ClipTokenizer, String> {
        let vocab_path = dir.join("vocab.json");
        let text = std::fs::read_to_string(&vocab_path)
            .map_err(|e| format!("{}: {e}", vocab_path.display()))?;
        let raw: HashMap<String, i64> = serde_json::from_str(&text).map_err(|e| {
            format!(
                "{}: not a token → id JSON object: {e}",
                vocab_path.display()
            )
        })?;
        let merges_path = dir.join("merges.txt");
        let text = std::fs::read_to_string(&merges_path)
            .map_err(|e| format!("{}: {e}", merges_path.display()))?;
        let mut ranks = HashMap::new();
        for (n, line) in text.lines().enumerate() {
            if line.starts_with("#version") || line.trim().is_empty() {
                continue;
            }
            let mut parts = line.split(' ');
            match (parts.next(), parts.next(), parts.next()) {
                (Some(a), Some(b), None) => {
                    let r = ranks.len();
                    ranks.entry((a.to_string(), b.to_string())).or_insert(r);
                }
                _ => {
                    return Err(format!(
                        "{}: line {}: expected two symbols separated by one space, got {line:?}",
                        merges_path.display(),
                        n + 1
                    ))
                }
            }
        }

        let mut special: HashMap<String, Value> = HashMap::new();
        for f in ["special_tokens_map.json", "tokenizer_config.json"] {
            let p = dir.join(f);
            if let Ok(text) = std::fs::read_to_string(&p) {
                let v: Value = serde_json::from_str(&text)
                    .map_err(|e| format!("{}: malformed JSON: {e}", p.display()))?;
                if let Value::Object(o) = v {
                    for (k, v) in o {
                        special.entry(k).or_insert(v);
                    }
                }
            }
        }
        let id_of = |key: &str, default: &str| -> Result<i64, String> {
            let tok = special
                .get(key)
                .and_then(token_content)
                .unwrap_or_else(|| default.to_string());
            raw.get(&tok).copied().ok_or_else(|| {
                format!(
                    "{}: the {key} {tok:?} is not in the vocabulary",
                    vocab_path.display()
                )
            })
        };
        let bos = id_of("bos_token", "<|startoftext|>")?;
        let eos = id_of("eos_token", "<|endoftext|>")?;
        let unk = id_of("unk_token", "<|endoftext|>")?;
        let pad = id_of("pad_token", "<|endoftext|>")?;
        let max_length = special
            .get("model_max_length")
            .and_then(|v| v.as_f64())
            .filter(|v| *v >= 2.0 && *v <= 4096.0)
            .map(|v| v as usize)
            .unwrap_or(77);
        let pattern = Regex::new(
            r"(?i)<\|startoftext\|>|<\|endoftext\|>|'s|'t|'re|'ve|'m|'ll|'d|\p{L}+|\p{N}|[^\s\p{L}\p{N}]+",
        )
        .expect("the pre-tokeniser pattern is a valid regex");
        Ok(ClipTokenizer {
            vocab: raw,
            ranks,
            byte_chars: byte_chars(),
            pattern,
            cache: Mutex::new(HashMap::new()),
            bos,
            eos,
            pad,
            unk,
            max_length,
        })
    }

    /// The BPE tokens of one pre-tokenised word (already in the byte alphabet).
    fn bpe(&self, word: &str) -> Vec<i64> {
        if let Some(ids) = self
            .cache
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .get(word)
        {
            return ids.clone();
        }
        let chars: Vec<char> = word.chars().collect();
        let mut syms: Vec<String> = chars.iter().map(|c| c.to_string()).collect();
        if let Some(last) = syms.last_mut() {
            last.push_str("</w>");
        }
        while syms.len() > 1 {
            let best = (0..syms.len() - 1)
                .filter_map(|i| {
                    self.ranks
                        .get(&(syms[i].clone(), syms[i + 1].clone()))
                        .map(|r| (*r, i))
                })
                .min();
            let Some((_, i)) = best else { break };
            let (a, b) = (syms[i].clone(), syms[i + 1].clone());
            let mut merged = Vec::with_capacity(syms.len());
            let mut k = 0;
            while k < syms.len() {
                if k + 1 < syms.len() && syms[k] == a && syms[k + 1] == b {
                    merged.push(format!("{a}{b}"));
                    k += 2;
                } else {
                    merged.push(std::mem::take(&mut syms[k]));
                    k += 1;
                }
            }
            syms = merged;
        }
        let ids: Vec<i64> = syms
            .iter()
            .map(|s| self.vocab.get(s).copied().unwrap_or(self.unk))
            .collect();
        self.cache
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .insert(word.to_string(), ids.clone());
        ids
    }

    /// The content tokens of `text`, without start/end tokens or padding.
    pub fn encode(&self, text: &str) -> Vec<i64> {
        let cleaned = html_unescape(&html_unescape(text));
        let cleaned = cleaned
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
            .to_lowercase();
        let mut out = vec![];
        for m in self.pattern.find_iter(&cleaned) {
            let s = m.as_str();
            if let Some(id) = self.vocab.get(s).filter(|_| s.starts_with("<|")) {
                out.push(*id);
                continue;
            }
            let word: String = s.bytes().map(|b| self.byte_chars[b as usize]).collect();
            out.extend(self.bpe(&word));
        }
        out
    }

    /// `max_length` ids: start token, the content truncated to fit, end token, padding.
    pub fn encode_padded(&self, text: &str) -> Vec<i64> {
        let body = self.encode(text);
        let keep = body.len().min(self.max_length - 2);
        let mut ids = Vec::with_capacity(self.max_length);
        ids.push(self.bos);
        ids.extend_from_slice(&body[..keep]);
        ids.push(self.eos);
        ids.resize(self.max_length, self.pad);
        ids
    }

    /// Number of tokens in the vocabulary file.
    pub fn vocab_size(&self) -> usize {
        self.vocab.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tok() -> ClipTokenizer {
        ClipTokenizer::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/clip")).unwrap()
    }

    /// Reference ids from open_clip's tokenizer with the full CLIP vocabulary
    /// (scripts/dev/make_clip_fixture.py); the fixture keeps the real ids.
    #[test]
    fn matches_reference_ids() {
        let t = tok();
        let cases: Value = serde_json::from_str(
            &std::fs::read_to_string(
                Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/clip/cases.json"),
            )
            .unwrap(),
        )
        .unwrap();
        let cases = cases["cases"].as_array().unwrap();
        assert!(cases.len() >= 10);
        for c in cases {
            let prompt = c["prompt"].as_str().unwrap();
            let want: Vec<i64> = c["ids"]
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v.as_i64().unwrap())
                .collect();
            let mut got = vec![t.bos];
            got.extend(t.encode(prompt));
            got.push(t.eos);
            assert_eq!(got, want, "prompt {prompt:?}");
        }
    }

    #[test]
    fn padding_and_truncation() {
        let t = tok();
        assert_eq!(t.max_length, 77);
        let ids = t.encode_padded("a photo of a cat");
        assert_eq!(&ids[..7], &[49406, 320, 1125, 539, 320, 2368, 49407]);
        assert_eq!(ids.len(), 77);
        // The fixture directory has no special-token files: padding is <|endoftext|>.
        assert!(ids[7..].iter().all(|&i| i == 49407));
        let long = "a red sofa ".repeat(40);
        let ids = t.encode_padded(&long);
        assert_eq!(ids.len(), 77);
        assert_eq!(ids[0], 49406);
        assert_eq!(ids[76], 49407);
        assert_eq!(ids[1..76], t.encode(&long)[..75]);
    }

    #[test]
    fn html_entities_and_whitespace() {
        let t = tok();
        assert_eq!(t.encode("a &amp; b"), t.encode("a & b"));
        assert_eq!(t.encode("  A\tPHOTO \n of"), t.encode("a photo of"));
        assert_eq!(html_unescape("&#233;&#xe9;&bogus;"), "éé&bogus;");
    }

    #[test]
    fn malformed_files_are_named() {
        let dir = std::env::temp_dir().join(format!("ds-tok-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("vocab.json"), "{\"a\": 1,").unwrap();
        std::fs::write(dir.join("merges.txt"), "#version: 0.2\na b\n").unwrap();
        let e = ClipTokenizer::load(&dir).err().unwrap();
        assert!(e.contains("vocab.json"), "{e}");
        std::fs::write(dir.join("vocab.json"), "{\"a\": 1}").unwrap();
        std::fs::write(dir.join("merges.txt"), "#version: 0.2\na b c\n").unwrap();
        let e = ClipTokenizer::load(&dir).err().unwrap();
        assert!(e.contains("merges.txt: line 2"), "{e}");
        std::fs::write(dir.join("merges.txt"), "a b\n").unwrap();
        let e = ClipTokenizer::load(&dir).err().unwrap();
        assert!(e.contains("bos_token"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }
}

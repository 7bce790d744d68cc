//! The crate's layers, read from its sources: the host-only modules (`plan`, `camera`, `shape`,
//! `scene`) never reach the GPU (`ash` or `crate::gpu`), and no two top-level modules import
//! each other.
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const HOST_ONLY: [&str; 4] = ["plan", "camera", "shape", "scene"];

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).expect("read src") {
        let p = e.expect("entry").path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The code of a file without its comments (doc comments name other modules freely).
fn code(text: &str) -> String {
    text.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The top-level module of `src/<m>.rs` or `src/<m>/...`, and the code of each of its files.
fn modules() -> BTreeMap<String, Vec<(PathBuf, String)>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = vec![];
    sources(&src, &mut files);
    let mut out: BTreeMap<String, Vec<(PathBuf, String)>> = BTreeMap::new();
    for f in files {
        let rel = f.strip_prefix(&src).expect("under src");
        let first = rel
            .components()
            .next()
            .expect("a component")
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        let text = std::fs::read_to_string(&f).expect("read source");
        out.entry(first).or_default().push((f, code(&text)));
    }
    out
}

/// The top-level modules `code` names as `crate::<m>`.
fn imports(code: &str, names: &BTreeSet<String>) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for (i, _) in code.match_indices("crate::") {
        let before = code[..i].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue; // `dreamscene::crate::` cannot occur; `foo_crate::` is another path
        }
        let rest = &code[i + "crate::".len()..];
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if names.contains(&name) {
            out.insert(name);
        }
    }
    // `use crate::{a, b::c}` groups.
    for (i, _) in code.match_indices("crate::{") {
        let rest = &code[i + "crate::{".len()..];
        let group = rest.split('}').next().unwrap_or("");
        for item in group.split(',') {
            let name: String = item
                .trim()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if names.contains(&name) {
                out.insert(name);
            }
        }
    }
    out
}

#[test]
fn host_only_modules_never_reach_the_gpu() {
    let mods = modules();
    for m in HOST_ONLY {
        for (path, code) in mods.get(m).map(Vec::as_slice).unwrap_or(&[]) {
            for banned in ["ash::", "use ash", "crate::gpu", "super::gpu"] {
                assert!(
                    !code.contains(banned),
                    "{} ({m}/ is host-only) uses `{banned}`",
                    path.display()
                );
            }
        }
    }
}

#[test]
fn no_two_modules_import_each_other() {
    let mods = modules();
    let names: BTreeSet<String> = mods.keys().cloned().collect();
    let mut edges: BTreeMap<String, BTreeMap<String, PathBuf>> = BTreeMap::new();
    for (m, files) in &mods {
        for (path, code) in files {
            for n in imports(code, &names) {
                if &n != m {
                    edges
                        .entry(m.clone())
                        .or_default()
                        .entry(n)
                        .or_insert(path.clone());
                }
            }
        }
    }
    let mut cycles = vec![];
    for (a, to) in &edges {
        for (b, via) in to {
            if a < b {
                if let Some(back) = edges.get(b).and_then(|t| t.get(a)) {
                    cycles.push(format!(
                        "{a} <-> {b} ({} and {})",
                        via.display(),
                        back.display()
                    ));
                }
            }
        }
    }
    assert!(
        cycles.is_empty(),
        "modules importing each other: {cycles:#?}"
    );
    // The check itself finds an import (so it cannot pass by reading nothing).
    assert!(
        edges.get("shape").is_some_and(|t| t.contains_key("plan")),
        "shape reads the knowledge base of plan"
    );
}

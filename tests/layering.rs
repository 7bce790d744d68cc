//! The crate's layers, read from its sources: the host-only modules (`plan`, `camera`, `shape`,
//! `scene`) never reach the GPU (`ash`, `gpu_allocator` or `crate::gpu`), and the top-level
//! modules import each other in no cycle (of two modules or more).
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

/// True when `code` reaches the GPU: `ash`, `gpu_allocator`, or the crate's `gpu` module, also
/// inside a `use crate::{…}` group.
fn reaches_gpu(code: &str, names: &BTreeSet<String>) -> Option<&'static str> {
    for banned in [
        "ash::",
        "use ash",
        "gpu_allocator",
        "crate::gpu",
        "super::gpu",
    ] {
        if code.contains(banned) {
            return Some(banned);
        }
    }
    imports(code, names)
        .contains("gpu")
        .then_some("crate::{gpu, ..}")
}

/// A cycle of module imports (any length), as the path `a -> b -> ... -> a`, if there is one.
fn find_cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|p| p == m) {
            let mut cycle = path[at..].to_vec();
            cycle.push(m.to_string());
            return Some(cycle);
        }
        if done.contains(m) {
            return None;
        }
        path.push(m.to_string());
        for n in edges.get(m).into_iter().flatten() {
            if let Some(c) = visit(n, edges, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(m.to_string());
        None
    }
    let mut done = BTreeSet::new();
    edges
        .keys()
        .find_map(|m| visit(m, edges, &mut vec![], &mut done))
}

/// Which top-level module imports which (`crate::<m>`), with a file that does.
fn import_graph(
    mods: &BTreeMap<String, Vec<(PathBuf, String)>>,
) -> BTreeMap<String, BTreeMap<String, PathBuf>> {
    let names: BTreeSet<String> = mods.keys().cloned().collect();
    let mut edges: BTreeMap<String, BTreeMap<String, PathBuf>> = BTreeMap::new();
    for (m, files) in mods {
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
    edges
}

#[test]
fn host_only_modules_never_reach_the_gpu() {
    let mods = modules();
    let names: BTreeSet<String> = mods.keys().cloned().collect();
    for m in HOST_ONLY {
        assert!(mods.contains_key(m), "src/{m} is read");
        for (path, code) in mods.get(m).map(Vec::as_slice).unwrap_or(&[]) {
            if let Some(banned) = reaches_gpu(code, &names) {
                panic!("{} ({m}/ is host-only) uses `{banned}`", path.display());
            }
        }
    }
}

#[test]
fn no_modules_import_each_other() {
    let mods = modules();
    let edges = import_graph(&mods);
    let graph: BTreeMap<String, BTreeSet<String>> = edges
        .iter()
        .map(|(m, to)| (m.clone(), to.keys().cloned().collect()))
        .collect();
    if let Some(cycle) = find_cycle(&graph) {
        let files: Vec<String> = cycle
            .windows(2)
            .map(|w| format!("{} imports {}", edges[&w[0]][&w[1]].display(), w[1]))
            .collect();
        panic!(
            "modules importing each other: {}\n{}",
            cycle.join(" -> "),
            files.join("\n")
        );
    }
    // The check itself finds an import (so it cannot pass by reading nothing).
    assert!(
        graph.get("shape").is_some_and(|t| t.contains("plan")),
        "shape reads the knowledge base of plan"
    );
}

/// The detectors on made-up sources: each pattern a module can use to reach the GPU or another
/// module is seen, and look-alikes (comments, other crates' paths) are not.
#[test]
fn the_checks_see_every_form_of_import() {
    let names: BTreeSet<String> = ["gpu", "plan", "shape", "util"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let set = |v: &[&str]| -> BTreeSet<String> { v.iter().map(|s| s.to_string()).collect() };
    assert_eq!(
        imports(&code("use crate::{gpu::Context, plan};"), &names),
        set(&["gpu", "plan"]),
        "a use group"
    );
    assert_eq!(
        imports(&code("let k = crate::util::ks(); // crate::shape"), &names),
        set(&["util"]),
        "a path in code, not one in a comment"
    );
    assert_eq!(
        imports(&code("use other_crate::plan;"), &names),
        set(&[]),
        "another crate's path"
    );
    for (text, reaches) in [
        ("use ash::vk;", true),
        ("use crate::{plan, gpu::Buffer};", true),
        ("fn f(c: &super::super::gpu::Context) {}", true),
        ("let a = gpu_allocator::MemoryLocation::GpuOnly;", true),
        ("// see crate::gpu for the kernels", false),
        ("use crate::plan::kb;", false),
    ] {
        assert_eq!(
            reaches_gpu(&code(text), &names).is_some(),
            reaches,
            "reaches the GPU: {text}"
        );
    }
    let graph = |pairs: &[(&str, &str)]| {
        let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (a, b) in pairs {
            g.entry(a.to_string()).or_default().insert(b.to_string());
        }
        g
    };
    assert_eq!(
        find_cycle(&graph(&[("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")])),
        Some(
            vec!["a", "b", "c", "a"]
                .into_iter()
                .map(String::from)
                .collect()
        ),
        "a three-module cycle"
    );
    assert_eq!(
        find_cycle(&graph(&[("a", "b"), ("a", "c"), ("b", "c"), ("c", "d")])),
        None,
        "a diamond is no cycle"
    );
}

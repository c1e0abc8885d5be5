//! Tidy checks on the source tree (rust-analyzer's habit): every module opens with a `//!`
//! comment stating its role and invariants, no placeholder macros are left in the code, every
//! layer uses only the layers `src/lib.rs` lists before it, and every source file is on the code
//! map of ARCHITECTURE.md.

use std::path::Path;

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn sources() -> Vec<(std::path::PathBuf, String)> {
    let mut files = Vec::new();
    rust_files(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut files,
    );
    files.sort();
    assert!(files.len() > 20, "the source tree was not found");
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect()
}

#[test]
fn every_module_opens_with_a_doc_comment() {
    let missing: Vec<String> = sources()
        .into_iter()
        .filter(|(_, text)| !text.trim_start().starts_with("//!"))
        .map(|(p, _)| p.display().to_string())
        .collect();
    assert!(
        missing.is_empty(),
        "modules without a //! opening: {missing:?}"
    );
}

#[test]
fn no_placeholders_in_the_code() {
    let placeholders = [concat!("todo", "!("), concat!("unimplemented", "!(")];
    let mut found = Vec::new();
    for (path, text) in sources() {
        for (n, line) in text.lines().enumerate() {
            if placeholders.iter().any(|p| line.contains(p)) {
                found.push(format!("{}:{}", path.display(), n + 1));
            }
        }
    }
    assert!(found.is_empty(), "placeholders left: {found:?}");
}

/// The top-level modules in the order `src/lib.rs` declares them.
fn layers() -> Vec<String> {
    let lib =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs")).unwrap();
    let layers: Vec<String> = lib
        .lines()
        .filter_map(|l| l.trim().strip_prefix("pub mod "))
        .map(|l| l.trim_end_matches(';').to_string())
        .collect();
    assert!(layers.len() > 8, "src/lib.rs lists no modules: {layers:?}");
    layers
}

/// The layers a line of code names through `crate::<layer>` (comments are skipped: doc links
/// may point upwards).
fn named_layers<'a>(line: &str, layers: &'a [String]) -> Vec<&'a str> {
    let code = line.split("//").next().unwrap_or("");
    let mut out = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        let rest = &code[i + "crate::".len()..];
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if let Some(l) = layers.iter().find(|l| **l == name) {
            out.push(l.as_str());
        }
    }
    // `use crate::{a, b::c}` names several.
    if let Some(group) = code.trim().strip_prefix("use crate::{") {
        for part in group.split(',') {
            let name = part.trim().split("::").next().unwrap_or("");
            if let Some(l) = layers.iter().find(|l| **l == name) {
                out.push(l.as_str());
            }
        }
    }
    out
}

/// The lines of `text`, a `use crate::{...};` group spread over several lines joined into its
/// first (the others left empty, so line numbers stay).
fn joined_uses(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut open: Option<usize> = None;
    for line in text.lines() {
        match open {
            Some(k) => {
                out[k].push_str(line.trim());
                out.push(String::new());
                if line.contains("};") {
                    open = None;
                }
            }
            None => {
                if line.trim().starts_with("use crate::{") && !line.contains("};") {
                    open = Some(out.len());
                }
                out.push(line.to_string());
            }
        }
    }
    out
}

#[test]
fn every_layer_uses_only_the_layers_listed_before_it() {
    let layers = layers();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut wrong = Vec::new();
    for (path, text) in sources() {
        let rel = path.strip_prefix(&src).unwrap();
        let Some(own) = rel.components().next().and_then(|c| c.as_os_str().to_str()) else {
            continue;
        };
        let own = own.trim_end_matches(".rs");
        let Some(rank) = layers.iter().position(|l| l == own) else {
            continue; // lib.rs, main.rs, mi_alloc.rs
        };
        for (n, line) in joined_uses(&text).iter().enumerate() {
            for used in named_layers(line, &layers) {
                let used_rank = layers.iter().position(|l| l == used).unwrap();
                if used_rank > rank {
                    wrong.push(format!(
                        "{}:{}: `{own}` uses `{used}`, listed after it in src/lib.rs",
                        path.display(),
                        n + 1
                    ));
                }
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "layer order broken:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_layer_order_check_sees_an_upward_use() {
    let layers: Vec<String> = ["base", "syntax", "plan", "cli"].map(String::from).to_vec();
    assert_eq!(
        named_layers("use crate::{syntax::ast, cli::run};", &layers),
        ["syntax", "cli"]
    );
    assert!(named_layers("/// see [`crate::cli`]", &layers).is_empty());
    let joined = joined_uses("use crate::{\n    base::Span,\n    cli::run,\n};\nfn f() {}");
    assert_eq!(named_layers(&joined[0], &layers), ["base", "cli"]);
}

#[test]
fn every_source_file_is_on_the_code_map() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let map = std::fs::read_to_string(root.join("ARCHITECTURE.md")).unwrap();
    let src = root.join("src");
    let mut missing = Vec::new();
    for (path, _) in sources() {
        let rel = path.strip_prefix(&src).unwrap();
        let parts: Vec<&str> = rel.iter().map(|c| c.to_str().unwrap()).collect();
        if parts.len() == 1 {
            if !map.contains(&format!("`src/{}`", parts[0])) {
                missing.push(rel.display().to_string());
            }
            continue;
        }
        // The layer's section of the map: from its heading to the next layer's.
        let heading = format!("**`src/{}/`**", parts[0]);
        let Some(start) = map.find(&heading) else {
            missing.push(rel.display().to_string());
            continue;
        };
        let section = &map[start..];
        let section = &section[..section[heading.len()..]
            .find("- **`src/")
            .map_or(section.len(), |e| e + heading.len())];
        let dirs = &parts[1..parts.len() - 1];
        let file = parts[parts.len() - 1];
        let named = dirs.iter().all(|d| {
            section.contains(&format!("`{d}/`")) || section.contains(&format!("`{d}.rs`"))
        }) && section.contains(&format!("`{file}`"));
        if !named {
            missing.push(rel.display().to_string());
        }
    }
    assert!(
        missing.is_empty(),
        "source files missing from ARCHITECTURE.md's code map: {missing:?}"
    );
}

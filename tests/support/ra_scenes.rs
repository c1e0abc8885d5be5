//! Real runs over KB_full for the explanation tests: AL_d scene text loaded against
//! `domains/ra/kb_full.ald`, planned by `lucent::plan`, and its executed plan explained through
//! `explain::history` (the Control adapter).
//!
//! Its loaders (`load_scene`, `load_text`, `load_at`) are the one AL_d file loader of the tests
//! and benches: `support/plan.rs` and `support/learn.rs` use it, and `benches/{explain,plan}.rs`
//! include this file with `#[path]`.
#![allow(dead_code)]

use std::path::Path;

use lucent::action::{self, ast::Description, ast::Value};
use lucent::base::SourceMap;
use lucent::control::Symbol;
use lucent::explain::history::{explain_history, History, HistoryConfig};
use lucent::plan::{plan, PlanConfig, Plans};

/// Loads scene text as if it were the file `domains/ra/scenes/NAME` (so `include "../kb_full.ald"`
/// resolves to the repository's KB_full).
pub fn load_text(name: &str, text: &str) -> (Description, SourceMap) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("domains/ra/scenes")
        .join(name);
    load_at(&path, text)
}

/// Loads scene text as the file `path` (its includes resolve from there).
pub fn load_at(path: &Path, text: &str) -> (Description, SourceMap) {
    let name = path.display().to_string();
    let mut sources = SourceMap::new();
    let file = sources.add(path.to_string_lossy().into_owned(), text.to_string());
    let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, file, &mut read);
    assert!(!parsed.has_errors(), "{name}: {:?}", parsed.diagnostics);
    (parsed.description, sources)
}

/// Loads a scene file of `domains/ra/scenes`.
pub fn load_scene(name: &str) -> (Description, SourceMap) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("domains/ra/scenes")
        .join(name);
    load_text(name, &std::fs::read_to_string(path).unwrap())
}

/// The planner's minimal plans, under a profile (`None`: KB_full).
pub fn plans(
    desc: &Description,
    sources: &SourceMap,
    profile: Option<&str>,
    max_horizon: usize,
) -> Result<Plans, lucent::plan::PlanError> {
    let mut config = PlanConfig {
        max_horizon,
        profile: profile.map(str::to_string),
        ..PlanConfig::default()
    };
    if profile.is_some() {
        // The learner profile turns the planning module off; the planner needs it.
        config
            .overrides
            .push(("planning".into(), Value::Bool(true)));
    }
    plan(desc, sources, &config)
}

/// The history of `actions` executed from the scene's initial state, under a profile.
pub fn history(
    desc: &Description,
    sources: &mut SourceMap,
    actions: &[Symbol],
    profile: Option<&str>,
) -> History {
    let config = HistoryConfig {
        profile: profile.map(str::to_string),
        ..HistoryConfig::default()
    };
    explain_history(desc, sources, actions, &config).unwrap_or_else(|e| panic!("{e}"))
}

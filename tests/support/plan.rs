//! Set-up shared by the planner's tests (`tests/plan/`, as `crate::support::plan`): loading an
//! AL_d problem of the repository, adding a scene and a goal to a domain, action lists, and
//! `lucent` run in-process.

use std::path::Path;

use lucent::action::ast::Description;
use lucent::base::SourceMap;
use lucent::control::Symbol;
use lucent::plan::act::Domain;

use super::{cli, ra_scenes};

/// The golden scenes of docs/domain.md 4.5.
pub const TABLETOP: &str = "domains/ra/scenes/tabletop_task.ald";
pub const EXCEPTION_GOAL: &str = "domains/ra/scenes/exception_goal.ald";
/// KB_full, the domain the scenes of facts are added to.
pub const DOMAIN: &str = "domains/ra/kb_full.ald";
/// A scene of facts (`domains/ra/README.md`, "Scenes as facts").
pub const SCENE: &str = "tests/data/plan/scene.lp";

/// Loads an AL_d file: a path relative to the repository, or a file name of
/// `domains/ra/scenes`; its includes resolve from its directory. Panics on a parse error.
pub fn load(file: &str) -> (Description, SourceMap) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let path = if file.contains('/') {
        root.join(file)
    } else {
        root.join("domains/ra/scenes").join(file)
    };
    ra_scenes::load_at(&path, &std::fs::read_to_string(&path).unwrap())
}

/// KB_full as the sense-plan-act loop takes it.
pub fn domain() -> Domain {
    let (description, sources) = load(DOMAIN);
    Domain {
        description,
        sources,
    }
}

/// KB_full with a scene (AL_d statements, e.g. `SceneFacts::to_ald`) and a goal statement
/// (`goal relation(on, a, b).`) added.
pub fn problem(scene_ald: String, goal: String) -> (Description, SourceMap) {
    let (mut desc, mut sources) = load(DOMAIN);
    add_statements(&mut desc, &mut sources, "<scene>", scene_ald).unwrap();
    add_statements(&mut desc, &mut sources, "<goal>", goal).unwrap();
    (desc, sources)
}

/// Adds the AL_d statements of `text` to `desc`, the text becoming file `name` of `sources`.
fn add_statements(
    desc: &mut Description,
    sources: &mut SourceMap,
    name: &str,
    text: String,
) -> Result<(), String> {
    let file = sources.add(name.to_string(), text.clone());
    let parsed = lucent::action::parse(file, &text);
    if parsed.has_errors() {
        let mut d = lucent::base::Diagnostics::default();
        d.extend(parsed.diagnostics);
        return Err(d.render(sources));
    }
    desc.statements.extend(parsed.description.statements);
    Ok(())
}

/// Action terms from their text (`pickup(rob1,a)`).
pub fn actions(text: &[&str]) -> Vec<Symbol> {
    text.iter().map(|a| Symbol::parse(a).unwrap()).collect()
}

/// `lucent ARGS` in-process from the repository's root: exit code, stdout, stderr.
pub fn lucent(args: &[&str]) -> (i32, String, String) {
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
    cli::lucent_in_process(args, "")
}

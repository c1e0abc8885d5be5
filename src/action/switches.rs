//! Switches: the translator's built-in switches and their defaults, what a caller chooses
//! ([`Options`]: a profile, switch values by name, typed [`Switches`]), and their resolution
//! into the final values the checker and the translation read.
//!
//! Invariants: precedence, lowest first: built-in defaults, `switch` declarations, `set`
//! statements, the chosen profile, [`Options::overrides`], then the typed [`Switches`] (this
//! file is the only place where the built-in switches' names meet the values the robot layers
//! set); a setting of an unknown switch, or of a value of another type, is a positioned error.

use std::collections::{BTreeMap, HashMap};

use crate::base::{Diagnostic, Span};

use super::ast::*;
use super::check::Checked;

fn err(diags: &mut Vec<Diagnostic>, span: Span, msg: impl Into<String>) {
    diags.push(Diagnostic::error(span, msg));
}

/// Built-in switches of the translator, with their defaults.
pub fn builtin_switches() -> Vec<(&'static str, Value)> {
    vec![
        ("horizon", Value::Int(9)),
        ("planning", Value::Bool(true)),
        ("horizon_mode", Value::Word("fixed".into())),
        ("observations_as_facts", Value::Bool(false)),
        ("stability_constraint", Value::Word("always".into())),
    ]
}

/// What the caller chooses: a profile, switch values by name (`-c name=value`, the
/// description's own switches) and the built-in switches as typed values.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// A profile declared in the description.
    pub profile: Option<String>,
    /// Switch values by name that override the description and the profile; names that are not
    /// switches are ignored (on the command line they may be grounding constants).
    pub overrides: Vec<(String, Value)>,
    /// The built-in switches the robot layers set, overriding everything else.
    pub switches: Switches,
}

impl Options {
    /// Options with the profile `profile` and nothing overridden.
    pub fn profile(profile: Option<&str>) -> Options {
        Options {
            profile: profile.map(str::to_string),
            ..Options::default()
        }
    }
}

/// How the translation lays out the steps of its horizon (the switch `horizon_mode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HorizonMode {
    /// Steps `0..=horizon`, with `:- not success` when planning: every plan reaching the goal
    /// by the horizon.
    Fixed,
    /// Steps `0..=horizon`, with the goal required exactly at the last step.
    Iterative,
    /// One `step(k)` part per step (see `action::parts`).
    Incremental,
    /// One action at every step before the horizon, goal or not: the transitions a plan
    /// checker explores.
    Transition,
}

impl HorizonMode {
    /// The switch value's word.
    pub fn word(self) -> &'static str {
        match self {
            HorizonMode::Fixed => "fixed",
            HorizonMode::Iterative => "iterative",
            HorizonMode::Incremental => "incremental",
            HorizonMode::Transition => "transition",
        }
    }
}

/// Typed values of the built-in switches; `None` keeps the value the description, its profile
/// or the overrides give.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Switches {
    /// The last step (`horizon`).
    pub horizon: Option<usize>,
    /// The planning module (`planning`): the goal, `success`, action choice.
    pub planning: Option<bool>,
    /// The layout of the steps (`horizon_mode`).
    pub horizon_mode: Option<HorizonMode>,
    /// `false` turns the state constraints written `never` off (`stability_constraint = off`).
    pub stability_constraint: Option<bool>,
}

impl Switches {
    /// Horizon `n`, planning module off: a history or a prediction over `n` steps.
    pub fn history(n: usize) -> Switches {
        Switches {
            horizon: Some(n),
            planning: Some(false),
            ..Switches::default()
        }
    }

    /// Horizon `n` with the planning module and steps laid out as `mode`.
    pub fn planning(n: usize, mode: HorizonMode) -> Switches {
        Switches {
            horizon: Some(n),
            planning: Some(true),
            horizon_mode: Some(mode),
            ..Switches::default()
        }
    }

    /// The switches as (name, value) pairs, in the checker's vocabulary.
    fn named(&self) -> Vec<(&'static str, Value)> {
        let mut out = Vec::new();
        if let Some(h) = self.horizon {
            out.push(("horizon", Value::Int(h as i64)));
        }
        if let Some(p) = self.planning {
            out.push(("planning", Value::Bool(p)));
        }
        if let Some(m) = self.horizon_mode {
            out.push(("horizon_mode", Value::Word(m.word().to_string())));
        }
        if self.stability_constraint == Some(false) {
            out.push(("stability_constraint", Value::Word("off".to_string())));
        }
        out
    }
}

fn same_type(a: &Value, b: &Value) -> bool {
    std::mem::discriminant(a) == std::mem::discriminant(b)
}

/// What is wrong with setting switch `name` to `value` (by `set` or in a profile) among
/// `switches`: an unknown name, or a value of another type than the switch's.
fn setting_error(switches: &BTreeMap<String, Value>, name: &Name, value: &Value) -> Option<String> {
    match switches.get(&name.text) {
        None => Some(format!("unknown switch `{}`", name.text)),
        Some(old) if !same_type(old, value) => Some(format!(
            "switch `{}` takes values like `{old}`, not `{value}`",
            name.text
        )),
        Some(_) => None,
    }
}

pub(super) fn resolve_switches(desc: &Description, options: &Options, c: &mut Checked) {
    for (name, value) in builtin_switches() {
        c.switches.insert(name.to_string(), value);
    }
    let mut declared_at: HashMap<String, Span> = HashMap::new();
    for s in &desc.statements {
        if let StatementKind::Switch { name, value } = &s.kind {
            if let Some(first) = declared_at.get(&name.text) {
                let d = Diagnostic::error(
                    name.span,
                    format!("switch `{}` is declared twice", name.text),
                )
                .with_note(Some(*first), "first declared here");
                c.diagnostics.push(d);
                continue;
            }
            if let Some(builtin) = c.switches.get(&name.text) {
                if !same_type(builtin, value) {
                    err(
                        &mut c.diagnostics,
                        name.span,
                        format!("built-in switch `{}` cannot take `{value}`", name.text),
                    );
                    continue;
                }
            }
            declared_at.insert(name.text.clone(), name.span);
            c.switches.insert(name.text.clone(), value.clone());
        }
    }
    for s in &desc.statements {
        if let StatementKind::Set { name, value } = &s.kind {
            match setting_error(&c.switches, name, value) {
                Some(msg) => err(&mut c.diagnostics, name.span, msg),
                None => {
                    c.switches.insert(name.text.clone(), value.clone());
                }
            }
        }
    }
    // Every profile's switch settings must name known switches with values of their type.
    let known = c.switches.clone();
    for s in &desc.statements {
        if let StatementKind::Profile { items, .. } = &s.kind {
            for item in items {
                if let ProfileItem::Set { name, value } = item {
                    if let Some(msg) = setting_error(&known, name, value) {
                        err(&mut c.diagnostics, name.span, msg);
                    }
                }
            }
        }
    }
    let mut found = options.profile.is_none();
    if let Some(profile) = &options.profile {
        for s in &desc.statements {
            if let StatementKind::Profile { name, items } = &s.kind {
                if &name.text != profile {
                    continue;
                }
                found = true;
                for item in items {
                    if let ProfileItem::Set { name, value } = item {
                        if known
                            .get(&name.text)
                            .is_some_and(|old| same_type(old, value))
                        {
                            c.switches.insert(name.text.clone(), value.clone());
                        }
                    }
                }
            }
        }
    }
    if !found {
        // At the start of the main file: included statements come before the main file's.
        let file = desc
            .statements
            .last()
            .map(|s| s.span.file)
            .unwrap_or_default();
        let span = Span::new(file, 0, 0);
        let mut known: Vec<&str> = desc
            .statements
            .iter()
            .filter_map(|s| match &s.kind {
                StatementKind::Profile { name, .. } => Some(name.text.as_str()),
                _ => None,
            })
            .collect();
        known.dedup();
        err(
            &mut c.diagnostics,
            span,
            format!(
                "unknown profile `{}` (the description declares: {})",
                options.profile.as_deref().unwrap_or(""),
                if known.is_empty() {
                    "none".to_string()
                } else {
                    known.join(", ")
                }
            ),
        );
    }
    for (name, value) in &options.overrides {
        if let Some(old) = c.switches.get(name) {
            if same_type(old, value) {
                c.switches.insert(name.clone(), value.clone());
            }
        }
    }
    for (name, value) in options.switches.named() {
        c.switches.insert(name.to_string(), value);
    }
}

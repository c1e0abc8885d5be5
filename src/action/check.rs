//! The AL_d checker: resolves the profile's switches, decides which statements are active, builds
//! the signature (sorts with their members, statics, fluents, actions) and checks every active
//! statement against it.
//!
//! Invariants:
//! - Every problem is a positioned error diagnostic; nothing panics on bad input.
//! - After a check without errors, every active statement's atoms name declared predicates with
//!   the right arity and role, ground arguments belong to their positions' sorts, and every
//!   variable has at least one sort ([`StatementInfo::var_sorts`]), so the translation is sorted
//!   and safe.
//! - Switches are resolved first, in the precedence [`super::switches`] states.
//! - Guards are read before anything else; statements whose guards fail, or whose label the
//!   profile drops, are not checked (so alternative versions of an axiom may share a label).

use std::collections::{BTreeMap, BTreeSet, HashMap};

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::{Term, TermKind};

use super::ast::*;
use super::switches::resolve_switches;
use super::switches::Options;

/// Names the translation uses for its own predicates; descriptions may not declare them.
pub const RESERVED: &[&str] = &[
    "holds",
    "occurs",
    "obs",
    "hpd",
    "step",
    "goal",
    "success",
    "something_happened",
    "known0",
    "inertial_fluent",
    "defined_fluent",
    "action",
    "true",
    "false",
    "horizon",
];

/// A ground member of a sort.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Member {
    /// An integer.
    Int(i64),
    /// A constant.
    Sym(String),
}

/// A declared sort.
#[derive(Clone, Debug)]
pub struct SortInfo {
    /// Index of the declaring statement.
    pub statement: usize,
    /// Its members (sorted).
    pub members: BTreeSet<Member>,
}

/// A declared static, fluent or action.
#[derive(Clone, Debug)]
pub struct Decl {
    /// Index of the declaring statement.
    pub statement: usize,
    /// What it is.
    pub kind: DeclKind,
    /// Argument sorts.
    pub params: Vec<String>,
}

/// The role of an atom.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A static.
    Static,
    /// An inertial or defined fluent.
    Fluent,
    /// An action.
    Action,
    /// A sort used as a unary predicate (`positional(S)`).
    Sort,
}

/// Per active statement: the sorts its variables and arithmetic arguments must belong to.
#[derive(Clone, Debug, Default)]
pub struct StatementInfo {
    /// Variables in first-occurrence order, each with the sorts of its positions (redundant
    /// supersets removed).
    pub var_sorts: Vec<(String, Vec<String>)>,
    /// Arithmetic arguments with the sort of their position (`height(N+1)`).
    pub term_sorts: Vec<(Term, String)>,
}

/// The result of checking.
#[derive(Clone, Debug, Default)]
pub struct Checked {
    /// Final switch values.
    pub switches: BTreeMap<String, Value>,
    /// Whether each statement takes part (guards hold, label not dropped, not an error).
    pub active: Vec<bool>,
    /// Sorts by name, in declaration order in `sort_order`.
    pub sorts: HashMap<String, SortInfo>,
    /// Sort names in declaration order.
    pub sort_order: Vec<String>,
    /// Statics, fluents and actions by name.
    pub decls: HashMap<String, Decl>,
    /// Declared names in declaration order.
    pub decl_order: Vec<String>,
    /// Per statement (parallel to the statements; default for inactive ones).
    pub info: Vec<StatementInfo>,
    /// Errors found.
    pub diagnostics: Vec<Diagnostic>,
}

impl Checked {
    /// The value of a boolean switch (false when unset or not boolean).
    pub fn flag(&self, name: &str) -> bool {
        matches!(self.switches.get(name), Some(Value::Bool(true)))
    }

    /// The value of an integer switch.
    pub fn int(&self, name: &str) -> Option<i64> {
        match self.switches.get(name) {
            Some(Value::Int(n)) => Some(*n),
            _ => None,
        }
    }

    /// The value of a word switch.
    pub fn word(&self, name: &str) -> Option<&str> {
        match self.switches.get(name) {
            Some(Value::Word(w)) => Some(w),
            _ => None,
        }
    }

    /// The role and declaration of a predicate name.
    pub fn role(&self, name: &str) -> Option<Role> {
        if let Some(d) = self.decls.get(name) {
            return Some(match d.kind {
                DeclKind::Static => Role::Static,
                DeclKind::Action => Role::Action,
                _ => Role::Fluent,
            });
        }
        self.sorts.contains_key(name).then_some(Role::Sort)
    }

    /// True when every member of `a` is a member of `b`.
    pub fn subsort(&self, a: &str, b: &str) -> bool {
        match (self.sorts.get(a), self.sorts.get(b)) {
            (Some(a), Some(b)) => a.members.is_subset(&b.members),
            _ => false,
        }
    }
}

fn err(diags: &mut Vec<Diagnostic>, span: Span, msg: impl Into<String>) {
    diags.push(Diagnostic::error(span, msg));
}

/// Checks `desc` under `options`.
pub fn check(desc: &Description, options: &Options) -> Checked {
    let mut c = Checked::default();
    let statements = &desc.statements;
    resolve_switches(desc, options, &mut c);

    // Labels that the profile drops, and label lookups.
    let mut all_labels: HashMap<&str, Vec<usize>> = HashMap::new();
    for (i, s) in statements.iter().enumerate() {
        if let Some(l) = &s.label {
            all_labels.entry(l.text.as_str()).or_default().push(i);
        }
    }
    // Every profile's dropped labels must exist, chosen or not.
    let mut dropped: BTreeSet<String> = BTreeSet::new();
    for s in statements {
        if let StatementKind::Profile { name, items } = &s.kind {
            let chosen = options.profile.as_ref() == Some(&name.text);
            for item in items {
                if let ProfileItem::Drop(label) = item {
                    if !all_labels.contains_key(label.text.as_str()) {
                        err(
                            &mut c.diagnostics,
                            label.span,
                            format!("unknown label `{}`", label.text),
                        );
                    } else if chosen {
                        dropped.insert(label.text.clone());
                    }
                }
            }
        }
    }

    // Which statements take part.
    for s in statements {
        let mut on = !matches!(s.kind, StatementKind::Error);
        for g in &s.guards {
            match c.switches.get(&g.switch.text) {
                Some(Value::Bool(b)) => on &= *b != g.negated,
                Some(v) => {
                    err(
                        &mut c.diagnostics,
                        g.switch.span,
                        format!(
                            "switch `{}` has the value `{v}`; a guard needs a true/false switch",
                            g.switch.text
                        ),
                    );
                    on = false;
                }
                None => {
                    err(
                        &mut c.diagnostics,
                        g.switch.span,
                        format!("unknown switch `{}`", g.switch.text),
                    );
                    on = false;
                }
            }
        }
        if let Some(l) = &s.label {
            on &= !dropped.contains(&l.text);
        }
        c.active.push(on);
    }
    c.info = vec![StatementInfo::default(); statements.len()];

    // Duplicate labels among active statements.
    let mut seen: HashMap<&str, Span> = HashMap::new();
    for (i, s) in statements.iter().enumerate() {
        if let (true, Some(l)) = (c.active[i], &s.label) {
            if let Some(first) = seen.get(l.text.as_str()) {
                let d = Diagnostic::error(l.span, format!("label `{}` is used twice", l.text))
                    .with_note(Some(*first), "first used here");
                c.diagnostics.push(d);
            } else {
                seen.insert(&l.text, l.span);
            }
        }
    }

    declare(statements, &mut c);
    for (i, s) in statements.iter().enumerate() {
        if c.active[i] {
            let info = check_statement(statements, i, s, &mut c);
            c.info[i] = info;
        }
    }
    c
}

/// Collects sorts and declarations of the active statements.
fn declare(statements: &[Statement], c: &mut Checked) {
    // Sorts first, so declarations can name sorts defined later.
    let mut sort_stmt: HashMap<String, usize> = HashMap::new();
    for (i, s) in statements.iter().enumerate() {
        if !c.active[i] {
            continue;
        }
        if let StatementKind::Sort { name, .. } = &s.kind {
            if RESERVED.contains(&name.text.as_str()) {
                err(
                    &mut c.diagnostics,
                    name.span,
                    format!("`{}` is reserved by the translation", name.text),
                );
            } else if let Some(&first) = sort_stmt.get(&name.text) {
                let d =
                    Diagnostic::error(name.span, format!("sort `{}` is defined twice", name.text))
                        .with_note(Some(statements[first].span), "first defined here");
                c.diagnostics.push(d);
            } else {
                sort_stmt.insert(name.text.clone(), i);
                c.sort_order.push(name.text.clone());
            }
        }
    }
    // Members, by depth-first evaluation with cycle detection.
    let order = c.sort_order.clone();
    let mut state: HashMap<String, u8> = HashMap::new();
    for name in &order {
        eval_sort(name, statements, &sort_stmt, &mut state, c);
    }
    for (i, s) in statements.iter().enumerate() {
        if !c.active[i] {
            continue;
        }
        if let StatementKind::Declaration { kind, name, params } = &s.kind {
            if RESERVED.contains(&name.text.as_str()) {
                err(
                    &mut c.diagnostics,
                    name.span,
                    format!("`{}` is reserved by the translation", name.text),
                );
                continue;
            }
            if c.sorts.contains_key(&name.text) {
                err(
                    &mut c.diagnostics,
                    name.span,
                    format!("`{}` is already a sort", name.text),
                );
                continue;
            }
            if let Some(first) = c.decls.get(&name.text) {
                let d = Diagnostic::error(name.span, format!("`{}` is declared twice", name.text))
                    .with_note(
                        Some(statements[first.statement].span),
                        "first declared here",
                    );
                c.diagnostics.push(d);
                continue;
            }
            for p in params {
                if !c.sorts.contains_key(&p.text) {
                    err(
                        &mut c.diagnostics,
                        p.span,
                        format!("unknown sort `{}`", p.text),
                    );
                }
            }
            c.decls.insert(
                name.text.clone(),
                Decl {
                    statement: i,
                    kind: *kind,
                    params: params.iter().map(|p| p.text.clone()).collect(),
                },
            );
            c.decl_order.push(name.text.clone());
        }
    }
}

fn eval_sort(
    name: &str,
    statements: &[Statement],
    sort_stmt: &HashMap<String, usize>,
    state: &mut HashMap<String, u8>,
    c: &mut Checked,
) -> Option<BTreeSet<Member>> {
    let i = *sort_stmt.get(name)?;
    match state.get(name) {
        Some(2) => return c.sorts.get(name).map(|s| s.members.clone()),
        Some(1) => return None,
        _ => {}
    }
    state.insert(name.to_string(), 1);
    let StatementKind::Sort { expr, .. } = &statements[i].kind else {
        return None;
    };
    let mut members = BTreeSet::new();
    for part in &expr.parts {
        match part {
            SortPart::Set(terms) => {
                for t in terms {
                    match ground_member(t) {
                        Some(m) => {
                            members.insert(m);
                        }
                        None => err(
                            &mut c.diagnostics,
                            t.span,
                            "a sort member must be a constant or an integer",
                        ),
                    }
                }
            }
            SortPart::Range(lo, hi) => match (ground_member(lo), ground_member(hi)) {
                (Some(Member::Int(lo)), Some(Member::Int(hi))) => {
                    if hi - lo > 1_000_000 {
                        err(
                            &mut c.diagnostics,
                            expr.span,
                            "an integer range of a sort may have at most a million members",
                        );
                    } else {
                        members.extend((lo..=hi).map(Member::Int));
                    }
                }
                _ => err(
                    &mut c.diagnostics,
                    expr.span,
                    "the ends of a sort range must be integers",
                ),
            },
            SortPart::Name(other) => {
                if !sort_stmt.contains_key(&other.text) {
                    err(
                        &mut c.diagnostics,
                        other.span,
                        format!("unknown sort `{}`", other.text),
                    );
                    continue;
                }
                match eval_sort(&other.text, statements, sort_stmt, state, c) {
                    Some(m) => members.extend(m),
                    None if state.get(other.text.as_str()) == Some(&1) => err(
                        &mut c.diagnostics,
                        other.span,
                        format!("sort `{}` is defined in terms of itself", other.text),
                    ),
                    None => {}
                }
            }
        }
    }
    state.insert(name.to_string(), 2);
    c.sorts.insert(
        name.to_string(),
        SortInfo {
            statement: i,
            members: members.clone(),
        },
    );
    Some(members)
}

/// The member a ground term denotes, if it is a constant or an integer.
pub fn ground_member(t: &Term) -> Option<Member> {
    match &t.kind {
        TermKind::Integer(n) => Some(Member::Int(*n)),
        TermKind::Constant(s) => Some(Member::Sym(s.to_string())),
        TermKind::Paren(inner) => ground_member(inner),
        _ => None,
    }
}

/// Variables of a term with their spans, in order.
pub fn term_vars<'t>(t: &'t Term, out: &mut Vec<(&'t str, Span)>) {
    match &t.kind {
        TermKind::Variable(v) => out.push((v, t.span)),
        TermKind::Function { args, .. } => {
            for alt in args {
                for a in alt {
                    term_vars(a, out);
                }
            }
        }
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => term_vars(arg, out),
        TermKind::Binary { lhs, rhs, .. } | TermKind::Interval { lo: lhs, hi: rhs } => {
            term_vars(lhs, out);
            term_vars(rhs, out);
        }
        TermKind::Pool(ts) | TermKind::ScriptCall { args: ts, .. } => {
            for a in ts {
                term_vars(a, out);
            }
        }
        _ => {}
    }
}

/// Collects the sorts of one statement's variables.
struct Scope<'c> {
    checked: &'c mut Checked,
    info: StatementInfo,
    /// Every variable occurrence in order.
    occurrences: Vec<(String, Span)>,
}

impl Scope<'_> {
    fn error(&mut self, span: Span, msg: impl Into<String>) {
        err(&mut self.checked.diagnostics, span, msg);
    }

    fn note_vars(&mut self, t: &Term) {
        let mut vs = Vec::new();
        term_vars(t, &mut vs);
        for (v, span) in vs {
            self.occurrences.push((v.to_string(), span));
        }
    }

    fn add_sort(&mut self, var: &str, sort: &str) {
        match self.info.var_sorts.iter_mut().find(|(v, _)| v == var) {
            Some((_, sorts)) => {
                if !sorts.iter().any(|s| s == sort) {
                    sorts.push(sort.to_string());
                }
            }
            None => self
                .info
                .var_sorts
                .push((var.to_string(), vec![sort.to_string()])),
        }
    }

    /// Checks an argument against the sort of its position.
    fn argument(&mut self, t: &Term, sort: &str) {
        self.note_vars(t);
        match &t.kind {
            TermKind::Variable(v) => self.add_sort(v, sort),
            TermKind::Integer(_) | TermKind::Constant(_) => {
                let m = ground_member(t).expect("a ground member");
                let ok = self
                    .checked
                    .sorts
                    .get(sort)
                    .is_none_or(|s| s.members.contains(&m));
                if !ok {
                    let shown = match &m {
                        Member::Int(n) => n.to_string(),
                        Member::Sym(s) => s.clone(),
                    };
                    self.error(t.span, format!("`{shown}` is not in sort `{sort}`"));
                }
            }
            TermKind::Binary { .. } | TermKind::Unary { .. } | TermKind::Paren(_) => {
                self.info.term_sorts.push((t.clone(), sort.to_string()));
            }
            _ => self.error(
                t.span,
                "an argument must be a constant, an integer, a variable or arithmetic",
            ),
        }
    }

    /// Checks an atom and returns its role.
    fn atom(&mut self, a: &Atom) -> Option<Role> {
        let name = &a.name.text;
        let Some(role) = self.checked.role(name) else {
            self.error(
                a.name.span,
                format!("`{name}` is not declared (as a sort, static, fluent or action)"),
            );
            for t in &a.args {
                self.note_vars(t);
            }
            return None;
        };
        let params: Vec<String> = match role {
            Role::Sort => vec![name.clone()],
            _ => self.checked.decls[name].params.clone(),
        };
        if params.len() != a.args.len() {
            self.error(
                a.span,
                format!(
                    "`{name}` takes {} argument(s), not {}",
                    params.len(),
                    a.args.len()
                ),
            );
            for t in &a.args {
                self.note_vars(t);
            }
            return Some(role);
        }
        for (t, s) in a.args.iter().zip(&params) {
            self.argument(t, s);
        }
        Some(role)
    }

    /// Checks a literal that must be a fluent (`what` names the place for messages).
    fn fluent(&mut self, l: &Lit, what: &str, inertial_only: bool) {
        let role = self.atom(&l.atom);
        let name = &l.atom.name.text;
        match role {
            Some(Role::Fluent)
                if inertial_only
                    && matches!(self.checked.decls[name].kind, DeclKind::Defined { .. }) =>
            {
                self.error(
                    l.atom.name.span,
                    format!("{what} must be an inertial fluent; `{name}` is a defined fluent"),
                );
            }
            Some(Role::Fluent) => {}
            Some(r) => self.error(
                l.atom.name.span,
                format!("{what} must be a fluent; `{name}` is {}", role_name(r)),
            ),
            None => {}
        }
    }

    /// Checks an action atom.
    fn action(&mut self, a: &Atom, what: &str) {
        match self.atom(a) {
            Some(Role::Action) | None => {}
            Some(r) => self.error(
                a.name.span,
                format!(
                    "{what} must be an action; `{}` is {}",
                    a.name.text,
                    role_name(r)
                ),
            ),
        }
    }

    /// Checks body items; `fluents` says whether fluents may occur.
    fn body(&mut self, body: &[BodyItem], fluents: bool) {
        for item in body {
            match item {
                BodyItem::Lit(l) => match self.atom(&l.atom) {
                    Some(Role::Action) => self.error(
                        l.atom.name.span,
                        format!(
                            "`{}` is an action; actions cannot be conditions",
                            l.atom.name.text
                        ),
                    ),
                    Some(Role::Fluent) if !fluents => self.error(
                        l.atom.name.span,
                        format!(
                            "`{}` is a fluent; a static cannot depend on fluents",
                            l.atom.name.text
                        ),
                    ),
                    Some(Role::Sort) if l.negated => {
                        self.error(l.span, "a sort condition cannot be negated")
                    }
                    _ => {}
                },
                BodyItem::Compare { lhs, rhs, .. } => {
                    self.note_vars(lhs);
                    self.note_vars(rhs);
                }
            }
        }
    }

    /// Every variable needs a sort; removes redundant supersets.
    fn finish(mut self, ground: Option<&str>) -> StatementInfo {
        let mut reported = BTreeSet::new();
        for (v, span) in std::mem::take(&mut self.occurrences) {
            if let Some(what) = ground {
                if reported.insert(v.clone()) {
                    self.error(span, format!("{what} must be ground; `{v}` is a variable"));
                }
                continue;
            }
            if !self.info.var_sorts.iter().any(|(x, _)| *x == v) && reported.insert(v.clone()) {
                self.error(
                    span,
                    format!(
                        "unsorted variable `{v}`: it occurs in no argument position with a sort"
                    ),
                );
            }
        }
        let checked = &*self.checked;
        for (_, sorts) in &mut self.info.var_sorts {
            let all = sorts.clone();
            sorts.retain(|s| {
                !all.iter()
                    .any(|o| o != s && checked.subsort(o, s) && !checked.subsort(s, o))
            });
            // Of equal sorts, keep the first.
            let mut kept: Vec<String> = Vec::new();
            for s in sorts.iter() {
                if !kept
                    .iter()
                    .any(|k| checked.subsort(k, s) && checked.subsort(s, k))
                {
                    kept.push(s.clone());
                }
            }
            *sorts = kept;
        }
        self.info
    }
}

/// How a role is named in messages.
pub fn role_name(r: Role) -> &'static str {
    match r {
        Role::Static => "a static",
        Role::Fluent => "a fluent",
        Role::Action => "an action",
        Role::Sort => "a sort",
    }
}

fn check_statement(
    statements: &[Statement],
    index: usize,
    s: &Statement,
    c: &mut Checked,
) -> StatementInfo {
    let mut scope = Scope {
        checked: c,
        info: StatementInfo::default(),
        occurrences: Vec::new(),
    };
    let mut ground = None;
    match &s.kind {
        StatementKind::Causal {
            action,
            effect,
            body,
        } => {
            scope.action(action, "the cause of a causal law");
            scope.fluent(effect, "the head of a causal law", true);
            scope.body(body, true);
        }
        StatementKind::Constraint { head, body } => match scope.atom(&head.atom) {
            Some(Role::Fluent) => scope.body(body, true),
            Some(Role::Static) => scope.body(body, false),
            Some(r) => {
                scope.error(
                    head.atom.name.span,
                    format!(
                        "the head of a state constraint must be a fluent or a static; `{}` is {}",
                        head.atom.name.text,
                        role_name(r)
                    ),
                );
                scope.body(body, true);
            }
            None => scope.body(body, true),
        },
        StatementKind::Impossible { action, body } => {
            scope.action(action, "an executability condition's action");
            scope.body(body, true);
        }
        StatementKind::Default { head, body } | StatementKind::Never { lit: head, body } => {
            let what = if matches!(s.kind, StatementKind::Default { .. }) {
                "a default"
            } else {
                "a never constraint"
            };
            scope.fluent(head, &format!("the literal of {what}"), false);
            scope.body(body, true);
        }
        StatementKind::Exception {
            default,
            head,
            body,
        } => {
            let target = statements.iter().enumerate().find(|(i, t)| {
                scope.checked.active[*i] && t.label.as_ref().is_some_and(|l| l.text == default.text)
            });
            match target {
                None => scope.error(default.span, format!("unknown label `{}`", default.text)),
                Some((_, t)) => match &t.kind {
                    StatementKind::Default { head: dh, .. } => {
                        if dh.atom.name.text != head.atom.name.text || dh.negated == head.negated {
                            scope.error(
                                head.span,
                                format!(
                                    "an exception to `{}` must assume the complement of its literal",
                                    default.text
                                ),
                            );
                        }
                    }
                    _ => scope.error(default.span, format!("`{}` is not a default", default.text)),
                },
            }
            scope.fluent(head, "the literal of an exception", false);
            scope.body(body, true);
        }
        StatementKind::Goal { body } => {
            scope.body(body, true);
            if !body
                .iter()
                .any(|b| matches!(b, BodyItem::Lit(l) if scope.checked.role(&l.atom.name.text) == Some(Role::Fluent)))
            {
                scope.error(s.span, "a goal needs at least one fluent literal");
            }
        }
        StatementKind::Observed { lit, step } => {
            scope.fluent(lit, "an observation", false);
            scope.note_vars(step);
            step_value(&mut scope, step);
            ground = Some("an observation");
        }
        StatementKind::Happened { action, step } => {
            scope.action(action, "a happened action");
            scope.note_vars(step);
            step_value(&mut scope, step);
            ground = Some("a happened action");
        }
        StatementKind::Initially { lit } => {
            scope.fluent(lit, "an initial literal", false);
            ground = Some("an initial literal");
        }
        StatementKind::InitialDefault { except } => {
            for name in except {
                match scope.checked.decls.get(&name.text) {
                    Some(d) if d.kind == DeclKind::Inertial => {}
                    _ => scope.error(
                        name.span,
                        format!("`{}` is not an inertial fluent", name.text),
                    ),
                }
            }
        }
        StatementKind::Switch { .. }
        | StatementKind::Set { .. }
        | StatementKind::Profile { .. }
        | StatementKind::Include { .. } => {
            if let Some(g) = s.guards.first() {
                scope.error(g.span, "switches, profiles and includes cannot be guarded");
            }
        }
        StatementKind::Sort { .. } | StatementKind::Declaration { .. } | StatementKind::Error => {}
    }
    let _ = index;
    scope.finish(ground)
}

/// A history step must be a non-negative integer.
fn step_value(scope: &mut Scope, step: &Term) {
    match ground_member(step) {
        Some(Member::Int(n)) if n >= 0 => {}
        _ => scope.error(step.span, "a step must be a non-negative integer"),
    }
}

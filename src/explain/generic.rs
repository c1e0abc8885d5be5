//! Why and why not for any program (the use case xclingo serves): the proof tree of an atom in
//! an answer set, over any [`Oracle`] (in practice `oracle::ProgramOracle` over a clingo
//! program grounded with provenance), written out as text: for a true atom the least proof of
//! `explain::support` (built bottom-up from the answer set, linear in the ground program; the
//! search of `explain::build` when an atom of it rests on a weight body), each step with the
//! rule instance and its source location; default-negated literals as "no evidence of"; for an
//! atom that does not hold, every rule for it with the body literal that blocks it.
//!
//! Invariants: the tree is re-checked (`tree::recheck`) before it is written; the answer's
//! literals are the leaves of the preferred proof (for a false atom, the blocking literals);
//! nothing here panics on any atom, known to the program or not.

use super::build::{BuildConfig, Builder};
use super::oracle::ProgramOracle;
use super::questions::{Answer, AnswerError};
use super::source::{self, World};
use super::support::Supports;
use super::tree::{recheck, AxiomKind, BodyLiteral, Kind, NodeId, Oracle, ProofTree, RuleInstance};
use super::unfired::{self, bindings_json, with};
use crate::control::Symbol;

/// What a step's text is written from: the oracle, the answer set's true atoms (for the
/// source-level views; built on first use, as a proof of plain rules never needs them), and
/// the notes the JSON carries.
struct Ctx<'a> {
    oracle: &'a ProgramOracle,
    world: std::cell::OnceCell<World>,
    notes: Vec<serde_json::Value>,
}

impl<'a> Ctx<'a> {
    fn new(oracle: &'a ProgramOracle) -> Self {
        Ctx {
            oracle,
            world: std::cell::OnceCell::new(),
            notes: Vec::new(),
        }
    }

    /// The answer set's true atoms as a [`World`].
    fn world(&self) -> &World {
        self.world
            .get_or_init(|| World::new(self.oracle.true_literals()))
    }
}

/// Whether `t` is an internal atom of the translation (`#aux(N)`), never shown.
fn internal(t: &Symbol) -> bool {
    t.name().is_some_and(|n| n.starts_with('#'))
}

/// Explains why `atom` holds (or, if it does not, why not) in the oracle's answer set.
pub fn why(oracle: &ProgramOracle, atom: &Symbol) -> Result<Answer, AnswerError> {
    let holds = oracle.holds(atom);
    // A true atom's least proof from the bottom-up supports; the search is the fallback.
    let tree = holds
        .then(|| Supports::new(oracle).tree(oracle, atom))
        .flatten()
        .unwrap_or_else(|| Builder::new(oracle, BuildConfig::default()).build(atom));
    recheck(&tree, oracle)?;
    let mut text = String::new();
    let mut literals = Vec::new();
    if holds {
        match tree.roots.first() {
            Some(&root) => {
                text.push_str(&format!("{atom} holds.\n"));
                let mut seen = Vec::new();
                let mut ctx = Ctx::new(oracle);
                let mut w = Writer {
                    tree: &tree,
                    out: &mut text,
                    leaves: &mut literals,
                    seen: &mut seen,
                };
                w.proof(&mut ctx, root, 1);
                let notes = std::mem::take(&mut ctx.notes);
                let mut tree = tree;
                tree.source_notes = notes;
                return Ok(Answer {
                    kind: "why",
                    text: text.trim_end().to_string(),
                    literals,
                    tree: Some(tree),
                });
            }
            None => text.push_str(&format!(
                "{atom} holds, but no support was found within the limits (depth {}, {} branches).\n",
                super::tree::MAX_DEPTH,
                super::tree::MAX_BRANCHES
            )),
        }
        return Ok(Answer {
            kind: "why",
            text: text.trim_end().to_string(),
            literals,
            tree: Some(tree),
        });
    }
    why_not_text(oracle, atom, tree)
}

/// Explains why `atom` does not hold (or, if it does, says so and explains why it does).
pub fn why_not(oracle: &ProgramOracle, atom: &Symbol) -> Result<Answer, AnswerError> {
    if oracle.holds(atom) {
        let mut a = why(oracle, atom)?;
        a.kind = "why_not";
        a.text = format!("{atom} is in the answer set. {}", a.text);
        return Ok(a);
    }
    let tree = Builder::new(oracle, BuildConfig::default()).build(atom);
    recheck(&tree, oracle)?;
    why_not_text(oracle, atom, tree)
}

fn why_not_text(
    oracle: &ProgramOracle,
    atom: &Symbol,
    mut tree: ProofTree,
) -> Result<Answer, AnswerError> {
    let mut text = format!("{atom} does not hold.");
    let mut literals = Vec::new();
    let mut ctx = Ctx::new(oracle);
    let rules = oracle.rules_for(atom);
    let unchosen = rules
        .iter()
        .find(|r| r.kind == AxiomKind::Choice && body_holds(oracle, r));
    match tree.roots.first() {
        _ if rules.is_empty() => removed(&mut ctx, atom, &mut text, &mut literals),
        _ if unchosen.is_some() => {
            let r = unchosen.expect("checked");
            not_chosen(&mut ctx, atom, r, &mut text);
        }
        Some(&root) => {
            let n = tree.node(root);
            text.push_str(" Every rule for it is blocked:");
            for (rule, c) in n.blocked.iter().zip(&n.children) {
                let child = tree.node(*c);
                let line = blocked_line(&mut ctx, rule, &child.literal, child.holds);
                text.push_str(&format!("\n  {line}"));
                if !internal(&child.literal) && !literals.contains(&child.literal) {
                    literals.push(child.literal.clone());
                }
            }
            let shown: Vec<&str> = n.blocked.iter().map(|r| r.label.as_str()).collect();
            source_rules(&mut ctx, atom, &shown, &mut text, &mut literals);
        }
        None => match rules
            .iter()
            .map(|r| Some((r, first_failing(oracle, r)?)))
            .collect::<Option<Vec<_>>>()
        {
            // The search could not show every blocker false (one rests on a choice that left
            // an atom out): each rule's first body literal that fails in the answer set.
            Some(blocked) => {
                text.push_str(" Every rule for it is blocked:");
                for (rule, (lit, holds)) in &blocked {
                    let line = blocked_line(&mut ctx, rule, lit, *holds);
                    text.push_str(&format!("\n  {line}"));
                    if !internal(lit) && !literals.contains(lit) {
                        literals.push(lit.clone());
                    }
                }
                let shown: Vec<&str> = blocked.iter().map(|(r, _)| r.label.as_str()).collect();
                source_rules(&mut ctx, atom, &shown, &mut text, &mut literals);
            }
            None => text.push_str(" Its rules could not all be shown blocked within the limits."),
        },
    }
    tree.source_notes = ctx.notes;
    Ok(Answer {
        kind: "why_not",
        text,
        literals,
        tree: Some(tree),
    })
}

/// What `--full` adds to an answer about `atom`: for a true atom, every ground rule instance
/// for it whose body holds in the answer set (the proof above uses one; the others are further
/// reasons, each a rule of the ground program the re-check would accept as a support step,
/// though one may rest on the atom itself); for a false atom, every body literal of each of
/// its ground rules that fails (the answer names only the first). Appended to the text, and
/// as a note `{"full": [...]}` in the JSON's `source`.
pub fn add_full(oracle: &ProgramOracle, atom: &Symbol, answer: &mut Answer) {
    let rules = oracle.rules_for(atom);
    let holds = oracle.holds(atom);
    let mut notes = Vec::new();
    let mut text = String::new();
    if holds {
        let supports: Vec<&RuleInstance> = rules.iter().filter(|r| body_holds(oracle, r)).collect();
        text.push_str(&format!(
            "\nEvery rule instance for {atom} whose body holds ({}):",
            supports.len()
        ));
        for r in supports {
            text.push_str(&format!("\n  {} `{r}`", r.label));
            notes.push(serde_json::json!({"label": r.label, "rule": r.to_string()}));
        }
    } else if !rules.is_empty() {
        text.push_str(&format!(
            "\nEvery failing body literal of each ground rule for {atom} ({} rules):",
            rules.len()
        ));
        for r in &rules {
            let failing: Vec<String> = r
                .body
                .iter()
                .filter_map(|b| match b {
                    BodyLiteral::Pos(t) if !oracle.holds(t) => Some(t.to_string()),
                    BodyLiteral::Not(t) if oracle.holds(t) => Some(format!("not {t}")),
                    _ => None,
                })
                .collect();
            let shown = if failing.is_empty() {
                // A choice whose body holds: nothing failed, the choice left the atom out.
                "none (the choice left it out)".to_string()
            } else {
                failing.join(", ")
            };
            text.push_str(&format!("\n  {} `{r}`: {shown}", r.label));
            notes.push(serde_json::json!({
                "label": r.label, "rule": r.to_string(), "failing": failing,
            }));
        }
    } else {
        return;
    }
    // Internal atoms (`#aux(N)`) of a rule's translation are not shown in the text.
    if text.contains("#aux") {
        text = text
            .lines()
            .filter(|l| !l.contains("#aux"))
            .collect::<Vec<_>>()
            .join("\n");
    }
    answer.text.push('\n');
    answer.text.push_str(&text);
    if let Some(tree) = &mut answer.tree {
        tree.source_notes
            .push(serde_json::json!({"atom": atom.to_string(), "full": notes}));
    }
}

/// The first body literal of `r` that fails in the answer set, and whether its atom holds
/// (a default-negated literal fails when it does).
fn first_failing(oracle: &dyn Oracle, r: &RuleInstance) -> Option<(Symbol, bool)> {
    r.body.iter().find_map(|b| match b {
        BodyLiteral::Pos(t) if !oracle.holds(t) => Some((t.clone(), false)),
        BodyLiteral::Not(t) if oracle.holds(t) => Some((t.clone(), true)),
        _ => None,
    })
}

/// Whether every body literal of `r` holds (positive true, default-negated false).
fn body_holds(oracle: &dyn Oracle, r: &RuleInstance) -> bool {
    r.body.iter().all(|b| match b {
        BodyLiteral::Pos(t) => oracle.holds(t),
        BodyLiteral::Not(t) => !oracle.holds(t),
        BodyLiteral::Test(_) => true,
    })
}

/// One blocked rule of a why-not: the ground instance and its blocking literal, or, when the
/// blocker is an internal atom (an aggregate that survived grounding), the source statement
/// and the aggregate with its value and elements.
fn blocked_line(ctx: &mut Ctx, rule: &RuleInstance, blocker: &Symbol, holds: bool) -> String {
    if internal(blocker) {
        if let Some((stmt, b)) = ctx.oracle.origin_of(rule) {
            let s = &ctx.oracle.labels.statements[stmt];
            let failing = source::body_aggregates(s)
                .into_iter()
                .filter_map(|(a, neg)| Some((source::aggregate(a, &b, ctx.world())?, neg)))
                .find(|(e, neg)| e.holds == *neg);
            if let Some((e, neg)) = failing {
                let blocker = source::Blocker::Aggregate(Box::new(e), neg);
                ctx.notes.push(serde_json::json!({
                    "blocked": rule.label, "statement": source::statement_text(s),
                    "bindings": bindings_json(&b), "blocker": blocker.to_json(),
                }));
                return format!(
                    "{} `{}`{}: {}",
                    rule.label,
                    source::statement_text(s),
                    with(&b),
                    blocker.words()
                );
            }
        }
    }
    let why = if holds {
        format!("not {blocker} fails, as {blocker} holds")
    } else {
        format!("{blocker} does not hold")
    };
    // A ground instance of a rule with body aggregates lost them at grounding: the statement
    // as written stands in its place.
    if let Some((stmt, b)) = ctx.oracle.origin_of(rule) {
        let s = &ctx.oracle.labels.statements[stmt];
        if !source::body_aggregates(s).is_empty() {
            let written = source::statement_text(s);
            return format!("{} `{written}`{}: {why}", rule.label, with(&b));
        }
    }
    format!("{} `{rule}`: {why}", rule.label)
}

/// Why not, for an atom without a ground rule: the source statements that could derive it,
/// each with the first body literal that cannot hold, explained one level down.
fn removed(ctx: &mut Ctx, atom: &Symbol, text: &mut String, literals: &mut Vec<Symbol>) {
    let cands = unfired::candidates(ctx.oracle, ctx.world(), atom);
    if cands.is_empty() {
        text.push_str(" No rule has it in its head.");
        return;
    }
    text.push_str(
        " No rule instance for it is left after grounding; the rules that could derive it:",
    );
    write_candidates(ctx, &cands, text, literals);
}

/// After the blocked ground rules of a why-not, the source statements that could derive the
/// atom and have no ground instance for it (grounding removed them), as [`removed`] writes them.
fn source_rules(
    ctx: &mut Ctx,
    atom: &Symbol,
    shown: &[&str],
    text: &mut String,
    literals: &mut Vec<Symbol>,
) {
    let cands: Vec<unfired::Candidate> = unfired::candidates(ctx.oracle, ctx.world(), atom)
        .into_iter()
        .filter(|c| !shown.contains(&c.label.as_str()))
        .collect();
    write_candidates(ctx, &cands, text, literals);
}

/// Each candidate statement with its blocked instances, each blocker one level down.
fn write_candidates(
    ctx: &mut Ctx,
    cands: &[unfired::Candidate],
    text: &mut String,
    literals: &mut Vec<Symbol>,
) {
    for c in cands {
        ctx.notes.push(c.to_json());
        text.push_str(&format!(
            "\n  {} `{}`{}",
            c.label,
            c.statement,
            with(&c.head)
        ));
        let blocked: Vec<&source::Instance> =
            c.instances.iter().filter(|i| i.blocker.is_some()).collect();
        if blocked.is_empty() {
            text.push_str(if c.choice {
                ": its body holds; it was not chosen"
            } else {
                ": its body holds, yet grounding made no instance"
            });
            continue;
        }
        for i in blocked.iter().take(unfired::MAX_REPORTED) {
            let Some(b) = &i.blocker else { continue };
            let extra: Bindings = i
                .bindings
                .iter()
                .filter(|x| !c.head.contains(x))
                .cloned()
                .collect();
            let pad = if blocked.len() > 1 { "\n    " } else { ": " };
            text.push_str(&format!("{pad}{}{}", lead(&extra), b.words()));
            if let source::Blocker::False(a) = b {
                if !literals.contains(a) {
                    literals.push(a.clone());
                }
                let deeper = if blocked.len() > 1 {
                    "\n      "
                } else {
                    "\n    "
                };
                text.push_str(&format!("{deeper}{}", one_level_down(ctx, a)));
            }
        }
        if blocked.len() > unfired::MAX_REPORTED {
            text.push_str(&format!(
                "\n    and {} more instances",
                blocked.len() - unfired::MAX_REPORTED
            ));
        }
    }
}

type Bindings = source::Bindings;

/// `for Y=2, ` before an instance's blocker, or nothing.
fn lead(b: &Bindings) -> String {
    if b.is_empty() {
        String::new()
    } else {
        format!("for {}, ", source::show_bindings(b))
    }
}

/// A false atom's own why-not in one line: no rule, the source rules and their first
/// blockers, a choice that left it out, or its blocked ground rules.
fn one_level_down(ctx: &Ctx, a: &Symbol) -> String {
    let rules = ctx.oracle.rules_for(a);
    if rules.is_empty() {
        let cands = unfired::candidates(ctx.oracle, ctx.world(), a);
        if cands.is_empty() {
            return format!("{a}: no rule has it in its head");
        }
        let parts: Vec<String> = cands
            .iter()
            .map(|c| {
                let first = c.instances.iter().find_map(|i| i.blocker.as_ref());
                match first {
                    Some(b) => format!("{} ({})", c.label, b.words()),
                    None => c.label.clone(),
                }
            })
            .collect();
        return format!("{a}: its rules cannot fire: {}", parts.join("; "));
    }
    if rules
        .iter()
        .any(|r| r.kind == AxiomKind::Choice && body_holds(ctx.oracle, r))
    {
        return format!("{a}: it was not chosen");
    }
    let labels: Vec<&str> = rules.iter().map(|r| r.label.as_str()).collect();
    format!("{a}: every rule for it is blocked ({})", labels.join("; "))
}

/// Why not, for an atom a choice could have taken: it was not chosen; what would break if
/// it were.
fn not_chosen(ctx: &mut Ctx, atom: &Symbol, r: &RuleInstance, text: &mut String) {
    let origin = ctx.oracle.origin_of(r);
    let (statement, b) = match &origin {
        Some((stmt, b)) => (
            source::statement_text(&ctx.oracle.labels.statements[*stmt]),
            b.clone(),
        ),
        None => (r.to_string(), Vec::new()),
    };
    text.push_str(&format!(
        " It was not chosen by {} `{statement}`{} (its body holds).",
        r.label,
        with(&b)
    ));
    let violations = unfired::if_true(ctx.oracle, ctx.world(), atom, origin.as_ref());
    if violations.is_empty() {
        text.push_str(
            " It could be: no constraint, bound or optimization would be violated with the \
             rest of the answer set unchanged.",
        );
    } else {
        text.push_str(" If it were true (the rest of the answer set unchanged), it would violate:");
        for v in &violations {
            text.push_str(&format!("\n  {}", v.words()));
        }
    }
    ctx.notes.push(serde_json::json!({
        "chosen": false, "label": r.label, "statement": statement,
        "bindings": bindings_json(&b),
        "violations": violations.iter().map(unfired::Violation::to_json).collect::<Vec<_>>(),
    }));
}

/// Writes a proof as indented text.
struct Writer<'t> {
    tree: &'t ProofTree,
    out: &'t mut String,
    leaves: &'t mut Vec<Symbol>,
    seen: &'t mut Vec<Symbol>,
}

impl Writer<'_> {
    /// Writes the preferred proof below `id`: its support, then the first support of each
    /// positive body literal. An internal atom's step is not written: its children stand at
    /// its place. A choice says "chosen" and names the choice as written; a rule with body
    /// aggregates is named as written, each aggregate with its value and elements.
    fn proof(&mut self, ctx: &mut Ctx, id: NodeId, depth: usize) {
        let tree = self.tree;
        let n = tree.node(id);
        let pad = "  ".repeat(depth);
        let hidden = internal(&n.literal);
        if !hidden {
            let line = self.step_line(ctx, id, &pad);
            self.out.push_str(&line);
        }
        let inner = if hidden { depth } else { depth + 1 };
        for t in &n.no_evidence {
            if !internal(t) {
                let p = "  ".repeat(inner);
                self.out.push_str(&format!("{p}no evidence of {t}\n"));
            }
        }
        if n.children.is_empty() {
            if !hidden && !self.leaves.contains(&n.literal) {
                self.leaves.push(n.literal.clone());
            }
            return;
        }
        for &c in &n.children {
            let lit = &tree.node(c).literal;
            if self.seen.contains(lit) {
                continue;
            }
            self.seen.push(lit.clone());
            self.proof(ctx, c, inner);
        }
    }

    /// The step's line (and its aggregates' lines).
    fn step_line(&mut self, ctx: &mut Ctx, id: NodeId, pad: &str) -> String {
        let n = self.tree.node(id);
        let how = match &n.kind {
            Kind::Axiom { label, .. } => format!("by {label}"),
            k => k.words(),
        };
        let plain = |rule: &str| format!("{pad}{}: {how}{rule}\n", n.literal);
        let Some(r) = &n.rule else {
            return plain("");
        };
        let ground = format!(" `{r}`");
        let Some((stmt, b)) = ctx.oracle.origin_of(r) else {
            return plain(&ground);
        };
        let s = &ctx.oracle.labels.statements[stmt];
        let aggs = source::body_aggregates(s);
        let shows_internal = r.body.iter().any(|l| match l {
            BodyLiteral::Pos(t) | BodyLiteral::Not(t) => internal(t),
            BodyLiteral::Test(x) => x.contains('#'),
        });
        let chosen = r.kind == AxiomKind::Choice;
        if !chosen && aggs.is_empty() && !shows_internal {
            return plain(&ground);
        }
        let written = source::statement_text(s);
        let verb = if chosen { "chosen by" } else { "by" };
        let mut line = format!(
            "{pad}{}: {verb} {} `{written}`{}\n",
            n.literal,
            r.label,
            with(&b)
        );
        let mut evals = Vec::new();
        for (a, neg) in aggs {
            if let Some(e) = source::aggregate(a, &b, ctx.world()) {
                let not = if neg { "not " } else { "" };
                let verdict = if e.holds != neg { "holds" } else { "fails" };
                line.push_str(&format!(
                    "{pad}  {not}{} {verdict}: {}\n",
                    e.text,
                    e.tally()
                ));
                evals.push(e.to_json());
            }
        }
        ctx.notes.push(serde_json::json!({
            "literal": n.literal.to_string(), "chosen": chosen, "label": r.label,
            "statement": written, "bindings": bindings_json(&b), "aggregates": evals,
        }));
        line
    }
}

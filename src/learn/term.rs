//! The learner's small term language: literals over constants and sorted variables, and axioms
//! (causal laws and executability conditions) with a canonical form up to variable renaming.
//!
//! Invariants: a literal is structured data (name, signed, arguments), never text to be sliced;
//! `relation(S, X, Y)` keeps the relation name `S` as a constant in argument 0; an axiom's body
//! is kept sorted and free of duplicates; [`Axiom::canonical`] is equal for two axioms exactly
//! when they are equal up to a sort-preserving renaming of their variables (docs/domain.md 5.8).

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;

/// The sort of a variable: its name prefix (docs/domain.md 5.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Sort {
    /// The robot (`R`).
    Robot,
    /// An object or the table (`O`).
    Object,
}

/// A variable: its sort and index (`R1`, `O5`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Var {
    /// The sort.
    pub sort: Sort,
    /// The index, from 1.
    pub index: u32,
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let prefix = match self.sort {
            Sort::Robot => 'R',
            Sort::Object => 'O',
        };
        write!(f, "{prefix}{}", self.index)
    }
}

/// A term: a constant or a variable.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Term {
    /// A constant (`rob1`, `table`, `on`).
    Const(String),
    /// A variable.
    Var(Var),
}

impl Term {
    /// The constant `name`.
    pub fn constant(name: &str) -> Term {
        Term::Const(name.to_string())
    }

    /// The variable, if this is one.
    pub fn var(&self) -> Option<Var> {
        match self {
            Term::Var(v) => Some(*v),
            Term::Const(_) => None,
        }
    }
}

impl fmt::Display for Term {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Term::Const(c) => f.write_str(c),
            Term::Var(v) => v.fmt(f),
        }
    }
}

/// The predicate of spatial relations; argument 0 is the relation name.
pub const RELATION: &str = "relation";
/// The predicate of the hand fluent `in_hand(R, O)`.
pub const IN_HAND: &str = "in_hand";
/// Predicates whose first argument is an entity and the rest values (`has_size(O1, small)`,
/// `tower_height(O1, 2)`): the values stay constants when lifted.
pub const VALUED: [&str; 4] = ["has_size", "has_surface", "has_shape", "tower_height"];

/// A literal `name(args)` or its classical negation; also used for action atoms.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Literal {
    /// False for a classically negated literal (`¬f`).
    pub positive: bool,
    /// The predicate name.
    pub name: String,
    /// The arguments.
    pub args: Vec<Term>,
}

impl Literal {
    /// A positive literal.
    pub fn new(name: &str, args: Vec<Term>) -> Literal {
        Literal {
            positive: true,
            name: name.to_string(),
            args,
        }
    }

    /// A positive ground literal from constant names.
    pub fn ground(name: &str, args: &[&str]) -> Literal {
        Literal::new(name, args.iter().map(|a| Term::constant(a)).collect())
    }

    /// `relation(rel, a, b)` over constants.
    pub fn relation(rel: &str, a: &str, b: &str) -> Literal {
        Literal::ground(RELATION, &[rel, a, b])
    }

    /// The complement `l̄`.
    pub fn complement(&self) -> Literal {
        Literal {
            positive: !self.positive,
            ..self.clone()
        }
    }

    /// The same literal with the given sign.
    pub fn with_sign(mut self, positive: bool) -> Literal {
        self.positive = positive;
        self
    }

    /// The argument positions that hold objects or the robot (not a relation name, not an
    /// attribute's value).
    pub fn entity_positions(&self) -> std::ops::Range<usize> {
        if self.name == RELATION {
            1.min(self.args.len())..self.args.len()
        } else if VALUED.contains(&self.name.as_str()) {
            0..1.min(self.args.len())
        } else {
            0..self.args.len()
        }
    }

    /// The variables in order of appearance (repeats included).
    pub fn vars(&self) -> impl Iterator<Item = Var> + '_ {
        self.args.iter().filter_map(Term::var)
    }

    /// The literal with every variable mapped through `map` (unmapped variables unchanged).
    pub fn rename(&self, map: &impl Fn(Var) -> Var) -> Literal {
        Literal {
            positive: self.positive,
            name: self.name.clone(),
            args: self
                .args
                .iter()
                .map(|t| match t {
                    Term::Var(v) => Term::Var(map(*v)),
                    c => c.clone(),
                })
                .collect(),
        }
    }

    /// The literal as an AL_d syntax-tree literal: constants that read as integers become
    /// integers, variables keep their names (`O1`).
    pub fn ald(&self) -> crate::action::ast::Lit {
        use crate::action::build::{self, Arg};
        let args: Vec<Arg> = self
            .args
            .iter()
            .map(|t| match t {
                Term::Const(c) => match c.parse::<i64>() {
                    Ok(n) => Arg::Int(n),
                    Err(_) => Arg::Const(c.clone()),
                },
                Term::Var(v) => Arg::Var(v.to_string()),
            })
            .collect();
        build::lit(!self.positive, &self.name, &args)
    }

    /// AL_d text as the knowledge base spells it: `relation(on, O1, O2)`, `-in_hand(R1, O1)`.
    pub fn to_ald(&self) -> String {
        let sign = if self.positive { "" } else { "-" };
        let args: Vec<String> = self.args.iter().map(Term::to_string).collect();
        if args.is_empty() {
            format!("{sign}{}", self.name)
        } else {
            format!("{sign}{}({})", self.name, args.join(", "))
        }
    }

    /// The short form for people: `on(O1, O2)` for `relation(on, O1, O2)` (docs/domain.md 0).
    pub fn short(&self) -> String {
        if self.name == RELATION && self.args.len() == 3 {
            let sign = if self.positive { "" } else { "-" };
            format!("{sign}{}({}, {})", self.args[0], self.args[1], self.args[2])
        } else {
            self.to_ald()
        }
    }
}

impl fmt::Display for Literal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.short())
    }
}

/// What an axiom says about its action.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum AxiomKind {
    /// `a causes head if body`.
    Causal {
        /// The effect.
        head: Literal,
    },
    /// `impossible a if body`.
    Executability,
    /// `head if body`: a state constraint. Its axiom's `action` holds the constraint's
    /// *subject*, the head's atom taken positively (`stable(O1)`), which names the variables
    /// first as an action does.
    Constraint {
        /// The consequence.
        head: Literal,
    },
}

/// A lifted causal law or executability condition.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Axiom {
    /// Causal law (with its head) or executability condition.
    pub kind: AxiomKind,
    /// The lifted action, e.g. `pickup(R1, O1)`.
    pub action: Literal,
    /// The conditions, sorted, without duplicates.
    pub body: Vec<Literal>,
}

impl Axiom {
    /// An axiom with its body sorted and deduplicated.
    pub fn new(kind: AxiomKind, action: Literal, mut body: Vec<Literal>) -> Axiom {
        body.sort();
        body.dedup();
        Axiom { kind, action, body }
    }

    /// The head literal of a causal law.
    pub fn head(&self) -> Option<&Literal> {
        match &self.kind {
            AxiomKind::Causal { head } | AxiomKind::Constraint { head } => Some(head),
            AxiomKind::Executability => None,
        }
    }

    /// True for an executability condition.
    pub fn is_executability(&self) -> bool {
        self.kind == AxiomKind::Executability
    }

    /// The literals that fix variable names first: the action, then the head.
    pub fn fixed_part(&self) -> Vec<&Literal> {
        let mut out = vec![&self.action];
        if let Some(h) = self.head() {
            out.push(h);
        }
        out
    }

    /// Every variable of the axiom, sorted, once.
    pub fn vars(&self) -> Vec<Var> {
        let mut vs: Vec<Var> = self
            .fixed_part()
            .into_iter()
            .chain(self.body.iter())
            .flat_map(|l| l.vars().collect::<Vec<_>>())
            .collect();
        vs.sort();
        vs.dedup();
        vs
    }

    /// The axiom with its variables renamed.
    pub fn rename(&self, map: &impl Fn(Var) -> Var) -> Axiom {
        let kind = match &self.kind {
            AxiomKind::Causal { head } => AxiomKind::Causal {
                head: head.rename(map),
            },
            AxiomKind::Constraint { head } => AxiomKind::Constraint {
                head: head.rename(map),
            },
            AxiomKind::Executability => AxiomKind::Executability,
        };
        Axiom::new(
            kind,
            self.action.rename(map),
            self.body.iter().map(|l| l.rename(map)).collect(),
        )
    }

    /// The canonical representative up to variable renaming: variables renumbered per sort in
    /// order of first appearance in the action, the head, then the body literals in the order
    /// that makes the renamed body smallest. Two axioms are equal up to renaming exactly when
    /// their canonical forms are equal.
    pub fn canonical(&self) -> Axiom {
        let mut map: BTreeMap<Var, Var> = BTreeMap::new();
        let mut next = [0u32; 2];
        for lit in self.fixed_part() {
            for v in lit.vars() {
                assign(&mut map, &mut next, v);
            }
        }
        let mut best: Option<Vec<Literal>> = None;
        let remaining: Vec<&Literal> = self.body.iter().collect();
        canonical_body(&remaining, &map, next, &mut Vec::new(), &mut best);
        let body = best.unwrap_or_default();
        let map_fixed = |v: Var| map[&v];
        let kind = match &self.kind {
            AxiomKind::Causal { head } => AxiomKind::Causal {
                head: head.rename(&map_fixed),
            },
            AxiomKind::Constraint { head } => AxiomKind::Constraint {
                head: head.rename(&map_fixed),
            },
            AxiomKind::Executability => AxiomKind::Executability,
        };
        Axiom::new(kind, self.action.rename(&map_fixed), body)
    }

    /// AL_d text of the statement as the knowledge base spells it, without the final period.
    pub fn to_ald(&self) -> String {
        self.render(Literal::to_ald)
    }

    /// The axiom as the labelled AL_d statement [`Axiom::to_ald`] writes, built as a value.
    pub fn statement(&self, label: &str) -> crate::action::ast::Statement {
        use crate::action::build;
        let body: Vec<_> = self.body.iter().map(Literal::ald).collect();
        match &self.kind {
            AxiomKind::Causal { head } => {
                build::causal(label, self.action.ald().atom, head.ald(), body)
            }
            AxiomKind::Executability => build::impossible(label, self.action.ald().atom, body),
            AxiomKind::Constraint { head } => build::constraint(label, head.ald(), body),
        }
    }

    /// The statement for people, with relations in their short form (`below(O1, O2)`).
    pub fn short(&self) -> String {
        self.render(Literal::short)
    }

    fn render(&self, lit: fn(&Literal) -> String) -> String {
        let body: Vec<String> = self.body.iter().map(lit).collect();
        let cond = if body.is_empty() {
            String::new()
        } else {
            format!(" if {}", body.join(", "))
        };
        match &self.kind {
            AxiomKind::Causal { head } => {
                format!("{} causes {}{cond}", lit(&self.action), lit(head))
            }
            AxiomKind::Executability => format!("impossible {}{cond}", lit(&self.action)),
            AxiomKind::Constraint { head } => format!("{}{cond}", lit(head)),
        }
    }
}

impl Axiom {
    /// Whether a ground instance of the axiom applies to `action` in the complete `state`
    /// (literals of both signs): the lifted action matches the ground one and some binding of
    /// the remaining variables puts every body literal in the state. For a causal law this is
    /// the axiom supporting its head at the next step; for an executability condition, the
    /// axiom forbidding the action. Distinct variables may take equal constants, as in the
    /// translated rules.
    pub fn fires(&self, action: &Literal, state: &[Literal]) -> bool {
        let (mut binding, mut added) = (BTreeMap::new(), Vec::new());
        if !match_literal(&self.action, action, &mut binding, &mut added) {
            return false;
        }
        match_body(&self.body, state, &mut binding, &mut added)
    }

    /// Parses the AL_d text [`Axiom::to_ald`] writes (without the final period), e.g.
    /// `impossible pickup(R1, O1) if relation(below, O1, O2)` or
    /// `putdown(R1, O1, O2) causes -in_hand(R1, O1)`. Variables are `R` or `O` and an index.
    pub fn parse_ald(text: &str) -> Option<Axiom> {
        let text = text.trim();
        let (main, body) = match text.split_once(" if ") {
            Some((m, b)) => (m, parse_literals(b)?),
            None => (text, Vec::new()),
        };
        if let Some(action) = main.strip_prefix("impossible ") {
            let action = parse_literal(action)?;
            return Some(Axiom::new(AxiomKind::Executability, action, body));
        }
        let Some((action, head)) = main.split_once(" causes ") else {
            let head = parse_literal(main)?;
            let subject = head.clone().with_sign(true);
            return Some(Axiom::new(AxiomKind::Constraint { head }, subject, body));
        };
        Some(Axiom::new(
            AxiomKind::Causal {
                head: parse_literal(head)?,
            },
            parse_literal(action)?,
            body,
        ))
    }
}

/// Binds the variables of `pattern` to the constants of `ground`, consistently with `binding`;
/// the variables it binds are pushed on `added`. On failure `binding` is left as it was.
fn match_literal(
    pattern: &Literal,
    ground: &Literal,
    binding: &mut BTreeMap<Var, String>,
    added: &mut Vec<Var>,
) -> bool {
    if pattern.positive != ground.positive
        || pattern.name != ground.name
        || pattern.args.len() != ground.args.len()
    {
        return false;
    }
    let mark = added.len();
    for (p, g) in pattern.args.iter().zip(&ground.args) {
        let ok = match (p, g) {
            (_, Term::Var(_)) => false,
            (Term::Const(k), Term::Const(c)) => k == c,
            (Term::Var(v), Term::Const(c)) => match binding.get(v) {
                Some(b) => b == c,
                None => {
                    binding.insert(*v, c.clone());
                    added.push(*v);
                    true
                }
            },
        };
        if !ok {
            unbind(binding, added, mark);
            return false;
        }
    }
    true
}

/// Undoes the bindings pushed on `added` after `mark`.
fn unbind(binding: &mut BTreeMap<Var, String>, added: &mut Vec<Var>, mark: usize) {
    for v in added.drain(mark..) {
        binding.remove(&v);
    }
}

/// Backtracking search for a binding that puts every literal of `body` in `state`.
fn match_body(
    body: &[Literal],
    state: &[Literal],
    binding: &mut BTreeMap<Var, String>,
    added: &mut Vec<Var>,
) -> bool {
    let Some((first, rest)) = body.split_first() else {
        return true;
    };
    for g in state {
        let mark = added.len();
        if match_literal(first, g, binding, added) {
            if match_body(rest, state, binding, added) {
                return true;
            }
            unbind(binding, added, mark);
        }
    }
    false
}

/// Splits `a(x, y), -b(z)` at the commas outside parentheses.
fn parse_literals(text: &str) -> Option<Vec<Literal>> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, ch) in text.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                out.push(parse_literal(&text[start..i])?);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(parse_literal(&text[start..])?);
    Some(out)
}

/// Parses `-name(arg, ...)` with constant and variable arguments.
fn parse_literal(text: &str) -> Option<Literal> {
    let text = text.trim();
    let (positive, text) = match text.strip_prefix('-') {
        Some(t) => (false, t),
        None => (true, text),
    };
    let (name, args) = match text.split_once('(') {
        Some((n, rest)) => (n, rest.strip_suffix(')')?),
        None => (text, ""),
    };
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return None;
    }
    let args = if args.is_empty() {
        Vec::new()
    } else {
        args.split(',')
            .map(|a| parse_term(a.trim()))
            .collect::<Option<_>>()?
    };
    Some(Literal {
        positive,
        name: name.to_string(),
        args,
    })
}

fn parse_term(text: &str) -> Option<Term> {
    let mut chars = text.chars();
    let first = chars.next()?;
    let sort = match first {
        'R' => Some(Sort::Robot),
        'O' => Some(Sort::Object),
        _ => None,
    };
    if let (Some(sort), Ok(index)) = (sort, chars.as_str().parse::<u32>()) {
        return Some(Term::Var(Var { sort, index }));
    }
    if first.is_ascii_lowercase() || first.is_ascii_digit() {
        return Some(Term::constant(text));
    }
    None
}

impl fmt::Display for Axiom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.short())
    }
}

fn sort_slot(sort: Sort) -> usize {
    match sort {
        Sort::Robot => 0,
        Sort::Object => 1,
    }
}

fn assign(map: &mut BTreeMap<Var, Var>, next: &mut [u32; 2], v: Var) -> Var {
    *map.entry(v).or_insert_with(|| {
        next[sort_slot(v.sort)] += 1;
        Var {
            sort: v.sort,
            index: next[sort_slot(v.sort)],
        }
    })
}

/// The literal with known variables renamed and unknown ones shown as index 0 (a wildcard that
/// sorts before every real index).
fn partial(lit: &Literal, map: &BTreeMap<Var, Var>) -> Literal {
    lit.rename(&|v| {
        map.get(&v).copied().unwrap_or(Var {
            sort: v.sort,
            index: 0,
        })
    })
}

/// Depth-first search for the body order whose renaming is smallest: at each step only the
/// literals whose partial renaming is minimal are tried (the others cannot start the smallest
/// sequence), so the search branches only on ties.
fn canonical_body(
    remaining: &[&Literal],
    map: &BTreeMap<Var, Var>,
    next: [u32; 2],
    prefix: &mut Vec<Literal>,
    best: &mut Option<Vec<Literal>>,
) {
    if remaining.is_empty() {
        let mut body = prefix.clone();
        body.sort();
        if best.as_ref().is_none_or(|b| body < *b) {
            *best = Some(body);
        }
        return;
    }
    let partials: Vec<Literal> = remaining.iter().map(|l| partial(l, map)).collect();
    let min = partials.iter().min().expect("non-empty").clone();
    for (i, lit) in remaining.iter().enumerate() {
        if partials[i] != min {
            continue;
        }
        let mut map2 = map.clone();
        let mut next2 = next;
        for v in lit.vars() {
            assign(&mut map2, &mut next2, v);
        }
        let renamed = lit.rename(&|v| map2[&v]);
        let rest: Vec<&Literal> = remaining
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, l)| *l)
            .collect();
        prefix.push(renamed);
        canonical_body(&rest, &map2, next2, prefix, best);
        prefix.pop();
    }
}

/// Shorthand for tests and targets: the variable `O{i}`.
pub fn o(i: u32) -> Term {
    Term::Var(Var {
        sort: Sort::Object,
        index: i,
    })
}

/// Shorthand for tests and targets: the variable `R{i}`.
pub fn r(i: u32) -> Term {
    Term::Var(Var {
        sort: Sort::Robot,
        index: i,
    })
}

/// A lifted `relation(rel, a, b)`.
pub fn rel(name: &str, a: Term, b: Term) -> Literal {
    Literal::new(RELATION, vec![Term::constant(name), a, b])
}

/// A lifted `in_hand(robot, object)` with a sign.
pub fn in_hand(positive: bool, robot: Term, object: Term) -> Literal {
    Literal::new(IN_HAND, vec![robot, object]).with_sign(positive)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pickup() -> Literal {
        Literal::new("pickup", vec![r(1), o(1)])
    }

    /// E7 as learned: `impossible pickup(R1, O1) if below(O1, O2)`. In a state where the duck
    /// stands on the red cube, it forbids picking up the cube (O2 = duck) and not the duck.
    #[test]
    fn fires_binds_the_action_then_searches_the_body() {
        let e7 = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![rel("below", o(1), o(2))],
        );
        let state = vec![
            Literal::relation("below", "red_cube_large", "yellow_duck"),
            Literal::relation("on", "yellow_duck", "red_cube_large"),
            Literal::ground(IN_HAND, &["rob1", "pitcher"]).with_sign(false),
        ];
        let pick = |o: &str| Literal::ground("pickup", &["rob1", o]);
        assert!(e7.fires(&pick("red_cube_large"), &state));
        assert!(!e7.fires(&pick("yellow_duck"), &state));
        // The body's sign counts: -in_hand(R1, O1) holds for the pitcher only.
        let e2 = Axiom::new(
            AxiomKind::Executability,
            Literal::new("putdown", vec![r(1), o(1), o(2)]),
            vec![in_hand(false, r(1), o(1))],
        );
        let put = |o: &str| Literal::ground("putdown", &["rob1", o, "table"]);
        assert!(e2.fires(&put("pitcher"), &state));
        assert!(!e2.fires(&put("yellow_duck"), &state));
        // An unconditional causal law fires whenever its action matches; another action never.
        let c3 = Axiom::new(
            AxiomKind::Causal {
                head: in_hand(true, r(1), o(1)),
            },
            pickup(),
            vec![],
        );
        assert!(c3.fires(&pick("yellow_duck"), &[]));
        assert!(!c3.fires(&put("yellow_duck"), &state));
    }

    #[test]
    fn parse_ald_reads_what_to_ald_writes() {
        let axioms = [
            Axiom::new(
                AxiomKind::Executability,
                pickup(),
                vec![rel("below", o(1), o(2)), in_hand(true, r(1), o(3))],
            ),
            Axiom::new(
                AxiomKind::Causal {
                    head: in_hand(false, r(1), o(1)),
                },
                Literal::new("putdown", vec![r(1), o(1), o(2)]),
                vec![],
            ),
        ];
        for a in axioms {
            assert_eq!(Axiom::parse_ald(&a.to_ald()), Some(a.clone()), "{a}");
        }
        assert_eq!(
            Axiom::parse_ald("impossible pickup(R1, O1) if relation(below, O1, O2)")
                .map(|a| a.body),
            Some(vec![rel("below", o(1), o(2))])
        );
        // Without `impossible` or `causes`, the text is a state constraint (the reader is
        // syntactic: whether the head is a fluent is the checker's business).
        assert_eq!(
            Axiom::parse_ald("-stable(O1) if irreg_below(O1)").map(|a| a.kind),
            Some(AxiomKind::Constraint {
                head: Literal::new("stable", vec![o(1)]).with_sign(false)
            })
        );
        let st1 = Axiom::parse_ald("-stable(O1) if irreg_below(O1)").unwrap();
        assert_eq!(Axiom::parse_ald(&st1.to_ald()), Some(st1));
        assert_eq!(Axiom::parse_ald("impossible pickup(R1, O1) if (("), None);
    }

    #[test]
    fn rendering() {
        let ax = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![rel("below", o(1), o(2))],
        );
        assert_eq!(ax.short(), "impossible pickup(R1, O1) if below(O1, O2)");
        assert_eq!(
            ax.to_ald(),
            "impossible pickup(R1, O1) if relation(below, O1, O2)"
        );
        let law = Axiom::new(
            AxiomKind::Causal {
                head: in_hand(false, r(1), o(1)),
            },
            Literal::new("putdown", vec![r(1), o(1), o(2)]),
            vec![in_hand(false, r(1), o(5))],
        );
        assert_eq!(
            law.to_ald(),
            "putdown(R1, O1, O2) causes -in_hand(R1, O1) if -in_hand(R1, O5)"
        );
    }

    #[test]
    fn canonical_up_to_renaming() {
        // impossible pickup(R1, O1) if below(O1, O7), on(O7, O3)  ==  ... below(O1, O2), on(O2, O9)
        let a = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![rel("below", o(1), o(7)), rel("on", o(7), o(3))],
        );
        let b = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![rel("on", o(2), o(9)), rel("below", o(1), o(2))],
        );
        assert_eq!(a.canonical(), b.canonical());
        assert_eq!(
            a.canonical().short(),
            "impossible pickup(R1, O1) if below(O1, O2), on(O2, O3)"
        );
        // The co-occurrence differs: on(O3, O2) is not a renaming of on(O2, O3) here.
        let c = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![rel("below", o(1), o(7)), rel("on", o(3), o(7))],
        );
        assert_ne!(a.canonical(), c.canonical());
        // Action variables are not free to rename: in_hand(R1, O1) is not in_hand(R1, O2).
        let d = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![in_hand(true, r(1), o(1))],
        );
        let e = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![in_hand(true, r(1), o(4))],
        );
        assert_ne!(d.canonical(), e.canonical());
        // Ties between symmetric body literals: both orders give one form.
        let f = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![
                rel("left", o(1), o(5)),
                rel("left", o(1), o(4)),
                rel("on", o(4), o(5)),
            ],
        );
        let g = Axiom::new(
            AxiomKind::Executability,
            pickup(),
            vec![
                rel("left", o(1), o(4)),
                rel("left", o(1), o(5)),
                rel("on", o(5), o(4)),
            ],
        );
        assert_eq!(f.canonical(), g.canonical());
    }
}

//! Proof trees (docs/domain.md 6.2): why a literal holds in an answer set, as the rule instances
//! that support it, recursively down to leaves; or why it does not hold, as the body literal that
//! blocks each rule for it. This module is the contract between the tree builder and its users
//! (questions, drawings, JSON): the data type, and an independent re-check of a tree against the
//! ground program and the model, reached through the [`Oracle`] trait.
//!
//! Shape: a flat vector of nodes, children before parents (egg's `RecExpr`). A node is one
//! literal with **one** support: a literal with several supports (E7 and the action CWA for
//! `-occurs(pickup(rob1,a),0)`) is several sibling nodes, one per branch, in preference order.
//! The tree's `roots` are the alternatives for the root literal. An edge goes from a node to a
//! child and carries the rule instance: the node's support for a literal that holds, the blocked
//! rule for a literal that does not ([`Kind::Unsupported`]).
//!
//! Invariants (checked by [`recheck`], on in every test): child ids are smaller than their
//! parent's; a node that holds has a rule instance whose head is its literal, which the ground
//! program has, and whose body holds (positive literals true, default-negated ones false); its
//! children are positive body literals and its "no evidence" literals default-negated ones; a
//! node that does not hold has one blocked rule per rule of the program for its literal, each
//! blocked by its child (a false positive body literal or a true default-negated one); no
//! literal repeats on a path from a root; every leaf is of a leaf kind; no node has more than
//! [`MAX_BRANCHES`] children. Depth is not checked: the builders bound their own search
//! ([`MAX_DEPTH`] for `explain::build`), and a correct proof may be long.

use std::fmt;

use crate::control::Symbol;

/// Maximum depth of the tree builder's search (docs/domain.md 6.2).
pub const MAX_DEPTH: usize = 50;
/// Maximum number of children of a node (docs/domain.md 6.2).
pub const MAX_BRANCHES: usize = 16;

/// Index of a node in [`ProofTree::nodes`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeId(pub u32);

impl NodeId {
    /// The index as `usize`.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// The category of a ground rule, from the action language's translation (docs/domain.md 6.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AxiomKind {
    /// A state constraint (`l if p`), spatial algebra included.
    StateConstraint,
    /// A causal law (`a causes l if p`).
    CausalLaw,
    /// An executability condition (`impossible a if p`).
    Executability,
    /// A default (`normally l if p`).
    Default,
    /// A consistency-restoring rule (an exception).
    CrRule,
    /// The inertia axiom.
    Inertia,
    /// A closed-world assumption (defined fluents or actions).
    ClosedWorld,
    /// History: observations, happened actions, initial-state defaults.
    History,
    /// A fact of the program (statics).
    Fact,
    /// Sort membership and the domains of fluents and actions (`object(a)`,
    /// `action(pickup(rob1,a))`): guards of every rule, static leaves never said in answers.
    Sort,
    /// The planning module.
    Planning,
    /// A rule of a program that is not an action description (the generic `--why`).
    Rule,
    /// A choice rule of such a program: its head atom was chosen, not derived (`{a} :- b.`).
    Choice,
}

impl AxiomKind {
    /// The kind in words ("executability condition").
    pub fn words(self) -> &'static str {
        match self {
            AxiomKind::StateConstraint => "state constraint",
            AxiomKind::CausalLaw => "causal law",
            AxiomKind::Executability => "executability condition",
            AxiomKind::Default => "default",
            AxiomKind::CrRule => "CR rule",
            AxiomKind::Inertia => "inertia",
            AxiomKind::ClosedWorld => "closed world",
            AxiomKind::History => "history",
            AxiomKind::Fact => "fact",
            AxiomKind::Sort => "sort",
            AxiomKind::Planning => "planning",
            AxiomKind::Rule => "rule",
            AxiomKind::Choice => "choice",
        }
    }
}

/// One literal of a rule body.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum BodyLiteral {
    /// A positive literal, true when the body holds.
    Pos(Symbol),
    /// A default-negated literal `not l`, false when the body holds.
    Not(Symbol),
    /// A comparison or other built-in test of the non-ground rule, true in every ground
    /// instance (grounding evaluated it); kept for the answer's wording.
    Test(String),
}

/// A ground rule instance with its origin.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RuleInstance {
    /// The axiom's name ("E7", "C1", "SR3", "inertia", or a source location for `--why`).
    pub label: String,
    /// The axiom's category.
    pub kind: AxiomKind,
    /// The ground rule's number in the ground program, when known.
    pub rule: Option<u32>,
    /// The head literal.
    pub head: Symbol,
    /// The body.
    pub body: Vec<BodyLiteral>,
}

impl RuleInstance {
    /// The positive body literals.
    pub fn positive(&self) -> impl Iterator<Item = &Symbol> {
        self.body.iter().filter_map(|b| match b {
            BodyLiteral::Pos(t) => Some(t),
            _ => None,
        })
    }

    /// The default-negated body literals.
    pub fn negative(&self) -> impl Iterator<Item = &Symbol> {
        self.body.iter().filter_map(|b| match b {
            BodyLiteral::Not(t) => Some(t),
            _ => None,
        })
    }
}

impl fmt::Display for RuleInstance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // A choice instance is written as the choice it is: `{color(1,green)} :- node(1).`
        if self.kind == AxiomKind::Choice {
            write!(f, "{{{}}}", self.head)?;
        } else {
            write!(f, "{}", self.head)?;
        }
        for (i, b) in self.body.iter().enumerate() {
            f.write_str(if i == 0 { " :- " } else { ", " })?;
            match b {
                BodyLiteral::Pos(t) => write!(f, "{t}")?,
                BodyLiteral::Not(t) => write!(f, "not {t}")?,
                BodyLiteral::Test(s) => f.write_str(s)?,
            }
        }
        f.write_str(".")
    }
}

/// How a node's literal is supported (or not).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Leaf: a static fact.
    Static,
    /// Leaf: a perception (step 0, or later under `observations_as_facts`).
    Observation,
    /// Leaf: an action that happened or was planned (`occurs` from `hpd` or the plan).
    Action,
    /// Leaf: the head of an applied CR rule.
    Assumption,
    /// Leaf: a literal supported only by a closed-world assumption.
    ClosedWorld,
    /// Inner: the inertia axiom carries the literal from the previous step.
    Inertia,
    /// Inner: a domain axiom.
    Axiom {
        /// The axiom's name ("E7").
        label: String,
        /// Its category.
        kind: AxiomKind,
    },
    /// The literal does not hold: each rule for it is blocked by a child.
    Unsupported,
}

impl Kind {
    /// Whether a node of this kind ends a path (docs/domain.md 6.2's leaf kinds).
    pub fn is_leaf_kind(&self) -> bool {
        matches!(
            self,
            Kind::Static | Kind::Observation | Kind::Action | Kind::Assumption | Kind::ClosedWorld
        )
    }

    /// The kind in words, for drawings ("E7 · executability condition", "observation").
    pub fn words(&self) -> String {
        match self {
            Kind::Static => "static".into(),
            Kind::Observation => "observation".into(),
            Kind::Action => "action".into(),
            Kind::Assumption => "assumption (CR rule)".into(),
            Kind::ClosedWorld => "closed world".into(),
            Kind::Inertia => "inertia".into(),
            Kind::Axiom { label, kind } => format!("{label} \u{b7} {}", kind.words()),
            Kind::Unsupported => "no support".into(),
        }
    }
}

/// One node: a literal with one support, or a literal that does not hold.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Node {
    /// The ground literal in the program's syntax (`holds(relation(on,a,b),0)`).
    pub literal: Symbol,
    /// The step of the literal (last argument of `holds`/`occurs`), `None` for statics.
    pub step: Option<u32>,
    /// Whether the literal is in the answer set.
    pub holds: bool,
    /// How it is supported.
    pub kind: Kind,
    /// The supporting rule instance (for a node that holds); `None` for [`Kind::Unsupported`].
    pub rule: Option<RuleInstance>,
    /// Children: body literals of `rule`; for [`Kind::Unsupported`], the blocking literals.
    pub children: Vec<NodeId>,
    /// For [`Kind::Unsupported`]: the rule each child blocks, parallel to `children`.
    pub blocked: Vec<RuleInstance>,
    /// Default-negated body literals of `rule`, said as "no evidence of …", never expanded.
    pub no_evidence: Vec<Symbol>,
}

impl Node {
    /// A node for a literal that holds, with its support; the step is read off the literal.
    pub fn supported(literal: Symbol, kind: Kind, rule: RuleInstance) -> Node {
        let no_evidence = rule.negative().cloned().collect();
        Node {
            step: step_of(&literal),
            literal,
            holds: true,
            kind,
            rule: Some(rule),
            children: Vec::new(),
            blocked: Vec::new(),
            no_evidence,
        }
    }

    /// A node for a literal that does not hold.
    pub fn unsupported(literal: Symbol) -> Node {
        Node {
            step: step_of(&literal),
            literal,
            holds: false,
            kind: Kind::Unsupported,
            rule: None,
            children: Vec::new(),
            blocked: Vec::new(),
            no_evidence: Vec::new(),
        }
    }
}

/// The step of a program literal: the last argument of `holds/2` and `occurs/2` (either sign).
pub fn step_of(literal: &Symbol) -> Option<u32> {
    match (literal.name(), literal.args()) {
        (Some("holds" | "occurs"), [_, Symbol::Number(n)]) if *n >= 0 => Some(*n as u32),
        _ => None,
    }
}

/// An edge: parent, child and the rule instance it belongs to.
#[derive(Clone, Copy, Debug)]
pub struct Edge<'t> {
    /// The node whose support (or blocked rule) the child belongs to.
    pub parent: NodeId,
    /// The body literal's node.
    pub child: NodeId,
    /// The rule instance.
    pub rule: &'t RuleInstance,
}

/// A learned axiom (docs/domain.md 5.9, written by `lucent learn`) as an explanation cites it.
#[derive(Clone, Debug, PartialEq)]
pub struct LearnedAxiom {
    /// Its AL_d label (`L2`), the label of its rule instances.
    pub label: String,
    /// Its strength in (0, 1] when the knowledge base was loaded.
    pub strength: f64,
    /// The axiom in AL_d (`impossible pickup(R1, O1) if relation(below, O1, O2)`).
    pub text: String,
}

/// A proof tree: nodes children-first, the alternatives for the root, the preferred path.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ProofTree {
    /// The nodes; every child id is smaller than its parent's.
    pub nodes: Vec<Node>,
    /// The root literal's nodes, one per support, preferred first.
    pub roots: Vec<NodeId>,
    /// The path the answer uses, from a root to a leaf (may be empty).
    pub path: Vec<NodeId>,
    /// The learned axioms among the tree's rule instances (supports and blocked rules), in
    /// the order the knowledge base lists them; empty when it has none.
    pub learned: Vec<LearnedAxiom>,
    /// What the generic `--why`/`--why-not` read off the program as written (chosen steps,
    /// aggregates with their elements, source rules that could not fire), as the `--outf=2`
    /// JSON's `source`; empty for other answers.
    pub source_notes: Vec<serde_json::Value>,
}

impl ProofTree {
    /// Adds a node whose children were added before it.
    ///
    /// Panics if a child id is not smaller than the new node's (API misuse).
    pub fn add(&mut self, node: Node) -> NodeId {
        let id = NodeId(self.nodes.len() as u32);
        assert!(
            node.children.iter().all(|c| *c < id),
            "children must be added before their parent"
        );
        self.nodes.push(node);
        id
    }

    /// The node with this id.
    pub fn node(&self, id: NodeId) -> &Node {
        &self.nodes[id.index()]
    }

    /// The children of `id` whose literals hold at a step (fluents and actions, not statics or
    /// sorts), in order.
    pub fn timed_children(&self, id: NodeId) -> impl Iterator<Item = NodeId> + '_ {
        self.node(id)
            .children
            .iter()
            .copied()
            .filter(|c| self.node(*c).step.is_some())
    }

    /// Calls `visit` on each child of `id` in order whose literal is not in `seen` yet, adding
    /// the literal to `seen` just before (so what `visit` adds to `seen` skips later children):
    /// the walk of a proof that says each literal once.
    pub fn each_unseen_child(
        &self,
        id: NodeId,
        seen: &mut Vec<Symbol>,
        mut visit: impl FnMut(NodeId, &mut Vec<Symbol>),
    ) {
        for c in &self.node(id).children {
            let lit = &self.node(*c).literal;
            if seen.contains(lit) {
                continue;
            }
            seen.push(lit.clone());
            visit(*c, seen);
        }
    }

    /// The tree cut down to the answer's path: the path's nodes with all their children, a
    /// child off the path kept as a leaf (its own children dropped), and the other roots
    /// dropped. A tree without a path is returned whole. The node order is kept, so children
    /// still come before their parents.
    pub fn around_path(&self) -> ProofTree {
        if self.path.is_empty() {
            return self.clone();
        }
        let mut on = vec![false; self.nodes.len()];
        let mut keep = vec![false; self.nodes.len()];
        for &id in &self.path {
            on[id.index()] = true;
            keep[id.index()] = true;
            for &c in &self.node(id).children {
                keep[c.index()] = true;
            }
        }
        let mut map = vec![None; self.nodes.len()];
        let mut out = ProofTree {
            learned: self.learned.clone(),
            ..ProofTree::default()
        };
        for (i, node) in self.nodes.iter().enumerate() {
            if !keep[i] {
                continue;
            }
            let mut n = node.clone();
            if on[i] {
                n.children = n
                    .children
                    .iter()
                    .map(|c| map[c.index()].expect("children come first"))
                    .collect();
            } else {
                n.children.clear();
            }
            map[i] = Some(out.add(n));
        }
        out.roots = self.roots.iter().filter_map(|r| map[r.index()]).collect();
        out.path = self.path.iter().filter_map(|p| map[p.index()]).collect();
        out
    }

    /// Every edge with its rule instance.
    pub fn edges(&self) -> Vec<Edge<'_>> {
        let mut out = Vec::new();
        for (i, n) in self.nodes.iter().enumerate() {
            for (k, &c) in n.children.iter().enumerate() {
                let rule = match (&n.rule, n.blocked.get(k)) {
                    (_, Some(r)) if n.kind == Kind::Unsupported => r,
                    (Some(r), _) => r,
                    (None, Some(r)) => r,
                    (None, None) => continue,
                };
                out.push(Edge {
                    parent: NodeId(i as u32),
                    child: c,
                    rule,
                });
            }
        }
        out
    }

    /// Whether the node is on the answer's path.
    pub fn on_path(&self, id: NodeId) -> bool {
        self.path.contains(&id)
    }

    /// The learned axiom a node's supporting rule instance comes from.
    pub fn learned_of(&self, id: NodeId) -> Option<&LearnedAxiom> {
        let label = &self.node(id).rule.as_ref()?.label;
        self.learned.iter().find(|l| &l.label == label)
    }

    /// Keeps, of `known` (a knowledge base's learned axioms), those whose label is the label of
    /// one of the tree's rule instances.
    pub fn note_learned(&mut self, known: &[LearnedAxiom]) {
        let used = |l: &LearnedAxiom| {
            self.nodes.iter().any(|n| {
                n.rule.as_ref().is_some_and(|r| r.label == l.label)
                    || n.blocked.iter().any(|r| r.label == l.label)
            })
        };
        self.learned = known.iter().filter(|l| used(l)).cloned().collect();
    }

    /// The leaves reachable from the roots.
    pub fn leaves(&self) -> Vec<NodeId> {
        let mut seen = vec![false; self.nodes.len()];
        let mut out = Vec::new();
        let mut stack: Vec<NodeId> = self.roots.iter().rev().copied().collect();
        while let Some(id) = stack.pop() {
            if id.index() >= self.nodes.len() || std::mem::replace(&mut seen[id.index()], true) {
                continue;
            }
            let n = self.node(id);
            if n.children.is_empty() {
                out.push(id);
            }
            stack.extend(n.children.iter().rev());
        }
        out
    }
}

/// The ground program and the answer set, as the re-check sees them. Implementations answer from
/// their own data (the ground rules with provenance, the model's atoms), not from the tree.
pub trait Oracle {
    /// Whether the ground literal is in the answer set.
    fn holds(&self, literal: &Symbol) -> bool;
    /// The ground program's rule instances with this head (with their labels and kinds).
    fn rules_for(&self, head: &Symbol) -> Vec<RuleInstance>;
    /// Whether a CR rule instance is applied in the answer set.
    fn applied(&self, rule: &RuleInstance) -> bool;
}

/// What the re-check found wrong, with the node.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("proof tree node {node}: {message}")]
pub struct RecheckError {
    /// The node's index.
    pub node: u32,
    /// What is wrong.
    pub message: String,
}

/// Checks a tree against the ground program and the model, independently of how it was built
/// (the invariants in this module's documentation).
pub fn recheck(tree: &ProofTree, oracle: &dyn Oracle) -> Result<(), RecheckError> {
    let err = |i: usize, message: String| RecheckError {
        node: i as u32,
        message,
    };
    let n = tree.nodes.len();
    for (i, node) in tree.nodes.iter().enumerate() {
        if node.children.len() > MAX_BRANCHES {
            return Err(err(i, format!("{} children", node.children.len())));
        }
        if node.children.iter().any(|c| c.index() >= i) {
            return Err(err(i, "a child is not before its parent".into()));
        }
        if node.step != step_of(&node.literal) {
            return Err(err(i, "the step is not the literal's".into()));
        }
        if oracle.holds(&node.literal) != node.holds {
            return Err(err(
                i,
                format!(
                    "{} is {} the answer set",
                    node.literal,
                    if node.holds { "not in" } else { "in" }
                ),
            ));
        }
        if node.holds {
            check_support(tree, oracle, node).map_err(|m| err(i, m))?;
        } else {
            check_blocked(tree, oracle, node).map_err(|m| err(i, m))?;
        }
    }
    for r in &tree.roots {
        if r.index() >= n {
            return Err(err(r.index(), "a root is not a node".into()));
        }
    }
    if let Some(first) = tree.roots.first() {
        let literal = &tree.node(*first).literal;
        if tree.roots.iter().any(|r| &tree.node(*r).literal != literal) {
            return Err(err(first.index(), "the roots are not one literal".into()));
        }
    }
    check_paths(tree).map_err(|(i, m)| err(i, m))?;
    if !tree.path.is_empty() {
        if !tree.roots.contains(&tree.path[0]) {
            return Err(err(
                tree.path[0].index(),
                "the path does not start at a root".into(),
            ));
        }
        for w in tree.path.windows(2) {
            if w[1].index() >= n || !tree.node(w[0]).children.contains(&w[1]) {
                return Err(err(w[0].index(), "the path leaves the tree".into()));
            }
        }
        let last = *tree.path.last().expect("non-empty path");
        if !tree.node(last).children.is_empty() {
            return Err(err(last.index(), "the path does not end at a leaf".into()));
        }
    }
    Ok(())
}

/// A node that holds: its rule exists, its body holds, its children and "no evidence" literals
/// come from the body, and its kind fits.
fn check_support(tree: &ProofTree, oracle: &dyn Oracle, node: &Node) -> Result<(), String> {
    let Some(rule) = &node.rule else {
        return Err("a literal that holds has no rule instance".into());
    };
    if rule.head != node.literal {
        return Err(format!("the rule's head {} is not the literal", rule.head));
    }
    if !oracle
        .rules_for(&rule.head)
        .iter()
        .any(|r| same_rule(r, rule))
    {
        return Err(format!("the ground program has no rule `{rule}`"));
    }
    for b in &rule.body {
        match b {
            BodyLiteral::Pos(t) if !oracle.holds(t) => {
                return Err(format!("body literal {t} does not hold"))
            }
            BodyLiteral::Not(t) if oracle.holds(t) => {
                return Err(format!("default-negated body literal {t} holds"))
            }
            _ => {}
        }
    }
    for c in &node.children {
        let child = tree.node(*c);
        if !child.holds || !rule.positive().any(|t| *t == child.literal) {
            return Err(format!(
                "child {} is not a positive body literal",
                child.literal
            ));
        }
    }
    for t in &node.no_evidence {
        if !rule.negative().any(|x| x == t) {
            return Err(format!("{t} is not a default-negated body literal"));
        }
    }
    let kind_fits = match &node.kind {
        Kind::Action => {
            matches!(node.literal.name(), Some("occurs"))
                && !node.literal.is_negative()
                && matches!(
                    rule.kind,
                    AxiomKind::Fact | AxiomKind::History | AxiomKind::Planning
                )
        }
        Kind::Static => {
            node.step.is_none() && matches!(rule.kind, AxiomKind::Fact | AxiomKind::Sort)
        }
        Kind::Assumption => rule.kind == AxiomKind::CrRule && oracle.applied(rule),
        // The CWAs, and the initial-state default D0 (a history rule with `not`).
        Kind::ClosedWorld => {
            rule.kind == AxiomKind::ClosedWorld
                || (rule.kind == AxiomKind::History && rule.negative().next().is_some())
        }
        Kind::Inertia => rule.kind == AxiomKind::Inertia,
        Kind::Axiom { label, kind } => *label == rule.label && *kind == rule.kind,
        Kind::Observation => matches!(rule.kind, AxiomKind::Fact | AxiomKind::History),
        Kind::Unsupported => false,
    };
    if !kind_fits {
        return Err(format!(
            "kind `{}` does not fit rule `{rule}` ({})",
            node.kind.words(),
            rule.kind.words()
        ));
    }
    if node.kind.is_leaf_kind() && !node.children.is_empty() {
        return Err(format!("a {} leaf has children", node.kind.words()));
    }
    Ok(())
}

/// A node that does not hold: one blocked rule per rule of the program, each blocked by its child.
fn check_blocked(tree: &ProofTree, oracle: &dyn Oracle, node: &Node) -> Result<(), String> {
    if node.kind != Kind::Unsupported || node.rule.is_some() {
        return Err("a literal that does not hold must be unsupported".into());
    }
    if node.blocked.len() != node.children.len() {
        return Err("blocked rules and children differ in number".into());
    }
    let rules = oracle.rules_for(&node.literal);
    for r in &rules {
        if !node.blocked.iter().any(|b| same_rule(b, r)) {
            return Err(format!("rule `{r}` is not shown blocked"));
        }
    }
    for (rule, c) in node.blocked.iter().zip(&node.children) {
        if !rules.iter().any(|r| same_rule(r, rule)) {
            return Err(format!("the ground program has no rule `{rule}`"));
        }
        let child = tree.node(*c);
        let blocks = if child.holds {
            rule.negative().any(|t| *t == child.literal)
        } else {
            rule.positive().any(|t| *t == child.literal)
        };
        if !blocks {
            return Err(format!(
                "child {} does not block rule `{rule}`",
                child.literal
            ));
        }
    }
    Ok(())
}

/// Two rule instances are the same ground rule: same head and the same body as a set (the
/// labels may differ in wording).
fn same_rule(a: &RuleInstance, b: &RuleInstance) -> bool {
    if a.rule.is_some() && b.rule.is_some() && a.rule != b.rule {
        return false;
    }
    a.head == b.head
        && a.body.iter().all(|x| b.body.contains(x))
        && b.body.iter().all(|x| a.body.contains(x))
}

/// No literal repeats on a path from a root, and every reachable leaf is of a leaf kind. No
/// depth is refused: a correct proof may be long (a builder bounds its own search).
fn check_paths(tree: &ProofTree) -> Result<(), (usize, String)> {
    // The reachable nodes, each once.
    let mut seen = vec![false; tree.nodes.len()];
    let mut stack: Vec<NodeId> = tree.roots.clone();
    let mut reachable = Vec::new();
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut seen[id.index()], true) {
            continue;
        }
        reachable.push(id);
        let node = tree.node(id);
        if node.children.is_empty() {
            let ok = node.kind.is_leaf_kind()
                || node.kind == Kind::Unsupported
                || node
                    .rule
                    .as_ref()
                    .is_some_and(|r| r.positive().next().is_none());
            if !ok {
                return Err((id.index(), format!("a leaf of kind {}", node.kind.words())));
            }
        }
        stack.extend(node.children.iter().copied());
    }
    // Children come before their parents, so a literal that is one node cannot repeat on a
    // path; only literals with several nodes need the walk over paths.
    let mut count: std::collections::HashMap<(&Symbol, bool), u32> = Default::default();
    for id in &reachable {
        let n = tree.node(*id);
        *count.entry((&n.literal, n.holds)).or_default() += 1;
    }
    if count.values().all(|&c| c == 1) {
        return Ok(());
    }
    let mut path: Vec<NodeId> = Vec::new();
    let mut stack: Vec<(NodeId, usize)> = tree.roots.iter().rev().map(|r| (*r, 0)).collect();
    let mut visits = 0usize;
    while let Some((id, depth)) = stack.pop() {
        visits += 1;
        if visits > 1_000_000 {
            return Err((id.index(), "too many paths to check".into()));
        }
        path.truncate(depth);
        let node = tree.node(id);
        if path
            .iter()
            .any(|p| tree.node(*p).literal == node.literal && tree.node(*p).holds == node.holds)
        {
            return Err((id.index(), format!("{} repeats on a path", node.literal)));
        }
        path.push(id);
        for c in node.children.iter().rev() {
            stack.push((*c, depth + 1));
        }
    }
    Ok(())
}

/// An [`Oracle`] over explicit data: ground rule instances and the atoms of a model. Tests use
/// it, and so can any caller that has the ground program in hand.
#[derive(Clone, Debug, Default)]
pub struct ModelOracle {
    /// The ground rule instances.
    pub rules: Vec<RuleInstance>,
    /// The literals of the answer set.
    pub model: std::collections::HashSet<Symbol>,
}

impl Oracle for ModelOracle {
    fn holds(&self, literal: &Symbol) -> bool {
        self.model.contains(literal)
    }

    fn rules_for(&self, head: &Symbol) -> Vec<RuleInstance> {
        self.rules
            .iter()
            .filter(|r| r.head == *head)
            .cloned()
            .collect()
    }

    fn applied(&self, rule: &RuleInstance) -> bool {
        rule.kind == AxiomKind::CrRule && self.model.contains(&rule.head)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf(tree: &mut ProofTree, name: &str, children: Vec<NodeId>) -> NodeId {
        let mut n = Node::unsupported(Symbol::parse(name).unwrap());
        n.children = children;
        tree.add(n)
    }

    /// r has children a and b, a has child d, b has child c; the path is r, b, c. Cut down to
    /// the path, d goes (a is off the path), and every kept node keeps its literal.
    #[test]
    fn around_the_path_keeps_the_path_and_its_childrens_literals() {
        let mut t = ProofTree::default();
        let d = leaf(&mut t, "d", vec![]);
        let a = leaf(&mut t, "a", vec![d]);
        let c = leaf(&mut t, "c", vec![]);
        let b = leaf(&mut t, "b", vec![c]);
        let r = leaf(&mut t, "r", vec![a, b]);
        let other = leaf(&mut t, "r2", vec![]);
        t.roots = vec![r, other];
        t.path = vec![r, b, c];
        let cut = t.around_path();
        let names: Vec<String> = cut.nodes.iter().map(|n| n.literal.to_string()).collect();
        assert_eq!(names, ["a", "c", "b", "r"]);
        assert!(cut.nodes[0].children.is_empty(), "a loses its child d");
        let path: Vec<String> = cut
            .path
            .iter()
            .map(|p| cut.node(*p).literal.to_string())
            .collect();
        assert_eq!(path, ["r", "b", "c"]);
        assert_eq!(cut.roots.len(), 1);
        let root = cut.node(cut.roots[0]);
        let kids: Vec<String> = root
            .children
            .iter()
            .map(|k| cut.node(*k).literal.to_string())
            .collect();
        assert_eq!(kids, ["a", "b"]);
        // Without a path the tree is whole.
        t.path.clear();
        assert_eq!(t.around_path(), t);
    }
}

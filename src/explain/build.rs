//! Building proof trees (docs/domain.md 6.2) over a ground program and one of its answer sets, seen
//! through the [`Oracle`] of `explain::tree`: the rule instances for a head (with their axiom
//! labels and categories), the model's literals, and which CR rules are applied.
//!
//! Algorithm (the paper's four steps on the ground program):
//! - **Support.** A rule instance supports a literal that holds if its head is the literal and
//!   its body holds: positive literals true, default-negated ones false; a CR rule only when it
//!   is applied.
//! - **Expansion.** Each support is a node; its children are the nodes of its positive body
//!   literals, each with its own supports as alternative siblings (at most [`MAX_BRANCHES`]
//!   children, at least the preferred support of every body literal). Default-negated literals
//!   are kept as "no evidence of" and not expanded.
//! - **Leaves.** Facts of the program are Static (no step), Observation (a `holds` literal) or
//!   Action (an `occurs` literal); history rules from `obs` are Observations and from `hpd`
//!   Actions; an applied CR rule is an Assumption; a closed-world rule a ClosedWorld leaf.
//! - **Loops and limits.** A support with a body literal already on the path to the root is
//!   dropped (cycles from converse pairs and SR1); depth at most [`MAX_DEPTH`]; a literal with no
//!   support left is dropped with its branch. A node budget bounds the work: past it, only the
//!   first support that completes is kept for each new literal.
//! - **Path choice.** Supports are ordered: facts and history; spatial algebra (labels of
//!   [`BuildConfig::spatial_labels`]); other domain axioms (applied CR rules included);
//!   inertia; closed-world rules. Ties: bodies that mention the root's object arguments first,
//!   then fewer nodes to a leaf, then the program's order. The preferred path follows the first
//!   alternative at each node, going down the first child that is a fluent or action literal
//!   (statics last), preferring literals that mention the root's objects.
//! - **False literals.** A literal that does not hold gets an `Unsupported` node: for each of
//!   its rule instances, the first body literal that blocks it (a false positive literal,
//!   explained the same way, or a true default-negated one, explained by its support).
//!
//! Invariants: the tree passes `tree::recheck` against the same oracle (tests run it on every
//! tree); building never panics on any oracle answer, and ends (paths never repeat a literal,
//! depth is bounded).

use std::collections::{HashMap, HashSet};

use super::pattern::SymbolExt;
use super::tree::{
    AxiomKind, Kind, Node, NodeId, Oracle, ProofTree, RuleInstance, MAX_BRANCHES, MAX_DEPTH,
};
use crate::control::Symbol;

/// Settings of the tree builder.
#[derive(Clone, Debug)]
pub struct BuildConfig {
    /// Label prefixes of the spatial-relation algebra (SR1-SR3), preferred right after facts
    /// and followed by normalization.
    pub spatial_labels: Vec<String>,
    /// Nodes after which only the first complete support of a new literal is expanded.
    pub node_budget: usize,
    /// Constants that do not count as the root's objects when breaking ties (the robot: every
    /// action and `in_hand` mentions `rob1`).
    pub agents: Vec<Symbol>,
}

impl Default for BuildConfig {
    fn default() -> Self {
        BuildConfig {
            spatial_labels: vec!["SR1".into(), "SR2".into(), "SR3".into()],
            node_budget: 4096,
            agents: Vec::new(),
        }
    }
}

/// Builds proof trees over one oracle.
pub struct Builder<'o> {
    oracle: &'o dyn Oracle,
    config: BuildConfig,
    tree: ProofTree,
    /// Object constants of the root literal (for tie-breaking).
    root_objects: Vec<Symbol>,
    /// The root's action or fluent (the first argument of `occurs`/`holds`).
    root_inner: Option<Symbol>,
    /// Literals on the current path.
    path: Vec<Symbol>,
    /// Finished expansions: literal -> (alternatives, literals used in their subtrees).
    memo: HashMap<Symbol, (Vec<NodeId>, HashSet<Symbol>)>,
    /// Subtree size of each node (nodes to its leaves, itself included).
    size: Vec<usize>,
    /// The lowest path position a cycle cut (or the depth limit, as position 0) referred to
    /// during the current expansion: a result that depends on the path above a literal is not
    /// memoized.
    lowest_cut: usize,
    /// Literals known to be (or not to be) sort guards.
    sort_cache: std::cell::RefCell<HashMap<Symbol, bool>>,
}

impl<'o> Builder<'o> {
    /// A builder over an oracle.
    pub fn new(oracle: &'o dyn Oracle, config: BuildConfig) -> Builder<'o> {
        Builder {
            oracle,
            config,
            tree: ProofTree::default(),
            root_objects: Vec::new(),
            root_inner: None,
            path: Vec::new(),
            memo: HashMap::new(),
            size: Vec::new(),
            lowest_cut: usize::MAX,
            sort_cache: Default::default(),
        }
    }

    /// The proof tree of a literal: why it holds, or why it does not.
    pub fn build(mut self, literal: &Symbol) -> ProofTree {
        self.root_objects = constants(literal);
        self.root_objects
            .retain(|c| !self.config.agents.contains(c));
        self.root_inner = match literal.name() {
            Some("occurs" | "holds") => literal.arg(0).cloned(),
            _ => None,
        };
        let roots = if self.oracle.holds(literal) {
            self.expand(literal, 0)
        } else {
            self.unsupported(literal, 0).into_iter().collect()
        };
        self.tree.roots = roots;
        self.tree.path = self.preferred_path();
        self.tree
    }

    fn add(&mut self, node: Node) -> NodeId {
        let size = 1 + node
            .children
            .iter()
            .map(|c| self.size[c.index()])
            .sum::<usize>();
        let id = self.tree.add(node);
        self.size.push(size);
        id
    }

    /// The alternatives (one node per support, preferred first) for a literal that holds;
    /// empty if no support survives the loop and depth checks.
    fn expand(&mut self, literal: &Symbol, depth: usize) -> Vec<NodeId> {
        if depth >= MAX_DEPTH {
            self.lowest_cut = 0;
            return Vec::new();
        }
        if let Some((alts, used)) = self.memo.get(literal) {
            if !self.path.iter().any(|p| used.contains(p)) {
                return alts.clone();
            }
        }
        let mut supports: Vec<RuleInstance> = self
            .oracle
            .rules_for(literal)
            .into_iter()
            .filter(|r| self.body_holds(r))
            .collect();
        supports.sort_by_key(|r| (self.rank(r), !self.mentions_root(r)));
        let position = self.path.len();
        let outer_cut = std::mem::replace(&mut self.lowest_cut, usize::MAX);
        self.path.push(literal.clone());
        let mut alts: Vec<(NodeId, u8, bool, usize)> = Vec::new();
        for (order, rule) in supports.into_iter().enumerate() {
            if alts.len() >= MAX_BRANCHES {
                break;
            }
            let over_budget = self.tree.nodes.len() >= self.config.node_budget;
            if over_budget && !alts.is_empty() {
                break;
            }
            let rank = self.rank(&rule);
            let mentions = self.mentions_root(&rule);
            if let Some(id) = self.support(literal, rule, depth) {
                alts.push((id, rank, !mentions, order));
            }
        }
        self.path.pop();
        // Preference: rank, then the root's objects, then fewer nodes, then program order.
        alts.sort_by_key(|&(id, rank, not_mentions, order)| {
            (rank, not_mentions, self.size[id.index()], order)
        });
        let alts: Vec<NodeId> = alts.into_iter().map(|a| a.0).collect();
        // Memoize only a result that no cut above this literal shaped.
        let context_free = self.lowest_cut >= position;
        self.lowest_cut = self.lowest_cut.min(outer_cut);
        if context_free {
            let mut used = HashSet::new();
            let mut seen = HashSet::new();
            for a in &alts {
                self.collect_literals(*a, &mut used, &mut seen);
            }
            self.memo.insert(literal.clone(), (alts.clone(), used));
        }
        alts
    }

    /// The literals of a subtree, each node visited once.
    fn collect_literals(&self, id: NodeId, out: &mut HashSet<Symbol>, seen: &mut HashSet<NodeId>) {
        if !seen.insert(id) {
            return;
        }
        let n = self.tree.node(id);
        out.insert(n.literal.clone());
        for c in &n.children {
            self.collect_literals(*c, out, seen);
        }
    }

    /// One support as a node, or `None` if its branch is dropped.
    fn support(&mut self, literal: &Symbol, rule: RuleInstance, depth: usize) -> Option<NodeId> {
        let kind = classify(literal, &rule);
        if kind.is_leaf_kind() {
            return Some(self.add(Node::supported(literal.clone(), kind, rule)));
        }
        let body: Vec<Symbol> = rule.positive().cloned().collect();
        if let Some(p) = body
            .iter()
            .filter_map(|b| self.path.iter().position(|x| x == b))
            .min()
        {
            self.lowest_cut = self.lowest_cut.min(p);
            return None;
        }
        let mut per_literal: Vec<Vec<NodeId>> = Vec::new();
        for b in &body {
            let alts = self.expand(b, depth + 1);
            if alts.is_empty() {
                return None;
            }
            per_literal.push(alts);
        }
        // At least the preferred support of every body literal; more while there is room.
        let mut children: Vec<NodeId> = per_literal.iter().map(|a| a[0]).collect();
        if children.len() > MAX_BRANCHES {
            return None;
        }
        'more: for k in 1.. {
            let mut any = false;
            for alts in &per_literal {
                if let Some(&a) = alts.get(k) {
                    any = true;
                    if children.len() >= MAX_BRANCHES {
                        break 'more;
                    }
                    children.push(a);
                }
            }
            if !any {
                break;
            }
        }
        // Keep each literal's alternatives together, in body order.
        let order: Vec<&Symbol> = body.iter().collect();
        children.sort_by_key(|c| {
            let lit = &self.tree.node(*c).literal;
            order.iter().position(|b| *b == lit).unwrap_or(usize::MAX)
        });
        let mut node = Node::supported(literal.clone(), kind, rule);
        node.children = children;
        Some(self.add(node))
    }

    /// Whether a rule instance supports its head in the model.
    fn body_holds(&self, rule: &RuleInstance) -> bool {
        rule.positive().all(|t| self.oracle.holds(t))
            && rule.negative().all(|t| !self.oracle.holds(t))
            && (rule.kind != AxiomKind::CrRule || self.oracle.applied(rule))
    }

    /// The preference rank of a support (docs/domain.md 6.2, path choice).
    fn rank(&self, rule: &RuleInstance) -> u8 {
        match rule.kind {
            AxiomKind::Fact | AxiomKind::Sort | AxiomKind::History
                if rule.negative().next().is_none() =>
            {
                0
            }
            _ if self.is_spatial(rule) => 1,
            AxiomKind::Inertia => 3,
            AxiomKind::ClosedWorld | AxiomKind::History => 4,
            _ => 2,
        }
    }

    fn is_spatial(&self, rule: &RuleInstance) -> bool {
        self.config
            .spatial_labels
            .iter()
            .any(|p| rule.label.starts_with(p.as_str()))
    }

    /// Whether a positive body literal mentions one of the root's objects; literals that only
    /// restate the root's own action or fluent (the sort guard `action(pickup(rob1,a))`) do
    /// not count.
    fn mentions_root(&self, rule: &RuleInstance) -> bool {
        // The sort test asks the oracle for the literal's rules: it comes last (it was 14% of
        // a belief question's time when it came first).
        rule.positive().any(|t| {
            !self
                .root_inner
                .as_ref()
                .is_some_and(|inner| contains(t, inner))
                && constants(t).iter().any(|c| self.root_objects.contains(c))
                && !self.is_sort(t)
        })
    }

    /// Whether every rule for a literal is a sort declaration (a guard that names the root's
    /// objects without saying anything about them).
    fn is_sort(&self, t: &Symbol) -> bool {
        if let Some(&b) = self.sort_cache.borrow().get(t) {
            return b;
        }
        let rules = self.oracle.rules_for(t);
        let b = !rules.is_empty() && rules.iter().all(|r| r.kind == AxiomKind::Sort);
        self.sort_cache.borrow_mut().insert(t.clone(), b);
        b
    }

    /// The node of a literal that does not hold: each of its rules with its first blocking body
    /// literal. `None` if a blocking literal cannot be explained within the limits.
    fn unsupported(&mut self, literal: &Symbol, depth: usize) -> Option<NodeId> {
        if depth >= MAX_DEPTH {
            return None;
        }
        let rules = self.oracle.rules_for(literal);
        if rules.len() > MAX_BRANCHES {
            return None;
        }
        self.path.push(literal.clone());
        let mut children = Vec::new();
        let mut blocked = Vec::new();
        let mut ok = true;
        for rule in rules {
            let mut found = None;
            // A false positive literal first, then a true default-negated one.
            for b in rule.positive() {
                if !self.oracle.holds(b) && !self.path.contains(b) {
                    if let Some(id) = self.unsupported(b, depth + 1) {
                        found = Some(id);
                        break;
                    }
                }
            }
            if found.is_none() {
                for b in rule.negative() {
                    if self.oracle.holds(b) && !self.path.contains(b) {
                        if let Some(&id) = self.expand(b, depth + 1).first() {
                            found = Some(id);
                            break;
                        }
                    }
                }
            }
            match found {
                Some(id) => {
                    children.push(id);
                    blocked.push(rule);
                }
                None => {
                    ok = false;
                    break;
                }
            }
        }
        self.path.pop();
        if !ok {
            return None;
        }
        let mut node = Node::unsupported(literal.clone());
        node.children = children;
        node.blocked = blocked;
        Some(self.add(node))
    }

    /// The answer's path: the first root, then at each node the preferred child.
    fn preferred_path(&self) -> Vec<NodeId> {
        let Some(&root) = self.tree.roots.first() else {
            return Vec::new();
        };
        let mut path = vec![root];
        let mut at = root;
        while let Some(next) = self.preferred_child(at) {
            path.push(next);
            at = next;
        }
        path
    }

    fn preferred_child(&self, id: NodeId) -> Option<NodeId> {
        let n = self.tree.node(id);
        // The first alternative of each body literal, in body order.
        let mut seen: Vec<&Symbol> = Vec::new();
        let mut firsts: Vec<NodeId> = Vec::new();
        for c in &n.children {
            let lit = &self.tree.node(*c).literal;
            if !seen.contains(&lit) {
                seen.push(lit);
                firsts.push(*c);
            }
        }
        firsts.into_iter().min_by_key(|c| {
            let child = self.tree.node(*c);
            let is_static = child.step.is_none();
            let mentions = constants(&child.literal)
                .iter()
                .any(|t| self.root_objects.contains(t));
            (is_static, !mentions)
        })
    }
}

/// Builds the proof tree of a literal with the default settings.
pub fn proof_tree(oracle: &dyn Oracle, literal: &Symbol) -> ProofTree {
    Builder::new(oracle, BuildConfig::default()).build(literal)
}

/// Whether `inner` occurs in `t` (as `t` itself or a subterm).
fn contains(t: &Symbol, inner: &Symbol) -> bool {
    t == inner || t.args().iter().any(|a| contains(a, inner))
}

/// The constants inside a term that are objects (not relation names, not numbers): the
/// arguments of `relation/3` after the first, and every constant argument elsewhere.
fn constants(t: &Symbol) -> Vec<Symbol> {
    let mut out = Vec::new();
    collect_constants(t, &mut out);
    out
}

fn collect_constants(t: &Symbol, out: &mut Vec<Symbol>) {
    let args = t.args();
    let skip = usize::from(t.name() == Some("relation"));
    for a in args.iter().skip(skip) {
        if a.is_constant() {
            if !out.contains(a) {
                out.push(a.clone());
            }
        } else {
            collect_constants(a, out);
        }
    }
}

/// The literal a relation literal normalizes to (docs/domain.md 6.2): follow spatial-algebra
/// supports down the preferred path from `start` to the first literal whose own support is not
/// spatial algebra. Returns that node.
///
/// Only *rewrites* are followed: spatial supports with one fluent body literal (SR1b
/// `above(A,B)` from `on(A,B)`, SR1c, SR2, SR3), which restate a literal as an equivalent one.
/// A spatial support with several fluent body literals (SR1a: `on(A,B)` from `above(A,B)` and
/// `touch(A,B)`) is a conjunction, not a restatement: the literal it supports is already
/// normal (at a step after 0, `on(C,B)` from E1 is such a literal: SR1a outranks its inertia
/// support, and following SR1a would name `touch(C,B)` instead of `on(C,B)`).
pub fn normalize(tree: &ProofTree, start: NodeId, spatial_labels: &[String]) -> NodeId {
    let mut at = start;
    loop {
        let n = tree.node(at);
        if !is_spatial_node(n, spatial_labels) || fluent_body_literals(tree, at) != 1 {
            return at;
        }
        // Follow the path if it continues from here, else the first fluent child.
        let next = tree
            .path
            .iter()
            .position(|p| *p == at)
            .and_then(|i| tree.path.get(i + 1))
            .copied()
            .or_else(|| tree.timed_children(at).next());
        match next {
            Some(c) => at = c,
            None => return at,
        }
    }
}

/// Whether a node's support is a spatial-algebra axiom (a label of `spatial_labels`).
pub fn is_spatial_node(n: &Node, spatial_labels: &[String]) -> bool {
    matches!(&n.kind, Kind::Axiom { label, .. }
        if spatial_labels.iter().any(|p| label.starts_with(p.as_str())))
}

/// The number of distinct fluent or action literals (literals with a step) among a node's
/// children: the body literals of its support that are traced.
fn fluent_body_literals(tree: &ProofTree, id: NodeId) -> usize {
    let mut seen: Vec<&Symbol> = Vec::new();
    for c in &tree.node(id).children {
        let child = tree.node(*c);
        if child.step.is_some() && !seen.contains(&&child.literal) {
            seen.push(&child.literal);
        }
    }
    seen.len()
}

/// Among the alternatives `parent` has for the literal of `chosen` (its children with that
/// literal), the one to show on the answer's path: `chosen` unless it is a spatial conjunction
/// (SR1a) and a support that is not spatial algebra (an observation, a causal law, inertia)
/// is there, which then says where the literal came from.
pub fn origin_alternative(
    tree: &ProofTree,
    parent: NodeId,
    chosen: NodeId,
    spatial_labels: &[String],
) -> NodeId {
    let lit = &tree.node(chosen).literal;
    if !is_spatial_node(tree.node(chosen), spatial_labels) {
        return chosen;
    }
    tree.node(parent)
        .children
        .iter()
        .copied()
        .find(|c| {
            let n = tree.node(*c);
            n.literal == *lit && !is_spatial_node(n, spatial_labels)
        })
        .unwrap_or(chosen)
}

/// The node kind of a support.
pub(super) fn classify(literal: &Symbol, rule: &RuleInstance) -> Kind {
    let is_action = literal.name() == Some("occurs") && !literal.is_negative();
    let is_holds = literal.name() == Some("holds");
    match rule.kind {
        AxiomKind::Fact if is_action => Kind::Action,
        AxiomKind::Fact if is_holds => Kind::Observation,
        AxiomKind::Fact | AxiomKind::Sort => Kind::Static,
        AxiomKind::History if is_action => Kind::Action,
        AxiomKind::History if rule.negative().next().is_some() => Kind::ClosedWorld,
        AxiomKind::History => Kind::Observation,
        AxiomKind::Planning if is_action => Kind::Action,
        AxiomKind::CrRule => Kind::Assumption,
        AxiomKind::ClosedWorld => Kind::ClosedWorld,
        AxiomKind::Inertia => Kind::Inertia,
        kind => Kind::Axiom {
            label: rule.label.clone(),
            kind,
        },
    }
}

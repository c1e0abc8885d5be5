//! The H3 experiment (docs/domain.md 7.5): belief tracing retrieves the supporting axioms of a
//! belief. This module holds the two pieces the tests and the experiment harness share:
//!
//! - **Scenes** ([`generate`]): symbolic tabletop scenes from a seed, in the two families of
//!   docs/domain.md 1.6 and 7.1: [`ScenePreset::Real`] (5-7 objects: cubes, a tennis ball, fruit, a
//!   pig, a pot; stacks or spread on the table) and [`ScenePreset::Simulated`] (7-9 objects, 3-5
//!   of them stacked: cylinders, spheres, cubes, a duck and household objects), with the
//!   attribute defaults of 1.6, a few `behind` pairs on the table (what the frontal camera sees),
//!   and a goal drawn as 7.1 says. [`Scene::to_ald`] writes the scene as an AL_d file that
//!   includes KB_full.
//! - **Tree checks** ([`check_tree`]): the three H3 criteria on one proof tree, written here
//!   independently of `tree::recheck` (which they also run): every branch body holds in the
//!   answer set, no literal repeats on a path from a root, and every leaf is one of the five
//!   kinds docs/domain.md 6.2 lists (Static, Observation, Action, Assumption, ClosedWorld). A
//!   literal that does not hold ends in an `Unsupported` node only when the program has no rule for
//!   it, which we count apart (`false_leaves`): docs/domain.md 6.2 has no kind for it.
//! - **Trials** ([`check_history`]): over an executed plan, the questions of docs/domain.md 7.5
//!   (the plan; why a random plan action; why not that action with one argument changed; a belief
//!   related to both) and more beliefs (the goal at the last step, where each object of the
//!   chosen action stood and whether it was held at every step, a tower height, a relation
//!   that did not hold), every proof tree built checked by [`check_tree`].
//!
//! Invariants: a scene is a function of `(preset, seed)`; every generated initial state is
//! physically sensible and consistent with KB_full: towers stand on the table, every object
//! under another one has a flat top and is not small, no tower is higher than 4 (so neither D1
//! nor D2 fires at step 0), and `behind` pairs join two objects standing on the table that are
//! not covered. Nothing here reads files, prints or solves.

use std::collections::HashSet;

use super::build::Builder;
use super::english::{holds, occurs, Question};
use super::lexicon::Lexicon;
use super::pattern::{Pattern, SymbolExt};
use super::questions::{answer, Mode, Scenario, Session};
use super::tree::{recheck, BodyLiteral, Kind, NodeId, Oracle, ProofTree};
use crate::base::rng::SplitMix64;
use crate::control::Symbol;

/// A family of scenes (docs/domain.md 1.6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ScenePreset {
    /// Like the paper's real scenes: 5-7 objects, stacked or spread.
    Real,
    /// Like the paper's simulated scenes: 7-9 objects, 3-5 of them stacked.
    Simulated,
}

impl ScenePreset {
    /// Both presets.
    pub const ALL: [ScenePreset; 2] = [ScenePreset::Real, ScenePreset::Simulated];

    /// The preset's name (`real`, `simulated`).
    pub fn name(self) -> &'static str {
        match self {
            ScenePreset::Real => "real",
            ScenePreset::Simulated => "simulated",
        }
    }

    /// The object pool: name, size, top surface (docs/domain.md 1.6 and its attribute defaults).
    /// Cubes and cylinders may be drawn medium instead of large (see [`generate`]).
    fn pool(self) -> &'static [(&'static str, &'static str, &'static str)] {
        match self {
            ScenePreset::Real => &[
                ("red_cube", "large", "flat"),
                ("blue_cube", "large", "flat"),
                ("orange_cube", "large", "flat"),
                ("purple_cube", "large", "flat"),
                ("green_cube", "large", "flat"),
                ("tennis_ball", "small", "irregular"),
                ("apple", "medium", "irregular"),
                ("capsicum", "medium", "irregular"),
                ("pig", "medium", "irregular"),
                ("pot", "large", "irregular"),
            ],
            ScenePreset::Simulated => &[
                ("red_cylinder", "large", "flat"),
                ("blue_cylinder", "large", "flat"),
                ("white_cube", "large", "flat"),
                ("black_cube", "large", "flat"),
                ("cracker_box", "large", "flat"),
                ("green_sphere", "medium", "irregular"),
                ("yellow_sphere", "small", "irregular"),
                ("yellow_duck", "medium", "irregular"),
                ("apple", "medium", "irregular"),
                ("pitcher", "large", "irregular"),
                ("mustard_bottle", "medium", "irregular"),
                ("mug", "medium", "irregular"),
            ],
        }
    }

    /// Object counts (inclusive) and stacked counts (inclusive, bases included).
    fn counts(self) -> ((u64, u64), (u64, u64)) {
        match self {
            ScenePreset::Real => ((5, 7), (2, 4)),
            ScenePreset::Simulated => ((7, 9), (3, 5)),
        }
    }
}

/// One object of a scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneObject {
    /// The constant (`blue_cube`).
    pub name: String,
    /// `small`, `medium` or `large`.
    pub size: &'static str,
    /// `flat` or `irregular`.
    pub surface: &'static str,
}

/// A planning goal (docs/domain.md 7.1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Goal {
    /// `on(X, Y)`.
    On(String, String),
    /// `in_hand(rob1, X)`.
    InHand(String),
}

impl Goal {
    /// The goal fluent in the program's syntax (`relation(on,a,b)`, `in_hand(rob1,a)`).
    pub fn fluent(&self) -> Symbol {
        match self {
            Goal::On(x, y) => Symbol::function(
                "relation",
                vec![
                    Symbol::constant("on"),
                    Symbol::constant(x),
                    Symbol::constant(y),
                ],
            ),
            Goal::InHand(x) => Symbol::function(
                "in_hand",
                vec![Symbol::constant("rob1"), Symbol::constant(x)],
            ),
        }
    }
}

/// A generated scene: objects, the initial state and a goal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Scene {
    /// The preset it was drawn from.
    pub preset: ScenePreset,
    /// The seed it was drawn with.
    pub seed: u64,
    /// The movable objects.
    pub objects: Vec<SceneObject>,
    /// Initial `on(A, B)` facts, bottom of each tower first; every object appears once as `A`.
    pub on: Vec<(String, String)>,
    /// Initial `behind(A, B)` facts (A is behind B, as the frontal camera sees it).
    pub behind: Vec<(String, String)>,
    /// The goal.
    pub goal: Goal,
}

impl Scene {
    /// A short name (`real-17`).
    pub fn name(&self) -> String {
        format!("{}-{}", self.preset.name(), self.seed)
    }

    /// The object constants.
    pub fn object_names(&self) -> Vec<&str> {
        self.objects.iter().map(|o| o.name.as_str()).collect()
    }

    /// The object's attributes, if it is in the scene.
    pub fn object(&self, name: &str) -> Option<&SceneObject> {
        self.objects.iter().find(|o| o.name == name)
    }

    /// What `name` stands on initially.
    pub fn support(&self, name: &str) -> Option<&str> {
        self.on
            .iter()
            .find(|(a, _)| a == name)
            .map(|(_, b)| b.as_str())
    }

    /// The scene as a problem without its domain: the objects, their sizes and surfaces, the
    /// initial `on` and `behind` relations and, when `with_goal`, the goal (the statements of
    /// [`Scene::to_ald`], as values).
    pub fn problem(&self, with_goal: bool) -> crate::plan::Problem {
        let c = |n: &str| Symbol::constant(n);
        let attribute =
            |p: &str, o: &SceneObject, v: &str| Symbol::function(p, vec![c(&o.name), c(v)]);
        let relation =
            |r: &str, a: &str, b: &str| Symbol::function("relation", vec![c(r), c(a), c(b)]);
        let mut statics: Vec<Symbol> = self
            .objects
            .iter()
            .map(|o| attribute("has_size", o, o.size))
            .collect();
        statics.extend(
            self.objects
                .iter()
                .map(|o| attribute("has_surface", o, o.surface)),
        );
        let mut initially: Vec<Symbol> =
            self.on.iter().map(|(a, b)| relation("on", a, b)).collect();
        initially.extend(self.behind.iter().map(|(a, b)| relation("behind", a, b)));
        let goal = match (&self.goal, with_goal) {
            (_, false) => Vec::new(),
            (Goal::On(x, y), true) => vec![relation("on", x, y)],
            (Goal::InHand(x), true) => vec![Symbol::function("in_hand", vec![c("rob1"), c(x)])],
        };
        crate::plan::Problem {
            objects: Some(self.object_names().iter().map(|n| n.to_string()).collect()),
            statics,
            initially,
            goal,
            ..Default::default()
        }
    }

    /// The scene as AL_d text including `include` (the path of `kb_full.ald` as the scene file
    /// names it), with the goal when `with_goal`.
    pub fn to_ald(&self, include: &str, with_goal: bool) -> String {
        let mut s = format!(
            "% Generated scene {} (lucent::explain::h3::generate, preset {}, seed {}).\n\
             include \"{include}\".\n\n",
            self.name(),
            self.preset.name(),
            self.seed
        );
        s.push_str(&format!(
            "sort movable = {{{}}}.\nsort unknown = {{}}.\n\n",
            self.object_names().join(", ")
        ));
        for o in &self.objects {
            s.push_str(&format!("has_size({}, {}).\n", o.name, o.size));
        }
        for o in &self.objects {
            s.push_str(&format!("has_surface({}, {}).\n", o.name, o.surface));
        }
        s.push('\n');
        for (a, b) in &self.on {
            s.push_str(&format!("initially relation(on, {a}, {b}).\n"));
        }
        for (a, b) in &self.behind {
            s.push_str(&format!("initially relation(behind, {a}, {b}).\n"));
        }
        if with_goal {
            match &self.goal {
                Goal::On(x, y) => s.push_str(&format!("\ngoal relation(on, {x}, {y}).\n")),
                Goal::InHand(x) => s.push_str(&format!("\ngoal in_hand(rob1, {x}).\n")),
            }
        }
        s
    }
}

/// Draws a scene (docs/domain.md 1.6, 7.1): the object count from the preset's range, the objects
/// from its pool (cubes and cylinders medium with probability 0.3); then towers: stacked objects
/// (the preset's range, at least two) are split into towers of two to four, each built bottom up
/// from objects with a flat top that are not small, any object on top; the others stand on the
/// table. With probability 0.5 each, up to two `behind` pairs among uncovered objects on the
/// table. The goal: with probability 0.2 `in_hand(rob1, X)`, else `on(X, Y)` with Y the table or
/// an object with a flat top that is not small, Y != X, not already true, and the tower Y would
/// top no higher than 4.
pub fn generate(preset: ScenePreset, seed: u64) -> Scene {
    let root = SplitMix64::new(seed ^ 0x4833_5343_454e_4500);
    let mut rng = root.fork(preset as u64 + 1);
    let ((lo, hi), (slo, shi)) = preset.counts();
    let count = (lo + rng.below(hi - lo + 1)) as usize;
    let mut pool: Vec<SceneObject> = preset
        .pool()
        .iter()
        .map(|(n, size, surface)| SceneObject {
            name: n.to_string(),
            size,
            surface,
        })
        .collect();
    rng.shuffle(&mut pool);
    // Two objects with a flat top first (so a tower of three can stand), then the rest in the
    // shuffled order.
    let flats: Vec<usize> = (0..pool.len())
        .filter(|&i| pool[i].surface == "flat")
        .take(2)
        .collect();
    let mut chosen: Vec<SceneObject> = flats.iter().map(|&i| pool[i].clone()).collect();
    chosen.extend(
        (0..pool.len())
            .filter(|i| !flats.contains(i))
            .map(|i| pool[i].clone()),
    );
    let mut pool = chosen;
    pool.truncate(count);
    for o in &mut pool {
        if o.surface == "flat" && rng.chance(0.3) {
            o.size = "medium";
        }
    }
    // Sort the scene's objects by name so the text does not depend on draw order.
    let mut objects = pool;
    objects.sort_by(|a, b| a.name.cmp(&b.name));

    let can_carry = |o: &SceneObject| o.surface == "flat" && o.size != "small";
    let mut order: Vec<usize> = (0..objects.len()).collect();
    rng.shuffle(&mut order);
    let stacked_target = (slo + rng.below(shi - slo + 1)) as usize;
    let mut placed = vec![false; objects.len()];
    let mut on: Vec<(String, String)> = Vec::new();
    let mut stacked = 0usize;
    // Towers: a base and one to three objects on it, while stacked objects are still wanted.
    while stacked_target.saturating_sub(stacked) >= 2 {
        let Some(base) = order
            .iter()
            .copied()
            .find(|&i| !placed[i] && can_carry(&objects[i]))
        else {
            break;
        };
        // The tower takes what is left when that fits, else leaves at least two for another.
        let left = stacked_target - stacked;
        let height = if left <= 4 {
            left
        } else {
            2 + rng.below((left - 2).min(4) as u64 - 1) as usize
        };
        placed[base] = true;
        on.push((objects[base].name.clone(), "table".into()));
        stacked += 1;
        let mut top = base;
        for level in 1..height {
            let last = level + 1 == height;
            let next = order
                .iter()
                .copied()
                .find(|&i| !placed[i] && (last || can_carry(&objects[i])))
                .or_else(|| order.iter().copied().find(|&i| !placed[i]));
            let Some(next) = next else { break };
            placed[next] = true;
            on.push((objects[next].name.clone(), objects[top].name.clone()));
            stacked += 1;
            if !can_carry(&objects[next]) {
                break;
            }
            top = next;
        }
    }
    // One stacked object short (a tower ended early on an irregular top, or the towers' sizes
    // left one over): one more object on a tower top that can carry it, below level 4.
    if stacked_target.saturating_sub(stacked) == 1 {
        let level_of = |on: &[(String, String)], x: &str| {
            let mut n = 1;
            let mut at = x.to_string();
            while let Some((_, b)) = on.iter().find(|(a, _)| *a == at) {
                if b == "table" {
                    break;
                }
                n += 1;
                at = b.clone();
            }
            n
        };
        let top = on
            .iter()
            .map(|(a, _)| a.clone())
            .filter(|a| !on.iter().any(|(_, b)| b == a))
            .filter(|a| on.iter().any(|(x, b)| x == a && b != "table"))
            .find(|a| {
                let o = objects
                    .iter()
                    .find(|o| o.name == *a)
                    .expect("placed object");
                can_carry(o) && level_of(&on, a) < 4
            });
        let extra = order.iter().copied().find(|&i| !placed[i]);
        if let (Some(top), Some(extra)) = (top, extra) {
            placed[extra] = true;
            on.push((objects[extra].name.clone(), top));
        }
    }
    for i in order {
        if !placed[i] {
            on.push((objects[i].name.clone(), "table".into()));
        }
    }
    let scene_on = on.clone();
    let support = |x: &str| {
        scene_on
            .iter()
            .find(|(a, _)| a == x)
            .map(|(_, b)| b.clone())
    };
    let covered = |x: &str| scene_on.iter().any(|(_, b)| b == x);
    // Behind pairs among uncovered objects standing on the table.
    let on_table: Vec<String> = objects
        .iter()
        .map(|o| o.name.clone())
        .filter(|n| support(n).as_deref() == Some("table") && !covered(n))
        .collect();
    let mut behind: Vec<(String, String)> = Vec::new();
    for _ in 0..2 {
        if on_table.len() >= 2 && rng.chance(0.5) {
            let a = rng.pick(&on_table).clone();
            let b = rng.pick(&on_table).clone();
            let used = |x: &String| behind.iter().any(|(p, q)| p == x || q == x);
            if a != b && !used(&a) && !used(&b) {
                behind.push((a, b));
            }
        }
    }
    // The level of each object (1 on the table).
    let level = |x: &str| {
        let mut n = 0;
        let mut at = x.to_string();
        while at != "table" {
            n += 1;
            at = support(&at).unwrap_or_else(|| "table".into());
            if n > 10 {
                break;
            }
        }
        n
    };
    let names: Vec<String> = objects.iter().map(|o| o.name.clone()).collect();
    let goal = if rng.chance(0.2) {
        Goal::InHand(rng.pick(&names).clone())
    } else {
        let mut pairs: Vec<(String, String)> = Vec::new();
        for x in &names {
            let mut places: Vec<String> = vec!["table".into()];
            places.extend(
                objects
                    .iter()
                    .filter(|o| can_carry(o) && o.name != *x)
                    .map(|o| o.name.clone()),
            );
            for y in places {
                let already = support(x).as_deref() == Some(y.as_str());
                // The tower under Y stays; X would stand at Y's level + 1 at most 4.
                let high = y != "table" && level(&y) + 1 > 4;
                if !already && !high {
                    pairs.push((x.clone(), y));
                }
            }
        }
        let (x, y) = rng.pick(&pairs).clone();
        Goal::On(x, y)
    };
    Scene {
        preset,
        seed,
        objects,
        on,
        behind,
        goal,
    }
}

/// What [`check_tree`] counted in a tree that passed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TreeCounts {
    /// Nodes.
    pub nodes: usize,
    /// Distinct root-to-leaf paths walked.
    pub paths: usize,
    /// Leaves by kind: Static, Observation, Action, Assumption, ClosedWorld.
    pub leaves: [usize; 5],
    /// Leaves of literals that do not hold and have no rule (a why-not tree's bottom).
    pub false_leaves: usize,
    /// The longest path (nodes).
    pub depth: usize,
}

impl TreeCounts {
    /// Adds another tree's counts.
    pub fn add(&mut self, other: &TreeCounts) {
        self.nodes += other.nodes;
        self.paths += other.paths;
        for k in 0..5 {
            self.leaves[k] += other.leaves[k];
        }
        self.false_leaves += other.false_leaves;
        self.depth = self.depth.max(other.depth);
    }
}

/// Names of the leaf kinds docs/domain.md 6.2 lists, in [`TreeCounts::leaves`] order.
pub const LEAF_KINDS: [&str; 5] = [
    "static",
    "observation",
    "action",
    "assumption",
    "closed world",
];

/// The H3 criteria on one tree (see the module documentation). `Err` names the first failure.
pub fn check_tree(tree: &ProofTree, oracle: &dyn Oracle) -> Result<TreeCounts, String> {
    recheck(tree, oracle).map_err(|e| format!("recheck: {e}"))?;
    let mut counts = TreeCounts {
        nodes: tree.nodes.len(),
        ..TreeCounts::default()
    };
    // Every branch body holds: the supporting rule's positive literals are in the model and its
    // default-negated ones are not (asked of the oracle here, not taken from the node).
    for (i, n) in tree.nodes.iter().enumerate() {
        if oracle.holds(&n.literal) != n.holds {
            return Err(format!("node {i}: {} has the wrong truth value", n.literal));
        }
        if let Some(rule) = &n.rule {
            for b in &rule.body {
                let ok = match b {
                    BodyLiteral::Pos(t) => oracle.holds(t),
                    BodyLiteral::Not(t) => !oracle.holds(t),
                    BodyLiteral::Test(_) => true,
                };
                if !ok {
                    return Err(format!("node {i}: body of `{rule}` does not hold"));
                }
            }
        }
    }
    // Paths: walked from every root, each literal at most once per path.
    let mut stack: Vec<(NodeId, Vec<(Symbol, bool)>)> =
        tree.roots.iter().map(|r| (*r, Vec::new())).collect();
    let mut walked = 0usize;
    while let Some((id, mut path)) = stack.pop() {
        walked += 1;
        if walked > 2_000_000 {
            return Err("more than 2,000,000 path nodes".into());
        }
        let n = tree.node(id);
        let key = (n.literal.clone(), n.holds);
        if path.contains(&key) {
            return Err(format!("{} repeats on a path", n.literal));
        }
        path.push(key);
        if n.children.is_empty() {
            counts.paths += 1;
            counts.depth = counts.depth.max(path.len());
            let k = match n.kind {
                Kind::Static => 0,
                Kind::Observation => 1,
                Kind::Action => 2,
                Kind::Assumption => 3,
                Kind::ClosedWorld => 4,
                Kind::Unsupported if oracle.rules_for(&n.literal).is_empty() => {
                    counts.false_leaves += 1;
                    continue;
                }
                _ => {
                    return Err(format!(
                        "leaf {} is of kind `{}`, not one of docs/domain.md 6.2",
                        n.literal,
                        n.kind.words()
                    ))
                }
            };
            counts.leaves[k] += 1;
            continue;
        }
        for c in &n.children {
            stack.push((*c, path.clone()));
        }
    }
    Ok(counts)
}

/// The distinct literals of a tree (for reports).
pub fn literals(tree: &ProofTree) -> HashSet<Symbol> {
    tree.nodes.iter().map(|n| n.literal.clone()).collect()
}

/// One trial's outcome: the trees checked and the failures found.
#[derive(Clone, Debug, Default)]
pub struct TrialReport {
    /// Questions asked through `questions::answer`.
    pub questions: usize,
    /// Proof trees checked.
    pub trees: usize,
    /// Their counts, summed.
    pub counts: TreeCounts,
    /// Each failure: the literal or question, and what failed.
    pub failures: Vec<String>,
    /// The questions asked, in order (the first four are docs/domain.md 7.5's: the plan, why X,
    /// why not X with one argument changed, a related belief; H4 asks them again elsewhere).
    pub asked: Vec<Question>,
}

impl TrialReport {
    fn check(&mut self, what: &str, tree: &ProofTree, oracle: &dyn Oracle) {
        self.trees += 1;
        match check_tree(tree, oracle) {
            Ok(c) => self.counts.add(&c),
            Err(e) => self.failures.push(format!("{what}: {e}")),
        }
    }
}

/// The H3 questions and beliefs over one executed history (see the module documentation): the
/// scenario (its oracle, plan and goal) and the scene's movable objects; choices drawn from
/// `seed`; every proof tree checked by [`check_tree`]. An answer that fails (`AnswerError`) is a
/// failure too. With `explain::history`, call it as
/// `check_history(&h.scenario(), &h.objects(), seed)`.
pub fn check_history(scn: &Scenario<'_>, objects: &[String], seed: u64) -> TrialReport {
    let mut rng = SplitMix64::new(seed ^ 0x4833_5452_4941_4c00);
    let oracle: &dyn Oracle = scn.oracle;
    let goal = scn.goal.clone();
    let plan = scn.plan.clone();
    let lexicon = Lexicon::ra();
    let mut report = TrialReport::default();
    let mut session = Session::default();
    let ask = |report: &mut TrialReport, q: Question, session: &mut Session| {
        report.questions += 1;
        report.asked.push(q.clone());
        match answer(scn, &lexicon, &q, Mode::Full, session) {
            Ok(a) => {
                if let Some(t) = &a.tree {
                    report.check(&format!("{q}"), t, oracle);
                }
                Some(a)
            }
            Err(e) => {
                report.failures.push(format!("{q}: {e}"));
                None
            }
        }
    };
    ask(&mut report, Question::DescribePlan, &mut session);
    let tree_of = |report: &mut TrialReport, lit: &Symbol| {
        let tree = Builder::new(oracle, scn.build.clone()).build(lit);
        report.check(&lit.to_string(), &tree, oracle);
    };
    let last = scn.last_step;
    for g in &goal {
        tree_of(&mut report, &holds(g, last));
    }
    if plan.is_empty() {
        return report;
    }
    // Why X: a random plan action; its reason literals traced as beliefs.
    let (step, action) = rng.pick(&plan).clone();
    let why = ask(
        &mut report,
        Question::WhyAction {
            action: Pattern::from(&action),
            step: Some(step),
        },
        &mut session,
    );
    if let Some(a) = &why {
        for lit in &a.literals {
            if oracle.holds(lit) {
                tree_of(&mut report, lit);
            }
        }
    }
    // Why not: one argument of X changed (the object, or the target of a putdown).
    let objects: Vec<Symbol> = objects
        .iter()
        .filter(|o| o.as_str() != "table")
        .map(Symbol::constant)
        .collect();
    let mut changed = action.clone();
    if let Symbol::Function { args, .. } = &mut changed {
        let k = 1 + rng.below(args.len().saturating_sub(1).max(1) as u64) as usize;
        if k < args.len() {
            let mut choices: Vec<Symbol> = objects.clone();
            if k == 2 {
                choices.push(Symbol::constant("table"));
            }
            choices.retain(|c| *c != args[k] && Some(c) != args.get(3 - k));
            if !choices.is_empty() {
                args[k] = rng.pick(&choices).clone();
            }
        }
    }
    let why_not = ask(
        &mut report,
        Question::WhyNotAction {
            action: Pattern::from(&changed),
            step: Some(step),
        },
        &mut session,
    );
    // A belief related to both: the why-not answer's first literal, else the why answer's.
    let related = why_not
        .as_ref()
        .and_then(|a| {
            a.literals
                .iter()
                .find(|l| l.name() == Some("holds"))
                .cloned()
        })
        .or_else(|| {
            why.as_ref().and_then(|a| {
                a.literals
                    .iter()
                    .find(|l| l.name() == Some("holds"))
                    .cloned()
            })
        });
    if let Some(lit) = related {
        let (fluent, at) = (lit.arg(0).cloned(), lit.arg(1).and_then(Symbol::as_number));
        if let (Some(f), Some(at)) = (fluent, at) {
            let f = if lit.is_negative() {
                f.complement().unwrap_or(f)
            } else {
                f
            };
            ask(
                &mut report,
                Question::Belief {
                    literal: f,
                    is_static: false,
                    step: Some(at as u32),
                },
                &mut session,
            );
        }
    }
    // More beliefs about the chosen action's objects at every step: where each stood (the
    // relations that hold with it first), whether it was held, and a relation that did not hold.
    let robot = Symbol::constant("rob1");
    for obj in action.args().iter().skip(1) {
        if obj.name() == Some("table") {
            continue;
        }
        for i in 0..=last {
            let mut found = false;
            for place in objects
                .iter()
                .chain(std::iter::once(&Symbol::constant("table")))
            {
                let on = holds(&relation("on", obj, place), i);
                if oracle.holds(&on) {
                    tree_of(&mut report, &on);
                    found = true;
                } else if !found && place != obj && rng.chance(0.1) {
                    tree_of(&mut report, &on);
                }
            }
            let held = holds(
                &Symbol::function("in_hand", vec![robot.clone(), obj.clone()]),
                i,
            );
            let lit = if oracle.holds(&held) {
                held
            } else {
                held.complement().expect("holds has a sign")
            };
            if oracle.holds(&lit) {
                tree_of(&mut report, &lit);
            }
            for n in 1..=6 {
                let th = holds(
                    &Symbol::function("tower_height", vec![obj.clone(), Symbol::Number(n)]),
                    i,
                );
                if oracle.holds(&th) {
                    tree_of(&mut report, &th);
                }
            }
        }
    }
    // The chosen action's own `occurs` literal and the changed one's complement.
    tree_of(&mut report, &occurs(&action, step));
    report
}

/// `relation(s, a, b)`.
fn relation(s: &str, a: &Symbol, b: &Symbol) -> Symbol {
    Symbol::function("relation", vec![Symbol::constant(s), a.clone(), b.clone()])
}

//! The rapier tabletop of [`crate::sim`] as a [`World`] of the sense-plan-act loop, and the
//! random goals of docs/domain.md 7.1.
//!
//! Perception goes through `sim::perceive_look` with the configured error model and confidence
//! threshold: perceived relations are doubtable readings with their confidence, the hand
//! (`in_hand`) is exact proprioception, sizes and surfaces are statics. Actions go through
//! `sim::execute` with its actuation noise; a failure is reported as the world's account
//! (`the grasp slipped`). Ground truth is measured geometrically (`sim::truth`).
//!
//! Invariants: the scene is the only state (a world is built from it for every look); a run is
//! a function of the scene's seed, the configuration and the actions asked for; goals are a
//! function of the scene and the goal seed, never already true, with a flat, non-small support.

use super::act::{Percept, Seen, World};
use crate::control::Symbol;
use crate::sim::{
    self, perceive_look, ActConfig, Action, Literal, Scene, SplitMix64, TruthConfig, TABLE,
};

/// Stream tag of goal draws.
const GOAL_STREAM: u64 = 0x474f_414c;

/// A simulated tabletop scene with its perception and actuation noise.
pub struct SimWorld {
    /// The scene; the source of truth between calls.
    pub scene: Scene,
    /// Actuation noise, the perception error model and the truth thresholds.
    pub act: ActConfig,
}

impl SimWorld {
    /// A world over `scene`.
    pub fn new(scene: Scene, act: ActConfig) -> Self {
        SimWorld { scene, act }
    }

    /// The relations that hold in the world now.
    fn truth(&self) -> Vec<sim::Relation> {
        let world = sim::World::build(&self.scene);
        sim::truth::relations(&self.scene, &world, &self.act.truth)
    }

    /// Whether every object that is not held stays put for the truth's stability test.
    pub fn all_stable(&self) -> bool {
        sim::truth::stability(&self.scene, &self.act.truth)
            .iter()
            .all(|s| s.stable)
    }
}

/// A perceived literal as a symbol (`relation(on,a,b)`).
fn literal_symbol(literal: &Literal) -> Symbol {
    let c = |n: &str| Symbol::constant(n);
    match literal {
        Literal::Relation(r) => relation_symbol(r),
        Literal::InHand(r, o) => Symbol::function("in_hand", vec![c(r), c(o)]),
        Literal::HasSize(o, s) => Symbol::function("has_size", vec![c(o), c(s.name())]),
        Literal::HasSurface(o, s) => Symbol::function("has_surface", vec![c(o), c(s.name())]),
    }
}

/// `relation(rel, a, b)`.
fn relation_symbol(r: &sim::Relation) -> Symbol {
    let c = |n: &str| Symbol::constant(n);
    Symbol::function("relation", vec![c(r.rel.name()), c(&r.a), c(&r.b)])
}

/// An action symbol (`pickup(rob1,a)`) as the simulator's action; `Err` for any other term.
pub fn sim_action(action: &Symbol) -> Result<Action, String> {
    let args: Option<Vec<&str>> = action
        .args()
        .iter()
        .map(|a| a.args().is_empty().then(|| a.name()).flatten())
        .collect();
    match (action.name(), args, action.is_negative()) {
        (Some(name), Some(args), false) => {
            Action::from_parts(name, &args).map_err(|e| e.to_string())
        }
        _ => Err(format!("`{action}` is not an action of the tabletop")),
    }
}

impl World for SimWorld {
    fn objects(&self) -> Vec<String> {
        self.scene.objects.iter().map(|o| o.name.clone()).collect()
    }

    fn perceive(&mut self, look: u32) -> Percept {
        let world = sim::World::build(&self.scene);
        let p = perceive_look(
            &self.scene,
            &world,
            &self.act.perception,
            &self.act.truth,
            look,
        );
        let mut out = Percept::default();
        for o in p.facts() {
            let fluent = literal_symbol(&o.literal);
            if o.literal.is_static() {
                if o.value {
                    out.statics.push(fluent);
                }
            } else {
                out.fluents.push(Seen {
                    fluent,
                    value: o.value,
                    confidence: o.confidence,
                    exact: matches!(o.literal, Literal::InHand(..)),
                });
            }
        }
        out
    }

    fn execute(&mut self, action: &Symbol) -> Result<Option<String>, String> {
        let action = sim_action(action)?;
        let report =
            sim::execute(&mut self.scene, &action, &self.act).map_err(|e| e.to_string())?;
        Ok(report.failure.map(|f| f.to_string()))
    }

    fn holds_in_truth(&mut self, literal: &Symbol) -> Option<bool> {
        if literal.is("in_hand", 2) {
            let object = literal.args()[1].name()?;
            return Some(self.scene.in_hand.as_deref() == Some(object));
        }
        if literal.is("relation", 3) {
            let text = literal.to_string();
            return Some(self.truth().iter().any(|r| r.to_string() == text));
        }
        None
    }
}

/// A random goal for the scene (docs/domain.md 7.1): with probability 0.2 `in_hand(rob1, X)`,
/// otherwise `relation(on, X, Y)` with X movable and Y the table or a flat, non-small object
/// other than X; never a goal that already holds. `None` if the scene admits none.
pub fn random_goal(world: &mut SimWorld, seed: u64) -> Option<Symbol> {
    let mut rng = SplitMix64::new(seed).fork(GOAL_STREAM);
    let scene = &world.scene;
    let names: Vec<String> = scene.objects.iter().map(|o| o.name.clone()).collect();
    let mut supports: Vec<String> = scene
        .objects
        .iter()
        .filter(|o| o.surface() == sim::Surface::Flat && o.size != sim::Size::Small)
        .map(|o| o.name.clone())
        .collect();
    supports.push(TABLE.to_string());
    let robot = scene.robot.clone();
    let truth: Vec<Symbol> = world.truth().iter().map(relation_symbol).collect();
    let held = scene.in_hand.clone();
    for _ in 0..64 {
        let x = &names[rng.range_usize(0, names.len() - 1)];
        let goal = if rng.chance(0.2) {
            if held.as_deref() == Some(x.as_str()) {
                continue;
            }
            Symbol::function(
                "in_hand",
                vec![Symbol::constant(&robot), Symbol::constant(x)],
            )
        } else {
            let y = &supports[rng.range_usize(0, supports.len() - 1)];
            let c = Symbol::constant;
            let g = Symbol::function("relation", vec![c("on"), c(x), c(y)]);
            if y == x || truth.contains(&g) {
                continue;
            }
            g
        };
        return Some(goal);
    }
    None
}

/// The default actuation and perception configuration of runs: `perception` relation error,
/// `actuation` failure rate, `threshold` confidence threshold.
pub fn act_config(perception: f64, actuation: f64, threshold: f64) -> ActConfig {
    ActConfig {
        failure_rate: actuation,
        perception: sim::ErrorModel {
            relation_error: perception,
            threshold,
            ..sim::ErrorModel::default()
        },
        truth: TruthConfig::default(),
        ..ActConfig::default()
    }
}

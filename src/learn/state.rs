//! The random one-step state generator (docs/domain.md 5.3) and sample collection with class
//! balance (5.4).
//!
//! Generator: pools of movable objects and places (the H1 scene: eight objects; four large
//! cubes, the small can and the table as places). `pickup` draws its object uniformly, and the
//! hand is not empty with probability 0.2; `putdown` draws an (object, place) pair with
//! object != place, and the hand is not empty with probability 0.7. A held object is drawn
//! uniformly from the objects and removed from both pools. The other objects are placed in
//! random order, each `on` a random place other than itself; a placed object stops being a
//! place, and a non-table place is used once. So stacks of three or more arise, cycles never.
//!
//! Collection: each trial adds at most one sample to each of two datasets, CL (causal laws) and
//! EC (executability conditions), by the first matching case of 5.4, with positives capped at
//! 0.6 T and the first 0.4 T samples taken freely; collection ends when a dataset holds T.
//!
//! Invariants: a state is a function of the generator's seed; the collector's decisions depend
//! only on the trials offered to it, in order.

use super::term::{Literal, IN_HAND};
use crate::base::rng::SplitMix64;

/// The pools of the generator.
#[derive(Clone, Debug, PartialEq)]
pub struct Pools {
    /// The robot constant.
    pub robot: String,
    /// The movable objects.
    pub objects: Vec<String>,
    /// The places (supports), the table included.
    pub places: Vec<String>,
    /// The table constant (a place that holds any number of objects).
    pub table: String,
    /// P(hand not empty) for `pickup`.
    pub p_hold_pickup: f64,
    /// P(hand not empty) for `putdown`.
    pub p_hold_putdown: f64,
}

impl Pools {
    /// The H1 learning scene (docs/domain.md 1.6): eight objects; the four large cubes, the small
    /// can and the table as places.
    pub fn h1() -> Pools {
        let cubes = [
            "green_cube_large",
            "red_cube_large",
            "yellow_cube_large",
            "white_cube_large",
        ];
        let mut objects: Vec<String> = cubes.iter().map(|s| s.to_string()).collect();
        objects.extend(
            ["white_can_small", "blue_ball", "pitcher", "yellow_duck"]
                .iter()
                .map(|s| s.to_string()),
        );
        let mut places: Vec<String> = cubes.iter().map(|s| s.to_string()).collect();
        places.push("white_can_small".into());
        places.push("table".into());
        Pools {
            robot: "rob1".into(),
            objects,
            places,
            table: "table".into(),
            p_hold_pickup: 0.2,
            p_hold_putdown: 0.7,
        }
    }
}

/// The type of a one-step action.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ActionType {
    /// `pickup(R, O)`.
    Pickup,
    /// `putdown(R, O, L)`.
    Putdown,
}

/// A random initial state and the action tried in it.
#[derive(Clone, Debug, PartialEq)]
pub struct OneStep {
    /// `(object, place)` for every `on` fact at step 0.
    pub on: Vec<(String, String)>,
    /// The held object, if any.
    pub held: Option<String>,
    /// The ground action, e.g. `pickup(rob1, red_cube_large)`.
    pub action: Literal,
}

impl OneStep {
    /// The step-0 facts as literals: `relation(on, O, L)` and `in_hand(R, O)`.
    pub fn facts(&self, robot: &str) -> Vec<Literal> {
        let mut out: Vec<Literal> = self
            .on
            .iter()
            .map(|(o, p)| Literal::relation("on", o, p))
            .collect();
        if let Some(h) = &self.held {
            out.push(Literal::ground(IN_HAND, &[robot, h]));
        }
        out
    }
}

/// Draws a state and arguments for an action of type `ty` (5.3).
pub fn generate(pools: &Pools, ty: ActionType, rng: &mut SplitMix64) -> OneStep {
    let mut objects = pools.objects.clone();
    let mut places = pools.places.clone();
    let (action, p_hold) = match ty {
        ActionType::Pickup => {
            let o = rng.pick(&pools.objects).clone();
            (
                Literal::ground("pickup", &[&pools.robot, &o]),
                pools.p_hold_pickup,
            )
        }
        ActionType::Putdown => {
            let (o, p) = loop {
                let o = rng.pick(&pools.objects).clone();
                let p = rng.pick(&pools.places).clone();
                if o != p {
                    break (o, p);
                }
            };
            (
                Literal::ground("putdown", &[&pools.robot, &o, &p]),
                pools.p_hold_putdown,
            )
        }
    };
    let held = if rng.chance(p_hold) {
        let h = rng.pick(&pools.objects).clone();
        objects.retain(|o| *o != h);
        places.retain(|p| *p != h);
        Some(h)
    } else {
        None
    };
    rng.shuffle(&mut objects);
    let mut on = Vec::new();
    for o in objects {
        let choices: Vec<&String> = places.iter().filter(|p| **p != o).collect();
        let place = (*rng.pick(&choices)).clone();
        // A placed object is no longer a place; a non-table place holds one object.
        places.retain(|p| *p != o && (*p != place || *p == pools.table));
        on.push((o, place));
    }
    OneStep { on, held, action }
}

/// The outcome of comparing the learner with the oracle on one trial (docs/domain.md 5.1).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outcome {
    /// Literals observed but not predicted (with `¬f` for inertia-persisted extras).
    pub unexpected: Vec<Literal>,
    /// Literals predicted but not observed.
    pub extra: Vec<Literal>,
    /// The learner predicted a successor state (it took the action to be executable).
    pub learner_executable: bool,
    /// The oracle has a successor state (the action was executable).
    pub oracle_executable: bool,
    /// The oracle could not realise the step-0 state (`States::unrealisable`): no sample.
    pub void: bool,
}

impl Outcome {
    /// True when the trial shows a discrepancy.
    pub fn surprising(&self) -> bool {
        !self.unexpected.is_empty() || !self.extra.is_empty()
    }
}

/// Which dataset a sample went to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Dataset {
    /// Causal laws.
    Cl,
    /// Executability conditions.
    Ec,
}

/// Collection settings.
#[derive(Clone, Debug, PartialEq)]
pub struct CollectConfig {
    /// Dataset size T.
    pub size: usize,
    /// Drop inconsistent trials that no positive case accepts (the code stores them with label
    /// 0, which contradicts their outcome).
    pub balance_fix: bool,
    /// \[ours\] A trial is evidence for a dataset only when the missing axiom could have shown
    /// in it: CL samples only from trials where both sides executed the action (effects are
    /// observable), EC samples only from trials where the learner took the action to be
    /// executable (else a known condition already forbids it). Off replicates the code.
    pub informative_only: bool,
}

impl Default for CollectConfig {
    fn default() -> Self {
        CollectConfig {
            size: 100,
            balance_fix: true,
            informative_only: true,
        }
    }
}

/// The samples of one dataset: (trial index, label).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Samples {
    /// `(trial, label)` in order of arrival.
    pub items: Vec<(usize, bool)>,
}

impl Samples {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// True when empty.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Number of label-1 samples.
    pub fn positives(&self) -> usize {
        self.items.iter().filter(|(_, l)| *l).count()
    }
}

/// The class-balancing collector of 5.4.
#[derive(Clone, Debug, Default)]
pub struct Collector {
    /// Settings.
    pub config: CollectConfig,
    /// The CL dataset.
    pub cl: Samples,
    /// The EC dataset.
    pub ec: Samples,
    /// Trials offered so far that would have been a label-1 sample of (CL, EC) had the
    /// dataset wanted one, wanted or not: the rate at which positives arrive.
    pub positives_seen: [usize; 2],
    /// Likewise for label-0 samples.
    pub negatives_seen: [usize; 2],
    /// Trials offered so far.
    pub offered: usize,
}

impl Collector {
    /// An empty collector.
    pub fn new(config: CollectConfig) -> Collector {
        Collector {
            config,
            ..Collector::default()
        }
    }

    fn cap(&self) -> usize {
        (0.6 * self.config.size as f64).round() as usize
    }

    fn free(&self) -> usize {
        (0.4 * self.config.size as f64).round() as usize
    }

    /// True when a dataset may take a label-0 sample: fewer than 0.4 T samples, or its
    /// positives have reached 0.6 T.
    fn wants_negative(&self, d: &Samples) -> bool {
        d.len() < self.free() || d.positives() >= self.cap()
    }

    /// True when one dataset holds T samples.
    pub fn full(&self) -> Option<Dataset> {
        if self.cl.len() >= self.config.size {
            Some(Dataset::Cl)
        } else if self.ec.len() >= self.config.size {
            Some(Dataset::Ec)
        } else {
            None
        }
    }

    /// How many consecutive trials without a new sample end collection \[ours\]: `base`, or
    /// `factor` times the mean gap (trials offered per would-be sample) of the rarest class a
    /// dataset that is not full still wants (positives below the cap; negatives by
    /// `Self::wants_negative`), whichever is longer; a class seen fewer than twice has no
    /// rate yet and does not count. Why: a sample that arrives once in 50 trials is given up
    /// after 100 quiet trials in 13% of episodes. E2's negatives (an executable putdown of the
    /// held object, ~1.3% of putdown trials before C2 is known) were, in run 16 of seed 0: the
    /// dataset kept 3 negatives, fewer than CART's `min_samples_leaf`, so no tree could split
    /// on `-in_hand(R1, O1)` and 85 of 100 learned `if above(O1, O3)` instead. A class never
    /// seen (CL negatives while every executable putdown surprises, before C2 is known) still
    /// ends collection after `base`. The window never exceeds `max` (a class seen twice in
    /// thousands of trials, as the physics world's rare outcomes are, would otherwise hold an
    /// episode for thousands more).
    pub fn stall_window(&self, base: usize, factor: f64, max: usize) -> usize {
        let cap = self.cap();
        let mut window = base;
        for (i, d) in [&self.cl, &self.ec].into_iter().enumerate() {
            if d.len() >= self.config.size {
                continue;
            }
            let wanted = [
                (d.positives() < cap, self.positives_seen[i]),
                (self.wants_negative(d), self.negatives_seen[i]),
            ];
            for (wants, seen) in wanted {
                if wants && seen >= 2 {
                    let gap = self.offered as f64 / seen as f64;
                    window = window.max((factor * gap).ceil() as usize);
                }
            }
        }
        window.min(max.max(base))
    }

    /// Offers trial `trial` with its outcome; returns the datasets that took a sample.
    pub fn offer(&mut self, trial: usize, outcome: &Outcome) -> Vec<(Dataset, bool)> {
        let mut added = Vec::new();
        if outcome.void {
            return added;
        }
        let informative = self.config.informative_only;
        let cl_ok = !informative || (outcome.learner_executable && outcome.oracle_executable);
        let ec_ok = !informative || outcome.learner_executable;
        self.offered += 1;
        if cl_ok && !outcome.unexpected.is_empty() {
            self.positives_seen[0] += 1;
        } else if cl_ok && !outcome.surprising() {
            self.negatives_seen[0] += 1;
        }
        if ec_ok && !outcome.extra.is_empty() {
            self.positives_seen[1] += 1;
        } else if ec_ok {
            self.negatives_seen[1] += 1;
        }
        let cap = self.cap();
        if !outcome.unexpected.is_empty() && self.cl.positives() < cap && cl_ok {
            // Case 1: a missing causal law; the action was executable, so EC gets a label 0.
            self.cl.items.push((trial, true));
            added.push((Dataset::Cl, true));
            if ec_ok && self.wants_negative(&self.ec) {
                self.ec.items.push((trial, false));
                added.push((Dataset::Ec, false));
            }
        } else if !outcome.extra.is_empty() && self.ec.positives() < cap && ec_ok {
            // Case 2: a missing executability condition.
            self.ec.items.push((trial, true));
            added.push((Dataset::Ec, true));
        } else if outcome.surprising() && self.config.balance_fix {
            // An inconsistent trial that no positive case took: the code stores it with label
            // 0 below; with the fix it is dropped, except that a causal-law surprise is a true
            // negative for EC (the action was executable).
            if !outcome.unexpected.is_empty() && ec_ok && self.wants_negative(&self.ec) {
                self.ec.items.push((trial, false));
                added.push((Dataset::Ec, false));
            }
        } else {
            // Case 3: a consistent trial (or, without the fix, any other).
            if cl_ok && self.wants_negative(&self.cl) {
                self.cl.items.push((trial, false));
                added.push((Dataset::Cl, false));
            }
            if ec_ok && self.wants_negative(&self.ec) {
                self.ec.items.push((trial, false));
                added.push((Dataset::Ec, false));
            }
        }
        added
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Follows `on` down from an object; a cycle would loop forever, so the depth is bounded.
    fn depth(state: &OneStep, o: &str) -> usize {
        let mut d = 0;
        let mut cur = o.to_string();
        while let Some((_, p)) = state.on.iter().find(|(x, _)| *x == cur) {
            d += 1;
            assert!(d <= 10, "cycle through {o}");
            cur = p.clone();
        }
        d
    }

    #[test]
    fn generated_states_are_well_formed() {
        let pools = Pools::h1();
        let mut rng = SplitMix64::new(9);
        let (mut held_pickup, mut held_putdown, mut tall) = (0, 0, 0);
        for i in 0..4000 {
            let ty = if i % 2 == 0 {
                ActionType::Pickup
            } else {
                ActionType::Putdown
            };
            let s = generate(&pools, ty, &mut rng);
            // Every object but the held one is on exactly one place; the held one on nothing.
            for o in &pools.objects {
                let n = s.on.iter().filter(|(x, _)| x == o).count();
                assert_eq!(n, usize::from(s.held.as_ref() != Some(o)));
            }
            // Every non-table support holds at most one object; only places support.
            for p in &pools.places {
                if *p != pools.table {
                    assert!(s.on.iter().filter(|(_, x)| x == p).count() <= 1);
                }
            }
            assert!(s.on.iter().all(|(o, p)| o != p && pools.places.contains(p)));
            // Every object reaches the table (no cycles).
            for (o, _) in &s.on {
                let d = depth(&s, o);
                tall += usize::from(d >= 3);
                let mut cur = o.clone();
                for _ in 0..d {
                    cur = s.on.iter().find(|(x, _)| *x == cur).unwrap().1.clone();
                }
                assert_eq!(cur, pools.table);
            }
            if s.held.is_some() {
                if ty == ActionType::Pickup {
                    held_pickup += 1;
                } else {
                    held_putdown += 1;
                }
            }
            if ty == ActionType::Putdown {
                assert_ne!(s.action.args[1], s.action.args[2]);
            }
        }
        // P(hand not empty): 0.2 and 0.7 over 2000 trials each.
        assert!((300..500).contains(&held_pickup), "{held_pickup}");
        assert!((1300..1500).contains(&held_putdown), "{held_putdown}");
        assert!(tall > 0, "stacks of three arise");
        // Same seed, same state.
        let a = generate(&pools, ActionType::Putdown, &mut SplitMix64::new(4));
        let b = generate(&pools, ActionType::Putdown, &mut SplitMix64::new(4));
        assert_eq!(a, b);
    }

    fn outcome(unexpected: bool, extra: bool, learner: bool, oracle: bool) -> Outcome {
        let l = Literal::ground("x", &[]);
        Outcome {
            unexpected: if unexpected { vec![l.clone()] } else { vec![] },
            extra: if extra { vec![l] } else { vec![] },
            learner_executable: learner,
            oracle_executable: oracle,
            void: false,
        }
    }

    /// A void trial (the world could not realise the state) gives no sample, in either mode.
    #[test]
    fn a_void_trial_gives_no_sample() {
        for informative_only in [true, false] {
            let mut c = Collector::new(CollectConfig {
                informative_only,
                ..CollectConfig::default()
            });
            let void = Outcome {
                void: true,
                ..outcome(false, false, true, true)
            };
            assert!(c.offer(0, &void).is_empty());
            assert!(c.cl.is_empty() && c.ec.is_empty());
            assert!(!c.offer(1, &outcome(false, false, true, true)).is_empty());
        }
    }

    /// The balance rules with T = 10 (cap 6 positives, 4 free samples), in the code's
    /// semantics (`informative_only` off) with and without `balance_fix`.
    #[test]
    fn class_balance_by_hand() {
        for fix in [false, true] {
            let mut c = Collector::new(CollectConfig {
                size: 10,
                balance_fix: fix,
                informative_only: false,
            });
            // Six causal-law surprises: CL 6 positives; EC takes label 0 while it has < 4.
            for t in 0..6 {
                c.offer(t, &outcome(true, false, true, true));
            }
            assert_eq!((c.cl.len(), c.cl.positives()), (6, 6));
            assert_eq!((c.ec.len(), c.ec.positives()), (4, 0));
            // A seventh: CL's positives are capped. The code stores it as a CL label 0 (and
            // EC wants no negative: 4 samples, 0 positives); the fix drops it.
            let added = c.offer(6, &outcome(true, false, true, true));
            if fix {
                assert_eq!(added, vec![]);
                assert_eq!(c.cl.len(), 6);
            } else {
                assert_eq!(added, vec![(Dataset::Cl, false)]);
                assert_eq!(c.cl.len(), 7);
            }
            // An executability surprise: EC label 1.
            assert_eq!(
                c.offer(7, &outcome(false, true, true, false)),
                vec![(Dataset::Ec, true)]
            );
            // A consistent trial: CL wants negatives (positives at the cap), EC does not.
            assert_eq!(
                c.offer(8, &outcome(false, false, true, true)),
                vec![(Dataset::Cl, false)]
            );
            assert_eq!(c.full(), None);
        }
    }

    /// With `informative_only`, trials where the action never ran give no CL sample, and
    /// trials the learner already forbade give no EC sample.
    #[test]
    fn informative_only_filters() {
        let mut c = Collector::new(CollectConfig {
            size: 10,
            ..CollectConfig::default()
        });
        // Both sides forbid the action: consistent, but neither dataset learns from it.
        assert_eq!(c.offer(0, &outcome(false, false, false, false)), vec![]);
        // The oracle forbids it, the learner does not: EC label 1.
        assert_eq!(
            c.offer(1, &outcome(false, true, true, false)),
            vec![(Dataset::Ec, true)]
        );
        // Executed on both sides and consistent: a negative for both.
        assert_eq!(
            c.offer(2, &outcome(false, false, true, true)),
            vec![(Dataset::Cl, false), (Dataset::Ec, false)]
        );
    }

    /// The stall window with T = 10 (cap 6), by hand. EC takes 6 positives (6 offered, 6
    /// positives seen: 5 * 6 / 6 = 5 < 100); 44 trials the learner forbids (nothing seen);
    /// 2 consistent trials, negatives for both (EC takes them: 8 samples, 6 positive). EC
    /// wants negatives (positives at the cap), seen 2 in 52: 5 * 52 / 2 = 130. CL wants
    /// positives too but has seen none, and negatives, seen 2: also 130.
    #[test]
    fn the_stall_window_follows_the_rarest_wanted_class() {
        let config = CollectConfig {
            size: 10,
            ..CollectConfig::default()
        };
        let mut c = Collector::new(config.clone());
        for t in 0..6 {
            c.offer(t, &outcome(false, true, true, false));
        }
        assert_eq!(c.stall_window(100, 5.0, 500), 100);
        for t in 6..50 {
            c.offer(t, &outcome(false, false, false, false));
        }
        assert_eq!(c.offer(50, &outcome(false, false, true, true)).len(), 2);
        c.offer(51, &outcome(false, false, true, true));
        assert_eq!(c.offered, 52);
        assert_eq!((c.positives_seen, c.negatives_seen), ([0, 6], [2, 2]));
        assert_eq!((c.ec.len(), c.ec.positives()), (8, 6));
        assert_eq!(c.stall_window(100, 5.0, 500), 130);
        assert_eq!(c.stall_window(200, 5.0, 500), 200);
        // A causal-law dataset capped without a negative ever seen keeps the base window (EC
        // has 4 samples and no positive: it wants none of the negatives it sees, 0 < 4 free
        // is false once it holds 4).
        let mut d = Collector::new(config.clone());
        for t in 0..60 {
            d.offer(t, &outcome(true, false, true, true));
        }
        assert_eq!((d.positives_seen, d.negatives_seen), ([60, 0], [0, 60]));
        assert_eq!((d.cl.positives(), d.ec.len()), (6, 4));
        assert_eq!(d.stall_window(100, 5.0, 500), 100);
        // Rare positives: 2 causal-law surprises in 80 trials (the rest consistent). CL has
        // 2 positives (< 6) and 3 negatives: it wants positives, seen 2 in 80: 5 * 40 = 200.
        let mut e = Collector::new(config);
        for t in 0..80 {
            e.offer(t, &outcome(t % 40 == 0, false, true, true));
        }
        assert_eq!((e.cl.len(), e.cl.positives()), (5, 2));
        assert_eq!(e.stall_window(100, 5.0, 500), 200);
        assert_eq!(e.stall_window(100, 5.0, 150), 150, "at most max");
    }
}

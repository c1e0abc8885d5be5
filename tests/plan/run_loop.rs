//! The sense-plan-act loop (`lucent::plan::act`) against a scripted world double (no physics,
//! so it runs without the `sim` feature): a three-block table whose perception and actions are
//! scripted per test. Checks that a clean run follows its first plan, that a failed action is a
//! discrepancy followed by a replan from the observed state, that contradictory readings are
//! doubted (the less confident one) instead of leaving the robot without an answer set, that a
//! budget ends a run with its reason, that a plan blocked by a misreading makes the robot look
//! again instead of giving up, that an action the current belief makes not executable is replanned
//! instead of executed, that a look contradicting the expectation is confirmed by more looks (a
//! single misreading outvoted, a repeated one believed), that a putdown after which the next
//! action was blocked is not repeated, and that a recorded discrepancy is what the learner's
//! surprise classification (docs/domain.md 5.1) consumes.

use std::collections::{BTreeMap, BTreeSet};

use lucent::control::Symbol;
use lucent::learn::surprise::classify;
use lucent::learn::term::Literal;
use lucent::plan::act::{run, Event, Percept, RunConfig, Seen, World};
use lucent::plan::history::{Ending, History};

use crate::support::plan as plan_support;

use plan_support::domain;

fn sym(text: &str) -> Symbol {
    Symbol::parse(text).unwrap()
}

/// A table with blocks: `on[x]` is x's support; one hand.
struct Blocks {
    on: BTreeMap<String, String>,
    held: Option<String>,
    /// Actions (by their index among executed actions) that slip: the world does nothing.
    slips: BTreeSet<usize>,
    executed: usize,
    /// Extra readings of the first perception of step 0: (fluent, confidence).
    phantom: Vec<(String, f64)>,
    /// Extra readings of one look: (actions executed before it, look, fluent, confidence).
    misread: Vec<(usize, u32, String, f64)>,
    /// Occlusion the domain does not predict: (o, l, x) means that while `o` rests on `l`
    /// every look sees `x` behind `o`.
    hides: Vec<(String, String, String)>,
    looks: usize,
}

impl Blocks {
    fn new(on: &[(&str, &str)]) -> Blocks {
        Blocks {
            on: on
                .iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect(),
            held: None,
            slips: BTreeSet::new(),
            executed: 0,
            phantom: Vec::new(),
            misread: Vec::new(),
            hides: Vec::new(),
            looks: 0,
        }
    }
}

impl World for Blocks {
    fn objects(&self) -> Vec<String> {
        let mut o: Vec<String> = self.on.keys().cloned().collect();
        o.extend(self.held.clone());
        o.sort();
        o
    }

    fn perceive(&mut self, look: u32) -> Percept {
        let mut p = Percept::default();
        for o in self.objects() {
            p.statics.push(sym(&format!("has_size({o},large)")));
            p.statics.push(sym(&format!("has_surface({o},flat)")));
            p.fluents.push(Seen {
                fluent: sym(&format!("in_hand(rob1,{o})")),
                value: self.held.as_deref() == Some(o.as_str()),
                confidence: 1.0,
                exact: true,
            });
        }
        for (a, b) in &self.on {
            p.fluents.push(Seen {
                fluent: sym(&format!("relation(on,{a},{b})")),
                value: true,
                confidence: 0.9,
                exact: false,
            });
        }
        if self.looks == 0 {
            for (f, c) in &self.phantom {
                p.fluents.push(Seen {
                    fluent: sym(f),
                    value: true,
                    confidence: *c,
                    exact: false,
                });
            }
        }
        for (o, l, x) in &self.hides {
            if self.on.get(o) == Some(l) {
                p.fluents.push(Seen {
                    fluent: sym(&format!("relation(behind,{x},{o})")),
                    value: true,
                    confidence: 0.9,
                    exact: false,
                });
            }
        }
        for (n, l, f, c) in &self.misread {
            if *n == self.executed && *l == look {
                p.fluents.push(Seen {
                    fluent: sym(f),
                    value: true,
                    confidence: *c,
                    exact: false,
                });
            }
        }
        self.looks += 1;
        p
    }

    fn execute(&mut self, action: &Symbol) -> Result<Option<String>, String> {
        let n = self.executed;
        self.executed += 1;
        let args: Vec<String> = action.args().iter().map(|a| a.to_string()).collect();
        if self.slips.contains(&n) {
            return Ok(Some("the grasp slipped".into()));
        }
        if action.is("pickup", 2) {
            let o = &args[1];
            if self.held.is_some() || self.on.values().any(|s| s == o) {
                return Ok(Some("blocked".into()));
            }
            self.on.remove(o);
            self.held = Some(o.clone());
        } else if action.is("putdown", 3) {
            if self.held.as_deref() != Some(args[1].as_str()) {
                return Ok(Some("not held".into()));
            }
            self.held = None;
            self.on.insert(args[1].clone(), args[2].clone());
        } else {
            return Err(format!("unknown action {action}"));
        }
        Ok(None)
    }

    fn holds_in_truth(&mut self, literal: &Symbol) -> Option<bool> {
        let args: Vec<String> = literal.args().iter().map(|a| a.to_string()).collect();
        if literal.is("relation", 3) && args[0] == "on" {
            return Some(self.on.get(&args[1]) == Some(&args[2]));
        }
        if literal.is("in_hand", 2) {
            return Some(self.held.as_deref() == Some(args[1].as_str()));
        }
        None
    }
}

fn go(world: &mut Blocks, goal: &str, config: &RunConfig) -> (History, Vec<String>) {
    let mut events = Vec::new();
    let h = run(&domain(), world, &[sym(goal)], "blocks", config, &mut |e| {
        events.push(match e {
            Event::Perceived { step, look, .. } => format!("perceived {step}/{look}"),
            Event::Planned(p) => format!("planned {}", p.actions.join(";")),
            Event::Acted { action, .. } => format!("acted {action}"),
            Event::Discrepancy(d) => format!("discrepancy {}", d.step),
        })
    });
    (h, events)
}

#[test]
fn a_clean_run_follows_its_first_plan_and_confirms_the_goal() {
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    let (h, events) = go(&mut w, "relation(on,a,c)", &RunConfig::default());
    assert_eq!(h.ending, Some(Ending::GoalObserved), "{events:?}");
    assert_eq!(h.goal_in_truth, Some(true));
    assert!(h.succeeded());
    assert_eq!(h.plans.len(), 1);
    assert!(h.discrepancies.is_empty());
    assert_eq!(h.plans[0].actions.len(), 4);
    assert_eq!(h.actions(), h.plans[0].actions);
    assert_eq!(h.steps.len(), 5);
    // The goal was seen twice at the last step: the first look and the confirming one.
    assert_eq!(h.steps[4].looks, 2);
    assert!(h.steps[4].belief.contains(&"relation(on,a,c)".to_string()));
    let back = History::from_json(&h.to_json()).unwrap();
    assert_eq!(back, h);
    assert!(h.to_ald().contains("happened pickup(rob1,b) at 0."));
}

#[test]
fn a_failed_action_is_a_discrepancy_and_the_robot_replans_from_what_it_sees() {
    let mut w = Blocks::new(&[("a", "table"), ("b", "table")]);
    w.slips.insert(0);
    let (h, events) = go(&mut w, "relation(on,a,b)", &RunConfig::default());
    assert!(h.succeeded(), "{events:?}");
    assert_eq!(h.discrepancies.len(), 1);
    let d = &h.discrepancies[0];
    assert_eq!(d.step, 0);
    assert_eq!(d.action, "pickup(rob1,a)");
    assert_eq!(d.failure.as_deref(), Some("the grasp slipped"));
    assert_eq!(d.extra, vec!["in_hand(rob1,a)".to_string()]);
    assert_eq!(h.plans.len(), 2);
    assert_eq!(h.plans[1].step, 1);
    assert_eq!(h.plans[1].reason, "discrepancy at step 0");
    assert_eq!(
        h.actions(),
        vec!["pickup(rob1,a)", "pickup(rob1,a)", "putdown(rob1,a,b)"]
    );

    // The learner's classification consumes the discrepancy as it is: the hand was predicted
    // full and observed empty, a literal predicted but not observed (docs/domain.md 5.1).
    let lit = |t: &str| {
        let s = sym(t);
        let a: Vec<String> = s.args().iter().map(|a| a.to_string()).collect();
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        Literal::ground(s.name().unwrap(), &a)
    };
    let before: Vec<Literal> = d.before.iter().map(|t| lit(t)).collect();
    let predicted: Vec<Literal> = d
        .predicted
        .as_ref()
        .unwrap()
        .iter()
        .map(|t| lit(t))
        .collect();
    let observed: Vec<Literal> = d.observed.iter().map(|t| lit(t)).collect();
    let outcome = classify(&before, Some(&predicted), Some(&observed));
    assert!(outcome.surprising());
    assert!(outcome.extra.contains(&lit("in_hand(rob1,a)")));
}

#[test]
fn contradictory_readings_are_doubted_not_fatal() {
    // The camera also reports `a` on `b` and `b` on `a` with little confidence: an object rests
    // on one thing at most, and two objects never rest on each other.
    let mut w = Blocks::new(&[("a", "table"), ("b", "table"), ("c", "table")]);
    w.phantom = vec![
        ("relation(on,a,b)".into(), 0.55),
        ("relation(on,b,a)".into(), 0.6),
    ];
    let (h, events) = go(&mut w, "relation(on,c,a)", &RunConfig::default());
    assert!(h.succeeded(), "{events:?}");
    let mut doubted = h.steps[0].doubted.clone();
    doubted.sort();
    assert_eq!(
        doubted,
        vec![
            "relation(on,a,b)".to_string(),
            "relation(on,b,a)".to_string()
        ]
    );
    assert!(h.steps[0]
        .belief
        .contains(&"relation(on,a,table)".to_string()));
    assert_eq!(h.actions(), vec!["pickup(rob1,c)", "putdown(rob1,c,a)"]);
}

#[test]
fn the_less_confident_of_two_readings_is_the_one_doubted() {
    // `c` is seen on the table (0.9) and on `a` (0.95): one must go, and it is the table.
    let mut w = Blocks::new(&[("a", "table"), ("b", "table"), ("c", "table")]);
    w.phantom = vec![("relation(on,c,a)".into(), 0.95)];
    let config = RunConfig {
        max_actions: 0,
        ..RunConfig::default()
    };
    let (h, _) = go(&mut w, "relation(on,a,b)", &config);
    assert_eq!(h.steps[0].doubted, vec!["relation(on,c,table)".to_string()]);
    assert_eq!(h.ending, Some(Ending::ActionBudget));
    assert!(!h.succeeded());
}

#[test]
fn budgets_end_a_run_with_their_reason() {
    let mut w = Blocks::new(&[("a", "table"), ("b", "table")]);
    w.slips = (0..10).collect();
    let config = RunConfig {
        max_plans: 3,
        ..RunConfig::default()
    };
    let (h, _) = go(&mut w, "in_hand(rob1,a)", &config);
    assert_eq!(h.ending, Some(Ending::ReplanBudget));
    assert_eq!(h.plans.len(), 3);
    assert_eq!(h.discrepancies.len(), 3);
    assert_eq!(h.goal_in_truth, Some(false));
    assert!(!h.succeeded());
}

#[test]
fn no_plan_from_a_misreading_makes_the_robot_look_again() {
    // `b` rests on `a`. The first look also sees `c` behind `a` and `b` behind `c`: E8 forbids
    // picking up an object behind another and E7 one below another, so `c` waits for `a`, `a`
    // for `b` and `b` for `c`: no action is executable and no plan exists. The second look
    // (a fresh perception) does not repeat the misreadings.
    let misread = |w: &mut Blocks| {
        for (x, y) in [("c", "a"), ("b", "c")] {
            w.misread
                .push((0, 0, format!("relation(behind,{x},{y})"), 0.9));
        }
    };
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    misread(&mut w);
    let mut config = RunConfig::default();
    config.plan.max_horizon = 4;
    let (h, events) = go(&mut w, "in_hand(rob1,c)", &config);
    assert!(h.succeeded(), "{events:?}");
    assert!(h.steps[0]
        .observed
        .iter()
        .any(|o| o.fluent == "relation(behind,c,a)"));
    assert_eq!(h.steps[0].looks, 2, "{events:?}");
    assert_eq!(h.plans.len(), 1);
    assert_eq!(
        h.plans[0].reason,
        "no plan of at most 4 steps at step 0, looked again"
    );
    assert_eq!(h.actions(), vec!["pickup(rob1,c)"]);

    // Without looking again the run ends where it began.
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    misread(&mut w);
    config.relooks = 0;
    let (h, events) = go(&mut w, "in_hand(rob1,c)", &config);
    assert_eq!(h.ending, Some(Ending::NoPlan { horizon: 4 }), "{events:?}");
    assert!(h.plans.is_empty());
}

#[test]
fn an_action_the_belief_makes_not_executable_is_replanned_not_executed() {
    // Plan: pickup b, putdown b on the table, pickup a, putdown a on c. After the second action
    // the robot sees `a` behind `c` in every look: E8 makes `pickup(rob1,a)` not executable in
    // its belief, while the compared fluents (`on`, `in_hand`) match the prediction, so there is
    // no discrepancy. The robot looks twice more, the majority agrees, and it replans before
    // acting: `c` must be lifted first.
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    for look in 0..3 {
        w.misread
            .push((2, look, "relation(behind,a,c)".into(), 0.9));
    }
    let (h, events) = go(&mut w, "relation(on,a,c)", &RunConfig::default());
    assert!(h.succeeded(), "{events:?}");
    assert_eq!(h.plans.len(), 2, "{events:?}");
    assert_eq!(h.plans[1].step, 2);
    assert_eq!(
        h.plans[1].reason,
        "pickup(rob1,a) not executable in the belief at step 2"
    );
    assert_eq!(h.plans[1].actions[0], "pickup(rob1,c)");
    // The action was never tried against the belief: no discrepancy, and step 2's action is
    // the new plan's first.
    assert!(h.discrepancies.is_empty(), "{:?}", h.discrepancies);
    assert_eq!(h.steps[2].happened.as_deref(), Some("pickup(rob1,c)"));
    assert_eq!(h.steps[2].looks, 3, "{events:?}");
}

#[test]
fn one_misreading_against_the_plan_is_outvoted_by_looking_again() {
    // As above, but only the first look after the second action sees `a` behind `c`: the two
    // confirming looks do not, so the robot keeps its plan. Without confirming looks the same
    // misreading costs a replan and two more actions.
    let misread = |w: &mut Blocks| w.misread.push((2, 0, "relation(behind,a,c)".into(), 0.9));
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    misread(&mut w);
    let (h, events) = go(&mut w, "relation(on,a,c)", &RunConfig::default());
    assert!(h.succeeded(), "{events:?}");
    assert_eq!(h.plans.len(), 1, "{events:?}");
    assert_eq!(h.actions().len(), 4);
    assert_eq!(h.steps[2].looks, 3);
    assert!(h.steps[2]
        .observed
        .iter()
        .any(|o| o.fluent == "relation(behind,a,c)"));
    assert!(!h.steps[2]
        .belief
        .contains(&"relation(behind,a,c)".to_string()));

    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    misread(&mut w);
    let config = RunConfig {
        confirm_looks: 0,
        ..RunConfig::default()
    };
    let (h, events) = go(&mut w, "relation(on,a,c)", &config);
    assert!(h.succeeded(), "{events:?}");
    assert_eq!(h.plans.len(), 2, "{events:?}");
    assert_eq!(h.actions().len(), 6);
}

#[test]
fn a_surprise_seen_once_is_no_discrepancy() {
    // After the first action (pickup b) one look also sees `c` on `a`, which nothing predicted:
    // the two confirming looks do not, so no discrepancy is recorded and the plan goes on.
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    w.misread.push((1, 0, "relation(on,c,a)".into(), 0.95));
    let (h, events) = go(&mut w, "relation(on,a,c)", &RunConfig::default());
    assert!(h.succeeded(), "{events:?}");
    assert!(h.discrepancies.is_empty(), "{:?}", h.discrepancies);
    assert_eq!(h.plans.len(), 1);
    assert_eq!(h.steps[1].looks, 3);

    // Seen in every look, it is believed: a discrepancy, and a replan from it.
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    for look in 0..3 {
        w.misread.push((1, look, "relation(on,c,a)".into(), 0.95));
    }
    let (h, events) = go(&mut w, "relation(on,a,c)", &RunConfig::default());
    assert!(!h.discrepancies.is_empty(), "{events:?}");
    assert_eq!(h.discrepancies[0].step, 0);
    assert_eq!(
        h.discrepancies[0].unexpected,
        vec!["relation(on,c,a)".to_string()]
    );
    assert_eq!(h.plans[1].reason, "discrepancy at step 0");
}

#[test]
fn a_putdown_that_hid_the_next_object_is_not_repeated() {
    // `b` rests on `a`; put down on `c`, `b` hides `a` from the camera (the domain does not
    // predict it, and E8 then forbids picking `a` up). The first minimal plan puts `b` on `c`;
    // after it the pickup of `a` is not executable, and every minimal plan from there moves `b`
    // again, the first of them onto `c` again. The robot prefers one that does not repeat the
    // putdown that hid `a`, and puts `b` on the table.
    let mut w = Blocks::new(&[("a", "table"), ("b", "a"), ("c", "table")]);
    w.hides.push(("b".into(), "c".into(), "a".into()));
    let mut config = RunConfig::default();
    config.plan.max_horizon = 4;
    let (h, events) = go(&mut w, "in_hand(rob1,a)", &config);
    assert!(h.succeeded(), "{events:?}");
    assert_eq!(h.plans[0].actions[1], "putdown(rob1,b,c)", "{events:?}");
    assert_eq!(
        h.plans[1].reason,
        "pickup(rob1,a) not executable in the belief at step 2"
    );
    assert!(h.plans[1].alternatives > 1, "{:?}", h.plans[1]);
    assert_eq!(h.plans[1].actions[1], "putdown(rob1,b,table)", "{events:?}");
    assert_eq!(h.plans.len(), 2);
}

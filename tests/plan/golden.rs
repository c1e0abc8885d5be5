//! The golden tests of docs/domain.md 4.5 through the planner (`lucent::plan`), on the scenes of
//! `domains/ra/scenes` under KB_full: the iterative horizon finds the minimal length itself.
//!
//! - tabletop task: length 3 and exactly the four plans (the pitcher to the table or to the
//!   green, yellow or white large cube, then the red cube picked up);
//! - execution example: length 6, the paper's plan among the minimal plans;
//! - exception goal: every minimal plan applies D1's exception exactly once, at the goal step;
//! - a too-small horizon budget is `no_plan_within(H)`;
//! - the incremental search (one step part per horizon) gives the same plans as translating
//!   and grounding every horizon afresh; the first-plan mode returns one of the minimal plans;
//! - the fixed horizon (the authors' mode) returns plans of several lengths, the minimal ones
//!   among them.

use crate::support::plan as plan_support;

use lucent::plan::{plan, PlanConfig, PlanError, Plans, Search};
use plan_support::load;

fn run(scene: &str, max_horizon: usize) -> Result<Plans, PlanError> {
    run_with(scene, max_horizon, Search::Incremental, true)
}

fn run_with(
    scene: &str,
    max_horizon: usize,
    search: Search,
    all: bool,
) -> Result<Plans, PlanError> {
    let (desc, sources) = load(scene);
    let config = PlanConfig {
        max_horizon,
        search,
        all,
        ..PlanConfig::default()
    };
    plan(&desc, &sources, &config)
}

fn texts(p: &Plans) -> Vec<String> {
    p.plans.iter().map(|p| p.to_text()).collect()
}

#[test]
fn incremental_and_retranslated_searches_find_the_same_plans() {
    for (scene, h) in [
        ("tabletop_task.ald", 4),
        ("exception_goal.ald", 3),
        ("execution_example.ald", 6),
    ] {
        let inc = run_with(scene, h, Search::Incremental, true).unwrap();
        let re = run_with(scene, h, Search::Retranslate, true).unwrap();
        assert_eq!(texts(&inc), texts(&re), "{scene}");
        assert_eq!(
            (inc.length, inc.cr_applied),
            (re.length, re.cr_applied),
            "{scene}"
        );
        let first = run_with(scene, h, Search::Incremental, false).unwrap();
        assert_eq!(first.plans.len(), 1, "{scene}");
        assert_eq!(first.length, inc.length, "{scene}");
        assert_eq!(first.cr_applied, inc.cr_applied, "{scene}");
        assert!(texts(&inc).contains(&first.plans[0].to_text()), "{scene}");
    }
}

#[test]
fn fixed_horizon_returns_longer_plans_too() {
    // Holding a takes an odd number of steps: 3, or 5 with a detour.
    const BLOCKS: &str = "tests/data/plan/three_blocks.ald";
    let fixed = run_with(BLOCKS, 5, Search::Fixed(5), true).unwrap();
    let minimal = run(BLOCKS, 5).unwrap();
    assert_eq!(fixed.length, 3);
    assert!(
        fixed.plans.len() > minimal.plans.len(),
        "{:#?}",
        texts(&fixed)
    );
    assert!(fixed.plans.iter().any(|p| p.actions.len() == 5));
    assert!(fixed.plans.iter().all(|p| p.actions.len() % 2 == 1));
    let shortest: Vec<String> = fixed
        .plans
        .iter()
        .filter(|p| p.actions.len() == 3)
        .map(|p| p.to_text())
        .collect();
    assert_eq!(shortest, texts(&minimal));
    assert!(fixed.answer_sets >= fixed.plans.len());
    assert_eq!(
        run_with(BLOCKS, 4, Search::Fixed(2), true).unwrap_err(),
        PlanError::NoPlanWithin(2)
    );
}

#[test]
fn tabletop_task_has_length_3_and_exactly_four_plans() {
    let found = run("tabletop_task.ald", 4).unwrap();
    assert_eq!(found.length, 3);
    assert_eq!(found.cr_applied, 0);
    let texts: Vec<String> = found.plans.iter().map(|p| p.to_text()).collect();
    let expected: Vec<String> = [
        "green_cube_large",
        "table",
        "white_cube_large",
        "yellow_cube_large",
    ]
    .iter()
    .map(|l| {
        format!(
            "pickup(rob1,pitcher)@0; putdown(rob1,pitcher,{l})@1; pickup(rob1,red_cube_large)@2"
        )
    })
    .collect();
    assert_eq!(texts, expected);
}

#[test]
fn tabletop_task_within_two_steps_is_no_plan() {
    assert_eq!(
        run("tabletop_task.ald", 2).unwrap_err(),
        PlanError::NoPlanWithin(2)
    );
}

#[test]
fn execution_example_has_length_6_with_the_papers_plan() {
    let found = run("execution_example.ald", 6).unwrap();
    assert_eq!(found.length, 6);
    let paper = "pickup(rob1,green_can)@0; putdown(rob1,green_can,table)@1; \
                 pickup(rob1,white_block)@2; putdown(rob1,white_block,green_can)@3; \
                 pickup(rob1,pitcher)@4; putdown(rob1,pitcher,red_block)@5";
    let texts: Vec<String> = found.plans.iter().map(|p| p.to_text()).collect();
    assert!(texts.iter().any(|t| t == paper), "{texts:#?}");
    for p in &found.plans {
        assert_eq!(p.actions.len(), 6);
    }
}

#[test]
fn exception_goal_applies_d1_once_at_the_goal_step() {
    let found = run("exception_goal.ald", 3).unwrap();
    assert_eq!(found.length, 2);
    assert_eq!(found.cr_applied, 1);
    assert!(!found.plans.is_empty());
    for p in &found.plans {
        assert_eq!(p.actions.len(), 2);
        let placed = p.actions[0].args()[1].to_string();
        assert!(
            p.actions[1].to_string().ends_with(",white_can_small)"),
            "{}",
            p.to_text()
        );
        assert_eq!(p.cr_applied.len(), 1);
        assert_eq!(p.cr_applied[0].to_string(), format!("d1x({placed},2)"));
    }
}

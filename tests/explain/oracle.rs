//! The adapter from a real Control to proof trees (`explain::oracle`, `explain::history`), on
//! KB_full (`domains/ra`): the paper's execution example after its six actions, and the tabletop
//! task after one of its plans. Every proof tree built over the real ground program and answer
//! set passes `tree::recheck`; the paper's questions get the paper's answers and literals.

use lucent::control::Symbol;
use lucent::explain::build::{BuildConfig, Builder};
use lucent::explain::english::Parser;
use lucent::explain::history::{explain_history, parse_actions, HistoryConfig};
use lucent::explain::lexicon::Lexicon;
use lucent::explain::questions::{answer, Mode, Session};
use lucent::explain::tree::{recheck, Kind, Oracle};

use crate::support::ra_scenes;

use ra_scenes::load_scene as load;

const PAPER_PLAN: &str = "pickup(rob1,green_can); putdown(rob1,green_can,table); \
    pickup(rob1,white_block); putdown(rob1,white_block,green_can); pickup(rob1,pitcher); \
    putdown(rob1,pitcher,red_block)";

fn paper() -> lucent::explain::history::History {
    let (desc, mut sources) = load("execution_example.ald");
    let actions: Vec<Symbol> = parse_actions(PAPER_PLAN).unwrap();
    explain_history(&desc, &mut sources, &actions, &HistoryConfig::default()).unwrap()
}

fn t(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

#[test]
fn every_true_fluent_and_action_literal_has_a_rechecked_tree() {
    let h = paper();
    let o = &h.oracle;
    let mut checked = 0;
    let mut with_path = 0;
    for lit in o.true_literals() {
        if !matches!(lit.name(), Some("holds" | "occurs")) {
            continue;
        }
        let tree = Builder::new(o, BuildConfig::default()).build(&lit);
        recheck(&tree, o).unwrap_or_else(|e| panic!("{lit}: {e}"));
        assert!(!tree.roots.is_empty(), "{lit} has no support");
        if !tree.path.is_empty() {
            with_path += 1;
        }
        checked += 1;
    }
    assert!(checked > 200, "{checked} literals");
    assert_eq!(with_path, checked);
}

#[test]
fn grounding_removed_facts_are_put_back() {
    let h = paper();
    let o = &h.oracle;
    // E10 for the mug at step 3: every body literal is a fact, so grounding made the head a
    // fact; the adapter puts the body back.
    let head = t("-occurs(putdown(rob1,white_block,mug),3)");
    assert!(o.holds(&head));
    let rules = o.rules_for(&head);
    let e10 = rules
        .iter()
        .find(|r| r.label == "E10")
        .expect("E10 instance");
    let body = e10.to_string();
    assert!(body.contains("has_surface(mug,irregular)"), "{body}");
    let tree = Builder::new(o, BuildConfig::default()).build(&head);
    recheck(&tree, o).unwrap();
    let root = tree.node(tree.roots[0]);
    assert!(
        matches!(&root.kind, Kind::Axiom { label, .. } if label == "E10"),
        "{:?}",
        root.kind
    );
}

#[test]
fn false_literals_are_explained_and_rechecked() {
    let h = paper();
    let o = &h.oracle;
    for lit in [
        "occurs(pickup(rob1,white_block),0)",
        "holds(relation(on,white_block,mug),3)",
        "holds(in_hand(rob1,mug),2)",
        "holds(stable(green_can),1)",
    ] {
        let lit = t(lit);
        assert!(!o.holds(&lit), "{lit}");
        let tree = Builder::new(o, BuildConfig::default()).build(&lit);
        recheck(&tree, o).unwrap_or_else(|e| panic!("{lit}: {e}"));
    }
}

#[test]
fn the_papers_questions_over_the_real_program() {
    let h = paper();
    let scn = h.scenario();
    let lexicon = Lexicon::ra();
    let objects = h.objects();
    let names: Vec<&str> = objects.iter().map(String::as_str).collect();
    let parser = Parser::new(&lexicon, &names);
    let mut session = Session::default();
    let mut ask = |q: &str, mode: Mode| {
        let question = parser.parse(q).unwrap_or_else(|e| panic!("{q}: {e:?}"));
        let a = answer(&scn, &lexicon, &question, mode, &mut session).unwrap();
        if let Some(tree) = &a.tree {
            recheck(tree, scn.oracle).unwrap();
        }
        let lits: Vec<String> = a.literals.iter().map(Symbol::to_string).collect();
        (a.text, lits)
    };
    let (text, lits) = ask("Please describe the plan.", Mode::Concise);
    assert!(text.starts_with("I picked up the green can."), "{text}");
    assert_eq!(lits.len(), 6);
    let (text, lits) = ask(
        "Why did you pick up the green can at step 0?",
        Mode::Concise,
    );
    assert_eq!(
        lits,
        [
            "holds(relation(below,white_block,green_can),0)",
            "occurs(pickup(rob1,white_block),2)"
        ],
        "{text}"
    );
    let (text, lits) = ask(
        "Why did you not put the white block on the mug?",
        Mode::Concise,
    );
    assert_eq!(lits, ["has_surface(mug,irregular)"], "{text}");
    let (text, lits) = ask(
        "Why did you not pick up the white block at step 0?",
        Mode::Concise,
    );
    assert_eq!(
        lits,
        ["holds(relation(on,green_can,white_block),0)"],
        "{text}"
    );
    let (text, lits) = ask(
        "Why did you not pick up the green can at step 5?",
        Mode::Concise,
    );
    assert_eq!(
        lits,
        ["holds(relation(on,white_block,green_can),5)"],
        "{text}"
    );
    let (text, lits) = ask(
        "Why did you believe the white block was on the green can?",
        Mode::Concise,
    );
    assert_eq!(
        lits,
        ["occurs(putdown(rob1,white_block,green_can),3)"],
        "{text}"
    );
}

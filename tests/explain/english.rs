//! The controlled-English parser (docs/domain.md 6.1) over the built-in lexicon: every request
//! pattern, synonyms, contractions, number words, step phrases, and the replies to questions
//! that are not understood. Snapshots list `question => parse`.

use lucent::control::Symbol;
use lucent::explain::english::{NotUnderstood, Parser, Question};
use lucent::explain::lexicon::Lexicon;
use lucent::explain::pattern::Pattern;

/// The execution-example scene of docs/domain.md 1.6.
const SCENE: &[&str] = &["red_block", "white_block", "green_can", "pitcher", "mug"];

fn run(objects: &[&str], questions: &[&str]) -> String {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, objects);
    let mut out = String::new();
    for q in questions {
        let line = match parser.parse(q) {
            Ok(question) => question.to_string(),
            Err(e) => format!("NOT UNDERSTOOD {e:?}"),
        };
        out.push_str(&format!("{q}\n  => {line}\n"));
    }
    out
}

fn t(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

#[test]
fn goals() {
    insta::assert_snapshot!(run(
        SCENE,
        &[
            "Put the pitcher on the red block.",
            "Please place the pitcher on top of the red block",
            "set the green can onto the table",
            "Put the white block on the green can and the pitcher on the red block.",
            "Pick up the white block.",
            "grab the green can",
            "Lift the mug",
            "Take the pitcher, please.",
            "Could you pick the mug up?",
            "put the green cylinder on the table",
        ]
    ));
}

#[test]
fn plan_description_and_no_plan() {
    insta::assert_snapshot!(run(
        SCENE,
        &[
            "Please describe the plan.",
            "What was your plan?",
            "What's your plan?",
            "describe what you did",
            "Why is there no plan?",
            "Why can't you put the pitcher on the mug?",
            "why could you not pick up the red block",
        ]
    ));
}

#[test]
fn why_and_why_not() {
    insta::assert_snapshot!(run(
        SCENE,
        &[
            "Why did you pick up the green can at step 0?",
            "Why did you pick up the green can at time step zero?",
            "why did you grab the green can in step 2",
            "Why did you put the white block on the green can?",
            "Why did you put the green can down at step one?",
            "Why did you not put the white block on the mug?",
            "Why didn't you pick up the white block at step 0?",
            "Why did you not pick white block at step 0?",
            "Why not lift the mug at step 3?",
            "Why did you not pick up green can at step 5?",
            "Why didn't you place the pitcher onto the green can at time-step four?",
        ]
    ));
}

#[test]
fn beliefs() {
    insta::assert_snapshot!(run(
        SCENE,
        &[
            "Why did you believe that the white block was below the green can in the initial state?",
            "Why did you believe the white block was on the green can?",
            "Why do you think the green can is in your hand at step 1?",
            "Why did you believe that the pitcher was not in your hand at step 2?",
            "Why did you believe that the white block was unstable at step 3?",
            "Why was the mug occluded?",
            "Why was the red block to the left of the mug at step 0?",
            "Why did you believe the pitcher was in front of the mug initially?",
            "Why is the green can small?",
            "Why did you believe that the mug had an irregular surface?",
            "Why did you believe that the white block was at level two at step 4?",
            "Why did you believe that the mug was occluded by the pitcher at step 0?",
            "why did you believe the white block was on a small base at step 3",
        ]
    ));
}

#[test]
fn what_if() {
    insta::assert_snapshot!(run(
        SCENE,
        &[
            "What if you had picked up the white block at step 0?",
            "What would happen if you put the pitcher on the mug at step 4?",
            "what if you grabbed the red block instead at step 2",
        ]
    ));
}

#[test]
fn sizes_and_kinds_resolve_against_scene_names() {
    let scene = &[
        "green_cube_large",
        "red_cube_large",
        "white_can_small",
        "blue_ball",
        "pitcher",
    ];
    insta::assert_snapshot!(run(
        scene,
        &[
            "pick up the green block",
            "put the large red cube on the green block",
            "put the white can on the blue sphere",
            "why did you pick up the small white cylinder at step 1",
            "pick up the block",
            "pick up the purple block",
            "pick up the small red block",
        ]
    ));
}

#[test]
fn not_understood() {
    insta::assert_snapshot!(run(
        SCENE,
        &[
            "",
            "?!",
            "Why did you flibber the mug?",
            "Pick up the purple block",
            "Why did you pick up the green can at step",
            "the the the",
            "Why did you believe that the mug was?",
            "Dance with the pitcher and sing",
        ]
    ));
}

#[test]
fn replies_name_the_problem_and_the_questions() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, SCENE);
    let mut out = String::new();
    for q in [
        "Why did you flibber the mug?",
        "Pick up the purple block",
        "pick up the block",
        "the the the",
    ] {
        let e = parser.parse(q).unwrap_err();
        out.push_str(&format!("{q}\n{}\n\n", e.reply(&lex)));
    }
    let _ = parser.parse("pick up the red block").unwrap();
    insta::assert_snapshot!(out);
}

#[test]
fn structured_results() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, SCENE);
    assert_eq!(
        parser.parse("Why did you pick up the green can at step 0?"),
        Ok(Question::WhyAction {
            action: Pattern::from(&t("pickup(rob1,green_can)")),
            step: Some(0)
        })
    );
    assert_eq!(
        parser.parse("Why did you not put the white block on the mug?"),
        Ok(Question::WhyNotAction {
            action: Pattern::from(&t("putdown(rob1,white_block,mug)")),
            step: None
        })
    );
    assert_eq!(
        parser.parse("why did you believe that the white block was unstable at step 3"),
        Ok(Question::Belief {
            literal: t("-stable(white_block)"),
            is_static: false,
            step: Some(3)
        })
    );
    assert_eq!(
        parser.parse("Pick up the purple block"),
        Err(NotUnderstood::UnknownObject {
            phrase: "the purple block".into(),
            known: vec![
                "the red block".into(),
                "the white block".into(),
                "the green can".into(),
                "the pitcher".into(),
                "the mug".into()
            ]
        })
    );
    let fluent = t("-stable(white_block)");
    assert_eq!(
        lucent::explain::english::holds(&fluent, 3).to_string(),
        "-holds(stable(white_block),3)"
    );
}

#[test]
fn without_a_scene_objects_are_their_words() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, &[]);
    assert_eq!(
        parser.parse("put the red block on the white block"),
        Ok(Question::Goal {
            literals: vec![t("relation(on,red_block,white_block)")]
        })
    );
}

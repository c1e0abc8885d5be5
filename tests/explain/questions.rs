//! The four questions (docs/domain.md 6.3-6.6) end to end, from English to the answer's text and
//! literals, over the hand-written program of the execution example (tests/support/ra_oracle.rs):
//! the paper's examples 1-3 (docs/domain.md 6.8), the missing-step rule, follow-up steps, concise
//! and full modes, and questions outside the history. Every proof tree is re-checked by `answer`.

use lucent::control::Symbol;
use lucent::explain::english::Parser;
use lucent::explain::lexicon::Lexicon;
use lucent::explain::questions::{answer, AnswerError, Mode, Scenario, Session};

use crate::support::ra_oracle;
use ra_oracle::{paper, t};

const SCENE: &[&str] = &[
    "red_block",
    "white_block",
    "green_can",
    "pitcher",
    "mug",
    "pig",
];

/// Asks each question in turn (one session), in a mode; lines of question, answer, literals.
fn dialogue(questions: &[&str], mode: Mode) -> String {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, SCENE);
    let (oracle, plan) = paper();
    let scn = Scenario::ra(&oracle, plan, vec![t("relation(on,pitcher,red_block)")], 6);
    let mut session = Session::default();
    let mut out = String::new();
    for q in questions {
        let question = parser.parse(q).unwrap_or_else(|e| panic!("{q}: {e:?}"));
        let a = answer(&scn, &lex, &question, mode, &mut session).unwrap();
        let lits: Vec<String> = a.literals.iter().map(Symbol::to_string).collect();
        out.push_str(&format!(
            "Q: {q}\nA: {}\n   [{}] {}\n",
            a.text,
            a.kind,
            lits.join(" ")
        ));
    }
    out
}

#[test]
fn example_1_plans_actions_beliefs() {
    insta::assert_snapshot!(dialogue(
        &[
            "Please describe the plan.",
            "Why did you pick up the green can at step 0?",
            "Why did you not put the white block on the mug?",
            "Why did you believe that the white block was below the green can in the initial state?",
        ],
        Mode::Concise
    ));
}

#[test]
fn example_2_belief_tracing_for_why_not() {
    let out = dialogue(
        &["Why did you not pick white block at step 0?"],
        Mode::Concise,
    );
    assert!(out.contains("A: Because I observed the green can on the white block at step 0."));
    assert!(out.contains("holds(relation(on,green_can,white_block),0)"));
}

#[test]
fn example_3_learning_and_explanation() {
    insta::assert_snapshot!(dialogue(
        &[
            "Why did you not pick up green can at step 5?",
            "Why did you believe the white block was on the green can?",
        ],
        Mode::Concise
    ));
    let full = dialogue(
        &["Why did you not pick up green can at step 5?"],
        Mode::Full,
    );
    assert!(
        full.contains(
            "Because the white block was on the green can and the pitcher was in my hand."
        ),
        "{full}"
    );
}

#[test]
fn other_answers() {
    insta::assert_snapshot!(dialogue(
        &[
            "Why did you pick up the green can?",
            "Why did you pick up the white block at step 1?",
            "Why did you not pick up the pig at step 2?",
            "Why did you not pick up the green can at step 0?",
            "Why did you pick up the green can at step 9?",
            "Why did you believe that the green can was not in your hand at step 0?",
            "Why did you believe that the green can was in your hand at step 0?",
            "Why did you believe that the mug had an irregular surface?",
            "Why did you believe that the white block was stable at step 4?",
        ],
        Mode::Concise
    ));
}

#[test]
fn tasks_and_counterfactuals_go_to_the_solver() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, SCENE);
    let (oracle, plan) = paper();
    let scn = Scenario::ra(&oracle, plan, Vec::new(), 6);
    for q in [
        "Why is there no plan?",
        "What if you had picked up the mug at step 0?",
        "Pick up the mug",
    ] {
        let question = parser.parse(q).unwrap();
        let r = answer(
            &scn,
            &lex,
            &question,
            Mode::Concise,
            &mut Session::default(),
        );
        assert_eq!(r.unwrap_err(), AnswerError::NeedsSolver, "{q}");
    }
}

#[test]
fn json_output() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, SCENE);
    let (oracle, plan) = paper();
    let scn = Scenario::ra(&oracle, plan, vec![t("relation(on,pitcher,red_block)")], 6);
    let q = parser
        .parse("Why did you not pick white block at step 0?")
        .unwrap();
    let a = answer(&scn, &lex, &q, Mode::Concise, &mut Session::default()).unwrap();
    let json = a.to_json();
    assert_eq!(json["type"], "why_not");
    assert_eq!(
        json["answer"],
        "Because I observed the green can on the white block at step 0."
    );
    assert_eq!(
        json["literals"],
        serde_json::json!(["holds(relation(on,green_can,white_block),0)"])
    );
    let path = json["tree"]["path"].as_array().unwrap();
    let nodes = json["tree"]["nodes"].as_array().unwrap();
    let last = path.last().unwrap().as_u64().unwrap() as usize;
    assert_eq!(nodes[last]["kind"], "observation");
    insta::assert_snapshot!(serde_json::to_string_pretty(&json).unwrap());
}

/// Random questions (words of the vocabulary, scene objects, numbers, junk, in random order and
/// in the shapes of real questions with random parts) never panic: each is either answered or
/// gets a reply that names what was not understood.
#[test]
fn random_questions_never_panic() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, SCENE);
    let (oracle, plan) = paper();
    let scn = Scenario::ra(&oracle, plan, vec![t("relation(on,pitcher,red_block)")], 6);
    let words = [
        "why",
        "did",
        "you",
        "not",
        "didn't",
        "pick",
        "up",
        "put",
        "down",
        "on",
        "the",
        "a",
        "white",
        "block",
        "green",
        "can",
        "mug",
        "pitcher",
        "pig",
        "at",
        "step",
        "time",
        "in",
        "initial",
        "state",
        "believe",
        "that",
        "was",
        "below",
        "above",
        "in",
        "your",
        "hand",
        "unstable",
        "occluded",
        "zero",
        "five",
        "99",
        "4294967296",
        "what",
        "if",
        "had",
        "plan",
        "describe",
        "please",
        "and",
        "of",
        "top",
        "front",
        "left",
        "right",
        "flibber",
        "?",
        ",",
        "level",
        "small",
        "irregular",
        "surface",
        "instead",
        "there",
        "no",
    ];
    let shapes = [
        "why did you {V} the {O} at step {N}",
        "why didn't you {V} the {O} on the {O} at time step {N}",
        "why did you believe that the {O} was {R} the {O} at step {N}",
        "why was the {O} {P} at step {N}",
        "what if you had {V} the {O} at step {N}",
    ];
    let verbs = ["pick up", "put", "grab", "place", "take", "lift", "set"];
    let objects = [
        "white block",
        "green can",
        "mug",
        "pig",
        "red block",
        "table",
        "blue block",
    ];
    let rels = [
        "on",
        "below",
        "above",
        "in front of",
        "to the left of",
        "touching",
    ];
    let props = [
        "unstable",
        "stable",
        "occluded",
        "in your hand",
        "at level 3",
        "small",
    ];
    let mut seed: u64 = 7;
    let mut next = |n: usize| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 33) as usize) % n
    };
    let (mut answered, mut replied) = (0, 0);
    for i in 0..2000 {
        let text = if i % 2 == 0 {
            let len = 1 + next(12);
            (0..len)
                .map(|_| words[next(words.len())])
                .collect::<Vec<_>>()
                .join(" ")
        } else {
            let mut s = shapes[next(shapes.len())].to_string();
            while let Some(k) = s.find('{') {
                let hole = &s[k..k + 3];
                let fill = match hole {
                    "{V}" => verbs[next(verbs.len())].to_string(),
                    "{O}" => objects[next(objects.len())].to_string(),
                    "{R}" => rels[next(rels.len())].to_string(),
                    "{P}" => props[next(props.len())].to_string(),
                    _ => next(9).to_string(),
                };
                s.replace_range(k..k + 3, &fill);
            }
            s
        };
        let mut session = Session::default();
        match parser.parse(&text) {
            Ok(q) => match answer(&scn, &lex, &q, Mode::Full, &mut session) {
                Ok(a) => {
                    assert!(!a.text.is_empty(), "{text}");
                    answered += 1;
                }
                Err(AnswerError::NeedsSolver) => answered += 1,
                Err(e) => panic!("{text}: {e}"),
            },
            Err(e) => {
                assert!(!e.reply(&lex).is_empty());
                replied += 1;
            }
        }
    }
    assert!(
        answered > 300 && replied > 300,
        "{answered} answered, {replied} replied"
    );
}

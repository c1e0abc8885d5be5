//! The paraphrase corpus (`tests/data/explain/paraphrases.txt`): questions and requests written
//! by hand the way people type them (tense, contractions, politeness, missing articles, case,
//! step phrases), each with the request it must parse to, written by hand beside it. Every
//! line must parse to exactly that request; a line expecting `unknown W...` must be refused
//! with a reply that names those words.

use lucent::explain::english::{NotUnderstood, Parser};
use lucent::explain::lexicon::Lexicon;

const CORPUS: &str = include_str!("../data/explain/paraphrases.txt");

/// The scenes the corpus's `@scene` lines name.
fn scene(name: &str) -> &'static [&'static str] {
    match name {
        "example" => &["red_block", "white_block", "green_can", "pitcher", "mug"],
        "real" => &[
            "red_cube",
            "blue_cube",
            "orange_cube",
            "green_cube",
            "tennis_ball",
            "apple",
            "capsicum",
            "pot",
            "pig",
        ],
        "simulated" => &[
            "red_cylinder",
            "white_cube",
            "black_cube",
            "cracker_box",
            "green_sphere",
            "yellow_duck",
            "apple",
            "pitcher",
            "mustard_bottle",
            "mug",
        ],
        other => panic!("the corpus names an unknown scene `{other}`"),
    }
}

/// The corpus's question type of an expected request.
fn kind(expected: &str) -> &'static str {
    let first = expected.split_whitespace().next().unwrap_or("");
    match first {
        "describe" if expected.starts_with("describe step") => "describe step",
        "describe" => "describe",
        "why" if expected.starts_with("why not") => "why not",
        "why" => "why",
        "belief" if expected.contains("has_size") || expected.contains("has_surface") => {
            "belief (attribute)"
        }
        "belief" => "belief",
        "goal" => "goal",
        "unknown" => "unknown",
        other => panic!("unknown expectation `{other}`"),
    }
}

#[test]
fn every_paraphrase_parses_to_its_request() {
    let lex = Lexicon::ra();
    let mut objects = scene("example");
    let mut failures = Vec::new();
    let mut counts: std::collections::BTreeMap<&str, usize> = Default::default();
    for (n, line) in CORPUS.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(name) = line.strip_prefix("@scene") {
            objects = scene(name.trim());
            continue;
        }
        let (question, expected) = line
            .rsplit_once(" | ")
            .unwrap_or_else(|| panic!("line {}: no ` | ` in `{line}`", n + 1));
        let (question, expected) = (question.trim(), expected.trim());
        *counts.entry(kind(expected)).or_default() += 1;
        let parser = Parser::new(&lex, objects);
        let got = parser.parse(question);
        let ok = match (&got, expected.strip_prefix("unknown ")) {
            (Err(NotUnderstood::UnknownWords(ws)), Some(words)) => {
                let ws: Vec<String> = ws.iter().map(|w| w.to_lowercase()).collect();
                let reply = parser.reply(got.as_ref().unwrap_err());
                ws.join(" ") == words && ws.iter().all(|w| reply.contains(w.as_str()))
            }
            (Ok(q), None) => q.to_string() == expected,
            _ => false,
        };
        if !ok {
            let got = match got {
                Ok(q) => q.to_string(),
                Err(e) => format!("{e:?}"),
            };
            failures.push(format!(
                "line {}: {question}\n    expected {expected}\n    got      {got}",
                n + 1
            ));
        }
    }
    let total: usize = counts.values().sum();
    eprintln!("{counts:?}, {total} in all");
    assert!(
        failures.is_empty(),
        "{} of {total} paraphrases not parsed as written:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(total >= 300, "the corpus has {total} questions");
    for (k, c) in &counts {
        assert!(*c >= 10, "{k}: only {c} questions");
    }
}

#[test]
fn a_sentence_of_known_words_names_what_was_not_understood() {
    let lex = Lexicon::ra();
    let parser = Parser::new(&lex, scene("real"));
    let e = parser
        .parse("why did you pick up the pot the apple")
        .unwrap_err();
    let reply = parser.reply(&e);
    assert!(
        reply.starts_with("I understood \"why did you pick up the pot\" but not \"the apple\"."),
        "{reply}"
    );
    // The examples name objects of the scene, not of another one.
    assert!(
        reply.contains("the red cube") && !reply.contains("green can"),
        "{reply}"
    );
}

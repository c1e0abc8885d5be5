//! Replies to questions that were not understood ([`NotUnderstood`]): what was not understood,
//! and example questions about the scene's objects (the lexicon's help lines); and lists in
//! English ("a, b, and c").
//!
//! Invariants: every reply is total: any [`NotUnderstood`] and any lexicon give a reply (an
//! example with no object to name says "it"), never a panic.

use crate::explain::lexicon::Lexicon;

/// Why a question was not understood.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotUnderstood {
    /// Nothing was asked.
    Empty,
    /// Words outside the vocabulary (as written).
    UnknownWords(Vec<String>),
    /// An object phrase that names no object of the scene.
    UnknownObject {
        /// The phrase as heard ("the purple block").
        phrase: String,
        /// The objects of the scene, in words.
        known: Vec<String>,
    },
    /// An object phrase that names several objects of the scene.
    AmbiguousObject {
        /// The phrase as heard ("the block").
        phrase: String,
        /// The objects it could name, in words.
        candidates: Vec<String>,
    },
    /// Every word is known, but the sentence fits no pattern: `understood` are the words the
    /// longest partial match took, `rest` the words after them (as written).
    NoPattern {
        /// The words a pattern matched before it failed.
        understood: Vec<String>,
        /// The words no pattern could take.
        rest: Vec<String>,
    },
}

impl NotUnderstood {
    /// The reply to the human: what was not understood, and what the robot can answer (the
    /// examples name the lexicon's help objects; [`Parser::reply`](super::Parser::reply) names
    /// the scene's).
    pub fn reply(&self, lexicon: &Lexicon) -> String {
        self.reply_about(lexicon, &lexicon.help_objects)
    }

    /// The reply, with the examples about these objects (in words, "the pot").
    pub fn reply_about(&self, lexicon: &Lexicon, objects: &[String]) -> String {
        let first = match self {
            NotUnderstood::Empty => "I did not hear a question.".to_string(),
            NotUnderstood::UnknownWords(words) => {
                let quoted: Vec<String> = words.iter().map(|w| format!("\"{w}\"")).collect();
                if quoted.len() == 1 {
                    format!("I do not know the word {}.", quoted[0])
                } else {
                    format!("I do not know the words {}.", join_and(&quoted))
                }
            }
            NotUnderstood::UnknownObject { phrase, known } => {
                if known.is_empty() {
                    format!("I do not know any object called \"{phrase}\".")
                } else {
                    format!(
                        "I do not know any object called \"{phrase}\"; I know {}.",
                        join_and(known)
                    )
                }
            }
            NotUnderstood::AmbiguousObject { phrase, candidates } => format!(
                "\"{phrase}\" could be {}; please say which.",
                join_or(candidates)
            ),
            NotUnderstood::NoPattern { understood, rest } => {
                let quote = |ws: &[String]| format!("\"{}\"", ws.join(" "));
                match (understood.is_empty(), rest.is_empty()) {
                    (_, true) => {
                        "I know these words, but I did not understand the question.".to_string()
                    }
                    (true, false) => format!(
                        "I know these words, but I did not understand {}.",
                        quote(rest)
                    ),
                    (false, false) => format!(
                        "I understood {} but not {}.",
                        quote(understood),
                        quote(rest)
                    ),
                }
            }
        };
        let mut out = first;
        if !lexicon.help.is_empty() {
            out.push_str(" I can answer requests and questions such as:");
            let pick = |i: usize| {
                objects
                    .get(i)
                    .or_else(|| lexicon.help_objects.get(i))
                    .map_or("it", String::as_str)
            };
            let capital = |s: &str| {
                let mut c = s.chars();
                c.next()
                    .map(|f| f.to_uppercase().chain(c).collect::<String>())
                    .unwrap_or_default()
            };
            for h in &lexicon.help {
                let line = h
                    .replace("{X}", pick(0))
                    .replace("{Y}", pick(1))
                    .replace("{Z}", pick(2));
                out.push_str("\n  ");
                out.push_str(&capital(&line));
            }
        }
        out
    }
}

/// "a", "a and b", "a, b, and c".
pub fn join_and(items: &[String]) -> String {
    join_with(items, "and")
}

/// "a", "a or b", "a, b, or c".
pub fn join_or(items: &[String]) -> String {
    join_with(items, "or")
}

fn join_with(items: &[String], word: &str) -> String {
    match items {
        [] => String::new(),
        [a] => a.clone(),
        [a, b] => format!("{a} {word} {b}"),
        [rest @ .., last] => format!("{}, {word} {last}", rest.join(", ")),
    }
}

//! The question parser's front: the scene's objects as the parser matches them, the
//! normalized tokens with politeness stripped and unknown words found, the [`Parser::parse`]
//! entry that runs the matcher, and the resolution of an object phrase to one scene constant.
//!
//! Invariants: an object phrase resolves to exactly one scene constant or to a
//! [`NotUnderstood`] that names the phrase (unknown, or ambiguous with its candidates); with no
//! scene objects, a phrase becomes the constant of its words. Parsing never panics.

use super::matcher::Matcher;
use super::{NotUnderstood, Question};
use crate::control::Symbol;
use crate::explain::lexicon::{Lexicon, Token};

/// An object of the scene as the parser matches it.
#[derive(Clone, Debug)]
struct SceneObject {
    /// The constant.
    constant: String,
    /// Its words with kinds canonicalized and sizes removed (`red_cube_large` -> red block).
    words: Vec<String>,
    /// Its size word, if its name has one.
    size: Option<String>,
}

/// The parser: a lexicon and the objects of the scene the questions are about.
#[derive(Clone, Debug)]
pub struct Parser<'a> {
    pub(super) lexicon: &'a Lexicon,
    objects: Vec<SceneObject>,
}

impl<'a> Parser<'a> {
    /// A parser for questions about a scene with these object constants (`table` is always an
    /// object). With no objects, object phrases become constants of their words joined by `_`
    /// (`the white block` -> `white_block`).
    pub fn new(lexicon: &'a Lexicon, objects: &[&str]) -> Parser<'a> {
        let mut names: Vec<&str> = objects.to_vec();
        if !objects.is_empty() && !names.contains(&"table") {
            names.push("table");
        }
        let objects = names
            .iter()
            .map(|c| {
                let mut words = Vec::new();
                let mut size = None;
                for part in c.split('_').filter(|p| !p.is_empty()) {
                    let w = lexicon.word(part);
                    if lexicon.sizes.contains(&w) {
                        size = Some(w);
                    } else if let Some(k) = lexicon.kind(&w) {
                        words.push(k.to_string());
                    } else {
                        words.push(w);
                    }
                }
                SceneObject {
                    constant: c.to_string(),
                    words,
                    size,
                }
            })
            .collect();
        Parser { lexicon, objects }
    }

    /// Parses one question or request.
    pub fn parse(&self, text: &str) -> Result<Question, NotUnderstood> {
        let tokens = self.lexicon.normalize(text);
        let words = self.strip_politeness(&tokens);
        if words.is_empty() {
            return Err(NotUnderstood::Empty);
        }
        let unknown: Vec<String> = {
            let mut seen = Vec::new();
            for t in words {
                if !self.lexicon.knows(&t.word)
                    && !self.is_object_word(&t.word)
                    && !seen.contains(&t.original)
                {
                    seen.push(t.original.clone());
                }
            }
            seen
        };
        if !unknown.is_empty() {
            return Err(NotUnderstood::UnknownWords(unknown));
        }
        let mut m = Matcher {
            p: self,
            toks: words,
            pos: 0,
            furthest: 0,
            error: None,
        };
        let result = m.request();
        let originals = |ts: &[Token]| {
            let mut out: Vec<String> = Vec::new();
            for t in ts {
                // A contraction is one written word for several tokens.
                if !(out.last() == Some(&t.original) && t.original.contains('\'')) {
                    out.push(t.original.clone());
                }
            }
            out
        };
        match (result, m.error) {
            (Some(_), Some(e)) => Err(e),
            (Some(q), None) => Ok(q),
            (None, Some(e)) => Err(e),
            (None, None) => Err(NotUnderstood::NoPattern {
                understood: originals(&words[..m.furthest]),
                rest: originals(&words[m.furthest..]),
            }),
        }
    }

    /// The reply to a question this parser did not understand, its examples about objects of
    /// the scene.
    pub fn reply(&self, e: &NotUnderstood) -> String {
        let mut objects = self.known_objects();
        if objects.len() < 3 {
            objects.extend(self.lexicon.help_objects.iter().cloned());
        }
        e.reply_about(self.lexicon, &objects)
    }

    /// The object constants in words, for replies ("the red cube" for `red_cube_large`).
    fn known_objects(&self) -> Vec<String> {
        self.objects
            .iter()
            .filter(|o| o.constant != "table")
            .map(|o| self.object_words(&o.constant))
            .collect()
    }

    /// A constant in words: "the" and its name's words without size words.
    fn object_words(&self, constant: &str) -> String {
        let words: Vec<&str> = constant
            .split('_')
            .filter(|p| !p.is_empty() && !self.lexicon.sizes.contains(&self.lexicon.word(p)))
            .collect();
        format!("the {}", words.join(" "))
    }

    fn strip_politeness<'t>(&self, mut toks: &'t [Token]) -> &'t [Token] {
        loop {
            let before = toks.len();
            for p in &self.lexicon.politeness {
                if starts_with(toks, p) {
                    toks = &toks[p.len()..];
                    break;
                }
            }
            for p in &self.lexicon.politeness {
                if toks.len() >= p.len() && starts_with(&toks[toks.len() - p.len()..], p) {
                    toks = &toks[..toks.len() - p.len()];
                    break;
                }
            }
            if toks.len() == before {
                return toks;
            }
        }
    }

    pub(super) fn is_object_word(&self, w: &str) -> bool {
        self.lexicon.colours.contains(w)
            || self.lexicon.sizes.contains(w)
            || self.lexicon.kind(w).is_some()
            || w == "table"
            || self.objects.iter().any(|o| o.words.iter().any(|x| x == w))
    }

    /// Resolves object words to one scene constant.
    pub(super) fn resolve(&self, words: &[&Token]) -> Result<Symbol, NotUnderstood> {
        let phrase = format!(
            "the {}",
            words
                .iter()
                .map(|t| t.original.as_str())
                .collect::<Vec<_>>()
                .join(" ")
        );
        let mut size = None;
        let mut ws = Vec::new();
        for t in words {
            if self.lexicon.sizes.contains(&t.word) {
                size = Some(t.word.clone());
            } else if let Some(k) = self.lexicon.kind(&t.word) {
                ws.push(k.to_string());
            } else {
                ws.push(t.word.clone());
            }
        }
        if self.objects.is_empty() {
            if ws.is_empty() {
                return Err(NotUnderstood::UnknownObject {
                    phrase,
                    known: Vec::new(),
                });
            }
            let mut name = ws.join("_");
            if let Some(s) = size {
                name = format!("{name}_{s}");
            }
            return Ok(Symbol::constant(&name));
        }
        let size_fits = |o: &SceneObject| match (&size, &o.size) {
            (Some(a), Some(b)) => a == b,
            _ => true,
        };
        let exact: Vec<&SceneObject> = self
            .objects
            .iter()
            .filter(|o| o.words == ws && size_fits(o))
            .collect();
        let candidates = if exact.is_empty() {
            self.objects
                .iter()
                .filter(|o| {
                    !ws.is_empty() && ws.iter().all(|w| o.words.contains(w)) && size_fits(o)
                })
                .collect()
        } else {
            exact
        };
        match candidates.as_slice() {
            [one] => Ok(Symbol::constant(&one.constant)),
            [] => Err(NotUnderstood::UnknownObject {
                phrase,
                known: self.known_objects(),
            }),
            many => Err(NotUnderstood::AmbiguousObject {
                phrase,
                candidates: many
                    .iter()
                    .map(|o| self.object_words(&o.constant))
                    .collect(),
            }),
        }
    }
}

pub(super) fn starts_with(toks: &[Token], phrase: &[String]) -> bool {
    toks.len() >= phrase.len() && toks.iter().zip(phrase).all(|(t, w)| &t.word == w)
}

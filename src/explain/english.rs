//! Controlled English in: questions and requests to the robot (docs/domain.md 6.1) parsed into a
//! structured [`Question`].
//!
//! The words come from the [`Lexicon`] (data, `domains/ra/lexicon.json`); this module holds only
//! the grammar, a handful of patterns over normalized tokens:
//!
//! ```text
//! request  = goal (["and"] (goal | object on object))*          -> Question::Goal
//!          | describe-phrase                                   -> Question::DescribePlan
//!          | describe-step-phrase (with a step in its {S})      -> DescribeStep
//!          | no-plan-phrase | "why" "can" ("not" "you" | "you" "not") goal   -> WhyNoPlan
//!          | why aux* "believe" ["that"] belief [step]          -> Belief
//!          | why aux* belief [step] | why aux* hold object [step]   -> Belief
//!          | why aux* action [step]   (aux has "not")          -> WhyNotAction
//!          | why aux* action [step]   (aux has no "not")       -> WhyAction
//!          | "what" ["would" "happen"] "if" ["you"] ["have"] action [step] ["instead"] -> WhatIf
//! why      = "why" | "how come" | "what was the reason (for)" | ... (lexicon)
//! aux      = do | be | have | can | could | will | would | you | not   (at most four)
//! goal     = verb [particle] object (["and"] object)* [particle] [on-phrase object]
//! action   = verb [particle] object [particle] [on-phrase object]
//! belief   = object ["be"|"do"] ["not"] (relation object | property)
//! step     = [at|in|on|during] ["the"] ["time"] "step" number | step-phrase | last-phrase
//! object   = ["the"|"your"|"my"] object-word+   (resolved against the scene; "a"/"an" and
//!            commas are dropped by normalization)
//! ```
//!
//! Invariants: parsing never panics and never guesses: a question is either fully understood
//! (every word consumed by the grammar, every object resolved to exactly one scene constant) or
//! answered by [`NotUnderstood`], whose reply ([`Parser::reply`]) names the words or the object
//! that were not understood (for known words in an unknown order, the words after the longest
//! partial match) and lists example questions about the scene's own objects. "Last" is the
//! step [`LAST`], resolved by the answerer against the history. Resolution of a missing step
//! is not the parser's job: the step stays `None` (docs/domain.md 6.1, "missing step").

use std::fmt;

use super::lexicon::{Lexicon, Token};
use super::pattern::{Pattern, SymbolExt};
use crate::control::Symbol;

/// A request or question, with its literals as structured terms in the program's syntax.
/// Fluents are given without `holds` and step (`relation(on,pitcher,red_block)`,
/// `-stable(a)`); actions as in `occurs` (`pickup(rob1,green_can)`), with `_` for a target
/// that was not named.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Question {
    /// A task for the planner: reach a state where all these fluents hold.
    Goal {
        /// The goal fluents (`relation(on,X,Y)`, `in_hand(rob1,X)`).
        literals: Vec<Symbol>,
    },
    /// "Describe the plan."
    DescribePlan,
    /// "What did you do at step N / first / last?"
    DescribeStep {
        /// The step ([`LAST`] for the last action of the plan).
        step: u32,
    },
    /// "Why did you ⟨action⟩ [at step N]?"
    WhyAction {
        /// The action pattern.
        action: Pattern,
        /// The step, if named.
        step: Option<u32>,
    },
    /// "Why did you not ⟨action⟩ [at step N]?"
    WhyNotAction {
        /// The action pattern.
        action: Pattern,
        /// The step, if named.
        step: Option<u32>,
    },
    /// "Why did you believe that ⟨literal⟩ [at step N]?"
    Belief {
        /// The fluent or static literal, possibly classically negated (`-stable(a)`).
        literal: Symbol,
        /// Whether the literal is a static (no step).
        is_static: bool,
        /// The step, if named.
        step: Option<u32>,
    },
    /// "Why is there no plan?" or "Why can you not ⟨goal⟩?"
    WhyNoPlan {
        /// The goal fluents named in the question (empty: the current task's goal).
        goal: Vec<Symbol>,
    },
    /// "What if you had ⟨action⟩ [at step N] (instead)?"
    WhatIf {
        /// The action pattern.
        action: Pattern,
        /// The step, if named.
        step: Option<u32>,
    },
}

impl Question {
    /// The question's type as a short name (`goal`, `plan`, `why`, `why_not`, `belief`,
    /// `no_plan`, `what_if`), as in `--outf=2` output.
    pub fn kind(&self) -> &'static str {
        match self {
            Question::Goal { .. } => "goal",
            Question::DescribePlan => "plan",
            Question::DescribeStep { .. } => "plan_step",
            Question::WhyAction { .. } => "why",
            Question::WhyNotAction { .. } => "why_not",
            Question::Belief { .. } => "belief",
            Question::WhyNoPlan { .. } => "no_plan",
            Question::WhatIf { .. } => "what_if",
        }
    }

    /// The step the question names, if any.
    pub fn step(&self) -> Option<u32> {
        match self {
            Question::WhyAction { step, .. }
            | Question::WhyNotAction { step, .. }
            | Question::Belief { step, .. }
            | Question::WhatIf { step, .. } => *step,
            Question::DescribeStep { step } => Some(*step),
            _ => None,
        }
    }
}

/// The step a question names with "last", "at the end", "in the final state": the last step of
/// the history for a belief, the last action's step for a question about actions. The answerer
/// resolves it against the history; the parser has none.
pub const LAST: u32 = u32::MAX;

/// A step in words for [`Question`]'s display: the number, `last`, or `?` when not named.
fn step_text(s: Option<u32>) -> String {
    match s {
        Some(LAST) => "last".to_string(),
        Some(n) => n.to_string(),
        None => "?".to_string(),
    }
}

/// The program literal of a fluent literal at a step: `holds(F, I)`, or `-holds(F, I)` when the
/// fluent is classically negated (`-stable(a)` at 2 is `-holds(stable(a),2)`).
pub fn holds(fluent: &Symbol, step: u32) -> Symbol {
    let positive = fluent.positive();
    let mut t = Symbol::function("holds", vec![positive, Symbol::Number(step as i32)]);
    if fluent.is_negative() {
        t = t.complement().expect("holds/2 has a sign");
    }
    t
}

/// The constant an object phrase that names no object of the scene stands for while the rest
/// of the question is matched (the question is then not understood, whatever it built).
const UNRESOLVED: &str = "unresolved_object";

/// The program literal `occurs(A, I)`.
pub fn occurs(action: &Symbol, step: u32) -> Symbol {
    Symbol::function("occurs", vec![action.clone(), Symbol::Number(step as i32)])
}

impl fmt::Display for Question {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let step = |s: &Option<u32>| step_text(*s);
        let list = |ts: &[Symbol]| {
            ts.iter()
                .map(Symbol::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        };
        match self {
            Question::Goal { literals } => write!(f, "goal {}", list(literals)),
            Question::DescribePlan => write!(f, "describe the plan"),
            Question::DescribeStep { step: s } => write!(f, "describe step {}", step(&Some(*s))),
            Question::WhyAction { action, step: s } => write!(f, "why {action} at {}", step(s)),
            Question::WhyNotAction { action, step: s } => {
                write!(f, "why not {action} at {}", step(s))
            }
            Question::Belief {
                literal,
                is_static,
                step: s,
            } => {
                if *is_static {
                    write!(f, "belief {literal}")
                } else {
                    write!(f, "belief {literal} at {}", step(s))
                }
            }
            Question::WhyNoPlan { goal } if goal.is_empty() => write!(f, "why no plan"),
            Question::WhyNoPlan { goal } => write!(f, "why no plan for {}", list(goal)),
            Question::WhatIf { action, step: s } => write!(f, "what if {action} at {}", step(s)),
        }
    }
}

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
    /// examples name the lexicon's help objects; [`Parser::reply`] names the scene's).
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
    lexicon: &'a Lexicon,
    objects: Vec<SceneObject>,
}

/// The result of a pattern that may have run out of matching input.
type Step<T> = Option<T>;

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

    fn is_object_word(&self, w: &str) -> bool {
        self.lexicon.colours.contains(w)
            || self.lexicon.sizes.contains(w)
            || self.lexicon.kind(w).is_some()
            || w == "table"
            || self.objects.iter().any(|o| o.words.iter().any(|x| x == w))
    }

    /// Resolves object words to one scene constant.
    fn resolve(&self, words: &[&Token]) -> Result<Symbol, NotUnderstood> {
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

fn starts_with(toks: &[Token], phrase: &[String]) -> bool {
    toks.len() >= phrase.len() && toks.iter().zip(phrase).all(|(t, w)| &t.word == w)
}

/// A backtracking matcher over the tokens of one question.
struct Matcher<'p, 'a, 't> {
    p: &'p Parser<'a>,
    toks: &'t [Token],
    pos: usize,
    /// The furthest position any alternative reached (what the reply says was understood).
    furthest: usize,
    /// The first object that failed to resolve inside an otherwise matching pattern.
    error: Option<NotUnderstood>,
}

impl Matcher<'_, '_, '_> {
    fn lex(&self) -> &Lexicon {
        self.p.lexicon
    }

    fn at_end(&self) -> bool {
        self.pos == self.toks.len()
    }

    fn peek(&self) -> Option<&str> {
        self.toks.get(self.pos).map(|t| t.word.as_str())
    }

    /// Consumes `word` if it is next.
    fn eat(&mut self, word: &str) -> bool {
        if self.peek() == Some(word) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    /// Consumes the phrase if it is next.
    fn eat_phrase(&mut self, phrase: &[String]) -> bool {
        if starts_with(&self.toks[self.pos..], phrase) {
            self.pos += phrase.len();
            true
        } else {
            false
        }
    }

    /// Runs `f`; on failure restores the position (and the error, so a failed alternative does
    /// not leave its object error behind).
    fn attempt<T>(&mut self, f: impl FnOnce(&mut Self) -> Step<T>) -> Step<T> {
        let pos = self.pos;
        let error = self.error.clone();
        let r = f(self);
        // Only what a pattern matched counts as understood (a failed alternative may have
        // taken words it then gave back).
        if r.is_some() {
            self.furthest = self.furthest.max(self.pos);
        }
        if r.is_none() {
            self.pos = pos;
            self.error = error;
        }
        r
    }

    fn request(&mut self) -> Step<Question> {
        let alternatives: [fn(&mut Self) -> Step<Question>; 9] = [
            Self::describe,
            Self::describe_step,
            Self::no_plan_phrase,
            Self::why_no_plan,
            Self::belief,
            Self::why_not,
            Self::why,
            Self::what_if,
            Self::goal_request,
        ];
        for alt in alternatives {
            if let Some(q) = self.attempt(|m| {
                let q = alt(m)?;
                m.at_end().then_some(q)
            }) {
                return Some(q);
            }
        }
        None
    }

    fn describe(&mut self) -> Step<Question> {
        let lex = self.p.lexicon;
        let rest = &self.toks[self.pos..];
        lex.describe
            .iter()
            .find(|p| p.len() == rest.len() && starts_with(rest, p))
            .map(|p| {
                self.pos += p.len();
                Question::DescribePlan
            })
    }

    /// A describe-step phrase with its `{S}` step: "what did you do first", "what was your last
    /// action".
    fn describe_step(&mut self) -> Step<Question> {
        let lex = self.p.lexicon;
        for phrase in &lex.describe_step {
            let found = self.attempt(|m| {
                let mut step = None;
                for w in phrase {
                    if w == "{S}" {
                        step = Some(m.step_phrase()?);
                    } else if !m.eat(w) {
                        return None;
                    }
                }
                m.at_end().then_some(step).flatten()
            });
            if let Some(step) = found {
                return Some(Question::DescribeStep { step });
            }
        }
        None
    }

    /// A phrase that opens a why question ("why", "how come", "what was the reason for").
    fn why_word(&mut self) -> bool {
        let lex = self.p.lexicon;
        lex.why.iter().any(|p| self.eat_phrase(p))
    }

    /// The auxiliaries between the why phrase and the verb, in any order ("did you not",
    /// "didn't you", "were you", "have you", "couldn't you", "you"): whether "you" and "not"
    /// were among them.
    fn auxiliaries(&mut self) -> (bool, bool) {
        let (mut you, mut not) = (false, false);
        for _ in 0..4 {
            match self.peek() {
                Some("do" | "be" | "have" | "can" | "could" | "will" | "would") => {}
                Some("you") => you = true,
                Some("not") if !not => not = true,
                _ => break,
            }
            self.pos += 1;
        }
        (you, not)
    }

    fn no_plan_phrase(&mut self) -> Step<Question> {
        let lex = self.p.lexicon;
        let rest = &self.toks[self.pos..];
        lex.no_plan
            .iter()
            .find(|p| p.len() == rest.len() && starts_with(rest, p))
            .map(|p| {
                self.pos += p.len();
                Question::WhyNoPlan { goal: Vec::new() }
            })
    }

    // "why" "can" ("not" "you" | "you" "not") goal ("and" ...)*
    fn why_no_plan(&mut self) -> Step<Question> {
        if !(self.eat("why") && self.eat("can")) {
            return None;
        }
        let negated = self.attempt(|m| (m.eat("not") && m.eat("you")).then_some(()));
        negated.or_else(|| self.attempt(|m| (m.eat("you") && m.eat("not")).then_some(())))?;
        let goal = self.goals()?;
        Some(Question::WhyNoPlan { goal })
    }

    // why aux* "believe" ["that"] belief [step] | why aux* belief [step]
    // | why aux* hold object [step]   (aux: do, be, have, can, you, not)
    fn belief(&mut self) -> Step<Question> {
        if !self.why_word() {
            return None;
        }
        let (you, not) = self.auxiliaries();
        if you {
            if self.eat("believe") {
                if not {
                    return None;
                }
                self.eat("that");
                // "why do you think you are holding the pot"
                if let Some(q) = self.attempt(|m| {
                    let (you, not) = m.auxiliaries();
                    if you {
                        m.holding(not)
                    } else {
                        None
                    }
                }) {
                    return Some(q);
                }
                return self.belief_body(false);
            }
            return self.holding(not);
        }
        self.belief_body(not)
    }

    /// hold object [step] after "you": "why were you holding the pot" asks about the robot's
    /// hand.
    fn holding(&mut self, not: bool) -> Step<Question> {
        let lex = self.p.lexicon;
        if !lex.holding.iter().any(|w| self.eat(w)) {
            return None;
        }
        let x = self.object()?;
        let literal = Symbol::function("in_hand", vec![Symbol::constant(&lex.robot), x]);
        let literal = if not { literal.complement()? } else { literal };
        let step = self.step_phrase();
        Some(Question::Belief {
            literal,
            is_static: false,
            step,
        })
    }

    /// object ["be"|"do"] ["not"] (property | relation object) [step]; `negated` when the
    /// auxiliaries before the subject said "not" ("why isn't the mug on the table").
    fn belief_body(&mut self, negated: bool) -> Step<Question> {
        let subject = self.object()?;
        if !self.eat("be") {
            self.eat("do");
        }
        let negated = self.eat("not") != negated;
        let (literal, is_static) = self
            .attempt(|m| m.property_literal(&subject))
            .or_else(|| self.attempt(|m| m.relation_literal(&subject)))?;
        let literal = if negated {
            literal.complement()?
        } else {
            literal
        };
        let step = self.step_phrase();
        Some(Question::Belief {
            literal,
            is_static,
            step: if is_static { None } else { step },
        })
    }

    /// relation object -> `relation(S, subject, object)`.
    fn relation_literal(&mut self, subject: &Symbol) -> Step<(Symbol, bool)> {
        let lex = self.p.lexicon;
        let name = lex
            .relations
            .iter()
            .flat_map(|r| r.hear.iter().map(move |h| (r, h)))
            .filter(|(_, h)| starts_with(&self.toks[self.pos..], h))
            .max_by_key(|(_, h)| h.len())
            .map(|(r, h)| (r.name.clone(), h.len()));
        let (name, len) = name?;
        self.pos += len;
        let object = self.object()?;
        Some((
            Symbol::function(
                "relation",
                vec![Symbol::constant(&name), subject.clone(), object],
            ),
            false,
        ))
    }

    /// A property phrase, with its `{Y}` object and `{N}` number.
    fn property_literal(&mut self, subject: &Symbol) -> Step<(Symbol, bool)> {
        let lex = self.p.lexicon;
        let robot = Pattern::from(&Symbol::constant(&lex.robot));
        for prop in &lex.properties {
            for phrase in &prop.hear {
                let found = self.attempt(|m| {
                    let mut bindings = vec![
                        ("X".to_string(), Pattern::from(subject)),
                        ("R".to_string(), robot.clone()),
                    ];
                    for w in phrase {
                        match w.as_str() {
                            "{Y}" => {
                                let y = m.object()?;
                                bindings.push(("Y".to_string(), Pattern::from(&y)));
                            }
                            "{N}" => {
                                let n = m.number()?;
                                bindings.push(("N".to_string(), Pattern::Num(n as i32)));
                            }
                            w => {
                                if !m.eat(w) {
                                    return None;
                                }
                            }
                        }
                    }
                    // The phrase must end the literal: a step phrase or the end follows.
                    let save = m.pos;
                    let step_follows = m.step_phrase().is_some() || m.at_end();
                    m.pos = save;
                    step_follows.then_some(bindings)
                });
                if let Some(bindings) = found {
                    if let Some(literal) = prop.literal.substitute(&bindings).to_symbol() {
                        return Some((literal, prop.is_static));
                    }
                }
            }
        }
        None
    }

    // why aux* action [step] with "not" among the auxiliaries ("why didn't you", "why not",
    // "how come you did not", "why couldn't you")
    fn why_not(&mut self) -> Step<Question> {
        if !self.why_word() {
            return None;
        }
        let (_, not) = self.auxiliaries();
        if !not {
            return None;
        }
        let action = self.action()?;
        let step = self.step_phrase();
        Some(Question::WhyNotAction { action, step })
    }

    // why aux* action [step] without "not" ("why did you", "how come you", "what was the reason
    // for", "why have you")
    fn why(&mut self) -> Step<Question> {
        if !self.why_word() {
            return None;
        }
        let (_, not) = self.auxiliaries();
        if not {
            return None;
        }
        let action = self.action()?;
        let step = self.step_phrase();
        Some(Question::WhyAction { action, step })
    }

    // "what" ["would" "happen"] "if" ["you"] ["have"] action [step] ["instead"] [step]
    fn what_if(&mut self) -> Step<Question> {
        if !self.eat("what") {
            return None;
        }
        if self.eat("would") && !self.eat("happen") {
            return None;
        }
        if !self.eat("if") {
            return None;
        }
        self.eat("you");
        self.eat("have");
        let action = self.action()?;
        let mut step = self.step_phrase();
        self.eat("instead");
        if step.is_none() {
            step = self.step_phrase();
        }
        Some(Question::WhatIf { action, step })
    }

    fn goal_request(&mut self) -> Step<Question> {
        let literals = self.goals()?;
        Some(Question::Goal { literals })
    }

    /// goal ("and" (goal | object on object))*
    fn goals(&mut self) -> Step<Vec<Symbol>> {
        let mut goals = self.goal()?;
        // Items are joined by "and" or by commas, which normalization drops.
        while !self.at_end() {
            let and = self.eat("and");
            match self.attempt(Self::goal) {
                Some(g) => goals.extend(g),
                None => match self.attempt(Self::placement) {
                    Some(g) => goals.push(g),
                    None if and => return None,
                    None => break,
                },
            }
        }
        Some(goals)
    }

    /// A goal: "put X on Y" -> `relation(on,X,Y)`; "pick up X" -> `in_hand(rob1,X)`; "put X
    /// and Y on Z" -> one literal per object.
    fn goal(&mut self) -> Step<Vec<Symbol>> {
        if let Some(goals) = self.attempt(Self::shared_goal) {
            return Some(goals);
        }
        let action = self.action()?;
        Some(vec![self.goal_literal(&action)?])
    }

    /// verb [particle] object ("and" object)+ [particle] [on-phrase object]: several objects
    /// with one verb and one target.
    fn shared_goal(&mut self) -> Step<Vec<Symbol>> {
        let lex = self.p.lexicon;
        for verb in &lex.verbs {
            let found = self.attempt(|m| {
                if !m.eat(&verb.verb) {
                    return None;
                }
                let particle = |m: &mut Self| {
                    if let Some(p) = &verb.particle {
                        m.eat(p);
                    }
                };
                particle(m);
                let mut xs = vec![m.object()?];
                // "X, Y and Z": commas are gone, so "and" is optional between items.
                while let Some(x) = m.attempt(|m| {
                    m.eat("and");
                    m.object()
                }) {
                    xs.push(x);
                }
                if xs.len() < 2 {
                    return None;
                }
                particle(m);
                let robot = Pattern::from(&Symbol::constant(&lex.robot));
                let mut bindings = vec![("R".to_string(), robot)];
                if verb.action.args().iter().any(|a| a.is_var("Y")) {
                    m.on_phrase()?;
                    let y = m.object()?;
                    bindings.push(("Y".to_string(), Pattern::from(&y)));
                }
                xs.iter()
                    .map(|x| {
                        let mut b = bindings.clone();
                        b.push(("X".to_string(), Pattern::from(x)));
                        m.goal_literal(&verb.action.substitute(&b))
                    })
                    .collect::<Option<Vec<Symbol>>>()
            });
            if found.is_some() {
                return found;
            }
        }
        None
    }

    /// The goal an action asks for: its effect (`relation(on,X,Y)`, `in_hand(rob1,X)`).
    fn goal_literal(&self, action: &Pattern) -> Option<Symbol> {
        match action.name()? {
            "putdown" => {
                let (x, y) = (action.arg(1)?.to_symbol()?, action.arg(2)?.to_symbol()?);
                Some(Symbol::function(
                    "relation",
                    vec![Symbol::constant("on"), x, y],
                ))
            }
            "pickup" => Some(Symbol::function(
                "in_hand",
                vec![
                    Symbol::constant(&self.lex().robot),
                    action.arg(1)?.to_symbol()?,
                ],
            )),
            _ => None,
        }
    }

    /// "X on Y" after "and" in a goal list.
    fn placement(&mut self) -> Step<Symbol> {
        let x = self.object()?;
        self.on_phrase()?;
        let y = self.object()?;
        Some(Symbol::function(
            "relation",
            vec![Symbol::constant("on"), x, y],
        ))
    }

    /// A phrase of the relation `on` ("on", "on top of").
    fn on_phrase(&mut self) -> Step<()> {
        let lex = self.p.lexicon;
        let on = lex.relations.iter().find(|r| r.name == "on")?;
        for h in &on.hear {
            if self.eat_phrase(h) {
                return Some(());
            }
        }
        None
    }

    /// verb [particle] object [particle] [on-phrase object], over the lexicon's verbs.
    fn action(&mut self) -> Step<Pattern> {
        let lex = self.p.lexicon;
        for verb in &lex.verbs {
            let found = self.attempt(|m| {
                if !m.eat(&verb.verb) {
                    return None;
                }
                let particle = |m: &mut Self| {
                    if let Some(p) = &verb.particle {
                        m.eat(p);
                    }
                };
                particle(m);
                let x = m.object()?;
                particle(m);
                let wants_target = verb.action.args().iter().any(|a| a.is_var("Y"));
                let mut bindings = vec![
                    (
                        "R".to_string(),
                        Pattern::from(&Symbol::constant(&lex.robot)),
                    ),
                    ("X".to_string(), Pattern::from(&x)),
                ];
                if wants_target {
                    // A target that is not named stays a variable: "why did you not put the
                    // white block down" asks about every target.
                    let y = m
                        .attempt(|m| {
                            m.on_phrase()?;
                            m.object()
                        })
                        .map_or_else(|| Pattern::Var("_".into()), |y| Pattern::from(&y));
                    bindings.push(("Y".to_string(), y));
                }
                Some(verb.action.substitute(&bindings))
            });
            if found.is_some() {
                return found;
            }
        }
        None
    }

    /// ["the"|"a"|"an"|"your"|"my"] object-word+, resolved against the scene. A phrase that
    /// does not resolve records the error (the first one) and still matches, so the question's
    /// shape is recognized and the reply can name the object.
    fn object(&mut self) -> Step<Symbol> {
        let before = self.pos;
        for det in ["the", "a", "an", "your", "my"] {
            if self.eat(det) {
                break;
            }
        }
        let start = self.pos;
        while self.pos < self.toks.len() && self.p.is_object_word(&self.toks[self.pos].word) {
            self.pos += 1;
        }
        // Sizes come before the noun ("the small red block"): a size word that ends a longer
        // phrase belongs to what follows ("the can small" is "the can" + "small").
        if self.pos > start + 1 && self.lex().sizes.contains(&self.toks[self.pos - 1].word) {
            self.pos -= 1;
        }
        if self.pos == start {
            self.pos = before;
            return None;
        }
        let words: Vec<&Token> = self.toks[start..self.pos].iter().collect();
        match self.p.resolve(&words) {
            Ok(t) => {
                // A resolved object phrase is understood, whatever follows it.
                self.furthest = self.furthest.max(self.pos);
                Some(t)
            }
            Err(e) => {
                if self.error.is_none() {
                    self.error = Some(e);
                }
                // A stand-in: with the error recorded, the parse fails whatever it builds.
                Some(Symbol::constant(UNRESOLVED))
            }
        }
    }

    fn number(&mut self) -> Step<u32> {
        let n = self.toks.get(self.pos)?.num?;
        self.pos += 1;
        Some(n)
    }

    /// [at|in|on|during] ["the"] ["time"] "step" number | a step phrase of the lexicon.
    fn step_phrase(&mut self) -> Option<u32> {
        let lex = self.p.lexicon;
        for (phrase, n) in &lex.step_phrases {
            if self.eat_phrase(phrase) {
                return Some(*n);
            }
        }
        for phrase in &lex.last_step_phrases {
            if self.eat_phrase(phrase) {
                return Some(LAST);
            }
        }
        self.attempt(|m| {
            for prep in ["at", "in", "on", "during"] {
                if m.eat(prep) {
                    break;
                }
            }
            m.eat("the");
            m.eat("time");
            if !m.eat("step") {
                return None;
            }
            m.number()
        })
    }
}

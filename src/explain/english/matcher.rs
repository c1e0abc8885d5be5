//! The backtracking matcher over the tokens of one question, and the question patterns of the
//! grammar in `explain::english` (describe, why no plan, belief, why not, why, what if, goal
//! request); the phrases they are made of are in `phrases`.
//!
//! Invariants: a failed alternative restores the position and the recorded object error
//! (`Matcher::attempt`); only what a pattern matched counts as understood (`furthest`); a
//! question matches only when a pattern consumes every token.

use super::parser::{starts_with, Parser};
use super::{NotUnderstood, Question};
use crate::control::Symbol;
use crate::explain::lexicon::{Lexicon, Token};

/// The result of a pattern that may have run out of matching input.
pub(super) type Step<T> = Option<T>;

/// A backtracking matcher over the tokens of one question.
pub(super) struct Matcher<'p, 'a, 't> {
    pub(super) p: &'p Parser<'a>,
    pub(super) toks: &'t [Token],
    pub(super) pos: usize,
    /// The furthest position any alternative reached (what the reply says was understood).
    pub(super) furthest: usize,
    /// The first object that failed to resolve inside an otherwise matching pattern.
    pub(super) error: Option<NotUnderstood>,
}

impl Matcher<'_, '_, '_> {
    pub(super) fn lex(&self) -> &Lexicon {
        self.p.lexicon
    }

    pub(super) fn at_end(&self) -> bool {
        self.pos == self.toks.len()
    }

    fn peek(&self) -> Option<&str> {
        self.toks.get(self.pos).map(|t| t.word.as_str())
    }

    /// Consumes `word` if it is next.
    pub(super) fn eat(&mut self, word: &str) -> bool {
        if self.peek() == Some(word) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    /// Consumes the phrase if it is next.
    pub(super) fn eat_phrase(&mut self, phrase: &[String]) -> bool {
        if starts_with(&self.toks[self.pos..], phrase) {
            self.pos += phrase.len();
            true
        } else {
            false
        }
    }

    /// Runs `f`; on failure restores the position (and the error, so a failed alternative does
    /// not leave its object error behind).
    pub(super) fn attempt<T>(&mut self, f: impl FnOnce(&mut Self) -> Step<T>) -> Step<T> {
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

    pub(super) fn request(&mut self) -> Step<Question> {
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

    /// hold object \[step\] after "you": "why were you holding the pot" asks about the robot's
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

    /// object ["be"|"do"] ["not"] (property | relation object) \[step\]; `negated` when the
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
}

//! The phrase patterns the question patterns are made of: belief literals (relations and the
//! lexicon's property phrases), goal lists, actions over the lexicon's verbs, object phrases
//! resolved against the scene, numbers and step phrases.
//!
//! Invariants: an object phrase that does not resolve still matches (as `UNRESOLVED`) with its
//! error recorded, so the question's shape is recognized and the reply names the object; an
//! action's target that is not named stays the variable `_`.

use super::matcher::{Matcher, Step};
use super::parser::starts_with;
use super::LAST;
use crate::control::Symbol;
use crate::explain::lexicon::{Token, Verb};
use crate::explain::pattern::Pattern;

/// The constant an object phrase that names no object of the scene stands for while the rest
/// of the question is matched (the question is then not understood, whatever it built).
const UNRESOLVED: &str = "unresolved_object";

impl Matcher<'_, '_, '_> {
    /// relation object -> `relation(S, subject, object)`.
    pub(super) fn relation_literal(&mut self, subject: &Symbol) -> Step<(Symbol, bool)> {
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
    pub(super) fn property_literal(&mut self, subject: &Symbol) -> Step<(Symbol, bool)> {
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

    /// goal ("and" (goal | object on object))*
    pub(super) fn goals(&mut self) -> Step<Vec<Symbol>> {
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

    /// verb \[particle\] object ("and" object)+ \[particle\] [on-phrase object]: several objects
    /// with one verb and one target.
    fn shared_goal(&mut self) -> Step<Vec<Symbol>> {
        let lex = self.p.lexicon;
        for verb in &lex.verbs {
            let found = self.attempt(|m| {
                m.verb_head(verb)?;
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
                m.particle(verb);
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

    /// The verb `verb` and then its particle, if it has one and it comes next.
    fn verb_head(&mut self, verb: &Verb) -> Step<()> {
        if !self.eat(&verb.verb) {
            return None;
        }
        self.particle(verb);
        Some(())
    }

    /// The particle of `verb` ("up"), if it has one and it comes next.
    fn particle(&mut self, verb: &Verb) {
        if let Some(p) = &verb.particle {
            self.eat(p);
        }
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

    /// verb \[particle\] object \[particle\] [on-phrase object], over the lexicon's verbs.
    pub(super) fn action(&mut self) -> Step<Pattern> {
        let lex = self.p.lexicon;
        for verb in &lex.verbs {
            let found = self.attempt(|m| {
                m.verb_head(verb)?;
                let x = m.object()?;
                m.particle(verb);
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
    pub(super) fn object(&mut self) -> Step<Symbol> {
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
    pub(super) fn step_phrase(&mut self) -> Option<u32> {
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

//! Explanations (docs/domain.md section 6): the robot says why it did what it did, why it did not
//! do something else, and why it believes what it believes, by tracing beliefs through the axioms
//! that produced them.
//!
//! Parts, in dependency order:
//! - [`pattern`]: terms with variables (the lexicon's entries, a question's action whose
//!   target was not named) and the literal helpers on `control::Symbol`, the one form of
//!   ground data here (atoms cross the front door as structured symbols, never as text);
//! - [`lexicon`]: the controlled vocabulary, data read from `domains/ra/lexicon.json`;
//! - [`english`]: questions in controlled English parsed into a [`english::Question`];
//! - [`verbalize`]: literals, actions and the answer templates of docs/domain.md 6.7 in English;
//! - [`tree`]: the proof-tree data type (flat, children before parents) and its independent
//!   re-check against the ground program and the model;
//! - [`build`]: proof trees built over a ground program and an answer set (docs/domain.md 6.2);
//! - [`questions`]: the four questions of docs/domain.md 6.3-6.6 over a program, answer set and
//!   plan;
//! - `oracle`: the adapter from a `control::Control` (ground program, provenance, a model)
//!   to the trees' `Oracle`;
//! - [`history`]: an AL_d planning problem and its executed actions, solved into an oracle;
//! - [`counterfactual`]: what if (the history with another action, re-solved) and why no plan
//!   (a minimal set of goal literals, observations and constraints, by deletion over
//!   assumptions);
//! - `source`: the program as written, evaluated over an answer set (statements matched
//!   against atoms, bodies joined, body aggregates with their elements);
//! - `unfired`: why not at the source level (the rules that could derive an atom and what
//!   blocks them; what would break if an unchosen atom were true);
//! - `generic`: why and why-not of an atom of any program's answer set, as text;
//! - `query`: non-ground queries (`reach(1,X)`): each matching atom explained by `generic`;
//! - [`unsat`]: why a program has no answer set: a minimal unsatisfiable subset of its facts
//!   and constraints, from the solver's cores shrunk by deletion;
//! - `scene` (feature `sim`): why the robot believes an object of a looked-at scene is
//!   (un)stable or (not) occluded, over the classification-mode answer set of `vision::reason`;
//! - [`draw`]: proof trees as DOT text and as SVG drawn here;
//! - [`draw_graph`]: a program's proof as SVG, each literal once with its rule, rows wrapped;
//! - [`h3`]: the H3 experiment's pieces: generated scenes (docs/domain.md 1.6, 7.1), the three
//!   checks of a proof tree (docs/domain.md 7.5) and one trial over a history.
//!
//! Invariants: nothing here reads files or the clock (the lexicon is passed as text or built
//! in); user input (questions) never panics, it is answered by a reply that says what was not
//! understood.

pub mod pattern;
pub mod lexicon;
pub mod english;
pub mod verbalize;
pub mod tree;
pub mod build;
pub mod questions;
pub(crate) mod oracle;
pub mod history;
mod source;
mod unfired;
pub(crate) mod generic;
pub mod unsat;
pub(crate) mod query;
mod support;
#[cfg(feature = "sim")]
pub mod scene;
pub mod counterfactual;
pub mod draw;
pub mod draw_graph;
pub mod h3;

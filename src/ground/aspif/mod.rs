//! Reading and writing aspif version 1, Potassco's intermediate format (what
//! `gringo --output=intermediate` writes and `clasp` reads), to and from [`GroundProgram`].
//!
//! # Format
//!
//! A header line `asp 1 0 <revision> [tags]` (the tag `incremental` allows several steps), then
//! statements, one per line, each a statement type followed by space-separated integers; every
//! step ends with the statement `0`. Statement types: 1 rule (`1 H n a1..an B ...`, `H` 0
//! disjunction / 1 choice, `B` 0 normal body `n l1..ln` / 1 weight body `lower n l1 w1 ..`),
//! 2 minimize (`2 prio n l1 w1 ..`), 3 project, 4 output (`4 m <m bytes of text> n l1..ln`),
//! 5 external (`5 a v`, v 0 free / 1 true / 2 false / 3 release), 6 assume, 7 heuristic
//! (`7 mod a bias prio n l1..ln`), 8 edge (`8 u v n l1..ln`), 9 theory (kept verbatim, the whole
//! line), 10 comment (the rest of the line).
//!
//! # Lucent's comment statements
//!
//! aspif cannot say which atoms apply consistency-restoring rules; Lucent writes them as
//! comment statements, which gringo and clasp ignore:
//!
//! - `10 lucent-cr <appl> <label>`: the CR rule whose application atom is `<appl>` has the ground
//!   label `<label>` (the rest of the line, e.g. `r(1,"a b")`); one line per CR rule, in order.
//! - `10 lucent-prefer <better> <worse>`: `prefer` between two CR rules, by application atom.
//! - `10 lucent-cr-minimize <priority>`: the next statement is the minimize statement that gives
//!   clasp the default cardinality-minimal CR semantics: `2 <priority> n appl1 1 .. appln 1`, over
//!   the application atoms in CR order at a priority above every user priority. It is not a user
//!   minimize: the reader checks it and leaves it out of [`GroundProgram::minimize`].
//!
//! # Invariants
//!
//! - The reader never panics: malformed input gives an [`AspifError`] with the line and column
//!   (1-based, column in bytes) of the offending token. Counts from the input never size an
//!   allocation beyond what the remaining input can hold.
//! - Round trip: `write(&read(text)?) == text` for any text written by gringo (or by this
//!   writer): [`AspifStep::layout`] records the order of the statements, which a
//!   [`GroundProgram`] alone does not keep. `read_program(write_program(p)) == p` for every
//!   program without `origins` (provenance is not part of aspif) whose projection is expressible.
//! - `GroundProgram::num_atoms` is the largest atom mentioned by any statement read so far
//!   (steps of an incremental program accumulate), theory statements excepted.
//! - Only output symbols, comments, theory lines and labels allocate strings while reading.
//! - Every sum the solver can form fits in an `i64`: in a weight body, the bound's and the
//!   weights' absolute values add up to at most [`WEIGHT_SUM_MAX`], and so do the weights of all
//!   minimize statements of one priority (clasp is stricter: it takes 32-bit weights only).

use std::io::Write as _;

use thiserror::Error;

use super::program::{
    Atom, BodyRef, CrRule, Edge, ExternalValue, GroundProgram, HeadKind, Heuristic,
    HeuristicModifier, Lit, Minimize, Output, Prefer, Weight,
};

mod read;
mod write;

use read::{Cursor, Reader};
use write::{write_statement, write_step};

/// The largest atom number aspif allows (literals are 32-bit signed integers).
pub const ATOM_MAX: u32 = i32::MAX as u32;

/// The largest sum of absolute values of a weight body's bound and weights, and of the weights
/// of one minimize priority: 2^62, so that sums, differences and negations of such values, as
/// the solver forms them for weight constraints and cost bounds, cannot overflow an `i64`.
pub const WEIGHT_SUM_MAX: i128 = 1 << 62;

/// What [`AspifErrorKind::WeightsTooLarge`] names for a weight body.
const WEIGHT_BODY: &str = "the bound and the weights of this weight body";

/// Comment tag naming a CR rule: `10 lucent-cr <appl> <label>`.
pub const CR_TAG: &str = "lucent-cr";
/// Comment tag for a preference: `10 lucent-prefer <better> <worse>`.
pub const PREFER_TAG: &str = "lucent-prefer";
/// Comment tag announcing the CR minimize statement: `10 lucent-cr-minimize <priority>`.
pub const CR_MINIMIZE_TAG: &str = "lucent-cr-minimize";

/// An aspif version triple: major, minor, revision.
pub type Version = (u32, u32, u32);

/// A whole aspif file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Aspif {
    /// The version triple of the header (major is always 1, minor 0).
    pub version: Version,
    /// Header tags after the version, e.g. `incremental`.
    pub tags: Vec<String>,
    /// The steps, each ended by a `0` statement; exactly one unless `incremental`.
    pub steps: Vec<AspifStep>,
}

/// One step of an aspif file: the program it adds and the order of its statements.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AspifStep {
    /// The statements of this step (`num_atoms` counts atoms of earlier steps too).
    pub program: GroundProgram,
    /// Text of comment statements other than Lucent's, without the leading `10 `.
    pub comments: Vec<String>,
    /// The statements in file order, as indexes into `program` and `comments`.
    pub layout: Vec<Stmt>,
}

/// One statement of a step, by index into the step's program (or comments).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stmt {
    /// `program.rules[i]`.
    Rule(u32),
    /// `program.minimize[i]`.
    Minimize(u32),
    /// One `3` statement: `program.projections[start..start + len]`.
    Project {
        /// First projection atom of the statement.
        start: u32,
        /// Number of atoms in the statement.
        len: u32,
    },
    /// `program.outputs[i]`.
    Output(u32),
    /// `program.externals[i]`.
    External(u32),
    /// One `6` statement: `program.assumptions[start..start + len]`.
    Assume {
        /// First assumption literal of the statement.
        start: u32,
        /// Number of literals in the statement.
        len: u32,
    },
    /// `program.heuristics[i]`.
    Heuristic(u32),
    /// `program.edges[i]`.
    Edge(u32),
    /// `program.theory[i]`, a whole `9` line.
    Theory(u32),
    /// `comments[i]`, a `10` line that is not Lucent's.
    Comment(u32),
    /// `10 lucent-cr` for `program.cr_rules[i]`.
    CrRule(u32),
    /// `10 lucent-prefer` for `program.prefers[i]`.
    Prefer(u32),
    /// `10 lucent-cr-minimize <priority>` and the minimize statement over the CR atoms after it.
    CrMinimize(Weight),
}

/// A malformed aspif input: where, and what is wrong.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
#[error("aspif:{line}:{column}: {kind}")]
pub struct AspifError {
    /// 1-based line of the offending token.
    pub line: u32,
    /// 1-based column (in bytes) of the offending token.
    pub column: u32,
    /// What is wrong.
    pub kind: AspifErrorKind,
}

/// The kinds of malformed aspif input.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum AspifErrorKind {
    /// The input ended inside a statement or before the end of a step.
    #[error("unexpected end of input, expected {expected}")]
    UnexpectedEof {
        /// What the reader was looking for.
        expected: &'static str,
    },
    /// A token is not what the grammar allows here.
    #[error("expected {expected}, found `{found}`")]
    Expected {
        /// What the reader was looking for.
        expected: &'static str,
        /// The offending token (truncated to 32 bytes).
        found: String,
    },
    /// A number does not fit its field.
    #[error("{what} `{token}` out of range {min}..={max}")]
    OutOfRange {
        /// The field.
        what: &'static str,
        /// The number as written (truncated to 32 bytes).
        token: String,
        /// Smallest allowed value.
        min: i128,
        /// Largest allowed value.
        max: i128,
    },
    /// The header is not `asp 1 0 <revision> [tags]`.
    #[error("bad header: {0}")]
    BadHeader(String),
    /// A statement type that aspif version 1 does not define.
    #[error("unknown statement type {0}")]
    UnknownStatement(i64),
    /// A value outside its enumeration (head type, body type, external value, modifier).
    #[error("{what} must be one of {allowed}, found {found}")]
    BadValue {
        /// The field.
        what: &'static str,
        /// The allowed values.
        allowed: &'static str,
        /// The value found.
        found: i64,
    },
    /// A weight body or a minimize priority whose weights (and bound) are too large to add up.
    #[error("{0} add up to more than 2^62 in absolute value")]
    WeightsTooLarge(String),
    /// A weight body with a negative weight (clasp rejects them too).
    #[error("negative weight {0} in a weight body")]
    NegativeWeight(i64),
    /// A statement is followed by more text on its line.
    #[error("unexpected `{0}` after the end of the statement")]
    Trailing(String),
    /// A statement after the last step of a non-incremental program.
    #[error("statement after the end of the program (the header has no `incremental` tag)")]
    AfterEnd,
    /// An output symbol or comment is not UTF-8.
    #[error("{0} is not valid UTF-8")]
    NotUtf8(&'static str),
    /// A malformed `10 lucent-...` comment.
    #[error("bad Lucent comment: {0}")]
    BadLucentComment(String),
    /// A single program was asked for, but the input has several steps.
    #[error("expected a single step, found {0}")]
    SeveralSteps(usize),
}

/// Reads an aspif file.
pub fn read(src: &[u8]) -> Result<Aspif, AspifError> {
    Reader {
        cur: Cursor { src, pos: 0 },
        num_atoms: 0,
        minimize_totals: std::collections::HashMap::new(),
        head_buf: Vec::new(),
        lit_buf: Vec::new(),
    }
    .file()
}

/// True when `text` starts with aspif's header line, `asp MAJOR MINOR REVISION` (optionally
/// followed by tags), as a ground program from `gringo` or `lucent --mode=gringo` does. No ASP
/// program starts that way (three integers after a constant are a syntax error), so clingo's
/// reading, where such an input is solved as a ground program, takes nothing from text input.
pub fn is_aspif(text: &[u8]) -> bool {
    let line = text.split(|&b| b == b'\n').next().unwrap_or_default();
    let line = line.strip_suffix(b"\r").unwrap_or(line);
    let mut words = line.split(|&b| b == b' ');
    words.next() == Some(b"asp")
        && (0..3).all(|_| {
            words
                .next()
                .is_some_and(|w| !w.is_empty() && w.iter().all(u8::is_ascii_digit))
        })
}

/// Reads an aspif file with a single step (incremental files with one step are accepted).
pub fn read_program(src: &[u8]) -> Result<GroundProgram, AspifError> {
    let aspif = read(src)?;
    if aspif.steps.len() != 1 {
        let end = Cursor {
            src,
            pos: src.len(),
        };
        return Err(end.error_at(src.len(), AspifErrorKind::SeveralSteps(aspif.steps.len())));
    }
    Ok(aspif
        .steps
        .into_iter()
        .next()
        .map(|s| s.program)
        .unwrap_or_default())
}

/// Writes an aspif file, statement by statement in each step's layout.
pub fn write(aspif: &Aspif) -> String {
    let mut out = Vec::with_capacity(1 << 12);
    let (major, minor, revision) = aspif.version;
    let _ = write!(out, "asp {major} {minor} {revision}");
    for tag in &aspif.tags {
        let _ = write!(out, " {tag}");
    }
    out.push(b'\n');
    for step in &aspif.steps {
        write_step(&mut out, step);
    }
    // Everything written is ASCII except symbols, comments and labels, which are `String`s.
    String::from_utf8(out).expect("aspif writer produced UTF-8 from UTF-8 parts")
}

/// Writes a program as a single-step aspif file in the canonical layout (see
/// [`AspifStep::from_program`]).
pub fn write_program(program: &GroundProgram) -> String {
    let mut out = Vec::with_capacity(1 << 12);
    write_program_to(program, &mut out).expect("writing to memory does not fail");
    String::from_utf8(out).expect("aspif writer produced UTF-8 from UTF-8 parts")
}

/// Like [`write_program`], streaming to `w` in blocks (a large ground program is never held
/// as text in memory).
pub fn write_program_to(
    program: &GroundProgram,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let mut buf = Vec::with_capacity(1 << 16);
    buf.extend_from_slice(b"asp 1 0 0\n");
    for stmt in canonical_layout(program) {
        // A free theory atom is an external for the solver only (see `TheoryAtom`).
        if let Stmt::External(i) = stmt {
            let a = program.externals[i as usize].0;
            if program.theory_atoms.iter().any(|t| t.atom == a) {
                continue;
            }
        }
        write_statement(&mut buf, program, &[], stmt);
        if buf.len() >= 1 << 16 {
            w.write_all(&buf)?;
            buf.clear();
        }
    }
    write::write_theory_atoms(&mut buf, &program.theory_atoms);
    buf.extend_from_slice(b"0\n");
    w.write_all(&buf)
}

impl AspifStep {
    /// A step holding `program` in the canonical layout: rules, user minimize statements, one
    /// projection statement, outputs, externals, one assumption statement, heuristics, edges,
    /// theory lines, then the CR comments and, when there are CR rules, the CR minimize at a
    /// priority one above the highest user priority (0 without user minimize statements).
    pub fn from_program(program: GroundProgram) -> AspifStep {
        AspifStep {
            layout: canonical_layout(&program),
            program,
            comments: Vec::new(),
        }
    }
}

/// The statements of `program` in the canonical layout (see [`AspifStep::from_program`]).
fn canonical_layout(program: &GroundProgram) -> Vec<Stmt> {
    let mut layout = Vec::new();
    let idx = |n: usize| 0..n as u32;
    layout.extend(idx(program.rules.len()).map(Stmt::Rule));
    layout.extend(idx(program.minimize.len()).map(Stmt::Minimize));
    if !program.projections.is_empty() {
        layout.push(Stmt::Project {
            start: 0,
            len: program.projections.len() as u32,
        });
    }
    layout.extend(idx(program.outputs.len()).map(Stmt::Output));
    layout.extend(idx(program.externals.len()).map(Stmt::External));
    if !program.assumptions.is_empty() {
        layout.push(Stmt::Assume {
            start: 0,
            len: program.assumptions.len() as u32,
        });
    }
    layout.extend(idx(program.heuristics.len()).map(Stmt::Heuristic));
    layout.extend(idx(program.edges.len()).map(Stmt::Edge));
    layout.extend(idx(program.theory.len()).map(Stmt::Theory));
    layout.extend(idx(program.cr_rules.len()).map(Stmt::CrRule));
    layout.extend(idx(program.prefers.len()).map(Stmt::Prefer));
    if !program.cr_rules.is_empty() {
        layout.push(Stmt::CrMinimize(cr_priority(program)));
    }
    layout
}

/// The priority of the CR minimize statement: one above every user priority.
pub fn cr_priority(program: &GroundProgram) -> Weight {
    program
        .minimize
        .iter()
        .map(|m| m.priority.saturating_add(1))
        .max()
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::program::{Body, Rule};

    #[test]
    fn reads_and_writes_a_small_program() {
        let text = "asp 1 0 0\n1 0 1 1 0 0\n1 1 2 2 3 1 2 2 1 2 -1 3\n4 1 a 1 1\n0\n";
        let aspif = read(text.as_bytes()).unwrap();
        let p = &aspif.steps[0].program;
        assert_eq!(p.num_atoms, 3);
        assert_eq!(p.rules.len(), 2);
        assert_eq!(
            p.rules.get(1).body,
            BodyRef::Weight {
                lower: 2,
                lits: &[(1, 2), (-1, 3)]
            }
        );
        assert_eq!(write(&aspif), text);
    }

    #[test]
    fn empty_comments_round_trip() {
        let text = "asp 1 0 0\n10\n10 x y\n0\n";
        assert_eq!(write(&read(text.as_bytes()).unwrap()), text);
    }

    #[test]
    fn symbols_may_contain_spaces() {
        let text = "asp 1 0 0\n4 5 \"x y\" 1 -19\n0\n";
        let p = read_program(text.as_bytes()).unwrap();
        assert_eq!(p.outputs[0].symbol, "\"x y\"");
        assert_eq!(p.num_atoms, 19);
    }

    #[test]
    fn cr_rules_round_trip() {
        let mut p = GroundProgram::new();
        let a = p.new_atom();
        let b = p.new_atom();
        p.rules.push(Rule {
            head_kind: HeadKind::Choice,
            head: vec![a, b],
            body: Body::Normal(vec![]),
        });
        p.minimize.push(Minimize {
            priority: 3,
            lits: vec![(a as Lit, 2)],
        });
        p.cr_rules.push(CrRule {
            appl: a,
            label: "r(1,\"a b\")".into(),
        });
        p.cr_rules.push(CrRule {
            appl: b,
            label: "s".into(),
        });
        p.prefers.push(Prefer {
            better: a,
            worse: b,
        });
        let text = write_program(&p);
        assert!(text.contains("10 lucent-cr 1 r(1,\"a b\")\n"));
        assert!(text.contains("10 lucent-cr-minimize 4\n2 4 2 1 1 2 1\n"));
        assert_eq!(read_program(text.as_bytes()).unwrap(), p);
    }

    #[test]
    fn errors_have_positions() {
        let e = read(b"asp 1 0 0\n1 0 1 x 0 0\n0\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 7));
        let e = read(b"asp 1 0 0\n1 0 1 0 0 0\n0\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 7));
        let e = read(b"asp 1 0 0\n11 0\n0\n").unwrap_err();
        assert_eq!(e.kind, AspifErrorKind::UnknownStatement(11));
    }
}

#[cfg(test)]
mod header_tests {
    use super::is_aspif;

    #[test]
    fn only_aspif_headers_are_aspif() {
        assert!(is_aspif(b"asp 1 0 0\n1 0 1 1 0 0\n0\n"));
        assert!(is_aspif(b"asp 1 0 0 incremental\r\n0\n"));
        assert!(is_aspif(b"asp 1 0 0"));
        assert!(!is_aspif(b"asp :- b.\n"));
        assert!(!is_aspif(b"asp(1). asp 1 0 0\n"));
        assert!(!is_aspif(b"asp 1 0\n"));
        assert!(!is_aspif(b"asp 1 0 x\n"));
        assert!(!is_aspif(b"% asp 1 0 0\n"));
        assert!(!is_aspif(b""));
    }
}

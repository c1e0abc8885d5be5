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
    Atom, Body, BodyRef, CrRule, Edge, ExternalValue, GroundProgram, HeadKind, Heuristic,
    HeuristicModifier, Lit, Minimize, Output, Prefer, Weight,
};

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
    }
    .file()
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
        write_statement(&mut buf, program, &[], stmt);
        if buf.len() >= 1 << 16 {
            w.write_all(&buf)?;
            buf.clear();
        }
    }
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

fn write_step(out: &mut Vec<u8>, step: &AspifStep) {
    write_statements(out, &step.program, &step.comments, &step.layout);
}

/// Writes the statements of `layout` over `p` and `comments`, then the step's closing `0`.
fn write_statements(out: &mut Vec<u8>, p: &GroundProgram, comments: &[String], layout: &[Stmt]) {
    for &stmt in layout {
        write_statement(out, p, comments, stmt);
    }
    out.extend_from_slice(b"0\n");
}

/// Writes one statement and its newline.
fn write_statement(out: &mut Vec<u8>, p: &GroundProgram, comments: &[String], stmt: Stmt) {
    match stmt {
        Stmt::Rule(i) => {
            let rule = p.rules.get(i as usize);
            out.extend_from_slice(match rule.head_kind {
                HeadKind::Disjunction => b"1 0",
                HeadKind::Choice => b"1 1",
            });
            write_lits(out, rule.head);
            match rule.body {
                BodyRef::Normal(lits) => {
                    out.extend_from_slice(b" 0");
                    write_lits(out, lits);
                }
                BodyRef::Weight { lower, lits } => {
                    out.extend_from_slice(b" 1");
                    push_int(out, lower);
                    write_wlits(out, lits);
                }
            }
        }
        Stmt::Minimize(i) => {
            let m = &p.minimize[i as usize];
            out.push(b'2');
            push_int(out, m.priority);
            write_wlits(out, &m.lits);
        }
        Stmt::Project { start, len } => {
            out.push(b'3');
            write_lits(out, &p.projections[start as usize..(start + len) as usize]);
        }
        Stmt::Output(i) => {
            let o = &p.outputs[i as usize];
            let _ = write!(out, "4 {} {}", o.symbol.len(), o.symbol);
            write_lits(out, &o.condition);
        }
        Stmt::External(i) => {
            let (atom, value) = p.externals[i as usize];
            let v = match value {
                ExternalValue::Free => 0,
                ExternalValue::True => 1,
                ExternalValue::False => 2,
                ExternalValue::Release => 3,
            };
            let _ = write!(out, "5 {atom} {v}");
        }
        Stmt::Assume { start, len } => {
            out.push(b'6');
            write_lits(out, &p.assumptions[start as usize..(start + len) as usize]);
        }
        Stmt::Heuristic(i) => {
            let h = &p.heuristics[i as usize];
            let m = match h.modifier {
                HeuristicModifier::Level => 0,
                HeuristicModifier::Sign => 1,
                HeuristicModifier::Factor => 2,
                HeuristicModifier::Init => 3,
                HeuristicModifier::True => 4,
                HeuristicModifier::False => 5,
            };
            let _ = write!(out, "7 {m} {} {} {}", h.atom, h.bias, h.priority);
            write_lits(out, &h.condition);
        }
        Stmt::Edge(i) => {
            let e = &p.edges[i as usize];
            let _ = write!(out, "8 {} {}", e.from, e.to);
            write_lits(out, &e.condition);
        }
        Stmt::Theory(i) => {
            let line = &p.theory[i as usize];
            assert!(
                !line.contains('\n'),
                "a theory line must not contain a newline"
            );
            out.extend_from_slice(line.as_bytes());
        }
        Stmt::Comment(i) => {
            let text = &comments[i as usize];
            assert!(
                !text.contains('\n'),
                "an aspif comment must not contain a newline"
            );
            if text.is_empty() {
                out.extend_from_slice(b"10");
            } else {
                let _ = write!(out, "10 {text}");
            }
        }
        Stmt::CrRule(i) => {
            let cr = &p.cr_rules[i as usize];
            assert!(
                !cr.label.contains('\n'),
                "a CR label must not contain a newline"
            );
            let _ = write!(out, "10 {CR_TAG} {} {}", cr.appl, cr.label);
        }
        Stmt::Prefer(i) => {
            let pr = &p.prefers[i as usize];
            let _ = write!(out, "10 {PREFER_TAG} {} {}", pr.better, pr.worse);
        }
        Stmt::CrMinimize(priority) => {
            let _ = write!(
                out,
                "10 {CR_MINIMIZE_TAG} {priority}\n2 {priority} {}",
                p.cr_rules.len()
            );
            for cr in &p.cr_rules {
                let _ = write!(out, " {} 1", cr.appl);
            }
        }
    }
    out.push(b'\n');
}

/// Writes ` n x1 .. xn`.
fn write_lits<T: Copy + Into<i64>>(out: &mut Vec<u8>, lits: &[T]) {
    push_int(out, lits.len() as i64);
    for &l in lits {
        push_int(out, l.into());
    }
}

/// Writes ` n l1 w1 .. ln wn`.
fn write_wlits(out: &mut Vec<u8>, lits: &[(Lit, Weight)]) {
    push_int(out, lits.len() as i64);
    for &(l, w) in lits {
        push_int(out, l.into());
        push_int(out, w);
    }
}

/// Writes a space and then `v` in decimal (the writer's hot path; `write!` is several times
/// slower).
fn push_int(out: &mut Vec<u8>, v: i64) {
    let mut buf = [0u8; 21];
    let mut i = buf.len();
    let mut n = v.unsigned_abs();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    if v < 0 {
        i -= 1;
        buf[i] = b'-';
    }
    out.push(b' ');
    out.extend_from_slice(&buf[i..]);
}

/// A position in the input; all token reading goes through it.
struct Cursor<'a> {
    src: &'a [u8],
    pos: usize,
}

impl<'a> Cursor<'a> {
    fn error_at(&self, pos: usize, kind: AspifErrorKind) -> AspifError {
        let pos = pos.min(self.src.len());
        let before = &self.src[..pos];
        let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
        let line_start = before
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |i| i + 1);
        AspifError {
            line: u32::try_from(line).unwrap_or(u32::MAX),
            column: u32::try_from(pos - line_start + 1).unwrap_or(u32::MAX),
            kind,
        }
    }

    fn skip_blanks(&mut self) {
        while let Some(b' ' | b'\t' | b'\r') = self.src.get(self.pos) {
            self.pos += 1;
        }
    }

    /// The token starting at `pos` (up to whitespace), truncated, for messages.
    fn token_text(&self, pos: usize) -> String {
        let rest = &self.src[pos.min(self.src.len())..];
        let end = rest
            .iter()
            .position(|b| b.is_ascii_whitespace())
            .unwrap_or(rest.len());
        String::from_utf8_lossy(&rest[..end.min(32)]).into_owned()
    }

    fn at_end(&self) -> bool {
        self.pos >= self.src.len()
    }

    /// Reads an integer token in `min..=max`.
    fn int(&mut self, what: &'static str, min: i64, max: i64) -> Result<i64, AspifError> {
        self.skip_blanks();
        let start = self.pos;
        match self.src.get(self.pos) {
            None => {
                return Err(self.error_at(start, AspifErrorKind::UnexpectedEof { expected: what }))
            }
            Some(b'\n') => {
                return Err(self.error_at(
                    start,
                    AspifErrorKind::Expected {
                        expected: what,
                        found: "end of line".into(),
                    },
                ))
            }
            _ => {}
        }
        let negative = self.src[self.pos] == b'-';
        if negative {
            self.pos += 1;
        }
        let digits = self.pos;
        let mut magnitude: u64 = 0;
        let mut overflow = false;
        while let Some(&b) = self.src.get(self.pos) {
            if !b.is_ascii_digit() {
                break;
            }
            match magnitude
                .checked_mul(10)
                .and_then(|m| m.checked_add(u64::from(b - b'0')))
            {
                Some(m) => magnitude = m,
                None => overflow = true,
            }
            self.pos += 1;
        }
        // An overflowing magnitude is beyond every field's range; the check below reports it.
        let mut value = if overflow {
            i128::from(u64::MAX) + 1
        } else {
            i128::from(magnitude)
        };
        let ends_token = matches!(
            self.src.get(self.pos),
            None | Some(b' ' | b'\t' | b'\r' | b'\n')
        );
        if self.pos == digits || !ends_token {
            return Err(self.error_at(
                start,
                AspifErrorKind::Expected {
                    expected: what,
                    found: self.token_text(start),
                },
            ));
        }
        if negative {
            value = -value;
        }
        if value < i128::from(min) || value > i128::from(max) {
            return Err(self.error_at(
                start,
                AspifErrorKind::OutOfRange {
                    what,
                    token: self.token_text(start),
                    min: min.into(),
                    max: max.into(),
                },
            ));
        }
        Ok(value as i64)
    }

    /// Reads a count of items (the caller bounds allocations with `capacity`).
    fn count(&mut self, what: &'static str) -> Result<usize, AspifError> {
        Ok(self.int(what, 0, i64::from(u32::MAX))? as usize)
    }

    /// A capacity for `n` items that cannot exceed what the remaining input can hold.
    fn capacity(&self, n: usize) -> usize {
        n.min((self.src.len() - self.pos.min(self.src.len())) / 2)
    }

    fn atom(&mut self) -> Result<Atom, AspifError> {
        Ok(self.int("atom", 1, i64::from(ATOM_MAX))? as Atom)
    }

    fn lit(&mut self) -> Result<Lit, AspifError> {
        self.skip_blanks();
        let start = self.pos;
        let l = self.int("literal", -i64::from(ATOM_MAX), i64::from(ATOM_MAX))?;
        if l == 0 {
            return Err(self.error_at(
                start,
                AspifErrorKind::OutOfRange {
                    what: "literal (0 is not a literal)",
                    token: "0".into(),
                    min: -i128::from(ATOM_MAX),
                    max: i128::from(ATOM_MAX),
                },
            ));
        }
        Ok(l as Lit)
    }

    /// Ends a statement: only blanks may remain on the line.
    fn end_of_line(&mut self) -> Result<(), AspifError> {
        self.skip_blanks();
        match self.src.get(self.pos) {
            None => Ok(()),
            Some(b'\n') => {
                self.pos += 1;
                Ok(())
            }
            Some(_) => Err(self.error_at(
                self.pos,
                AspifErrorKind::Trailing(self.token_text(self.pos)),
            )),
        }
    }

    /// The rest of the line (without the newline), consuming the newline.
    fn rest_of_line(&mut self) -> &'a [u8] {
        let rest = &self.src[self.pos..];
        let len = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        self.pos += len;
        if self.pos < self.src.len() {
            self.pos += 1;
        }
        let line = &rest[..len];
        line.strip_suffix(b"\r").unwrap_or(line)
    }
}

/// Reading state: the cursor, the largest atom seen and, per minimize priority, the sum of the
/// absolute values of its weights so far (all steps: the solver adds them up the same way).
struct Reader<'a> {
    cur: Cursor<'a>,
    num_atoms: u32,
    minimize_totals: std::collections::HashMap<Weight, i128>,
}

/// What a step's reader remembers about the CR minimize while the step is open.
struct CrMinimizeSeen {
    priority: Weight,
    lits: Vec<(Lit, Weight)>,
    pos: usize,
}

impl<'a> Reader<'a> {
    fn note_atom(&mut self, a: Atom) {
        self.num_atoms = self.num_atoms.max(a);
    }

    fn note_lit(&mut self, l: Lit) {
        self.note_atom(l.unsigned_abs());
    }

    fn lits(&mut self) -> Result<Vec<Lit>, AspifError> {
        let n = self.cur.count("number of literals")?;
        let mut lits = Vec::with_capacity(self.cur.capacity(n));
        for _ in 0..n {
            let l = self.cur.lit()?;
            self.note_lit(l);
            lits.push(l);
        }
        Ok(lits)
    }

    fn atoms(&mut self) -> Result<Vec<Atom>, AspifError> {
        let n = self.cur.count("number of atoms")?;
        let mut atoms = Vec::with_capacity(self.cur.capacity(n));
        for _ in 0..n {
            let a = self.cur.atom()?;
            self.note_atom(a);
            atoms.push(a);
        }
        Ok(atoms)
    }

    /// Reads weighted literals; `total` is the running sum of absolute values (of the bound and
    /// weights read before), checked against [`WEIGHT_SUM_MAX`] at every weight.
    fn wlits(
        &mut self,
        allow_negative: bool,
        what: &str,
        total: &mut i128,
    ) -> Result<Vec<(Lit, Weight)>, AspifError> {
        let n = self.cur.count("number of weighted literals")?;
        let mut lits = Vec::with_capacity(self.cur.capacity(n));
        for _ in 0..n {
            let l = self.cur.lit()?;
            self.note_lit(l);
            self.cur.skip_blanks();
            let at = self.cur.pos;
            let w = self.cur.int("weight", i64::MIN, i64::MAX)?;
            if w < 0 && !allow_negative {
                return Err(self.cur.error_at(at, AspifErrorKind::NegativeWeight(w)));
            }
            *total += i128::from(w).abs();
            if *total > WEIGHT_SUM_MAX {
                return Err(self
                    .cur
                    .error_at(at, AspifErrorKind::WeightsTooLarge(what.to_string())));
            }
            lits.push((l, w));
        }
        Ok(lits)
    }

    fn file(mut self) -> Result<Aspif, AspifError> {
        let (version, tags) = self.header()?;
        let incremental = tags.iter().any(|t| t == "incremental");
        let mut steps = Vec::new();
        loop {
            steps.push(self.step()?);
            skip_whitespace(&mut self.cur);
            if self.cur.at_end() {
                break;
            }
            if !incremental {
                return Err(self.cur.error_at(self.cur.pos, AspifErrorKind::AfterEnd));
            }
        }
        Ok(Aspif {
            version,
            tags,
            steps,
        })
    }

    fn header(&mut self) -> Result<(Version, Vec<String>), AspifError> {
        let line_start = self.cur.pos;
        let line = self.cur.rest_of_line();
        let bad = |cur: &Cursor, msg: &str| {
            cur.error_at(line_start, AspifErrorKind::BadHeader(msg.into()))
        };
        let line = std::str::from_utf8(line).map_err(|_| bad(&self.cur, "not UTF-8"))?;
        let mut words = line.split_ascii_whitespace();
        if words.next() != Some("asp") {
            return Err(bad(
                &self.cur,
                "the input does not start with `asp` (is it aspif?)",
            ));
        }
        let mut num = |name: &str| -> Result<u32, AspifError> {
            words
                .next()
                .and_then(|w| w.parse::<u32>().ok())
                .ok_or_else(|| bad(&self.cur, &format!("missing or bad {name} version number")))
        };
        let version = (num("major")?, num("minor")?, num("revision")?);
        if version.0 != 1 || version.1 != 0 {
            return Err(bad(
                &self.cur,
                &format!(
                    "unsupported version {}.{}.{} (only 1.0.x)",
                    version.0, version.1, version.2
                ),
            ));
        }
        let tags = words.map(str::to_owned).collect();
        Ok((version, tags))
    }

    fn step(&mut self) -> Result<AspifStep, AspifError> {
        let mut step = AspifStep::default();
        let mut cr_minimize: Option<CrMinimizeSeen> = None;
        let mut expect_cr_minimize: Option<(Weight, usize)> = None;
        loop {
            skip_whitespace(&mut self.cur);
            let stmt_pos = self.cur.pos;
            if self.cur.at_end() {
                return Err(self.cur.error_at(
                    stmt_pos,
                    AspifErrorKind::UnexpectedEof {
                        expected: "a statement or `0` (end of step)",
                    },
                ));
            }
            let kind = self.cur.int("statement type", 0, i64::MAX)?;
            if let Some((priority, _)) = expect_cr_minimize {
                if kind != 2 {
                    return Err(self.cur.error_at(
                        stmt_pos,
                        AspifErrorKind::BadLucentComment(format!(
                        "`{CR_MINIMIZE_TAG} {priority}` must be followed by a minimize statement"
                    )),
                    ));
                }
            }
            let p = &mut step.program;
            match kind {
                0 => {
                    self.cur.end_of_line()?;
                    break;
                }
                1 => {
                    let head_kind = match self.cur.int("head type", 0, i64::MAX)? {
                        0 => HeadKind::Disjunction,
                        1 => HeadKind::Choice,
                        v => {
                            return Err(self.bad_value(
                                "head type",
                                "0 (disjunction), 1 (choice)",
                                v,
                            ))
                        }
                    };
                    let head = self.atoms()?;
                    let body = match self.cur.int("body type", 0, i64::MAX)? {
                        0 => Body::Normal(self.lits()?),
                        1 => {
                            self.cur.skip_blanks();
                            let at = self.cur.pos;
                            let lower = self.cur.int("lower bound", i64::MIN, i64::MAX)?;
                            let mut total = i128::from(lower).abs();
                            if total > WEIGHT_SUM_MAX {
                                return Err(self.cur.error_at(
                                    at,
                                    AspifErrorKind::WeightsTooLarge(WEIGHT_BODY.into()),
                                ));
                            }
                            Body::Weight {
                                lower,
                                lits: self.wlits(false, WEIGHT_BODY, &mut total)?,
                            }
                        }
                        v => return Err(self.bad_value("body type", "0 (normal), 1 (weight)", v)),
                    };
                    let p = &mut step.program;
                    step.layout.push(Stmt::Rule(p.rules.len() as u32));
                    p.rules.push_parts(head_kind, &head, body.as_ref());
                }
                2 => {
                    let priority = self.cur.int("priority", i64::MIN, i64::MAX)?;
                    let mut total = self.minimize_totals.get(&priority).copied().unwrap_or(0);
                    let what =
                        format!("the weights of the minimize statements of priority {priority}");
                    let lits = self.wlits(true, &what, &mut total)?;
                    self.minimize_totals.insert(priority, total);
                    if let Some((expected, marker_pos)) = expect_cr_minimize.take() {
                        if priority != expected {
                            return Err(self.cur.error_at(stmt_pos, AspifErrorKind::BadLucentComment(
                                format!("CR minimize has priority {priority}, the comment says {expected}"),
                            )));
                        }
                        step.layout.push(Stmt::CrMinimize(priority));
                        cr_minimize = Some(CrMinimizeSeen {
                            priority,
                            lits,
                            pos: marker_pos,
                        });
                    } else {
                        let p = &mut step.program;
                        step.layout.push(Stmt::Minimize(p.minimize.len() as u32));
                        p.minimize.push(Minimize { priority, lits });
                    }
                }
                3 => {
                    let atoms = self.atoms()?;
                    let p = &mut step.program;
                    step.layout.push(Stmt::Project {
                        start: p.projections.len() as u32,
                        len: atoms.len() as u32,
                    });
                    p.projections.extend(atoms);
                }
                4 => {
                    let symbol = self.symbol()?;
                    let condition = self.lits()?;
                    let p = &mut step.program;
                    step.layout.push(Stmt::Output(p.outputs.len() as u32));
                    p.outputs.push(Output { symbol, condition });
                }
                5 => {
                    let atom = self.cur.atom()?;
                    self.note_atom(atom);
                    let value = match self.cur.int("external value", 0, i64::MAX)? {
                        0 => ExternalValue::Free,
                        1 => ExternalValue::True,
                        2 => ExternalValue::False,
                        3 => ExternalValue::Release,
                        v => return Err(self.bad_value("external value", "0..=3", v)),
                    };
                    let p = &mut step.program;
                    step.layout.push(Stmt::External(p.externals.len() as u32));
                    p.externals.push((atom, value));
                }
                6 => {
                    let lits = self.lits()?;
                    let p = &mut step.program;
                    step.layout.push(Stmt::Assume {
                        start: p.assumptions.len() as u32,
                        len: lits.len() as u32,
                    });
                    p.assumptions.extend(lits);
                }
                7 => {
                    let modifier = match self.cur.int("heuristic modifier", 0, i64::MAX)? {
                        0 => HeuristicModifier::Level,
                        1 => HeuristicModifier::Sign,
                        2 => HeuristicModifier::Factor,
                        3 => HeuristicModifier::Init,
                        4 => HeuristicModifier::True,
                        5 => HeuristicModifier::False,
                        v => return Err(self.bad_value("heuristic modifier", "0..=5", v)),
                    };
                    let atom = self.cur.atom()?;
                    self.note_atom(atom);
                    let bias = self
                        .cur
                        .int("heuristic bias", i32::MIN.into(), i32::MAX.into())?
                        as i32;
                    let priority = self.cur.int("heuristic priority", 0, u32::MAX.into())? as u32;
                    let condition = self.lits()?;
                    let p = &mut step.program;
                    step.layout.push(Stmt::Heuristic(p.heuristics.len() as u32));
                    p.heuristics.push(Heuristic {
                        modifier,
                        atom,
                        bias,
                        priority,
                        condition,
                    });
                }
                8 => {
                    let from = self
                        .cur
                        .int("edge node", i32::MIN.into(), i32::MAX.into())?
                        as i32;
                    let to = self
                        .cur
                        .int("edge node", i32::MIN.into(), i32::MAX.into())?
                        as i32;
                    let condition = self.lits()?;
                    let p = &mut step.program;
                    step.layout.push(Stmt::Edge(p.edges.len() as u32));
                    p.edges.push(Edge {
                        from,
                        to,
                        condition,
                    });
                }
                9 => {
                    self.cur.pos = stmt_pos;
                    let line = self.cur.rest_of_line();
                    let line = std::str::from_utf8(line).map_err(|_| {
                        self.cur
                            .error_at(stmt_pos, AspifErrorKind::NotUtf8("theory statement"))
                    })?;
                    step.layout.push(Stmt::Theory(p.theory.len() as u32));
                    p.theory.push(line.to_owned());
                    continue;
                }
                10 => {
                    match self.cur.src.get(self.cur.pos) {
                        Some(b' ') => self.cur.pos += 1,
                        None | Some(b'\n') => {}
                        Some(_) => {
                            return Err(self.cur.error_at(
                                self.cur.pos,
                                AspifErrorKind::Trailing(self.cur.token_text(self.cur.pos)),
                            ))
                        }
                    }
                    let text_pos = self.cur.pos;
                    let text = self.cur.rest_of_line();
                    let text = std::str::from_utf8(text).map_err(|_| {
                        self.cur
                            .error_at(text_pos, AspifErrorKind::NotUtf8("comment"))
                    })?;
                    self.comment(&mut step, text, text_pos, &mut expect_cr_minimize)?;
                    continue;
                }
                other => {
                    return Err(self
                        .cur
                        .error_at(stmt_pos, AspifErrorKind::UnknownStatement(other)));
                }
            }
            self.cur.end_of_line()?;
        }
        if let Some((priority, pos)) = expect_cr_minimize {
            return Err(self.cur.error_at(
                pos,
                AspifErrorKind::BadLucentComment(format!(
                    "`{CR_MINIMIZE_TAG} {priority}` is not followed by a minimize statement"
                )),
            ));
        }
        if let Some(seen) = cr_minimize {
            let expected: Vec<(Lit, Weight)> = step
                .program
                .cr_rules
                .iter()
                .map(|cr| (cr.appl as Lit, 1))
                .collect();
            if seen.lits != expected {
                return Err(self.cur.error_at(
                    seen.pos,
                    AspifErrorKind::BadLucentComment(format!(
                        "the CR minimize at priority {} is not `appl 1` over the CR atoms in order",
                        seen.priority
                    )),
                ));
            }
        }
        step.program.num_atoms = self.num_atoms;
        Ok(step)
    }

    /// Handles a comment statement: Lucent's tags are parsed, other text is kept.
    fn comment(
        &mut self,
        step: &mut AspifStep,
        text: &str,
        text_pos: usize,
        expect_cr_minimize: &mut Option<(Weight, usize)>,
    ) -> Result<(), AspifError> {
        let bad = |msg: String| {
            self.cur
                .error_at(text_pos, AspifErrorKind::BadLucentComment(msg))
        };
        let (tag, rest) = text.split_once(' ').unwrap_or((text, ""));
        let p = &mut step.program;
        match tag {
            CR_TAG => {
                let (appl, label) = rest.split_once(' ').unwrap_or((rest, ""));
                let appl = parse_atom(appl).ok_or_else(|| bad(format!("bad CR atom `{appl}`")))?;
                if label.is_empty() {
                    return Err(bad(format!("CR rule {appl} has no label")));
                }
                self.num_atoms = self.num_atoms.max(appl);
                step.layout.push(Stmt::CrRule(p.cr_rules.len() as u32));
                p.cr_rules.push(CrRule {
                    appl,
                    label: label.to_owned(),
                });
            }
            PREFER_TAG => {
                let mut words = rest.split(' ');
                let pair = (
                    words.next().and_then(parse_atom),
                    words.next().and_then(parse_atom),
                );
                let (Some(better), Some(worse), None) = (pair.0, pair.1, words.next()) else {
                    return Err(bad(format!(
                        "`{PREFER_TAG}` needs two atoms, found `{rest}`"
                    )));
                };
                self.num_atoms = self.num_atoms.max(better).max(worse);
                step.layout.push(Stmt::Prefer(p.prefers.len() as u32));
                p.prefers.push(Prefer { better, worse });
            }
            CR_MINIMIZE_TAG => {
                let priority = rest
                    .parse::<Weight>()
                    .map_err(|_| bad(format!("bad CR priority `{rest}`")))?;
                *expect_cr_minimize = Some((priority, text_pos));
            }
            _ => {
                step.layout.push(Stmt::Comment(step.comments.len() as u32));
                step.comments.push(text.to_owned());
            }
        }
        Ok(())
    }

    /// Reads `m <m bytes>` of an output statement.
    fn symbol(&mut self) -> Result<String, AspifError> {
        let len = self.cur.count("symbol length")?;
        let at = self.cur.pos;
        if self.cur.src.get(at) != Some(&b' ') {
            return Err(self.cur.error_at(
                at,
                AspifErrorKind::Expected {
                    expected: "a space before the symbol",
                    found: self.cur.token_text(at),
                },
            ));
        }
        let start = at + 1;
        let end = start
            .checked_add(len)
            .filter(|&e| e <= self.cur.src.len())
            .ok_or_else(|| {
                self.cur.error_at(
                    start,
                    AspifErrorKind::UnexpectedEof {
                        expected: "the output symbol's bytes",
                    },
                )
            })?;
        let text = std::str::from_utf8(&self.cur.src[start..end]).map_err(|_| {
            self.cur
                .error_at(start, AspifErrorKind::NotUtf8("output symbol"))
        })?;
        self.cur.pos = end;
        Ok(text.to_owned())
    }

    fn bad_value(&self, what: &'static str, allowed: &'static str, found: i64) -> AspifError {
        // The value was just read: point at its first byte.
        let mut start = self.cur.pos;
        while start > 0 && !self.cur.src[start - 1].is_ascii_whitespace() {
            start -= 1;
        }
        self.cur.error_at(
            start,
            AspifErrorKind::BadValue {
                what,
                allowed,
                found,
            },
        )
    }
}

fn skip_whitespace(cur: &mut Cursor) {
    while let Some(b' ' | b'\t' | b'\r' | b'\n') = cur.src.get(cur.pos) {
        cur.pos += 1;
    }
}

fn parse_atom(s: &str) -> Option<Atom> {
    s.parse::<Atom>()
        .ok()
        .filter(|&a| (1..=ATOM_MAX).contains(&a))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::program::Rule;

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

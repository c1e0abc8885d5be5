//! The aspif reader: a byte cursor over the input and a reader that builds [`super::Aspif`]
//! step by step.
//!
//! Invariants (see the module above): it never panics, every error carries the 1-based line and
//! byte column of its token, and no count read from the input sizes an allocation beyond what
//! the rest of the input can hold ([`Cursor::capacity`]).

use super::*;

/// A position in the input; all token reading goes through it.
pub(super) struct Cursor<'a> {
    pub(super) src: &'a [u8],
    pub(super) pos: usize,
}

impl<'a> Cursor<'a> {
    pub(super) fn error_at(&self, pos: usize, kind: AspifErrorKind) -> AspifError {
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
    #[inline]
    fn int(&mut self, what: &'static str, min: i64, max: i64) -> Result<i64, AspifError> {
        self.skip_blanks();
        // The common token first: at most 18 digits (no overflow in `i64`), optionally
        // negative, ending at a blank or the end, in range. Anything else (errors included)
        // takes the general path below from the same position.
        let src = self.src;
        let mut p = self.pos;
        let negative = src.get(p) == Some(&b'-');
        if negative {
            p += 1;
        }
        let digits = p;
        let mut magnitude: u64 = 0;
        while p - digits < 19 {
            match src.get(p) {
                Some(&b) if b.is_ascii_digit() => {
                    magnitude = magnitude * 10 + u64::from(b - b'0');
                    p += 1;
                }
                _ => break,
            }
        }
        let len = p - digits;
        if len > 0 && len <= 18 && matches!(src.get(p), None | Some(b' ' | b'\t' | b'\r' | b'\n')) {
            let value = if negative {
                -(magnitude as i64)
            } else {
                magnitude as i64
            };
            if (min..=max).contains(&value) {
                self.pos = p;
                return Ok(value);
            }
        }
        self.int_general(what, min, max)
    }

    /// [`Cursor::int`] for every token, with its errors (after blanks are skipped).
    #[cold]
    fn int_general(&mut self, what: &'static str, min: i64, max: i64) -> Result<i64, AspifError> {
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
pub(super) struct Reader<'a> {
    pub(super) cur: Cursor<'a>,
    pub(super) num_atoms: u32,
    pub(super) minimize_totals: std::collections::HashMap<Weight, i128>,
    /// Scratch for a rule's head atoms, reused from rule to rule.
    pub(super) head_buf: Vec<Atom>,
    /// Scratch for a rule's normal body, reused from rule to rule.
    pub(super) lit_buf: Vec<Lit>,
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
        let mut lits = Vec::new();
        self.lits_into(&mut lits)?;
        Ok(lits)
    }

    /// Reads a counted list of literals into `lits` (cleared first), so that a caller reading
    /// many statements reuses one buffer.
    fn lits_into(&mut self, lits: &mut Vec<Lit>) -> Result<(), AspifError> {
        lits.clear();
        let n = self.cur.count("number of literals")?;
        lits.reserve(self.cur.capacity(n));
        for _ in 0..n {
            let l = self.cur.lit()?;
            self.note_lit(l);
            lits.push(l);
        }
        Ok(())
    }

    fn atoms(&mut self) -> Result<Vec<Atom>, AspifError> {
        let mut atoms = Vec::new();
        self.atoms_into(&mut atoms)?;
        Ok(atoms)
    }

    /// Reads a counted list of atoms into `atoms` (cleared first), as [`Reader::lits_into`].
    fn atoms_into(&mut self, atoms: &mut Vec<Atom>) -> Result<(), AspifError> {
        atoms.clear();
        let n = self.cur.count("number of atoms")?;
        atoms.reserve(self.cur.capacity(n));
        for _ in 0..n {
            let a = self.cur.atom()?;
            self.note_atom(a);
            atoms.push(a);
        }
        Ok(())
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

    pub(super) fn file(mut self) -> Result<Aspif, AspifError> {
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
                1 => self.rule_statement(&mut step)?,
                2 => self.minimize_statement(
                    &mut step,
                    stmt_pos,
                    &mut expect_cr_minimize,
                    &mut cr_minimize,
                )?,
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
                    p.outputs.push(Output::new(symbol, condition));
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
                7 => self.heuristic_statement(&mut step)?,
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
        free_theory_atoms(&mut step.program);
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

    /// Reads the rest of a rule statement (aspif statement 1) into `step`.
    fn rule_statement(&mut self, step: &mut AspifStep) -> Result<(), AspifError> {
        let head_kind = match self.cur.int("head type", 0, i64::MAX)? {
            0 => HeadKind::Disjunction,
            1 => HeadKind::Choice,
            v => return Err(self.bad_value("head type", "0 (disjunction), 1 (choice)", v)),
        };
        // The head and a normal body are read into the reader's buffers, which are taken out
        // and put back: a rule costs no allocation of its own.
        let mut head = std::mem::take(&mut self.head_buf);
        let mut lits = std::mem::take(&mut self.lit_buf);
        let read = self.rule_parts(step, head_kind, &mut head, &mut lits);
        self.head_buf = head;
        self.lit_buf = lits;
        read
    }

    /// [`Reader::rule_statement`] after the head type, with its buffers.
    fn rule_parts(
        &mut self,
        step: &mut AspifStep,
        head_kind: HeadKind,
        head: &mut Vec<Atom>,
        lits: &mut Vec<Lit>,
    ) -> Result<(), AspifError> {
        self.atoms_into(head)?;
        let body = match self.cur.int("body type", 0, i64::MAX)? {
            0 => {
                self.lits_into(lits)?;
                BodyRef::Normal(lits)
            }
            1 => {
                self.cur.skip_blanks();
                let at = self.cur.pos;
                let lower = self.cur.int("lower bound", i64::MIN, i64::MAX)?;
                let mut total = i128::from(lower).abs();
                if total > WEIGHT_SUM_MAX {
                    return Err(self
                        .cur
                        .error_at(at, AspifErrorKind::WeightsTooLarge(WEIGHT_BODY.into())));
                }
                let wlits = self.wlits(false, WEIGHT_BODY, &mut total)?;
                let p = &mut step.program;
                step.layout.push(Stmt::Rule(p.rules.len() as u32));
                p.rules.push_parts(
                    head_kind,
                    head,
                    BodyRef::Weight {
                        lower,
                        lits: &wlits,
                    },
                );
                return Ok(());
            }
            v => return Err(self.bad_value("body type", "0 (normal), 1 (weight)", v)),
        };
        let p = &mut step.program;
        step.layout.push(Stmt::Rule(p.rules.len() as u32));
        p.rules.push_parts(head_kind, head, body);
        Ok(())
    }

    /// Reads the rest of a minimize statement (aspif statement 2) into `step`: the CR minimize
    /// when a `CR_MINIMIZE_TAG` comment announced it (`expect_cr_minimize`, then taken, the
    /// statement recorded in `cr_minimize` to be checked at the end of the step).
    fn minimize_statement(
        &mut self,
        step: &mut AspifStep,
        stmt_pos: usize,
        expect_cr_minimize: &mut Option<(Weight, usize)>,
        cr_minimize: &mut Option<CrMinimizeSeen>,
    ) -> Result<(), AspifError> {
        let priority = self.cur.int("priority", i64::MIN, i64::MAX)?;
        let mut total = self.minimize_totals.get(&priority).copied().unwrap_or(0);
        let what = format!("the weights of the minimize statements of priority {priority}");
        let lits = self.wlits(true, &what, &mut total)?;
        self.minimize_totals.insert(priority, total);
        if let Some((expected, marker_pos)) = expect_cr_minimize.take() {
            if priority != expected {
                return Err(self.cur.error_at(
                    stmt_pos,
                    AspifErrorKind::BadLucentComment(format!(
                        "CR minimize has priority {priority}, the comment says {expected}"
                    )),
                ));
            }
            step.layout.push(Stmt::CrMinimize(priority));
            *cr_minimize = Some(CrMinimizeSeen {
                priority,
                lits,
                pos: marker_pos,
            });
        } else {
            let p = &mut step.program;
            step.layout.push(Stmt::Minimize(p.minimize.len() as u32));
            p.minimize.push(Minimize { priority, lits });
        }
        Ok(())
    }

    /// Reads the rest of a heuristic statement (aspif statement 7) into `step`.
    fn heuristic_statement(&mut self, step: &mut AspifStep) -> Result<(), AspifError> {
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
            .int("heuristic bias", i32::MIN.into(), i32::MAX.into())? as i32;
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
        Ok(())
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

/// Theory atoms (`9 5 a ...`, `9 6 a ...` with `a != 0`) that no rule of the step heads are
/// free, as clasp reads them: they become free externals of the program (not of the layout,
/// so the step is written back as it was read).
fn free_theory_atoms(p: &mut GroundProgram) {
    let atoms: Vec<Atom> = p
        .theory
        .iter()
        .filter_map(|line| {
            let mut f = line.split_ascii_whitespace();
            let (Some("9"), Some("5" | "6"), Some(a)) = (f.next(), f.next(), f.next()) else {
                return None;
            };
            a.parse::<Atom>().ok().filter(|&a| a != 0)
        })
        .collect();
    if atoms.is_empty() {
        return;
    }
    let headed: hashbrown::HashSet<Atom> = p
        .rules
        .iter()
        .flat_map(|r| r.head.iter().copied())
        .collect();
    for a in atoms {
        if !headed.contains(&a) && !p.externals.iter().any(|&(b, _)| b == a) {
            p.externals.push((a, ExternalValue::Free));
            p.num_atoms = p.num_atoms.max(a);
        }
    }
}

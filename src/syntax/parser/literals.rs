//! Rule heads and bodies: disjunctions, choices, head and body aggregates, conditional
//! literals, comparisons and the literals they are made of.
//!
//! Invariant: aggregates and conditions count toward [`super::MAX_DEPTH`]; a body ends at the
//! `.` (or `:+`'s `.`) with gringo's wording when it is missing.

use super::*;

impl<'a> Parser<'a> {
    // ----- heads -----

    /// A rule head, and the term its first literal was read from (a CR rule's label candidate).
    pub(super) fn head(&mut self) -> PResult<(Head, Option<Term>)> {
        let start = self.tok.start();
        if self.at(T::LBrace) {
            return Ok((Head::Choice(Box::new(self.choice(start, None)?)), None));
        }
        if self.at(T::Amp) {
            return Ok((Head::Theory(Box::new(self.theory_atom()?)), None));
        }
        if self.at_aggregate() {
            return Ok((
                Head::Aggregate(Box::new(self.head_aggregate(start, None)?)),
                None,
            ));
        }
        let mut first = Vec::with_capacity(1);
        let mut first_term = None;
        if self.at(T::Not) || (self.at(T::Hash) && matches!(self.cur(), "#true" | "#false")) {
            self.literal(Ctx::Single, &mut first)?;
        } else {
            let term = self.term()?;
            let term = match self.lower_guard(term) {
                Ok(guard) => {
                    let head = if self.at(T::LBrace) {
                        Head::Choice(Box::new(self.choice(start, Some(guard))?))
                    } else {
                        Head::Aggregate(Box::new(self.head_aggregate(start, Some(guard))?))
                    };
                    return Ok((head, None));
                }
                Err(term) => term,
            };
            // Only `label : head :+ body` needs the term back (as the label), and only when a
            // `:` follows an atom; copy it just then.
            if !self.at_cmp() && self.at(T::Colon) {
                first_term = Some(term.clone());
            }
            self.literal_tail(start, Sign::Positive, term, Ctx::Single, &mut first)?;
        }
        let mut elements = Vec::with_capacity(1);
        let literal = first.remove(0);
        elements.push(self.head_element(start, literal, true)?);
        // gringo separates disjunction elements by `|`, `;` or `,` (a `,` after a condition
        // continues the condition, which `condition` has consumed already).
        while self.at(T::Bar) || self.at(T::Semi) || self.at(T::Comma) {
            self.bump();
            let start = self.tok.start();
            let literal = self.single_literal()?;
            elements.push(self.head_element(start, literal, true)?);
        }
        Ok((Head::Disjunction(elements), first_term))
    }

    /// After a term: the lower guard it is when a choice or an aggregate follows (`t {`,
    /// `t #count`: `t <=`; `t op {`, `t op #count`, the operator consumed); the term itself
    /// otherwise.
    fn lower_guard(&mut self, term: Term) -> Result<Guard, Term> {
        if self.at(T::LBrace) || self.at_aggregate() {
            return Ok(Guard {
                op: CmpOp::Le,
                term,
            });
        }
        if let Some(op) = cmp_op(self.tok.kind) {
            let next = self.peek();
            if next.kind == T::LBrace || aggregate_function(next.kind, self.word(next)).is_some() {
                self.bump();
                return Ok(Guard { op, term });
            }
        }
        Err(term)
    }

    /// True when the current token is a comparison operator.
    pub(super) fn at_cmp(&self) -> bool {
        cmp_op(self.tok.kind).is_some()
    }

    /// The optional `: condition` after a head literal.
    pub(super) fn head_element(
        &mut self,
        start: u32,
        literal: Literal,
        in_disjunction: bool,
    ) -> PResult<ConditionalLiteral> {
        let has_colon = self.eat(T::Colon);
        let condition = if has_colon {
            self.condition(!in_disjunction)?
        } else {
            Vec::new()
        };
        Ok(ConditionalLiteral {
            span: self.span_from(start),
            literal,
            condition,
            has_colon,
        })
    }

    /// `{ l : c ; ... } [upper]` after an optional lower guard.
    pub(super) fn choice(&mut self, start: u32, lower: Option<Guard>) -> PResult<Choice> {
        self.enter()?;
        let elements = self.conditional_set()?;
        let upper = self.upper_guard()?;
        self.leave();
        Ok(Choice {
            span: self.span_from(start),
            lower,
            elements,
            upper,
        })
    }

    /// `{ l : c ; ... }`, the braces included.
    pub(super) fn conditional_set(&mut self) -> PResult<Vec<ConditionalLiteral>> {
        self.braced_elements(|p, start| {
            let literal = p.single_literal()?;
            p.head_element(start, literal, false)
        })
    }

    /// `{ e ; ... }`, the braces included: the elements `element` reads, each called with the
    /// offset its element starts at. Choices and both kinds of aggregates share this shape.
    fn braced_elements<E>(
        &mut self,
        mut element: impl FnMut(&mut Self, u32) -> PResult<E>,
    ) -> PResult<Vec<E>> {
        self.expect(T::LBrace, &["{"])?;
        let mut elements = Vec::new();
        if !self.at(T::RBrace) {
            loop {
                let start = self.tok.start();
                elements.push(element(self, start)?);
                if !self.eat(T::Semi) {
                    break;
                }
            }
        }
        self.expect(T::RBrace, &["}", ";"])?;
        Ok(elements)
    }

    /// The aggregate function keyword at the current token, consumed.
    fn aggregate_keyword(&mut self) -> AggregateFunction {
        let function = aggregate_function(self.tok.kind, self.cur()).expect("at an aggregate");
        self.bump();
        function
    }

    /// An aggregate element's tuple `t1, ..., tn`, empty when a `:` follows at once.
    fn aggregate_tuple(&mut self) -> PResult<Vec<Term>> {
        let mut terms = Vec::new();
        if !self.at(T::Colon) {
            loop {
                terms.push(self.term()?);
                if !self.eat(T::Comma) {
                    break;
                }
            }
        }
        Ok(terms)
    }

    /// An aggregate element's optional `: condition`.
    fn aggregate_condition(&mut self) -> PResult<Vec<Literal>> {
        if self.eat(T::Colon) {
            self.condition(true)
        } else {
            Ok(Vec::new())
        }
    }

    /// An upper guard after `}`: `op term` or a bare term (meaning `<= term`).
    pub(super) fn upper_guard(&mut self) -> PResult<Option<Guard>> {
        if let Some(op) = cmp_op(self.tok.kind) {
            self.bump();
            let term = self.term()?;
            return Ok(Some(Guard { op, term }));
        }
        // A `|` after `}` can only open an absolute value: no aggregate or choice is followed
        // by a disjunction separator.
        if self.starts_term(self.tok) {
            let term = self.term()?;
            return Ok(Some(Guard {
                op: CmpOp::Le,
                term,
            }));
        }
        Ok(None)
    }

    /// `#f { terms : literal : condition ; ... } [upper]` in a head.
    pub(super) fn head_aggregate(
        &mut self,
        start: u32,
        lower: Option<Guard>,
    ) -> PResult<HeadAggregate> {
        self.enter()?;
        let function = self.aggregate_keyword();
        let elements = self.braced_elements(|p, start| {
            let terms = p.aggregate_tuple()?;
            p.expect(T::Colon, &[":"])?;
            let literal = p.single_literal()?;
            let condition = p.aggregate_condition()?;
            Ok(HeadAggregateElement {
                span: p.span_from(start),
                terms,
                literal,
                condition,
            })
        })?;
        let upper = self.upper_guard()?;
        self.leave();
        Ok(HeadAggregate {
            span: self.span_from(start),
            function,
            lower,
            elements,
            upper,
        })
    }

    // ----- bodies -----

    /// Body literals separated by `,` or `;`, up to (not including) the closing `.`.
    pub(super) fn body(&mut self) -> PResult<Vec<BodyLiteral>> {
        self.body_end = &[];
        let mut body = Vec::new();
        if self.at(T::Dot) {
            return Ok(body);
        }
        loop {
            self.body_literal(&mut body)?;
            if !(self.eat(T::Comma) || self.eat(T::Semi)) {
                break;
            }
        }
        Ok(body)
    }

    /// One body literal (several for a comparison chain).
    pub(super) fn body_literal(&mut self, out: &mut Vec<BodyLiteral>) -> PResult<()> {
        let start = self.tok.start();
        let sign = self.sign()?;
        if self.at(T::LBrace) || self.at_aggregate() {
            return self.body_aggregate_literal(start, sign, None, out);
        }
        if self.at(T::Amp) {
            let atom = Box::new(self.theory_atom()?);
            out.push(BodyLiteral::Theory { sign, atom });
            self.body_end = AFTER_AGGREGATE;
            return Ok(());
        }
        let mut lits = Vec::with_capacity(1);
        if self.at(T::Hash) && (matches!(self.cur(), "#true" | "#false") || self.at_sort_name()) {
            self.atom_literal(start, sign, &mut lits)?;
        } else {
            let term = self.term()?;
            let term = match self.lower_guard(term) {
                Ok(guard) => return self.body_aggregate_literal(start, sign, Some(guard), out),
                Err(term) => term,
            };
            self.literal_tail(start, sign, term, Ctx::Chain, &mut lits)?;
        }
        if lits.len() == 1 && self.at(T::Colon) {
            self.bump();
            let condition = self.condition(true)?;
            let literal = lits.pop().expect("one literal");
            self.body_end = match condition.last() {
                Some(l) if !matches!(l.atom, Atom::Symbolic(_)) => AFTER_CONDITION,
                _ => &[],
            };
            out.push(BodyLiteral::Conditional(ConditionalLiteral {
                span: self.span_from(start),
                literal,
                condition,
                has_colon: true,
            }));
            return Ok(());
        }
        self.body_end = match lits.last() {
            Some(l) if !matches!(l.atom, Atom::Symbolic(_)) => AFTER_BUILTIN,
            _ => &[],
        };
        out.extend(lits.into_iter().map(BodyLiteral::Literal));
        Ok(())
    }

    /// A body aggregate with its sign, after its optional lower guard.
    fn body_aggregate_literal(
        &mut self,
        start: u32,
        sign: Sign,
        lower: Option<Guard>,
        out: &mut Vec<BodyLiteral>,
    ) -> PResult<()> {
        let aggregate = self.body_aggregate(start, lower)?;
        out.push(BodyLiteral::Aggregate {
            sign,
            aggregate: Box::new(aggregate),
        });
        self.body_end = AFTER_AGGREGATE;
        Ok(())
    }

    /// `not`, `not not` or nothing.
    pub(super) fn sign(&mut self) -> PResult<Sign> {
        if !self.eat(T::Not) {
            return Ok(Sign::Positive);
        }
        if !self.eat(T::Not) {
            return Ok(Sign::Not);
        }
        if self.at(T::Not) {
            return Err(self.unexpected(&[]));
        }
        Ok(Sign::NotNot)
    }

    /// A body aggregate after its optional lower guard.
    pub(super) fn body_aggregate(
        &mut self,
        start: u32,
        lower: Option<Guard>,
    ) -> PResult<BodyAggregate> {
        self.enter()?;
        let (function, elements, set_syntax) = if self.at(T::LBrace) {
            let set = self.conditional_set()?;
            (AggregateFunction::Count, Vec::new(), set)
        } else {
            let function = self.aggregate_keyword();
            let elements = self.braced_elements(|p, start| {
                let terms = p.aggregate_tuple()?;
                let condition = p.aggregate_condition()?;
                Ok(BodyAggregateElement {
                    span: p.span_from(start),
                    terms,
                    condition,
                })
            })?;
            (function, elements, Vec::new())
        };
        let upper = self.upper_guard()?;
        self.leave();
        Ok(BodyAggregate {
            span: self.span_from(start),
            function,
            lower,
            elements,
            set_syntax,
            upper,
        })
    }

    /// A condition: literals separated by `,` (possibly none, before `;`, `|`, `}` or `.`).
    /// `bar_starts` says whether a `|` opens an absolute value here; in a head disjunction it
    /// separates elements instead.
    pub(super) fn condition(&mut self, bar_starts: bool) -> PResult<Vec<Literal>> {
        let mut lits = Vec::new();
        if !(self.starts_literal() || (bar_starts && self.at(T::Bar))) {
            return Ok(lits);
        }
        loop {
            self.literal(Ctx::Chain, &mut lits)?;
            if !self.eat(T::Comma) {
                break;
            }
        }
        Ok(lits)
    }

    /// One literal (several for a comparison chain when `ctx` allows chains).
    pub(super) fn literal(&mut self, ctx: Ctx, out: &mut Vec<Literal>) -> PResult<()> {
        let start = self.tok.start();
        let sign = self.sign()?;
        if self.at(T::Hash) && (matches!(self.cur(), "#true" | "#false") || self.at_sort_name()) {
            return self.atom_literal(start, sign, out);
        }
        let term = self.term()?;
        self.literal_tail(start, sign, term, ctx, out)
    }

    /// Exactly one literal, no comparison chain (a head element, a choice or head aggregate
    /// element).
    fn single_literal(&mut self) -> PResult<Literal> {
        let mut lits = Vec::with_capacity(1);
        self.literal(Ctx::Single, &mut lits)?;
        Ok(lits.remove(0))
    }

    /// `#true`, `#false` or a SPARC sort atom `#s(t)`.
    pub(super) fn atom_literal(
        &mut self,
        start: u32,
        sign: Sign,
        out: &mut Vec<Literal>,
    ) -> PResult<()> {
        let tok = self.bump();
        let atom = match self.word(tok) {
            "#true" => Atom::Boolean(true),
            "#false" => Atom::Boolean(false),
            word => {
                let sort = word[1..].to_string();
                self.expect(T::LParen, &["("])?;
                let arg = self.term()?;
                self.expect(T::RParen, &[")"])?;
                Atom::Sort {
                    sort,
                    arg: Box::new(arg),
                }
            }
        };
        out.push(Literal {
            span: self.span_from(start),
            sign,
            atom,
        });
        Ok(())
    }

    /// The rest of a literal whose first term was read: a comparison (chain) or an atom.
    pub(super) fn literal_tail(
        &mut self,
        start: u32,
        sign: Sign,
        term: Term,
        ctx: Ctx,
        out: &mut Vec<Literal>,
    ) -> PResult<()> {
        let Some(op) = cmp_op(self.tok.kind) else {
            let Ok(atom) = term_to_atom(term) else {
                return Err(self.unexpected(&[]));
            };
            out.push(Literal {
                span: self.span_from(start),
                sign,
                atom: Atom::Symbolic(atom),
            });
            return Ok(());
        };
        self.bump();
        let mut lhs = term;
        let mut op = op;
        let mut lit_start = start;
        loop {
            let rhs = self.term()?;
            let next_start = rhs.span.start;
            let chained = ctx == Ctx::Chain && self.at_cmp();
            // In a chain `a < b < c` the middle term is shared: the next part starts with a copy.
            let next_lhs = chained.then(|| rhs.clone());
            out.push(Literal {
                span: self.span_from(lit_start),
                sign,
                atom: Atom::Comparison {
                    lhs: Box::new(lhs),
                    op,
                    rhs: Box::new(rhs),
                },
            });
            let Some(next_lhs) = next_lhs else {
                return Ok(());
            };
            match cmp_op(self.tok.kind) {
                Some(next) if sign == Sign::Positive => {
                    self.bump();
                    lhs = next_lhs;
                    op = next;
                    lit_start = next_start;
                }
                Some(_) => {
                    let span = self.span_of(self.tok);
                    return Err(self.error(
                        span,
                        "syntax error, negated comparison chains are not supported",
                    ));
                }
                None => return Ok(()),
            }
        }
    }
}

//! SPARC declarations: sort definitions (sort expressions with precedence climbing, records
//! with conditions, concatenations) and predicate declarations.
//!
//! Invariant: sort-expression nesting counts toward [`super::MAX_DEPTH`] like term nesting.

use super::*;

impl<'a> Parser<'a> {
    // ----- SPARC declarations -----

    /// `#name = sort_expression.`
    pub(super) fn sort_def(&mut self) -> PResult<StatementKind> {
        // A sort may be named like a clingo directive (`#program = {a}.`): the `=` tells.
        let defines = self.at(T::Hash) && self.peek().kind == T::Eq;
        if !self.at_sort_name() && !defines {
            return Err(self.unexpected(&["<SORT>"]));
        }
        let name = self.bump();
        self.sort_names.insert(self.word(name).to_string());
        let name = self.word(name)[1..].to_string();
        self.expect(T::Eq, &["="])?;
        let expr = self.sort_expr(0)?;
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::SortDef(Box::new(SortDef { name, expr })))
    }

    /// A sort expression with operators of at least `min_level` (`+ -` are 0, `*` is 1).
    pub(super) fn sort_expr(&mut self, min_level: u8) -> PResult<SortExpr> {
        self.enter()?;
        let mut lhs = self.sort_primary()?;
        let mut folds = 0;
        loop {
            let level = match self.tok.kind {
                T::Plus | T::Minus => 0,
                T::Star => 1,
                _ => break,
            };
            if level < min_level {
                break;
            }
            let op = self.bump().kind;
            let rhs = self.sort_expr(level + 1)?;
            let span = lhs.span.to(rhs.span);
            let (l, r) = (Box::new(lhs), Box::new(rhs));
            let kind = match op {
                T::Plus => SortExprKind::Union(l, r),
                T::Minus => SortExprKind::Difference(l, r),
                _ => SortExprKind::Intersection(l, r),
            };
            lhs = SortExpr { span, kind };
            self.enter()?;
            folds += 1;
        }
        self.depth -= folds;
        self.leave();
        Ok(lhs)
    }

    /// A sort expression without binary operators.
    pub(super) fn sort_primary(&mut self) -> PResult<SortExpr> {
        let start = self.tok.start();
        let record = self.at(T::Ident) && self.peek().kind == T::LParen;
        let kind = match self.tok.kind {
            T::LBrace => {
                self.bump();
                let mut items = Vec::new();
                if !self.at(T::RBrace) {
                    loop {
                        items.push(self.term()?);
                        if !self.eat(T::Comma) {
                            break;
                        }
                    }
                }
                self.expect(T::RBrace, &["}", "\",\""])?;
                SortExprKind::Set(items)
            }
            T::LBrack => {
                let mut parts = Vec::new();
                while self.at(T::LBrack) {
                    let part_start = self.bump().start();
                    let kind = self.concat_part()?;
                    self.expect(T::RBrack, &["]"])?;
                    parts.push(SortExpr {
                        span: self.span_from(part_start),
                        kind,
                    });
                }
                SortExprKind::Concat(parts)
            }
            T::LParen => {
                self.bump();
                let inner = self.sort_expr(0)?;
                self.expect(T::RParen, &[")"])?;
                SortExprKind::Paren(Box::new(inner))
            }
            T::Hash if self.at_sort_name() => {
                let tok = self.bump();
                SortExprKind::Ref(self.word(tok)[1..].to_string())
            }
            T::Ident if record => self.record()?,
            _ => {
                let lo = self.unary()?;
                self.expect(T::Dots, &[".."])?;
                let hi = self.unary()?;
                SortExprKind::Range(lo, hi)
            }
        };
        Ok(SortExpr {
            span: self.span_from(start),
            kind,
        })
    }

    /// The inside of one `[...]` part of a concatenation: `#s`, `lo..hi` or `a, b`.
    pub(super) fn concat_part(&mut self) -> PResult<SortExprKind> {
        if self.at_sort_name() {
            let tok = self.bump();
            return Ok(SortExprKind::Ref(self.word(tok)[1..].to_string()));
        }
        let first = self.unary()?;
        if self.eat(T::Dots) {
            let hi = self.unary()?;
            return Ok(SortExprKind::Range(first, hi));
        }
        let mut items = vec![first];
        while self.eat(T::Comma) {
            items.push(self.unary()?);
        }
        Ok(SortExprKind::Set(items))
    }

    /// `name(#s1[(X)], ...) [: condition]`
    pub(super) fn record(&mut self) -> PResult<SortExprKind> {
        let name = self.bump();
        let name = self.word(name).to_string();
        self.expect(T::LParen, &["("])?;
        let mut args = Vec::new();
        loop {
            let start = self.tok.start();
            if self.at_sort_name() {
                let tok = self.bump();
                let sort = SortExprKind::Ref(self.word(tok)[1..].to_string());
                let sort = SortExpr {
                    span: self.span_from(start),
                    kind: sort,
                };
                let var = if self.eat(T::LParen) {
                    let v = self.expect(T::Variable, &["<VARIABLE>"])?;
                    let v = self.word(v).to_string();
                    self.expect(T::RParen, &[")"])?;
                    Some(v)
                } else {
                    None
                };
                args.push((sort, var));
            } else {
                args.push((self.sort_expr(0)?, None));
            }
            if !self.eat(T::Comma) {
                break;
            }
        }
        self.expect(T::RParen, &[")", "\",\""])?;
        let condition = if self.eat(T::Colon) {
            Some(Box::new(self.record_condition()?))
        } else {
            None
        };
        Ok(SortExprKind::Record {
            name,
            args,
            condition,
        })
    }

    /// A record sort's condition: comparisons joined by `and` (or `,`) and `or`, `not(c)`,
    /// `(c)`; `and` binds tighter than `or`.
    pub(super) fn record_condition(&mut self) -> PResult<RecordCondition> {
        self.enter()?;
        let mut lhs = self.record_conjunction()?;
        while self.at(T::Ident) && self.cur() == "or" {
            self.bump();
            let rhs = self.record_conjunction()?;
            lhs = RecordCondition::Or(Box::new(lhs), Box::new(rhs));
        }
        self.leave();
        Ok(lhs)
    }

    /// Comparisons joined by `and`, or by `,` when a variable or `not` follows (otherwise the
    /// `,` ends the record, which may be an argument of another record).
    pub(super) fn record_conjunction(&mut self) -> PResult<RecordCondition> {
        let mut lhs = self.record_condition_primary()?;
        while (self.at(T::Comma) && matches!(self.peek().kind, T::Variable | T::Not))
            || (self.at(T::Ident) && self.cur() == "and")
        {
            self.bump();
            let rhs = self.record_condition_primary()?;
            lhs = RecordCondition::And(Box::new(lhs), Box::new(rhs));
        }
        Ok(lhs)
    }

    /// `not(c)`, `(c)` or `t1 op t2` with simple operands (variables, constants, numbers).
    pub(super) fn record_condition_primary(&mut self) -> PResult<RecordCondition> {
        if self.eat(T::Not) {
            self.expect(T::LParen, &["("])?;
            let inner = self.record_condition()?;
            self.expect(T::RParen, &[")"])?;
            return Ok(RecordCondition::Not(Box::new(inner)));
        }
        if self.eat(T::LParen) {
            let inner = self.record_condition()?;
            self.expect(T::RParen, &[")"])?;
            return Ok(RecordCondition::Paren(Box::new(inner)));
        }
        let lhs = self.unary()?;
        let Some(op) = cmp_op(self.tok.kind) else {
            return Err(self.unexpected(&["<", "<=", "=", "!=", ">", ">="]));
        };
        self.bump();
        let rhs = self.unary()?;
        Ok(RecordCondition::Compare { lhs, op, rhs })
    }

    /// `name(#s1, ..., #sn).`
    pub(super) fn predicate_decl(&mut self) -> PResult<StatementKind> {
        let name = self.identifier()?;
        let mut sorts = Vec::new();
        if self.eat(T::LParen) {
            if !self.at(T::RParen) {
                loop {
                    if !self.at_sort_name() {
                        return Err(self.unexpected(&["<SORT>"]));
                    }
                    let tok = self.bump();
                    sorts.push(self.word(tok)[1..].to_string());
                    if !self.eat(T::Comma) {
                        break;
                    }
                }
            }
            self.expect(T::RParen, &[")", "\",\""])?;
        }
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::PredicateDecl(PredicateDecl { name, sorts }))
    }
}

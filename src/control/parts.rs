//! Adding programs and grounding parts: text and files parsed into statements, filed into
//! `#program name(params).` parts (`base` before any directive, per file, or the part a
//! [`Control::add`] call names; an included file's parts do not leak), `#include <incmode>.` taken out, constants evaluated (`-c` before
//! `#const`), and ground requests grouped (parts without parameters together, then each group of
//! parts whose parameter bindings agree) and handed to the Control's grounding session
//! (`ground::incremental`), which continues from the earlier groundings (see `context`).
//!
//! Invariant: a part instance is grounded at most once; a failed grounding leaves the part's
//! statements where they were.

use super::*;

impl Control {
    /// Adds `text` to the part `part(params)` (clingo's `Control.add(name, params, program)`):
    /// its statements belong to that part until a `#program` directive in the text switches
    /// part, so `add("step", &["t"], "q(t).")` and grounding `step(1)` give `q(1)`.
    /// Diagnostics name the text `<block>`, as clingo's do.
    pub fn add(&mut self, part: &str, params: &[&str], text: &str) -> Result<(), Error> {
        if ground::aspif::is_aspif(text.as_bytes()) {
            return self.add_aspif("<block>", text.as_bytes());
        }
        let file = self.sources.add("<block>", text);
        let params: Vec<String> = params.iter().map(|p| p.to_string()).collect();
        self.add_file_in(file, None, Some((part, &params)))
    }

    /// Parses `text` as a source named `name` (a file name in diagnostics) and keeps its
    /// statements: those before any `#program` directive belong to `base`, as a file's do.
    pub fn add_source(&mut self, name: &str, text: &str) -> Result<(), Error> {
        if ground::aspif::is_aspif(text.as_bytes()) {
            return self.add_aspif(name, text.as_bytes());
        }
        let file = self.sources.add(name, text);
        self.add_file(file, None)
    }

    /// Reads the file at `path` and adds it (clingo's `load`).
    pub fn load(&mut self, path: impl AsRef<Path>) -> Result<(), Error> {
        let path = path.as_ref();
        match std::fs::read_to_string(path) {
            Ok(text) => self.add_source(&path.display().to_string(), &text),
            Err(e) => {
                let cmd = self.sources.add("<cmd>", "");
                let mut d = self.new_diags();
                d.push(
                    Diagnostic::error(Span::new(cmd, 0, 0), "file could not be opened")
                        .with_snippet(format!("{}: {e}", path.display())),
                );
                Err(self.error(d))
            }
        }
    }

    /// Parses the file `file` of [`Control::sources`] (added by the caller) in `dialect`
    /// (detected when `None`), resolves its includes and keeps its statements.
    pub fn add_file(&mut self, file: FileId, dialect: Option<Dialect>) -> Result<(), Error> {
        self.add_file_in(file, dialect, None)
    }

    /// [`Control::add_file`] with the file's statements before any directive in part `start`
    /// (`base` when `None`).
    fn add_file_in(
        &mut self,
        file: FileId,
        dialect: Option<Dialect>,
        start: Option<(&str, &[String])>,
    ) -> Result<(), Error> {
        let text = &self.sources.get(file).text;
        let dialect = dialect
            .or(self.config.dialect)
            .unwrap_or_else(|| crate::syntax::detect_dialect(text));
        let parse = crate::syntax::parse(file, text, dialect);
        let mut d = self.new_diags();
        d.extend(parse.diagnostics);
        self.add_parsed(
            parse.program,
            d,
            start.map(|(name, params)| (file, name, params)),
        )
    }

    /// Adds `facts` (functions, a negative one as a classically negated fact) to the base part,
    /// as values: nothing is printed and parsed. Clingo's Python API does this through its
    /// backend; here the facts join the program like any statement of `base`.
    pub fn add_facts(&mut self, facts: &[Symbol]) -> Result<(), Error> {
        let statements = facts
            .iter()
            .map(|f| {
                let positive = if f.is_negative() {
                    f.complement().unwrap_or_else(|| f.clone())
                } else {
                    f.clone()
                };
                let ast::TermKind::Function { name, args, .. } = positive.to_term().kind else {
                    return Err(Error {
                        diagnostics: Diagnostics::default(),
                        message: format!("`{f}` is not an atom and cannot be a fact"),
                    });
                };
                let atom = ast::SymbolicAtom {
                    span: Span::default(),
                    negated: f.is_negative(),
                    name,
                    args,
                };
                Ok(crate::syntax::build::fact(Span::default(), atom))
            })
            .collect::<Result<Vec<_>, Error>>()?;
        self.add_program(Program {
            dialect: Dialect::Clingo,
            statements,
        })
    }

    /// Keeps the statements of an already parsed program. Spans refer to files of
    /// [`Control::sources`] (a generated program may use default spans).
    pub fn add_program(&mut self, program: Program) -> Result<(), Error> {
        let d = self.new_diags();
        self.add_parsed(program, d, None)
    }

    fn add_parsed(
        &mut self,
        program: Program,
        mut d: Diagnostics,
        start: Option<(FileId, &str, &[String])>,
    ) -> Result<(), Error> {
        if self.sources.is_empty() {
            // Default spans name file 0: give it a name.
            self.sources.add("<program>", "");
        }
        // `#include <incmode>.` is clingo's incremental mode: taken out here (it is no file),
        // its part `#program check(t). #external query(t).` added below.
        let mut program = program;
        let before = program.statements.len();
        program.statements.retain(
            |s| !matches!(&s.kind, StatementKind::Include(i) if i.system && i.path == "incmode"),
        );
        let wants_incmode = program.statements.len() != before;
        let mut load =
            |path: &std::path::Path| std::fs::read_to_string(path).map_err(|e| e.to_string());
        // Resolving copies the statements: only when there is an include.
        let program = if program
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::Include(_)))
        {
            ground::include::resolve_includes(&program, &mut self.sources, &mut d, &mut load)
        } else {
            program
        };
        if d.has_errors() {
            return Err(self.error(d));
        }
        self.diags.extend(d.items().iter().cloned());
        if self.dialect.is_none() {
            self.dialect = Some(program.dialect);
        }
        self.split(program.statements, program.dialect, start);
        if wants_incmode && !self.incmode {
            self.incmode = true;
            let text = "#program check(t).\n#external query(t).\n";
            let file = self.sources.add("<incmode>", text);
            let parse = crate::syntax::parse(file, text, Dialect::Clingo);
            self.split(parse.program.statements, Dialect::Clingo, None);
        }
        Ok(())
    }

    /// Files the statements into parts: each file starts in `base` (the file of `start` in the
    /// part it names: [`Control::add`]'s text); `#program` switches the part of the file it is
    /// written in (an included file's parts do not leak).
    fn split(
        &mut self,
        statements: Vec<Statement>,
        dialect: Dialect,
        start: Option<(FileId, &str, &[String])>,
    ) {
        let mut current: HashMap<FileId, usize> = HashMap::new();
        for st in statements {
            if dialect == Dialect::Sparc {
                let b = self.block("base", &[]);
                self.blocks[b].statements.push(st);
                continue;
            }
            if let StatementKind::ProgramPart(p) = &st.kind {
                let b = self.block(&p.name, &p.params);
                current.insert(st.span.file, b);
                continue;
            }
            let b = match current.get(&st.span.file) {
                Some(&b) => b,
                None if start.is_some_and(|(f, _, _)| f == st.span.file) => {
                    let (_, name, params) = start.expect("checked");
                    let b = self.block(name, params);
                    current.insert(st.span.file, b);
                    b
                }
                None => self.block("base", &[]),
            };
            let global = match &st.kind {
                StatementKind::Const(_) => true,
                StatementKind::Show(s) => !matches!(**s, ast::Show::Term { .. }),
                _ => false,
            };
            if global {
                self.globals.push((b, st.clone()));
            }
            self.blocks[b].statements.push(st);
        }
    }

    fn block(&mut self, name: &str, params: &[String]) -> usize {
        if let Some(i) = self
            .blocks
            .iter()
            .position(|b| b.name == name && b.params == params)
        {
            return i;
        }
        self.blocks.push(Block {
            name: name.to_string(),
            params: params.to_vec(),
            statements: Vec::new(),
        });
        self.blocks.len() - 1
    }

    /// The value of the constant `name` (`-c` first, then `#const`), if it is defined and
    /// evaluates to a symbol.
    pub fn get_const(&self, name: &str) -> Option<Symbol> {
        self.get_const_depth(name, 0)
    }

    fn eval_const(&self, t: &ast::Term, depth: usize) -> Option<Symbol> {
        use ast::TermKind as K;
        if depth > 64 {
            return None;
        }
        Some(match &t.kind {
            K::Integer(n) => Symbol::Number(*n as i32),
            K::String(s) => Symbol::String(s.clone()),
            K::Infimum => Symbol::Inf,
            K::Supremum => Symbol::Sup,
            K::Constant(c) => match self.get_const_depth(c, depth + 1) {
                Some(v) => v,
                None => Symbol::constant(c.as_str()),
            },
            K::Function { name, args, .. } if args.len() <= 1 => {
                let list = args.first().map(Vec::as_slice).unwrap_or(&[]);
                let mut out = Vec::new();
                for a in list {
                    out.push(self.eval_const(a, depth + 1)?);
                }
                Symbol::function(name.as_str(), out)
            }
            K::Unary {
                op: ast::UnaryOp::Minus,
                arg,
            } => match self.eval_const(arg, depth + 1)? {
                Symbol::Number(n) => Symbol::Number(n.wrapping_neg()),
                Symbol::Function {
                    name,
                    args,
                    negative,
                } if !name.is_empty() => Symbol::Function {
                    name,
                    args,
                    negative: !negative,
                },
                _ => return None,
            },
            K::Binary { op, lhs, rhs } => {
                let a = self.eval_const(lhs, depth + 1)?.as_number()?;
                let b = self.eval_const(rhs, depth + 1)?.as_number()?;
                Symbol::Number(match op {
                    ast::BinaryOp::Add => a.wrapping_add(b),
                    ast::BinaryOp::Sub => a.wrapping_sub(b),
                    ast::BinaryOp::Mul => a.wrapping_mul(b),
                    ast::BinaryOp::Div if b != 0 => a.wrapping_div(b),
                    ast::BinaryOp::Mod if b != 0 => a.wrapping_rem(b),
                    _ => return None,
                })
            }
            _ => return None,
        })
    }

    /// Every constant defined (`-c` and `#const`), each once, with its value as
    /// [`Control::get_const`] gives it: a snapshot a client can read while the control is busy
    /// (clingo allows `get_const` inside a model callback).
    pub fn consts(&self) -> Vec<(String, Symbol)> {
        let mut names: Vec<&str> = self
            .config
            .ground
            .consts
            .iter()
            .map(|(n, _)| n.as_str())
            .chain(self.globals.iter().filter_map(|(_, st)| match &st.kind {
                StatementKind::Const(c) => Some(c.name.as_str()),
                _ => None,
            }))
            .collect();
        names.sort_unstable();
        names.dedup();
        names
            .into_iter()
            .filter_map(|n| Some((n.to_string(), self.get_const(n)?)))
            .collect()
    }

    fn get_const_depth(&self, name: &str, depth: usize) -> Option<Symbol> {
        let term = self
            .config
            .ground
            .consts
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.clone())
            .or_else(|| {
                self.globals.iter().find_map(|(_, st)| match &st.kind {
                    StatementKind::Const(c) if c.name == name => Some(c.value.clone()),
                    _ => None,
                })
            })?;
        self.eval_const(&term, depth)
    }

    /// Grounds the given parts (clingo's `ground`). Each part `name(args)` instantiates every
    /// `#program name(params).` block with as many parameters, the parameters bound to `args`.
    /// Parts without parameters are grounded first, together; then each group of parts whose
    /// parameter bindings agree. A part instance grounded before is skipped.
    pub fn ground(&mut self, parts: &[Part]) -> Result<(), Error> {
        self.ground_in(parts, None)
    }

    /// [`Control::ground`] with `context` supplying the functions that `@f(...)` calls
    /// (clingo's `ground(parts, context)`; see [`Context`]).
    pub fn ground_with_context(
        &mut self,
        parts: &[Part],
        context: &mut dyn Context,
    ) -> Result<(), Error> {
        self.ground_in(parts, Some(context))
    }

    fn ground_in(
        &mut self,
        parts: &[Part],
        mut context: Option<&mut (dyn Context + '_)>,
    ) -> Result<(), Error> {
        self.begin_update();
        let mut plain: Vec<usize> = Vec::new();
        let mut groups: Vec<(Binding, Vec<usize>)> = Vec::new();
        let mut requested: Vec<Part> = Vec::new();
        for part in parts {
            if self.grounded.contains(part) || requested.contains(part) {
                continue;
            }
            requested.push(part.clone());
            for (i, b) in self.blocks.iter().enumerate() {
                if b.name != part.name || b.params.len() != part.args.len() {
                    continue;
                }
                if b.params.is_empty() {
                    plain.push(i);
                    continue;
                }
                let binding: Vec<(String, Symbol)> = b
                    .params
                    .iter()
                    .cloned()
                    .zip(part.args.iter().cloned())
                    .collect();
                let fits = |g: &Vec<(String, Symbol)>| {
                    binding
                        .iter()
                        .all(|(n, v)| g.iter().all(|(m, w)| m != n || w == v))
                };
                match groups.iter_mut().find(|(g, _)| fits(g)) {
                    Some((g, blocks)) => {
                        for kv in &binding {
                            if !g.contains(kv) {
                                g.push(kv.clone());
                            }
                        }
                        blocks.push(i);
                    }
                    None => groups.push((binding, vec![i])),
                }
            }
        }
        if !plain.is_empty() || self.groundings == 0 && groups.is_empty() {
            self.ground_blocks(&plain, &[], context.as_deref_mut())?;
        }
        for (binding, blocks) in groups {
            self.ground_blocks(&blocks, &binding, context.as_deref_mut())?;
        }
        self.grounded.extend(requested);
        Ok(())
    }

    /// Grounds the statements of `blocks` with `binding` as constants, against the atoms of
    /// earlier groundings, and merges the result.
    pub(super) fn ground_blocks(
        &mut self,
        blocks: &[usize],
        binding: &[(String, Symbol)],
        context: Option<&mut (dyn Context + '_)>,
    ) -> Result<(), Error> {
        let first = self.groundings == 0;
        let mut statements: Vec<Statement> = Vec::new();
        // A part without parameters is grounded once: its statements move into the grounding
        // (and back if it fails) instead of being copied.
        let take = binding.is_empty();
        let mut counts = Vec::with_capacity(blocks.len());
        // With provenance on, the part of each statement (the Control's statement table).
        let mut parts: Vec<Part> = Vec::new();
        for &b in blocks {
            counts.push(self.blocks[b].statements.len());
            if self.config.ground.provenance {
                let block = &self.blocks[b];
                let args = block
                    .params
                    .iter()
                    .map(|p| {
                        let v = binding.iter().find(|(n, _)| n == p);
                        v.map(|(_, v)| v.clone()).expect("every parameter is bound")
                    })
                    .collect();
                let part = Part::new(block.name.clone(), args);
                parts.extend(std::iter::repeat_n(part, block.statements.len()));
            }
            if take {
                statements.append(&mut self.blocks[b].statements);
            } else {
                statements.extend(self.blocks[b].statements.iter().cloned());
            }
        }
        for (b, st) in &self.globals {
            if !blocks.contains(b) {
                statements.push(st.clone());
                if self.config.ground.provenance {
                    let block = &self.blocks[*b];
                    parts.push(Part::new(block.name.clone(), Vec::new()));
                }
            }
        }
        let own = statements.len();
        let program = Program {
            dialect: self.dialect.unwrap_or_default(),
            statements,
        };
        let mut gconfig = self.config.ground.clone();
        gconfig
            .consts
            .extend(binding.iter().map(|(n, v)| (n.clone(), v.to_term())));
        let syms = std::mem::take(&mut self.syms);
        let mut adapter = context.map(functions::Adapter);
        let mut grounding = self
            .session
            .ground(&program, Some(&self.sources), &gconfig, syms, {
                adapter.as_mut().map(|a| a as &mut dyn crate::ground::Calls)
            });
        self.syms = std::mem::take(&mut grounding.symbols);
        let mut found = std::mem::take(&mut grounding.diagnostics);
        for &k in &self.config.disabled_warnings {
            found.disable(k);
        }
        let mut d = self.new_diags();
        d.extend(
            found
                .items()
                .iter()
                .filter(|x| {
                    x.is_error()
                        || x.kind
                            .is_none_or(|k| !self.config.disabled_warnings.contains(&k))
                })
                .cloned(),
        );
        if d.has_errors() {
            if take {
                let mut rest = program.statements.into_iter();
                for (&b, &n) in blocks.iter().zip(&counts) {
                    self.blocks[b].statements = rest.by_ref().take(n).collect();
                }
            }
            return Err(self.error(d));
        }
        self.diags.extend(d.items().iter().cloned());
        self.groundings += 1;
        let offset = self.stmts.len() as u32;
        if self.config.ground.provenance {
            let statements = program.statements.into_iter().take(own);
            self.stmts.extend(
                parts
                    .into_iter()
                    .zip(statements)
                    .map(|(part, statement)| GroundedStatement { part, statement }),
            );
        }
        if first {
            self.adopt(grounding);
            Ok(())
        } else {
            self.merge(grounding, offset).map_err(|e| {
                let mut d = self.new_diags();
                d.push(e);
                self.error(d)
            })
        }
    }
}

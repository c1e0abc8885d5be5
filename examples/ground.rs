//! Grounds files with Lucent's grounder and prints the result, as `gringo` would: aspif by
//! default, `--text` for the readable form. Used by `scripts/bench_ground.sh` until the command
//! line grounds (`lucent --mode=gringo`).
//!
//! Usage: `ground [--text] [--origins] [-c name=value]... [files]` (no file: standard input).

use std::io::Read;

use lucent::base::{FileId, SourceMap};
use lucent::ground::{aspif, ground, text, GroundConfig};
use lucent::syntax::ast::{self, Dialect};
use lucent::syntax::parse;

fn main() {
    let mut args = std::env::args().skip(1);
    let mut files = Vec::new();
    let mut as_text = false;
    let mut origins = false;
    let mut consts = Vec::new();
    while let Some(a) = args.next() {
        match a.as_str() {
            "--text" => as_text = true,
            "--origins" => origins = true,
            "-c" => consts.push(args.next().expect("-c needs name=value")),
            _ => files.push(a),
        }
    }
    let mut sources = SourceMap::new();
    let mut program = ast::Program::default();
    let mut failed = false;
    if files.is_empty() {
        files.push("-".to_string());
    }
    for f in &files {
        let text = if f == "-" {
            let mut s = String::new();
            std::io::stdin()
                .read_to_string(&mut s)
                .expect("reading standard input");
            s
        } else {
            std::fs::read_to_string(f).unwrap_or_else(|e| panic!("reading {f}: {e}"))
        };
        let id: FileId = sources.add(f.clone(), text.clone());
        let dialect = if f.ends_with(".sp") {
            Dialect::Sparc
        } else {
            Dialect::Clingo
        };
        let parsed = parse(id, &text, dialect);
        for d in &parsed.diagnostics {
            eprint!("{}", d.render(&sources));
            failed |= d.is_error();
        }
        program.dialect = parsed.program.dialect;
        program.statements.extend(parsed.program.statements);
    }
    let mut config = GroundConfig {
        provenance: origins,
        ..GroundConfig::default()
    };
    for c in consts {
        let (name, value) = c.split_once('=').expect("-c name=value");
        let id = sources.add("<cmd>", value.to_string());
        let parsed = parse(id, &format!("#const {name} = {value}."), Dialect::Clingo);
        if let Some(ast::StatementKind::Const(def)) =
            parsed.program.statements.first().map(|s| &s.kind)
        {
            config.consts.push((name.to_string(), def.value.clone()));
        }
    }
    let mut diags = lucent::base::Diagnostics::default();
    let mut load = |p: &std::path::Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
    let program =
        lucent::ground::include::resolve_includes(&program, &mut sources, &mut diags, &mut load);
    eprint!("{}", diags.render(&sources));
    if failed || diags.has_errors() {
        std::process::exit(65);
    }
    let result = ground(&program, Some(&sources), &config);
    eprint!("{}", result.diagnostics.render(&sources));
    if result.diagnostics.has_errors() {
        std::process::exit(65);
    }
    if as_text {
        print!(
            "{}",
            text::write_text(&result, if origins { Some(&sources) } else { None })
        );
    } else {
        let stdout = std::io::stdout();
        let mut out = std::io::BufWriter::new(stdout.lock());
        aspif::write_program_to(&result.program, &mut out)
            .and_then(|()| std::io::Write::flush(&mut out))
            .expect("writing standard output");
    }
}

//! `lucent explain` and `lucent ask`: the robot's explanations (docs/domain.md section 6) on the
//! command line, and `--why`/`--why-not` for any clingo program.
//!
//! - `lucent explain SCENE.ald... [--happened PLAN] [--goal LITS] -q QUESTION`: one question
//!   about a history: the description and scene files (AL_d; a scene usually includes the
//!   domain), the goal (the scene's `goal`, or `--goal`), and either an executed plan
//!   (`--happened "a@0; b@1"`, need not be minimal) or the first minimal plan the planner finds.
//! - `lucent explain PROGRAM.lp --why ATOM` / `--why-not ATOM`: the proof (or the blocked rules)
//!   of an atom in the program's first answer set; `--why-unsat`: why it has none
//!   (`cli::explain_program`).
//! - `lucent ask SCENE.ald... [--happened PLAN]` or `lucent ask --run RUN.json [DOMAIN.ald]`:
//!   questions read line by line, each answered in turn; follow-up questions take their step
//!   from the previous one. The session keeps its questions: `history` lists them, `!N` asks
//!   question N again and `!!` the last one. When standard input and output are a terminal the
//!   lines are read by a line editor (rustyline: cursor keys, up and down recall earlier
//!   questions); otherwise (pipes, scripts, tests) by the plain line reader, which echoes each
//!   question so that a transcript reads as a dialogue.
//! - `--run RUN.json` (both verbs): a run `lucent run` saved (`--save-history`, or its `--outf=2`
//!   output) instead of a scene: its step-0 perception, statics, goal and executed actions
//!   (`explain::history::scene_of_run`), over the domain files given (default: the built-in
//!   KB_full).
//!
//! Output: the English answer, or with `--outf=2` JSON `{type, answer, literals, tree}`;
//! `--dot FILE` / `--svg FILE` write the proof tree with the answer's path highlighted.
//!
//! Invariants: files are read and written here only; bad input files are positioned diagnostics
//! and exit 65; a question that is not understood gets the reply that says what was not
//! understood and what can be asked (exit 65 for `explain`, the session goes on for `ask`);
//! nothing the user types panics.

use std::io::{BufRead, IsTerminal, Write};

use crate::action::{self, ast::Value};
use crate::base::SourceMap;
use crate::explain::counterfactual::{what_if, why_no_plan};
use crate::explain::draw;
use crate::explain::english::{Parser, Question};
use crate::explain::history::{
    explain_steps, parse_actions, Failed, History, HistoryConfig, Steps, Surprise, Unexpected,
};
use crate::explain::lexicon::Lexicon;
use crate::explain::questions::{answer, Answer, AnswerError, Mode, Session};
use crate::explain::verbalize::Verbalizer;
use crate::plan::{plan, PlanConfig};

use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};

/// The command line of `lucent explain` and `lucent ask`; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent explain SCENE.ald... [--happened PLAN] [--goal LITERALS] -q QUESTION [options]
       lucent explain PROGRAM.lp (--why ATOM | --why-not ATOM | --why-unsat) [options]
       lucent ask SCENE.ald... [--happened PLAN] [--goal LITERALS] [options]
       lucent ask --run RUN.json [DOMAIN.ald] [options]

Answers questions about a history of the robot (docs/domain.md 6): plan description, why did you
X, why did you not X, why did you believe Y. The history is the scene (AL_d files, usually a
scene that includes domains/ra/kb_full.ald) with an executed plan (--happened \"a@0; b@1\" or
one action per `;`), or else the first minimal plan the planner finds for the goal.
With --run, the history is a run saved by `lucent run` (--save-history FILE or its --outf=2
output) over the domain files given (default: the built-in KB_full); an action the world
reported as failed keeps its step as an attempt without effect, and what the robot saw of
its object right after is taken as observed. A history the knowledge calls impossible is
repaired with the fewest surprises (an action executed although the robot believed it could
not be), which the answers name. With --why/--why-not, explains an atom of the first answer set
of any clingo program. In `ask`, `history` lists the questions asked so far, `!N` asks question
N again, `!!` the last one; an empty line or `quit` ends the session. On a terminal the
line can be edited, and the up and down keys recall earlier questions.
",
    options: OPTIONS,
    epilogue: "",
};

/// The options of `lucent explain` and `lucent ask`.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("question", Some('q'), Value, "TEXT", "the question (explain)", "Options"),
    opt("happened", None, Value, "PLAN", "the executed actions, in step order", "Options"),
    opt("run", None, Value, "FILE", "a run saved by `lucent run` (JSON) instead of a scene", "Options"),
    opt("goal", None, Value, "LITERALS", "a goal (AL_d literals, `relation(on, a, b), in_hand(rob1, c)`)", "Options"),
    opt("profile", None, Value, "NAME", "the description's profile", "Options"),
    opt("const", Some('c'), Value, "NAME=VALUE", "a switch of the description (or a constant of a clingo program)", "Options"),
    opt("max-horizon", None, Value, "H", "the planner's horizon budget (default 10)", "Options"),
    opt("full", None, Flag, "", "full mode: every reason, not only the first (with --why: every rule instance for the atom whose body holds; with --why-not: every failing body literal of each rule)", "Options"),
    opt("outf", None, Value, "N", "0: English (default); 2: JSON {\"type\", \"answer\", \"literals\", \"tree\"}", "Options"),
    opt("dot", None, Value, "FILE", "the proof tree as Graphviz DOT", "Options"),
    opt("svg", None, Value, "FILE", "the proof tree as SVG", "Options"),
    opt("why", None, Value, "ATOM", "the proof of ATOM in the first answer set of a clingo program", "Options"),
    opt("why-not", None, Value, "ATOM", "why ATOM is false in the first answer set of a clingo program: the rules that could derive it, each blocked", "Options"),
    opt("why-unsat", None, Flag, "", "why a clingo program has no answer set: a minimal unsatisfiable subset of its facts and constraints", "Options"),
    opt("assume", None, Value, "SIG", "with --why-unsat: only facts of predicate SIG (`edge/2`) are candidates (repeatable)", "Options"),
    opt("models", Some('n'), Value, "N", "with --why/--why-not: explain in each of the first N answer sets (0: all)", "Options"),
    opt("assume-choices", None, Flag, "", "with --why-unsat: choice rules are candidates too", "Options"),
];

/// The parsed command line.
#[derive(Default)]
struct Args {
    files: Vec<String>,
    question: Option<String>,
    happened: Option<String>,
    goal: Option<String>,
    profile: Option<String>,
    overrides: Vec<(String, String)>,
    max_horizon: Option<usize>,
    full: bool,
    json: bool,
    dot: Option<String>,
    svg: Option<String>,
    why: Option<String>,
    why_not: Option<String>,
    why_unsat: bool,
    assume: Vec<String>,
    assume_choices: bool,
    /// Answer sets to explain in (`--models`; 0: all).
    models: usize,
    run: Option<String>,
    /// The run itself, when the caller has it as a value (`run` then only names it).
    run_value: Option<crate::plan::history::History>,
}

fn usage(err: &mut dyn Write, verb: &str, msg: &str) -> std::io::Result<i32> {
    writeln!(
        err,
        "*** ERROR: (lucent): {msg} (try `lucent {verb} --help`)"
    )?;
    Ok(super::EXIT_USAGE)
}

fn parse_args(args: &[String]) -> Result<Args, String> {
    let mut a = Args {
        models: 1,
        ..Args::default()
    };
    for arg in options::scan(OPTIONS, args) {
        let (spec, v) = match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => (spec, v.unwrap_or_default()),
            Arg::Word(w) | Arg::Literal(w) => {
                a.files.push(w);
                continue;
            }
        };
        match spec.long {
            "question" => a.question = Some(v),
            "happened" => a.happened = Some(v),
            "run" => a.run = Some(v),
            "goal" => a.goal = Some(v),
            "profile" => a.profile = Some(v),
            "max-horizon" => a.max_horizon = Some(spec.number(&v)?),
            "full" => a.full = true,
            "outf" => a.json = spec.outf(&v)?,
            "dot" => a.dot = Some(v),
            "svg" => a.svg = Some(v),
            "why" => a.why = Some(v),
            "why-not" => a.why_not = Some(v),
            "why-unsat" => a.why_unsat = true,
            "assume" => a.assume.push(v),
            "assume-choices" => a.assume_choices = true,
            "models" => a.models = spec.number(&v)?,
            "const" => a.overrides.push(spec.assignment(&v)?),
            _ => {} // --help, answered before parsing
        }
    }
    Ok(a)
}

/// The front shared by `explain` and `ask`: `--help` prints the help, then the arguments are
/// parsed and must name a scene file or a run; `missing` is the usage message when they do not.
/// `Err(code)` is the exit code when the verb should stop here.
fn parse_verb_args(
    args: &[String],
    verb: &str,
    missing: &str,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<Result<Args, i32>> {
    if VERB.asks_for_help(args) {
        write!(out, "{}", VERB.help())?;
        return Ok(Err(0));
    }
    let a = match parse_args(args) {
        Ok(a) => a,
        Err(m) => return usage(err, verb, &m).map(Err),
    };
    if a.files.is_empty() && a.run.is_none() {
        return usage(err, verb, missing).map(Err);
    }
    Ok(Ok(a))
}

/// `lucent explain`.
pub fn run_explain(
    args: &[String],
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let a = match parse_verb_args(args, "explain", "`lucent explain` needs a file", out, err)? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    if a.why_unsat {
        return super::explain_program::run_why_unsat(
            &a.files,
            &a.overrides,
            &a.assume,
            a.assume_choices,
            a.json,
            out,
            err,
        );
    }
    if a.why.is_some() || a.why_not.is_some() {
        return run_generic(&a, out, err);
    }
    let Some(question) = a.question.clone() else {
        return usage(
            err,
            "explain",
            "`lucent explain` needs a question (-q TEXT)",
        );
    };
    let (history, no_plan) = match load_history(&a, err)? {
        Ok(h) => h,
        Err(code) => return Ok(code),
    };
    let lexicon = Lexicon::ra();
    let mut session = Session::default();
    let reply = respond(&history, no_plan, &lexicon, &question, &a, &mut session);
    emit(&reply, Some(&history), &a, out, err)?;
    Ok(if reply.understood {
        0
    } else {
        super::EXIT_INPUT
    })
}

/// Where `lucent ask` reads its lines.
pub trait LineSource {
    /// The next line without its end, after showing `prompt` (empty: none); `None` at the end
    /// of the input.
    fn next_line(&mut self, prompt: &str, out: &mut dyn Write) -> std::io::Result<Option<String>>;
    /// Whether the reader shows what is typed itself (a terminal): otherwise the session echoes
    /// each question after the prompt.
    fn shows_input(&self) -> bool;
    /// Keeps a question for recall (the up key of a line editor).
    fn remember(&mut self, _question: &str) {}
}

/// The plain line reader: pipes, scripts and tests.
pub struct PlainLines<'a> {
    input: &'a mut dyn BufRead,
    echo: bool,
}

impl<'a> PlainLines<'a> {
    /// Reads from `input`; with `echo`, the session echoes each question (the input is not a
    /// terminal, so the transcript would otherwise show only the answers).
    pub fn new(input: &'a mut dyn BufRead, echo: bool) -> Self {
        PlainLines { input, echo }
    }
}

impl LineSource for PlainLines<'_> {
    fn next_line(&mut self, prompt: &str, out: &mut dyn Write) -> std::io::Result<Option<String>> {
        if !prompt.is_empty() {
            write!(out, "{prompt}")?;
            out.flush()?;
        }
        let mut line = String::new();
        if self.input.read_line(&mut line)? == 0 {
            return Ok(None);
        }
        Ok(Some(line))
    }

    fn shows_input(&self) -> bool {
        !self.echo
    }
}

/// The line editor of a terminal session (rustyline without its optional features: no file
/// history, no custom bindings): cursor keys, Home/End, up and down through this session's
/// questions. Ctrl-D and Ctrl-C end the session.
pub struct EditorLines {
    editor: rustyline::DefaultEditor,
}

impl EditorLines {
    /// An editor on the process's terminal; `None` when the terminal cannot be set up.
    pub fn new() -> Option<Self> {
        rustyline::DefaultEditor::new()
            .ok()
            .map(|editor| EditorLines { editor })
    }
}

impl LineSource for EditorLines {
    fn next_line(&mut self, prompt: &str, out: &mut dyn Write) -> std::io::Result<Option<String>> {
        // What the session wrote so far must be on the screen before the editor draws.
        out.flush()?;
        match self.editor.readline(prompt) {
            Ok(line) => Ok(Some(line)),
            Err(rustyline::error::ReadlineError::Eof)
            | Err(rustyline::error::ReadlineError::Interrupted) => Ok(None),
            Err(rustyline::error::ReadlineError::Io(e)) => Err(e),
            Err(e) => Err(std::io::Error::other(e.to_string())),
        }
    }

    fn shows_input(&self) -> bool {
        true
    }

    fn remember(&mut self, question: &str) {
        // A full or failing history only loses the recall of this one question.
        let _ = self.editor.add_history_entry(question);
    }
}

/// True when this command line is `lucent ask` on a terminal (standard input and output), the
/// case [`run_ask_on_terminal`] serves with a line editor.
pub fn wants_line_editor(args: &[String]) -> bool {
    args.first().is_some_and(|a| a == "ask")
        && std::io::stdin().is_terminal()
        && std::io::stdout().is_terminal()
}

/// `lucent ask` on the process's terminal with a line editor (falling back to the plain reader
/// when the terminal cannot be set up); `args` are the verb's arguments. Returns the exit code.
pub fn run_ask_on_terminal(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    let result = match EditorLines::new() {
        Some(mut editor) => run_ask(args, &mut editor, out, err),
        None => {
            let stdin = std::io::stdin();
            let mut lock = stdin.lock();
            run_ask(args, &mut PlainLines::new(&mut lock, false), out, err)
        }
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            if e.kind() != std::io::ErrorKind::BrokenPipe {
                let _ = writeln!(err, "*** ERROR: (lucent): {e}");
            }
            super::EXIT_UNAVAILABLE
        }
    }
}

/// `lucent ask`: one question per line from `lines`.
pub fn run_ask(
    args: &[String],
    lines: &mut dyn LineSource,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let a = match parse_verb_args(
        args,
        "ask",
        "`lucent ask` needs a scene file or --run RUN.json",
        out,
        err,
    )? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    let (history, no_plan) = match load_history(&a, err)? {
        Ok(h) => h,
        Err(code) => return Ok(code),
    };
    let lexicon = Lexicon::ra();
    let mut session = Session::default();
    let plan: Vec<String> = history
        .plan
        .iter()
        .map(|(i, x)| format!("{x}@{i}"))
        .collect();
    if !a.json {
        writeln!(out, "History: {}", plan.join("; "))?;
        writeln!(
            out,
            "Ask me about it (`history` lists your questions, `!N` asks one again; an empty \
             line or `quit` ends)."
        )?;
    }
    let mut asked: Vec<String> = Vec::new();
    let prompt = if a.json { "" } else { "> " };
    while let Some(line) = lines.next_line(prompt, out)? {
        let typed = line.trim();
        if typed.is_empty() || typed == "quit" || typed == "exit" {
            break;
        }
        if !a.json && !lines.shows_input() {
            writeln!(out, "{typed}")?;
        }
        if typed == "history" {
            if asked.is_empty() {
                writeln!(out, "No questions yet.")?;
            }
            for (k, q) in asked.iter().enumerate() {
                writeln!(out, "{:>3}  {q}", k + 1)?;
            }
            continue;
        }
        let q = match recall(typed, &asked) {
            Recall::Question(q) => q,
            Recall::Again(q) => {
                if !a.json {
                    writeln!(out, "{q}")?;
                }
                q
            }
            Recall::Missing(n) => {
                writeln!(
                    out,
                    "There is no question {n} in this session: `history` lists them."
                )?;
                continue;
            }
        };
        let reply = respond(&history, no_plan, &lexicon, &q, &a, &mut session);
        emit(&reply, Some(&history), &a, out, err)?;
        lines.remember(&q);
        asked.push(q);
    }
    Ok(0)
}

/// What a typed line asks for in a session.
#[derive(Debug, PartialEq)]
enum Recall {
    /// A new question.
    Question(String),
    /// An earlier question, asked again (`!N`, `!!`).
    Again(String),
    /// `!N` for a question the session does not have.
    Missing(String),
}

/// Reads `!!` (the last question) and `!N` (question N, from 1); anything else is a question.
fn recall(typed: &str, asked: &[String]) -> Recall {
    let Some(rest) = typed.strip_prefix('!') else {
        return Recall::Question(typed.to_string());
    };
    let found = match rest.trim() {
        "!" => asked.last(),
        n => n
            .parse::<usize>()
            .ok()
            .and_then(|k| k.checked_sub(1))
            .and_then(|k| asked.get(k)),
    };
    match found {
        Some(q) => Recall::Again(q.clone()),
        None => Recall::Missing(typed.to_string()),
    }
}

/// One reply: the answer (or the reply to a question not understood).
struct Reply {
    answer: Answer,
    understood: bool,
}

fn respond(
    history: &History,
    no_plan: Option<usize>,
    lexicon: &Lexicon,
    question: &str,
    a: &Args,
    session: &mut Session,
) -> Reply {
    let objects = history.objects();
    let names: Vec<&str> = objects.iter().map(String::as_str).collect();
    let parser = Parser::new(lexicon, &names);
    let q = match parser.parse(question) {
        Ok(q) => q,
        Err(e) => {
            return Reply {
                answer: Answer {
                    kind: "not_understood",
                    text: parser.reply(&e),
                    literals: Vec::new(),
                    tree: None,
                },
                understood: false,
            }
        }
    };
    let horizon = a.max_horizon.unwrap_or(10);
    match &q {
        Question::WhyNoPlan { goal } => {
            let answer = match why_no_plan(&history.problem, lexicon, goal, horizon) {
                Ok(x) => x,
                Err(e) => Answer {
                    kind: "no_plan",
                    text: e.to_string(),
                    literals: Vec::new(),
                    tree: None,
                },
            };
            return Reply {
                answer,
                understood: true,
            };
        }
        Question::WhatIf { action, step } => {
            return Reply {
                answer: what_if(history, lexicon, action, *step, session),
                understood: true,
            };
        }
        _ => {}
    }
    if let Some(h) = no_plan {
        return Reply {
            answer: Answer {
                kind: q.kind(),
                text: format!(
                    "I found no plan of at most {h} steps, so I have no history to explain. \
                     You can ask: why is there no plan?"
                ),
                literals: Vec::new(),
                tree: None,
            },
            understood: true,
        };
    }
    let scn = history.scenario();
    let mode = if a.full { Mode::Full } else { Mode::Concise };
    match answer(&scn, lexicon, &q, mode, session) {
        Ok(mut answer) => {
            // Where the answer is about a surprising action, say the surprise.
            let v = Verbalizer::new(lexicon);
            if matches!(q, Question::DescribePlan) && !history.failed.is_empty() {
                // The attempts that failed, in their places.
                let mut said: Vec<(u32, String)> = history
                    .plan
                    .iter()
                    .map(|(i, x)| (*i, v.plan(&[(*i, x.clone())], true)))
                    .collect();
                said.extend(history.failed.iter().map(|f| (f.step, f.say(&v))));
                said.sort_by_key(|(i, _)| *i);
                answer.text = said
                    .into_iter()
                    .map(|(_, t)| t)
                    .collect::<Vec<_>>()
                    .join(" ");
            }
            if let Question::WhyAction { action, step } = &q {
                // An attempt that failed: say so, rather than "I did not do that".
                let tried: Vec<String> = history
                    .failed
                    .iter()
                    .filter(|f| {
                        step.is_none_or(|i| i == f.step)
                            && action.matches(&f.action, &mut Default::default())
                    })
                    .map(|f| f.say(&v))
                    .collect();
                let did = history.plan.iter().any(|(i, x)| {
                    step.is_none_or(|s| s == *i) && action.matches(x, &mut Default::default())
                });
                if !tried.is_empty() && !did {
                    answer.text = tried.join(" ");
                }
            }
            if matches!(q, Question::DescribePlan) {
                for u in &history.unexpected {
                    answer.text.push(' ');
                    answer.text.push_str(&u.say(&v));
                }
            }
            for s in &history.surprises {
                let matters = match &q {
                    Question::DescribePlan => true,
                    Question::WhyAction { action, step } => {
                        step.is_none_or(|i| i == s.step)
                            && action.matches(&s.action, &mut Default::default())
                    }
                    _ => false,
                };
                if matters {
                    answer.text.push(' ');
                    // Without --happened or --run the plan is the planner's own.
                    if a.happened.is_none() && a.run.is_none() {
                        answer.text.push_str(&s.say_planned(&v));
                    } else {
                        answer.text.push_str(&s.say(&v));
                    }
                }
            }
            Reply {
                answer,
                understood: true,
            }
        }
        Err(AnswerError::NeedsSolver) => Reply {
            answer: Answer {
                kind: q.kind(),
                text: match q.kind() {
                    "goal" => "That is a task, not a question about my history: \
                               `lucent plan` plans it."
                        .into(),
                    _ => "I cannot answer that kind of question.".into(),
                },
                literals: Vec::new(),
                tree: None,
            },
            understood: true,
        },
        Err(AnswerError::Recheck(e)) => Reply {
            answer: Answer {
                kind: q.kind(),
                text: format!("My explanation failed its own check ({e}); I will not give it."),
                literals: Vec::new(),
                tree: None,
            },
            understood: true,
        },
    }
}

fn emit(
    reply: &Reply,
    history: Option<&History>,
    a: &Args,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<()> {
    if a.json {
        let mut json = reply.answer.to_json();
        if let Some(h) = history {
            if !h.surprises.is_empty() {
                json["surprises"] = h.surprises.iter().map(Surprise::to_json).collect();
            }
            if !h.unexpected.is_empty() {
                json["unexpected"] = h.unexpected.iter().map(Unexpected::to_json).collect();
            }
            if !h.failed.is_empty() {
                json["failed"] = h.failed.iter().map(Failed::to_json).collect();
            }
        }
        writeln!(out, "{json}")?;
    } else {
        writeln!(out, "{}", reply.answer.text)?;
    }
    write_pictures(&reply.answer, a, err)
}

fn write_pictures(answer: &Answer, a: &Args, err: &mut dyn Write) -> std::io::Result<()> {
    for (file, svg) in [(&a.dot, false), (&a.svg, true)] {
        let Some(file) = file else { continue };
        let Some(tree) = &answer.tree else {
            writeln!(
                err,
                "lucent: this answer has no proof tree; {file} not written"
            )?;
            continue;
        };
        if tree.roots.is_empty() {
            // An atom decided by a choice has its reason in the text, not in rules to draw.
            writeln!(
                err,
                "lucent: this answer's proof tree is empty (the answer names the choice that \
                 decides it); {file} not written"
            )?;
            continue;
        }
        // A program's proof: each literal once, with its rule (`explain::draw_graph`).
        let program = a.why.is_some() || a.why_not.is_some();
        let text = if svg && program {
            crate::explain::draw_graph::svg(tree)
        } else if program {
            crate::explain::draw_graph::dot(tree)
        } else if svg {
            draw::svg(tree)
        } else {
            draw::dot(tree)
        };
        if let Err(e) = std::fs::write(file, text) {
            writeln!(err, "*** ERROR: (lucent): {file}: {e}")?;
        }
    }
    Ok(())
}

/// Reads the AL_d files, adds `--goal`, and makes the history (the executed plan, or the first
/// minimal plan). `Err(code)` after the error was written.
fn load_history(
    a: &Args,
    err: &mut dyn Write,
) -> std::io::Result<Result<(History, Option<usize>), i32>> {
    let mut sources = SourceMap::new();
    let mut desc = action::ast::Description::default();
    let mut read =
        |path: &std::path::Path| super::builtin::read_to_string(path).map_err(|e| e.to_string());
    let mut diags = crate::base::Diagnostics::default();
    let mut files: Vec<(String, Option<String>)> =
        a.files.iter().map(|f| (f.clone(), None)).collect();
    let mut run_actions = None;
    let mut run_scene = None;
    if let Some(path) = &a.run {
        let loaded = match &a.run_value {
            Some(run) => crate::explain::history::scene_of_run(run),
            None => super::builtin::read_to_string(path)
                .map_err(|e| e.to_string())
                .and_then(|t| crate::plan::history::History::from_json(&t))
                .and_then(|run| crate::explain::history::scene_of_run(&run)),
        };
        let (scene, actions) = match loaded {
            Ok(x) => x,
            Err(e) => {
                writeln!(err, "*** ERROR: (lucent): {path}: {e}")?;
                return Ok(Err(super::EXIT_INPUT));
            }
        };
        if files.is_empty() {
            files.push((
                "domains/ra/kb_full.ald (built in)".into(),
                Some(super::KB_FULL.to_string()),
            ));
        }
        run_scene = Some(scene);
        run_actions = Some(actions);
    }
    for (name, given) in files {
        let text = match given.map_or_else(|| super::builtin::read_to_string(&name), Ok) {
            Ok(t) => t,
            Err(e) => {
                writeln!(err, "*** ERROR: (lucent): {name}: {e}")?;
                return Ok(Err(super::EXIT_INPUT));
            }
        };
        let id = sources.add(name.clone(), text);
        let parsed = action::load(&mut sources, id, &mut read);
        diags.extend(parsed.diagnostics);
        desc.statements.extend(parsed.description.statements);
    }
    // The run's scene (objects, statics, initial state, goal) as statements built from values.
    if let Some(scene) = run_scene {
        desc.statements.extend(scene.statements());
    }
    if let Some(goal) = &a.goal {
        let text = format!("goal {goal}.\n");
        let id = sources.add("<goal>", text.clone());
        let parsed = action::parse(id, &text);
        diags.extend(parsed.diagnostics);
        // The command line's goal replaces the scene's.
        desc.statements
            .retain(|s| !matches!(s.kind, action::ast::StatementKind::Goal { .. }));
        desc.statements.extend(parsed.description.statements);
    }
    if diags.has_errors() {
        write!(err, "{}", diags.render(&sources))?;
        writeln!(err, "*** ERROR: (lucent): not a valid AL_d description")?;
        return Ok(Err(super::EXIT_INPUT));
    }
    let overrides: Vec<(String, Value)> = a
        .overrides
        .iter()
        .map(|(n, v)| (n.clone(), super::action::value_of(v)))
        .collect();
    let mut no_plan = None;
    let steps: Steps = match (&a.happened, run_actions) {
        (Some(text), _) => match parse_actions(text) {
            Ok(x) => Steps {
                actions: x.into_iter().map(Some).collect(),
                ..Steps::default()
            },
            Err(m) => {
                writeln!(err, "*** ERROR: (lucent): --happened: {m}")?;
                return Ok(Err(super::EXIT_INPUT));
            }
        },
        (None, Some(steps)) => steps,
        (None, None) => {
            let config = PlanConfig {
                max_horizon: a.max_horizon.unwrap_or(10),
                profile: a.profile.clone(),
                overrides: overrides.clone(),
                ..PlanConfig::default()
            };
            match plan(&desc, &sources, &config) {
                Ok(found) => Steps {
                    actions: found.plans[0].actions.iter().cloned().map(Some).collect(),
                    ..Steps::default()
                },
                Err(crate::plan::PlanError::NoPlanWithin(h)) => {
                    // No history: the initial state alone, for "why is there no plan?".
                    no_plan = Some(h);
                    Steps::default()
                }
                Err(e) => {
                    writeln!(err, "*** ERROR: (lucent): {e}")?;
                    return Ok(Err(match e {
                        crate::plan::PlanError::Input(_) => super::EXIT_INPUT,
                        _ => super::EXIT_UNSAT,
                    }));
                }
            }
        }
    };
    let config = HistoryConfig {
        profile: a.profile.clone(),
        overrides,
    };
    match explain_steps(&desc, &mut sources, &steps, &config) {
        Ok(h) => Ok(Ok((h, no_plan))),
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {}", e.to_string().trim_end())?;
            Ok(Err(match e {
                crate::explain::history::HistoryError::Input(_) => super::EXIT_INPUT,
                crate::explain::history::HistoryError::Inconsistent(_) => super::EXIT_UNSAT,
            }))
        }
    }
}

/// `--why ATOM` / `--why-not ATOM` over any clingo program.
fn run_generic(a: &Args, out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let (atom_text, negative) = match (&a.why, &a.why_not) {
        (Some(x), None) => (x.clone(), false),
        (None, Some(x)) => (x.clone(), true),
        _ => return usage(err, "explain", "give one of --why and --why-not"),
    };
    let query = match crate::explain::query::parse(&atom_text) {
        Ok(q) => q,
        Err(m) => {
            writeln!(err, "*** ERROR: (lucent): {m}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let oracles = match super::explain_program::oracles(&a.files, &a.overrides, a.models, err)? {
        Ok(o) => o,
        Err(code) => return Ok(code),
    };
    if oracles.is_empty() {
        return super::explain_program::say_unsat(a.json, out);
    }
    let answers: Vec<Answer> = oracles
        .iter()
        .map(|oracle| {
            crate::explain::query::explain(oracle, &query, negative, a.full).unwrap_or_else(|e| {
                Answer {
                    kind: if negative { "why_not" } else { "why" },
                    text: format!("The explanation failed its own check ({e}); it is not given."),
                    literals: Vec::new(),
                    tree: None,
                }
            })
        })
        .collect();
    if answers.len() > 1 {
        let all = super::explain_program::per_model(&answers);
        if a.json {
            writeln!(out, "{}", all.1)?;
        } else {
            writeln!(out, "{}", all.0.text)?;
        }
        write_pictures(&all.0, a, err)?;
        return Ok(0);
    }
    let reply = Reply {
        answer: answers
            .into_iter()
            .next()
            .expect("one answer per answer set"),
        understood: true,
    };
    emit(&reply, None, a, out, err)?;
    Ok(0)
}

/// Answers questions about a run of `lucent run` as `lucent ask --run FILE` would (`name`
/// names the run in messages): one `(question, answer)` pair per question, in order, each
/// answer with its proof tree when it has one; the step of a question carries to the next.
/// `Err` with the error's text when the run has no history.
#[cfg(feature = "sim")]
pub(super) fn ask_run(
    run: &crate::plan::history::History,
    name: &str,
    questions: &[String],
) -> Result<Vec<(String, Answer)>, String> {
    let mut a = parse_args(&["--run".to_string(), name.to_string()])?;
    a.run_value = Some(run.clone());
    let mut err = Vec::new();
    let loaded = load_history(&a, &mut err).map_err(|e| e.to_string())?;
    let Ok((history, no_plan)) = loaded else {
        return Err(String::from_utf8_lossy(&err).trim().to_string());
    };
    let lexicon = Lexicon::ra();
    let mut session = Session::default();
    Ok(questions
        .iter()
        .map(|q| {
            let reply = respond(&history, no_plan, &lexicon, q, &a, &mut session);
            (q.clone(), reply.answer)
        })
        .collect())
}

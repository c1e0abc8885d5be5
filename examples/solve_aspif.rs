//! Reads an aspif program (a file, or standard input for `-` or no file) and prints its answer
//! sets as clasp does, using Lucent's solver. A development tool for `scripts/bench_solve.sh`;
//! the real command line is `lucent --mode=clasp`. It uses mimalloc as its global allocator, the
//! `lucent` binary's (`src/mi_alloc.rs`).
//!
//! Usage: `solve_aspif [-n N] [--opt-mode=opt|optN|enum[,B..]|ignore]
//! [--enum-mode=auto|brave|cautious] [--project] [--cr=subset] [--time-limit=S] [--parallel-mode=N]
//! [--init-moms|--no-init-moms] [--vsids-decay=X] [--restarts=L,N|glucose|no]
//! [--save-progress=N] [--eq=0|1] [--score-other=all|no] [--profile=decision|auto|fixed|complement] [--sign-occ=0|1] [--block-restarts=0|1] [--phase-switch=CONFLICTS|0] [--solve-limit=CONFLICTS] [--body-phase=true|false] [--del-cfl=[+,]FIRST,INC[,REPEAT]] [--deletion=sorted|basic] [--loops=shared|atom] [-q] [FILE]`; the search options override the solver's search defaults, for tuning experiments.

use lucent::ground::aspif;
use lucent::solve::{
    Config, CrMode, Deletion, EnumMode, OptMode, Outcome, ReduceSchedule, RestartPolicy,
    SearchProfile, Solver,
};
use std::io::Read;

// The `lucent` binary's global allocator (`src/mi_alloc.rs`), so that this measures what
// `lucent --mode=clasp` does.
#[path = "../src/mi_alloc.rs"]
mod mi_alloc;

#[global_allocator]
static GLOBAL: mi_alloc::Mi = mi_alloc::Mi;
use std::process::ExitCode;
use std::time::{Duration, Instant};

fn main() -> ExitCode {
    mi_alloc::purge_at_once();
    let start = Instant::now();
    // As `lucent --mode=clasp`: nothing printed reads a model's supports.
    let mut config = Config {
        supports: false,
        ..Config::default()
    };
    let mut models: Option<usize> = None;
    let mut file: Option<String> = None;
    let mut quiet = false;
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut i = 0;
    while i < args.len() {
        let a = &args[i];
        if a == "-n" {
            i += 1;
            models = args.get(i).and_then(|s| s.parse().ok());
        } else if let Some(v) = a.strip_prefix("-n") {
            models = v.parse().ok();
        } else if let Some(v) = a.strip_prefix("--models=") {
            models = v.parse().ok();
        } else if let Some(v) = a.strip_prefix("--opt-mode=") {
            config.opt_mode = OptMode::from_name(v).unwrap_or_default();
        } else if let Some(v) = a.strip_prefix("--enum-mode=") {
            config.enum_mode = EnumMode::from_name(v).unwrap_or_default();
        } else if a == "--project" {
            config.project = lucent::solve::Project::Auto;
        } else if let Some(v) = a.strip_prefix("--cr=") {
            config.cr_mode = CrMode::from_name(v).unwrap_or_default();
        } else if let Some(v) = a.strip_prefix("--time-limit=") {
            if let Ok(s) = v.parse::<u64>() {
                config.deadline = Some(start + Duration::from_secs(s));
            }
        } else if let Some(v) = a.strip_prefix("--parallel-mode=") {
            config.threads = v
                .split(',')
                .next()
                .and_then(|n| n.parse().ok())
                .unwrap_or(1);
        } else if a == "--init-moms" || a == "--no-init-moms" {
            config.init_moms = a == "--init-moms";
        } else if let Some(v) = a.strip_prefix("--del-cfl=") {
            let v = v.strip_prefix("+,").unwrap_or(v);
            let mut it = v.split(',').filter_map(|x| x.parse().ok());
            config.reduce = ReduceSchedule::Conflicts {
                first: it.next().unwrap_or(2000),
                inc: it.next().unwrap_or(300),
                repeat: it.next().unwrap_or(0),
            };
        } else if let Some(v) = a.strip_prefix("--loops=") {
            config.shared_loops = v == "shared";
        } else if let Some(v) = a.strip_prefix("--deletion=") {
            config.deletion = if v.starts_with("basic") {
                Deletion::Basic
            } else {
                Deletion::Sorted
            };
        } else if let Some(v) = a.strip_prefix("--save-progress=") {
            config.profile = SearchProfile::Fixed;
            config.save_progress = v.parse().unwrap_or(0);
        } else if let Some(v) = a.strip_prefix("--body-phase=") {
            config.body_phase_true = v == "true";
        } else if let Some(v) = a.strip_prefix("--vsids-decay=") {
            config.profile = SearchProfile::Fixed;
            config.var_decay = v.parse().unwrap_or(config.var_decay);
        } else if let Some(v) = a.strip_prefix("--restarts=") {
            config.profile = SearchProfile::Fixed;
            config.restarts = match v.split_once(',') {
                Some(("L", u)) => RestartPolicy::Luby(u.parse().unwrap_or(100)),
                _ if v == "no" => RestartPolicy::Never,
                _ => RestartPolicy::Glucose,
            };
        } else if let Some(v) = a.strip_prefix("--score-other=") {
            config.score_other = v == "all";
        } else if let Some(v) = a.strip_prefix("--profile=") {
            config.profile = match v {
                "fixed" => SearchProfile::Fixed,
                "auto" => SearchProfile::Auto,
                "complement" => SearchProfile::Complement,
                _ => SearchProfile::Decision,
            };
        } else if let Some(v) = a.strip_prefix("--phase-switch=") {
            config.phase_switch = v.parse().ok().filter(|&k| k > 0);
        } else if let Some(v) = a.strip_prefix("--block-restarts=") {
            config.restart_blocking = v != "0";
        } else if let Some(v) = a.strip_prefix("--sign-occ=") {
            config.sign_from_learnts = v != "0";
        } else if let Some(v) = a.strip_prefix("--solve-limit=") {
            config.conflict_limit = v.parse().ok();
        } else if let Some(v) = a.strip_prefix("--seed=") {
            config.seed = v.parse().unwrap_or(config.seed);
        } else if let Some(v) = a.strip_prefix("--rand-freq=") {
            let p: f64 = v.parse().unwrap_or(0.0);
            config.random_freq_permille = (p.clamp(0.0, 1.0) * 1000.0).round() as u32;
        } else if let Some(v) = a.strip_prefix("--eq=") {
            config.eq = v != "0";
        } else if a == "-q" {
            quiet = true;
        } else {
            file = Some(a.clone());
        }
        i += 1;
    }
    let mut bytes = Vec::new();
    let read = match file.as_deref() {
        None | Some("-") => std::io::stdin().read_to_end(&mut bytes).map(|_| ()),
        Some(path) => std::fs::read(path).map(|b| bytes = b),
    };
    if let Err(e) = read {
        eprintln!("error: cannot read input: {e}");
        return ExitCode::from(65);
    }
    let program = match aspif::read_program(&bytes) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(65);
        }
    };
    // The text is not needed once read; free it before the solver is built.
    drop(bytes);
    let optimizing = !program.minimize.is_empty() && config.opt_mode != OptMode::Ignore;
    config.models = models.unwrap_or(if optimizing || config.enum_mode != EnumMode::Auto {
        0
    } else {
        1
    });
    let threads = config.threads;
    let mut solver = Solver::from_program(program, config);
    let mut count = 0;
    let mut last_costs: Vec<i64> = Vec::new();
    let mut print = |m: &lucent::solve::Model| {
        count += 1;
        last_costs = m.costs.clone();
        if !quiet {
            println!("Answer: {}", m.number);
            println!("{}", m.symbols.join(" "));
            if !m.costs.is_empty() {
                let c: Vec<String> = m.costs.iter().map(|c| c.to_string()).collect();
                println!("Optimization: {}", c.join(" "));
            }
        }
        true
    };
    let result = if threads >= 2 {
        // The portfolio answers once, with the winner's models.
        let r = solver.solve();
        for m in &r.models {
            print(m);
        }
        r
    } else {
        solver.for_each_model(&[], &mut print)
    };
    println!(
        "{}",
        match result.outcome {
            Outcome::Satisfiable => "SATISFIABLE",
            Outcome::Unsatisfiable => "UNSATISFIABLE",
            Outcome::Unknown => "UNKNOWN",
            Outcome::Optimum => "OPTIMUM FOUND",
        }
    );
    println!();
    println!(
        "Models       : {}{}",
        count,
        if result.exhausted { "" } else { "+" }
    );
    if !last_costs.is_empty() {
        let c: Vec<String> = last_costs.iter().map(|c| c.to_string()).collect();
        println!("Optimization : {}", c.join(" "));
    }
    println!("Choices      : {}", result.stats.choices);
    println!("Conflicts    : {}", result.stats.conflicts);
    println!("Restarts     : {}", result.stats.restarts);
    println!("Propagations : {}", result.stats.propagations);
    println!("Loop nogoods : {}", result.stats.loop_nogoods);
    println!("Variables    : {}", result.stats.vars);
    println!("Constraints  : {}", result.stats.clauses);
    println!("Time         : {:.3}s", start.elapsed().as_secs_f64());
    ExitCode::from(match result.outcome {
        Outcome::Unknown => 1,
        Outcome::Unsatisfiable => 20,
        _ if result.exhausted => 30,
        _ => 10,
    })
}

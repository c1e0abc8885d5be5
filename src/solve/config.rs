//! Solver configuration: every knob the command line maps clingo/clasp options onto, and the
//! clasp names of its modes (`OptMode::from_name`, `EnumMode::from_name`, ...), which the command
//! line parses into these types directly.
//!
//! Invariant: a `Config` is a plain value; the solver never reads the clock or the environment
//! except through the deadline and the interrupt flag given here (ARCHITECTURE.md, invariants:
//! limits reach the solver as values, it answers with a stop reason).

use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Instant;

/// What to do with `#minimize` statements (clasp `--opt-mode`).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub enum OptMode {
    /// Find an optimum by branch and bound, reporting each improving model.
    #[default]
    Opt,
    /// Find an optimum, then enumerate all optimal models.
    OptN,
    /// Enumerate models, optionally only those whose cost is lexicographically at most the
    /// bound (highest priority first; missing components are unbounded).
    Enum(Vec<i64>),
    /// Ignore the optimization statements (`--opt-mode=ignore`).
    Ignore,
}

impl OptMode {
    /// The mode clasp's `--opt-mode` names: `opt`, `optN`, `enum` or `ignore`, optionally
    /// followed by bounds (`enum,3,4`). Every bound must be an integer; only `enum` keeps them
    /// (clasp's initial bound of `opt` is not implemented). `None` for anything else.
    pub fn from_name(text: &str) -> Option<OptMode> {
        let mut parts = text.split(',');
        let name = parts.next()?;
        let bounds = parts
            .map(|b| b.trim().parse::<i64>().ok())
            .collect::<Option<Vec<_>>>()?;
        match name {
            "opt" => Some(OptMode::Opt),
            "optN" => Some(OptMode::OptN),
            "enum" => Some(OptMode::Enum(bounds)),
            "ignore" => Some(OptMode::Ignore),
            _ => None,
        }
    }
}

/// How an optimum is searched for (clasp `--opt-strategy`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum OptStrategy {
    /// Model-guided branch and bound: each model's costs bound the next one from above
    /// (`solver/strategies.rs`).
    #[default]
    Bb,
    /// Core-guided: unsatisfiable cores under the assumption that every cost literal is false
    /// raise a lower bound until a model meets it, relaxed with OLL's cardinality outputs
    /// (`solver/core_guided.rs`).
    Usc,
}

impl OptStrategy {
    /// The strategy clasp's `--opt-strategy=<s>[,<tactics>...]` names: `bb` with any of clasp's
    /// tactics (`lin`, `hier`, `inc`, `dec`, or a number; the search is the same), `usc` with
    /// an optional relaxation among `oll`, `one`, `k`, `pmres` (all run OLL: the optimum and the
    /// optimal models are the same, only the cores' encoding differs) followed by clasp's
    /// numeric options, which are accepted and ignored. `None` for anything else.
    pub fn from_name(text: &str) -> Option<OptStrategy> {
        let mut parts = text.split(',').map(str::trim);
        let name = parts.next()?;
        let known: &[&str] = match name {
            "bb" => &["lin", "hier", "inc", "dec"],
            "usc" => &[
                "oll", "one", "k", "pmres", "disjoint", "succinct", "stratify",
            ],
            _ => return None,
        };
        parts
            .all(|t| known.contains(&t) || t.parse::<u64>().is_ok())
            .then_some(if name == "bb" {
                OptStrategy::Bb
            } else {
                OptStrategy::Usc
            })
    }
}

/// How models are enumerated or summarised (clasp `--enum-mode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum EnumMode {
    /// Plain enumeration of answer sets.
    #[default]
    Auto,
    /// Brave consequences: shown atoms true in some answer set.
    Brave,
    /// Cautious consequences: shown atoms true in every answer set.
    Cautious,
}

impl EnumMode {
    /// The mode clasp's `--enum-mode` names: `auto`, `bt` and `record` (clasp's two ways of
    /// enumerating answer sets, which here are the one plain enumeration), `brave`, `cautious`.
    pub fn from_name(name: &str) -> Option<EnumMode> {
        match name {
            "auto" | "bt" | "record" => Some(EnumMode::Auto),
            "brave" => Some(EnumMode::Brave),
            "cautious" => Some(EnumMode::Cautious),
            _ => None,
        }
    }
}

/// Which answer sets count for programs with consistency-restoring rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CrMode {
    /// Minimal number of applied CR rules (SPARC's semantics).
    #[default]
    Cardinality,
    /// Set-inclusion-minimal sets of applied CR rules (original CR-Prolog).
    Subset,
}

impl CrMode {
    /// The mode `--cr` names: `card` (or `cardinality`), `subset`.
    pub fn from_name(name: &str) -> Option<CrMode> {
        match name {
            "card" | "cardinality" => Some(CrMode::Cardinality),
            "subset" => Some(CrMode::Subset),
            _ => None,
        }
    }
}

/// Projective enumeration (clasp `--project=<mode>`): which atoms tell answer sets apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Project {
    /// No projection: every answer set is reported.
    #[default]
    No,
    /// `#project` atoms when the program has any, else the shown atoms (`--project`,
    /// `--project=auto`).
    Auto,
    /// The shown atoms, whatever `#project` says (`--project=show`).
    Show,
    /// The `#project` atoms only; none at all when the program has none, so one answer set
    /// is reported (`--project=project`).
    Project,
}

impl Project {
    /// The mode clasp's `--project=<mode>[,<bt>]` names: `show`, `project`, `auto`, `no` or
    /// `0` (the last two without `<bt>`); `None` for anything else.
    pub fn from_name(text: &str) -> Option<Project> {
        match text.split(',').next()? {
            "show" => Some(Project::Show),
            "project" => Some(Project::Project),
            "auto" => Some(Project::Auto),
            "no" | "0" if !text.contains(',') => Some(Project::No),
            _ => None,
        }
    }

    /// Whether answer sets are projected at all.
    pub fn is_on(self) -> bool {
        self != Project::No
    }
}

/// The decision heuristic (clasp `--heuristic`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Heuristic {
    /// VSIDS with phase saving; clasp's `berkmin`, `vmtf`, `unit` and `none` are this one too
    /// (they change the search order, never the answers).
    #[default]
    Vsids,
    /// Follow the program's `#heuristic` statements without a condition, with the modifiers
    /// level, sign, true and false, before VSIDS (`--heuristic=domain`).
    Domain,
}

impl Heuristic {
    /// The heuristic clasp's `--heuristic=<h>[,<n>]` names, in any case: `berkmin`, `vmtf`,
    /// `vsids`, `unit` and `none` are [`Heuristic::Vsids`], `domain` [`Heuristic::Domain`].
    pub fn from_name(text: &str) -> Option<Heuristic> {
        let name = text.split(',').next()?.to_ascii_lowercase();
        match name.as_str() {
            "berkmin" | "vmtf" | "vsids" | "unit" | "none" => Some(Heuristic::Vsids),
            "domain" => Some(Heuristic::Domain),
            _ => None,
        }
    }
}

/// Solver configuration.
#[derive(Clone, Debug)]
pub struct Config {
    /// Number of models to compute; 0 means all (`-n`). With `#minimize` in `Opt` mode, 0 means
    /// "until the optimum is proven" and N stops after N improving models, as in clasp; the
    /// command line passes 0 there unless the user gave `-n`. [`Config::AUTO_MODELS`] is
    /// clasp's default (`-n -1`): 0 for a program that optimizes or for consequences (brave,
    /// cautious), else 1, decided at each call.
    pub models: usize,
    /// Optimization mode.
    pub opt_mode: OptMode,
    /// Optimization strategy (`--opt-strategy`).
    pub opt_strategy: OptStrategy,
    /// Enumeration mode.
    pub enum_mode: EnumMode,
    /// Semantics for CR rules.
    pub cr_mode: CrMode,
    /// Enumerate projected models only (`--project=<mode>`, see [`Project`]).
    pub project: Project,
    /// Stop with `UNKNOWN` once this instant has passed.
    pub deadline: Option<Instant>,
    /// Stop with `UNKNOWN` once this flag becomes true (e.g. set by a signal handler).
    pub interrupt: Option<Arc<AtomicBool>>,
    /// Seed of the pseudo-random generator used for tie breaking and random decisions.
    pub seed: u64,
    /// Probability, in 1/1000, of a random decision instead of the VSIDS choice.
    pub random_freq_permille: u32,
    /// The decision heuristic.
    pub heuristic: Heuristic,
    /// VSIDS decay factor, in (0, 1). 0.92 as clasp's tweety (ARCHITECTURE.md, "Search
    /// settings", has the measurements).
    pub var_decay: f64,
    /// Initial phase of decision variables: false first when `true` (clasp's default for atoms).
    pub default_phase_false: bool,
    /// Initial phase of body variables (clasp's `--sign-def=asp` tries bodies true).
    pub body_phase_true: bool,
    /// Save phases only on backjumps over more than this many levels (clasp
    /// `--save-progress`); 0 saves on every backtrack.
    pub save_progress: u32,
    /// Restart policy.
    pub restarts: RestartPolicy,
    /// Whether the search settings depend on the program class (`SearchProfile`).
    pub profile: SearchProfile,
    /// When learnt clauses are reduced.
    pub reduce: ReduceSchedule,
    /// Which learnt clauses a reduction deletes.
    pub deletion: Deletion,
    /// Seed the VSIDS activities from clause occurrences before the first decision (clasp
    /// `--init-moms`).
    pub init_moms: bool,
    /// Stop with `UNKNOWN` after this many conflicts (clasp `--solve-limit`; for tuning).
    pub conflict_limit: Option<u64>,
    /// Learn an unfounded set as one shared loop formula (`engine/loops.rs`) instead of one
    /// clause per atom. Off by default: it halves the peak memory on labyrinth but raised the
    /// conflict counts (docs/design/solver.md, "Loop nogoods").
    pub shared_loops: bool,
    /// Bump the variables of loop nogoods when they are learnt (clasp `--score-other=all`).
    pub score_other: bool,
    /// Decide variables without a saved phase with the polarity that occurs more often in
    /// learnt clauses (clasp's VSIDS sign score). Only matters when phases are rarely saved
    /// (`save_progress` > 0); the tweety values of `SearchProfile` turn it on.
    pub sign_from_learnts: bool,
    /// Postpone glucose restarts while the trail is much longer than on average.
    pub restart_blocking: bool,
    /// After this many conflicts in one search call without a model, a program without
    /// `#minimize` and without tweety's values (tight ones under `SearchProfile::Auto`, all
    /// under `Complement`) switches to clasp's phase handling for the rest of the call: saved
    /// phases are forgotten once, phases are saved only on backjumps over more than 160
    /// levels, and the sign score decides the rest (`Engine::phase_switch`).
    /// A long run without a model is the mark of a refutation such as pigeons 10/9, where this
    /// halves the conflicts and their cost; satisfiable planning rows lose from it when it
    /// starts early (docs/bench/pigeon-2026-12-06.txt). `None` never switches.
    pub phase_switch: Option<u64>,
    /// Merge atoms equivalent to a literal or to a rule body by their completion before search
    /// (clasp `--eq`, on in all of clasp's configurations; see `translate::equivalences`). On
    /// by default: over the benchmark pairs it lowers conflicts and CPU time
    /// (docs/design/solver.md, "Search settings"). Atoms that a later step may still close a
    /// positive cycle through (they depend on an external atom) are not merged.
    pub eq: bool,
    /// Check every model with an independent stable-model test before reporting it (debug aid).
    pub check_models: bool,
    /// Number of portfolio threads (`--parallel-mode=N`); 1 is sequential.
    pub threads: usize,
    /// Compute every model's [`Model::support`](crate::solve::Model) (one supporting rule per
    /// true atom). Callers that never read supports turn it off: building them was ~5% of a
    /// learning run, whose one-step programs are solved thousands of times (docs/bench/h1.md).
    pub supports: bool,
}

/// Which search settings apply.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SearchProfile {
    /// `var_decay`, `restarts`, `save_progress` and `sign_from_learnts` as configured, except
    /// for programs with positive loops (an unfounded-set propagator is installed) and no
    /// `#minimize`: these get clasp's `tweety` values instead (decay 0.92, Luby restarts with
    /// unit 60, save-progress 160, and clasp's sign score from learnt-clause occurrences for
    /// variables without a saved phase); tight decision programs get the phase switch
    /// (`Config::phase_switch`). The default until 2026-12-07 (chosen on 2026-12-03, when the
    /// tweety values cost 1.17 times the conflicts on tight programs); a tuning option now.
    Auto,
    /// The tweety values for every program without `#minimize`, tight or not (clasp's choice);
    /// the configured values for the others. The default since 2026-12-07: on the current
    /// solver, over the 45 tight decision rows of the benchmark table, the tweety values take
    /// 0.91 times the conflicts of `Auto`'s, and end to end against clingo the geometric mean
    /// is 0.84 instead of 0.88 (docs/bench/profile-2026-12-07.md).
    #[default]
    Decision,
    /// The configured values for every program.
    Fixed,
    /// The other half of `Decision`: the configured values, with the phase switch, for every
    /// program (never tweety's). The second thread of a two-thread portfolio searches with it,
    /// so that the two threads run the two profiles whose conflict counts differ most from row
    /// to row (docs/bench/threads-2026-12-07d.md: each wins rows by up to 25 times).
    Complement,
}

/// Which learnt clauses a reduction deletes. Both delete up to half of the learnt clauses and
/// never a clause with LBD at most 2 or one that is the reason of an assignment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Deletion {
    /// Glucose's order: sort by LBD (highest first), then by MiniSat activity (a float bumped
    /// when the clause takes part in conflict analysis, decayed by 0.999 per conflict), and
    /// delete the first half.
    Sorted,
    /// clasp's `--deletion=basic,50 --del-glue=2`: the activity is a use counter (bumped in
    /// conflict analysis and in clause minimisation, starting at 1 plus the number of
    /// restarts, halved at every reduction); going from the oldest clause to the newest, every
    /// clause whose activity is not above 1.5 times the average is deleted until half of the
    /// learnt clauses are gone. Learnt clauses of at most three literals are never deleted
    /// (clasp keeps them in its short implication graph). The default since 2026-12-03: over
    /// the benchmark rows it took 0.975x the conflicts and 0.979x the CPU time of `Sorted`,
    /// and pigeons 10/9 on our grounder's program 100,689 conflicts instead of 297,153
    /// (docs/bench/solve-2026-12-03.txt).
    #[default]
    Basic,
}

/// When learnt clauses are reduced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReduceSchedule {
    /// When the number of learnt clauses exceeds a limit that starts at 4000 plus the trail
    /// length and grows by 10% per reduction (MiniSat).
    Size,
    /// Every `first + i * inc` conflicts (Glucose; clasp `--del-cfl=+,first,inc,repeat`).
    Conflicts {
        /// Conflicts before the first reduction.
        first: u64,
        /// Growth of the interval per reduction.
        inc: u64,
        /// After this many reductions `i` starts again at 0 and the next run is one reduction
        /// longer (clasp's `<lim>` of a schedule); 0 lets `i` grow for ever.
        repeat: u64,
    },
}

/// When the search restarts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RestartPolicy {
    /// Luby sequence times the given unit (in conflicts).
    Luby(u32),
    /// Glucose-style: restart when the recent average LBD exceeds the global average.
    Glucose,
    /// Never restart.
    Never,
}

impl Config {
    /// `models` decided per call as clasp's default: the optimum (0) for a program that
    /// optimizes, else one model.
    pub const AUTO_MODELS: usize = usize::MAX;
}

impl Default for Config {
    fn default() -> Config {
        Config {
            models: 1,
            opt_mode: OptMode::Opt,
            opt_strategy: OptStrategy::Bb,
            enum_mode: EnumMode::Auto,
            cr_mode: CrMode::Cardinality,
            project: Project::No,
            deadline: None,
            interrupt: None,
            seed: 1,
            heuristic: Heuristic::Vsids,
            random_freq_permille: 0,
            var_decay: 0.92,
            default_phase_false: true,
            body_phase_true: true,
            save_progress: 0,
            restarts: RestartPolicy::Glucose,
            profile: SearchProfile::Decision,
            init_moms: true,
            reduce: ReduceSchedule::Conflicts {
                first: 2000,
                inc: 300,
                repeat: 0,
            },
            deletion: Deletion::Basic,
            score_other: false,
            shared_loops: false,
            sign_from_learnts: false,
            restart_blocking: true,
            phase_switch: Some(20_000),
            conflict_limit: None,
            eq: true,
            check_models: false,
            threads: 1,
            supports: true,
        }
    }
}

impl Config {
    /// A configuration computing all models (`-n 0`).
    pub fn all_models() -> Config {
        Config {
            models: 0,
            ..Config::default()
        }
    }
}

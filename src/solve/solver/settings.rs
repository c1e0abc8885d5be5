//! Settings changed between calls: the search settings the engine copies from `Config` when the
//! solver is made (seed, VSIDS decay, restart policy, the `Settings` fields) are copied again
//! at the start of the next call when the caller changed them (`Solver::config_mut`), as clingo
//! reads its configuration at every solve call. The settings are compared with the
//! configuration they were last made from (`Solver::applied`). What shapes the translation or
//! the initial activities (`eq`, `shared_loops`, `init_moms`, `profile`, `heuristic`) is read
//! once, when the solver is made; the limits, the model count and the optimization and
//! enumeration modes are read by every call anyway.
//!
//! Invariant: a setting the caller did not change keeps the value the search profile gave it
//! (the profile's decay, restarts and phase settings survive a change of seed); a changed one
//! takes the configured value, overriding the profile.

use super::{restart_state, Solver};

impl Solver {
    /// Copies into the engine the settings that changed since they were last applied.
    pub(super) fn apply_config(&mut self) {
        let (c, a) = (&self.config, &self.applied);
        let e = &mut self.engine;
        if c.seed != a.seed {
            e.reseed(c.seed);
        }
        if c.var_decay != a.var_decay {
            e.configure(c.var_decay, c.seed);
        }
        if c.restarts != a.restarts {
            e.sched.restarts = restart_state(c.restarts);
        }
        let s = &mut e.settings;
        if c.reduce != a.reduce {
            s.reduce = c.reduce;
        }
        if c.deletion != a.deletion {
            s.deletion = c.deletion;
        }
        if c.random_freq_permille != a.random_freq_permille {
            s.random_permille = c.random_freq_permille.min(1000);
        }
        if c.default_phase_false != a.default_phase_false {
            s.default_phase = !c.default_phase_false;
        }
        if c.body_phase_true != a.body_phase_true {
            s.body_phase = c.body_phase_true;
        }
        if c.save_progress != a.save_progress {
            s.save_progress = c.save_progress;
        }
        if c.score_other != a.score_other {
            s.score_other = c.score_other;
        }
        if c.sign_from_learnts != a.sign_from_learnts {
            s.sign_from_learnts = c.sign_from_learnts;
        }
        if c.restart_blocking != a.restart_blocking {
            s.restart_blocking = c.restart_blocking;
        }
        if c.phase_switch != a.phase_switch {
            s.phase_switch = c.phase_switch;
        }
        self.applied = self.config.clone();
    }
}

//! A Control configured from clingo's command-line options (clingo's `Control(arguments)`,
//! the Python package's `Control(["-n", "0", ...])`): [`Control::from_args`].
//!
//! Read: the model count (`N`, `-n N`, `-nN`, `--models=N`), constants (`-c name=value`,
//! `--const`), `--opt-mode`, `--enum-mode` (`-e`: brave and cautious consequences, every
//! model by default as in clingo), `--project[=mode]`, the thread count (`-t N`,
//! `--parallel-mode=N[,mode]`), `--heuristic`, `--opt-strategy`, `--seed`, `--rand-freq` and
//! `--restarts` (`no`, `L,n` Luby restarts of unit n, `D,...` dynamic ones; clasp's fixed and
//! geometric schedules are read as Luby's), each written `--opt=value` or `--opt value`;
//! warning options (`-W`, `--warn`), clingo's search presets (`--configuration`), the default
//! decision sign (`--sign-def`) and the switches `--stats`, `--restart-on-model`,
//! `--keep-facts`, `--single-shot`, `--sat-prepro` are accepted and change nothing a Control
//! reports (they tune clasp's search, which Lucent does not have, or its statistics, which a
//! Control always keeps).
//!
//! Invariant: any other option, or a bad value, is an error naming it (clingo raises a
//! `RuntimeError` for both); nothing is half-applied, the Control is made only from a
//! complete reading.

use super::*;

/// Why [`Control::from_args`] refused its arguments.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArgsError(pub String);

impl std::fmt::Display for ArgsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ArgsError {}

/// The long name of a short option.
fn long_of(short: char) -> Option<&'static str> {
    Some(match short {
        'n' => "models",
        'c' => "const",
        't' => "parallel-mode",
        'W' => "warn",
        'e' => "enum-mode",
        _ => return None,
    })
}

/// `option value` is invalid.
fn invalid(name: &str, value: &str) -> ArgsError {
    ArgsError(format!("invalid value for option --{name}: '{value}'"))
}

/// Reads `args` into `config`.
fn read(args: &[&str], config: &mut ControlConfig) -> Result<(), ArgsError> {
    let mut i = 0;
    while i < args.len() {
        let a = args[i];
        i += 1;
        if !a.is_empty() && a.bytes().all(|b| b.is_ascii_digit()) {
            config.solve.models = a.parse().map_err(|_| invalid("models", a))?;
            continue;
        }
        // The option's long name and its value, if written in the same argument.
        let (name, inline): (&str, Option<&str>) = if let Some(long) = a.strip_prefix("--") {
            match long.split_once('=') {
                Some((n, v)) => (n, Some(v)),
                None => (long, None),
            }
        } else if let Some(short) = a.strip_prefix('-') {
            let mut chars = short.chars();
            let name = chars
                .next()
                .and_then(long_of)
                .ok_or_else(|| ArgsError(format!("unknown option: {a}")))?;
            let rest = chars.as_str();
            (name, (!rest.is_empty()).then_some(rest))
        } else {
            return Err(ArgsError(format!("unknown option: {a}")));
        };
        const KNOWN: [&str; 14] = [
            "restarts",
            "sign-def",
            "models",
            "enum-mode",
            "const",
            "opt-mode",
            "project",
            "parallel-mode",
            "heuristic",
            "warn",
            "opt-strategy",
            "seed",
            "rand-freq",
            "configuration",
        ];
        // Switches that change how fast, never what, a Control answers: accepted as clingo's
        // Control accepts them (statistics are always kept; Lucent has one search setting).
        const NO_EFFECT: [&str; 5] = [
            "stats",
            "restart-on-model",
            "keep-facts",
            "single-shot",
            "sat-prepro",
        ];
        if NO_EFFECT.contains(&name) {
            continue;
        }
        if !KNOWN.contains(&name) {
            return Err(ArgsError(format!("unknown option: {a}")));
        }
        // `--project` alone is `auto`; every other option needs a value.
        let value = match (name, inline) {
            (_, Some(v)) => v,
            ("project", None) => "auto",
            (_, None) => {
                let v = args
                    .get(i)
                    .ok_or_else(|| ArgsError(format!("option --{name} needs a value")))?;
                i += 1;
                v
            }
        };
        match name {
            "models" => {
                config.solve.models = value.parse().map_err(|_| invalid(name, value))?;
            }
            "const" => {
                let (n, v) = value.split_once('=').ok_or_else(|| invalid(name, value))?;
                let term = const_term(v).ok_or_else(|| invalid(name, value))?;
                config.ground.consts.push((n.to_string(), term));
            }
            "opt-mode" => {
                config.solve.opt_mode =
                    solve::OptMode::from_name(value).ok_or_else(|| invalid(name, value))?;
            }
            "project" => {
                config.solve.project =
                    solve::Project::from_name(value).ok_or_else(|| invalid(name, value))?;
            }
            "parallel-mode" => {
                let n = value.split(',').next().unwrap_or("");
                let threads: usize = n.parse().map_err(|_| invalid(name, value))?;
                if !(1..=64).contains(&threads) {
                    return Err(invalid(name, value));
                }
                config.solve.threads = threads;
            }
            "heuristic" => {
                config.solve.heuristic =
                    solve::Heuristic::from_name(value).ok_or_else(|| invalid(name, value))?;
            }
            "enum-mode" => {
                config.solve.enum_mode =
                    solve::EnumMode::from_name(value).ok_or_else(|| invalid(name, value))?;
            }
            "opt-strategy" => {
                config.solve.opt_strategy =
                    solve::OptStrategy::from_name(value).ok_or_else(|| invalid(name, value))?;
            }
            "seed" => {
                config.solve.seed = value.parse().map_err(|_| invalid(name, value))?;
            }
            "rand-freq" => match value.parse::<f64>() {
                Ok(p) if (0.0..=1.0).contains(&p) => {
                    config.solve.random_freq_permille = (p * 1000.0).round() as u32;
                }
                _ => return Err(invalid(name, value)),
            },
            "restarts" => {
                let mut parts = value.split(',');
                let kind = parts.next().unwrap_or("");
                let unit: Option<u32> = parts.next().and_then(|n| n.parse().ok());
                config.solve.restarts = match (kind, unit) {
                    ("no" | "0", _) => solve::RestartPolicy::Never,
                    ("D" | "d", _) => solve::RestartPolicy::Glucose,
                    ("L" | "l" | "F" | "f" | "x" | "+", Some(n)) if n > 0 => {
                        solve::RestartPolicy::Luby(n)
                    }
                    _ => return Err(invalid(name, value)),
                };
            }
            // clasp's default sign of a decision; Lucent's heuristic chooses its own.
            "sign-def" if !["asp", "pos", "neg", "rnd", "0", "1", "2", "3"].contains(&value) => {
                return Err(invalid(name, value));
            }
            // clingo's search presets; Lucent has one search setting, which answers the same.
            "configuration" => {
                const PRESETS: [&str; 8] = [
                    "auto", "frumpy", "jumpy", "tweety", "handy", "crafty", "trendy", "many",
                ];
                if !PRESETS.contains(&value) {
                    return Err(invalid(name, value));
                }
            }
            _ => {} // `warn`, a valid `sign-def`: accepted, nothing to change.
        }
    }
    Ok(())
}

impl Control {
    /// A Control configured by clingo's command-line `args` (see the module documentation):
    /// `Control::from_args(&["-n", "0", "-c", "k=2"])`. Unknown options and bad values are
    /// errors.
    ///
    /// ```
    /// use lucent::control::Control;
    /// let ctl = Control::from_args(&["0", "--opt-mode=optN", "-c", "k=2", "-t", "2"]).unwrap();
    /// assert_eq!(ctl.config().solve.models, 0);
    /// assert_eq!(ctl.config().solve.threads, 2);
    /// // clingo's search options: those that change the search, and presets that only tune it
    /// let ctl = Control::from_args(&["--opt-strategy=usc", "--seed=7", "--rand-freq=0.05",
    ///                                "--configuration=trendy", "--stats"]).unwrap();
    /// assert_eq!(ctl.config().solve.seed, 7);
    /// assert_eq!(ctl.config().solve.random_freq_permille, 50);
    /// assert!(Control::from_args(&["--configuration=fast"]).is_err());
    /// assert!(Control::from_args(&["--rand-freq=2"]).is_err());
    /// assert!(Control::from_args(&["--no-such-option"]).is_err());
    /// assert!(Control::from_args(&["--models=x"]).is_err());
    /// ```
    pub fn from_args(args: &[&str]) -> Result<Control, ArgsError> {
        let mut config = ControlConfig::default();
        read(args, &mut config)?;
        Ok(Control::new(config))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config(args: &[&str]) -> ControlConfig {
        Control::from_args(args).unwrap().config().clone()
    }

    #[test]
    fn every_spelling_of_the_options_is_read() {
        for args in [
            &["-n", "3"][..],
            &["-n3"],
            &["--models=3"],
            &["--models", "3"],
            &["3"],
        ] {
            assert_eq!(config(args).solve.models, 3, "{args:?}");
        }
        assert_eq!(config(&[]).solve.models, solve::Config::AUTO_MODELS);
        for args in [&["-t", "2"][..], &["-t2"], &["--parallel-mode=2,compete"]] {
            assert_eq!(config(args).solve.threads, 2, "{args:?}");
        }
        assert_eq!(config(&["--project"]).solve.project, solve::Project::Auto);
        assert_eq!(
            config(&["--project=show"]).solve.project,
            solve::Project::Show
        );
        assert_eq!(
            config(&["--heuristic", "Domain"]).solve.heuristic,
            solve::Heuristic::Domain
        );
        assert_eq!(
            config(&["--opt-mode=optN"]).solve.opt_mode,
            solve::OptMode::OptN
        );
        let c = config(&["-c", "k=2", "--const=s=\"a\"", "-cf=g(1)"]);
        let names: Vec<&str> = c.ground.consts.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["k", "s", "f"]);
        config(&["-W", "none", "--warn=no-atom-undefined"]);
        for (value, policy) in [
            ("no", solve::RestartPolicy::Never),
            ("L,64", solve::RestartPolicy::Luby(64)),
            ("F,100", solve::RestartPolicy::Luby(100)),
            ("D,100,0.7", solve::RestartPolicy::Glucose),
        ] {
            let arg = format!("--restarts={value}");
            assert_eq!(config(&[&arg]).solve.restarts, policy, "{value}");
        }
        config(&["--sign-def=pos"]);
    }

    #[test]
    fn bad_options_are_errors() {
        for (args, message) in [
            (&["--frobnicate"][..], "unknown option: --frobnicate"),
            (&["-x"], "unknown option: -x"),
            (&["file.lp"], "unknown option: file.lp"),
            (&["-n"], "option --models needs a value"),
            (&["-n", "x"], "invalid value for option --models: 'x'"),
            (&["-c", "k"], "invalid value for option --const: 'k'"),
            (
                &["--opt-mode=best"],
                "invalid value for option --opt-mode: 'best'",
            ),
            (
                &["-t", "0"],
                "invalid value for option --parallel-mode: '0'",
            ),
            (
                &["--heuristic=x"],
                "invalid value for option --heuristic: 'x'",
            ),
            (&["--project=x"], "invalid value for option --project: 'x'"),
            (
                &["--restarts=L"],
                "invalid value for option --restarts: 'L'",
            ),
            (
                &["--sign-def=up"],
                "invalid value for option --sign-def: 'up'",
            ),
            (&["--supp-models"], "unknown option: --supp-models"),
        ] {
            let e = Control::from_args(args).err().expect("an error");
            assert_eq!(e.0, message, "{args:?}");
        }
    }
}

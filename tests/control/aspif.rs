//! Ground programs in aspif given to `Control::add` and `Control::load`, as clingo 5.8 reads
//! them there (`ctl.load("prog.aspif")`). Expected answers recorded from clingo 5.8.3's Python
//! API with the commands beside them.

use lucent::control::{Control, ControlConfig, Part, Symbol};
use lucent::solve::OptMode;

/// `printf 'a :- not b.\nb :- not a.\n' | gringo` (clingo 5.4.1's gringo).
const CHOICE: &str = "asp 1 0 0\n1 0 1 1 0 1 -2\n1 0 1 2 0 1 -1\n4 1 b 1 1\n4 1 a 1 2\n0\n";

/// `printf '{a;b;d}.\n:- not d.\n#show c : a, b.\n#show a/0.\n#show d/0.\n#minimize{1:a; 1:b}.\n'
/// | gringo`: a choice, a constraint, a minimize statement over an auxiliary atom, and a shown
/// term `c` defined by an auxiliary atom.
const SHOWN: &str = "asp 1 0 0\n1 1 3 1 2 3 0 0\n1 0 0 0 1 -3\n1 0 1 4 0 1 1\n1 0 1 4 0 1 2\n\
                     2 0 1 4 1\n4 1 a 1 1\n4 1 d 1 3\n1 0 1 5 0 2 1 2\n4 1 c 1 5\n0\n";

fn shown_sets(ctl: &mut Control) -> Vec<Vec<String>> {
    let mut sets: Vec<Vec<String>> = ctl
        .solve_all(&Default::default())
        .models
        .iter()
        .map(|m| {
            let mut s: Vec<String> = m.shown.iter().map(|s| s.to_string()).collect();
            s.sort();
            s
        })
        .collect();
    sets.sort();
    sets
}

/// clingo 5.8.3: `ctl = Control(["0"]); ctl.add("base", [], CHOICE); ctl.ground(...)` answers
/// [b] and [a]; so does `ctl.load(path)`.
#[test]
fn an_aspif_program_added_or_loaded_is_solved() {
    let mut ctl = Control::from_args(&["0"]).unwrap();
    ctl.add("base", &[], CHOICE).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    assert_eq!(shown_sets(&mut ctl), [["a"], ["b"]]);
    assert!(ctl.lookup(&Symbol::constant("a")).is_some());

    let dir = std::env::temp_dir().join(format!("lucent-control-aspif-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("choice.aspif");
    std::fs::write(&path, CHOICE).unwrap();
    let mut ctl = Control::from_args(&["0"]).unwrap();
    ctl.load(&path).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    assert_eq!(shown_sets(&mut ctl), [["a"], ["b"]]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// clingo 5.8.3, `Control(["0", "--opt-mode=enum"])` with SHOWN loaded (the minimize statement
/// ignored without a bound): shown [a, c, d], [a, d], [d], [d]; `Control(["0",
/// "--opt-mode=optN"])`: the optimal model shows [d] at cost 0.
#[test]
fn outputs_minimize_and_constraints_of_aspif_are_kept() {
    let mut config = ControlConfig::default();
    config.solve.models = 0;
    config.solve.opt_mode = OptMode::Ignore;
    let mut ctl = Control::new(config);
    ctl.add("base", &[], SHOWN).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    assert_eq!(
        shown_sets(&mut ctl),
        [vec!["a", "c", "d"], vec!["a", "d"], vec!["d"], vec!["d"]]
    );

    let mut ctl = Control::from_args(&["0", "--opt-mode=optN"]).unwrap();
    ctl.add("base", &[], SHOWN).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let models = ctl.solve_all(&Default::default()).models;
    let best: Vec<_> = models.iter().filter(|m| m.optimal).collect();
    assert!(!best.is_empty());
    for m in best {
        assert_eq!(m.costs, [0]);
        let shown: Vec<String> = m.shown.iter().map(|s| s.to_string()).collect();
        assert_eq!(shown, ["d"]);
    }
}

/// A malformed ground program is an error at its position, as `--mode=clasp` reports it.
#[test]
fn malformed_aspif_is_an_error_with_its_position() {
    let mut ctl = Control::new(ControlConfig::default());
    let err = ctl.add("base", &[], "asp 1 0 0\n1 0 1 1 0\n").unwrap_err();
    assert!(err.to_string().contains("malformed aspif input"), "{err}");
    assert!(err.to_string().contains("<block>:2:"), "{err}");
}

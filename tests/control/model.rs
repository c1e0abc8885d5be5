//! `Model::atoms_named` against `Model::atoms` filtered by name, arity and sign: the same
//! symbols in the same order, for every model of a small program.

use lucent::control::{Control, ControlConfig, Part, SolveOptions};

#[test]
fn atoms_named_is_atoms_filtered() {
    let text = "{ occurs(a, 0); occurs(b, 1) }. -occurs(c, 2). occurs. occurs(d). \
                occurs(e, 3) :- occurs(a, 0). h(occurs(f, 4)). other(1, 2).";
    let mut cc = ControlConfig::default();
    cc.solve.models = 0;
    let mut ctl = Control::new(cc);
    ctl.add("base", &[], text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let mut seen = 0;
    ctl.solve(&SolveOptions::default(), |m| {
        for (name, arity) in [
            ("occurs", 2),
            ("occurs", 0),
            ("occurs", 1),
            ("other", 2),
            ("h", 1),
        ] {
            let filtered: Vec<String> = m
                .atoms()
                .into_iter()
                .filter(|s| s.is(name, arity) && !s.is_negative())
                .map(|s| s.to_string())
                .collect();
            let named: Vec<String> = m
                .atoms_named(name, arity)
                .into_iter()
                .map(|s| s.to_string())
                .collect();
            assert_eq!(named, filtered, "{name}/{arity}");
        }
        seen += 1;
        true
    });
    assert_eq!(seen, 4);
}

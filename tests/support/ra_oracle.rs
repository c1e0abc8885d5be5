//! Hand-written ground programs shaped like the RA translation (docs/domain.md 3), as oracles for
//! the proof-tree and question tests: rules written `head :- body` with `h(F,I)` for `holds(F,I)`.

use std::collections::HashSet;

use lucent::control::Symbol;
use lucent::explain::tree::AxiomKind::{self, *};
use lucent::explain::tree::{BodyLiteral, ModelOracle, RuleInstance};

pub fn t(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

/// Splits at top-level commas.
fn split_top(s: &str) -> Vec<String> {
    let (mut depth, mut cur, mut out) = (0, String::new(), Vec::new());
    for c in s.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                out.push(cur.trim().to_string());
                cur.clear();
                continue;
            }
            _ => {}
        }
        cur.push(c);
    }
    if !cur.trim().is_empty() {
        out.push(cur.trim().to_string());
    }
    out
}

/// `label kind: head :- body.` with `h(F,I)` for `holds(F,I)`, `-h` for `-holds`.
pub fn rule(label: &str, kind: AxiomKind, text: &str) -> RuleInstance {
    let expand = |s: &str| s.replace("-h(", "-holds(").replace("h(", "holds(");
    let text = expand(text.trim_end_matches('.'));
    let (head, body) = match text.split_once(":-") {
        Some((h, b)) => (h.trim().to_string(), split_top(b)),
        None => (text.trim().to_string(), Vec::new()),
    };
    RuleInstance {
        label: label.into(),
        kind,
        rule: None,
        head: t(&head),
        body: body
            .iter()
            .map(|b| match b.strip_prefix("not ") {
                Some(n) => BodyLiteral::Not(t(n)),
                None => BodyLiteral::Pos(t(b)),
            })
            .collect(),
    }
}

/// Example 3 of docs/domain.md 6.8 in small: the white block was put on the green can at step 3,
/// the pitcher picked up at step 4; steps 3 to 5.
pub fn example3() -> ModelOracle {
    let on = |i| format!("h(relation(on,white_block,green_can),{i})");
    let above = |i| format!("h(relation(above,white_block,green_can),{i})");
    let below = |i| format!("h(relation(below,green_can,white_block),{i})");
    let touch = |i| format!("h(relation(touch,white_block,green_can),{i})");
    let rules = vec![
        rule("fact", Fact, "hpd(putdown(rob1,white_block,green_can),3)"),
        rule("fact", Fact, "hpd(pickup(rob1,pitcher),4)"),
        rule("fact", Fact, "complement(above,below)"),
        rule("fact", Fact, "complement(below,above)"),
        rule("fact", Fact, "action(pickup(rob1,green_can))"),
        rule("history", History, "occurs(putdown(rob1,white_block,green_can),3) :- hpd(putdown(rob1,white_block,green_can),3)"),
        rule("history", History, "occurs(pickup(rob1,pitcher),4) :- hpd(pickup(rob1,pitcher),4)"),
        rule("C1", CausalLaw, &format!("{} :- occurs(putdown(rob1,white_block,green_can),3)", on(4))),
        rule("C3", CausalLaw, "h(in_hand(rob1,pitcher),5) :- occurs(pickup(rob1,pitcher),4)"),
        rule("inertia", Inertia, &format!("{} :- {}, not -{}", on(5), on(4), on(5))),
        rule("inertia", Inertia, &format!("{} :- {}, not -{}", above(5), above(4), above(5))),
        rule("SR1a", StateConstraint, &format!("{} :- {}, {}", on(5), above(5), touch(5))),
        rule("SR1b", StateConstraint, &format!("{} :- {}", above(4), on(4))),
        rule("SR1b", StateConstraint, &format!("{} :- {}", above(5), on(5))),
        rule("SR1c", StateConstraint, &format!("{} :- {}", touch(5), on(5))),
        rule("SR3", StateConstraint, &format!("{} :- {}, complement(above,below)", below(5), above(5))),
        rule("SR3", StateConstraint, &format!("{} :- {}, complement(below,above)", above(5), below(5))),
        rule("E7", Executability, &format!("-occurs(pickup(rob1,green_can),5) :- action(pickup(rob1,green_can)), {}", below(5))),
        rule("E5", Executability, "-occurs(pickup(rob1,green_can),5) :- action(pickup(rob1,green_can)), h(in_hand(rob1,pitcher),5)"),
        rule("action CWA", ClosedWorld, "-occurs(pickup(rob1,green_can),5) :- action(pickup(rob1,green_can)), not occurs(pickup(rob1,green_can),5)"),
        rule("history", History, "occurs(pickup(rob1,green_can),5) :- hpd(pickup(rob1,green_can),5)"),
        rule("D1", Default, "-h(stable(white_block),5) :- h(small_base(white_block),5), not h(stable(white_block),5)"),
        rule("D1x", CrRule, "h(stable(white_block),4) :- h(small_base(white_block),4)"),
        rule("SB", StateConstraint, &format!("h(small_base(white_block),4) :- {}, has_size(green_can,small)", above(4))),
        rule("fact", Fact, "has_size(green_can,small)"),
    ];
    let mut model: HashSet<Symbol> = HashSet::new();
    for r in &rules {
        if matches!(
            r.head.name(),
            Some("hpd") | Some("complement") | Some("action") | Some("has_size")
        ) {
            model.insert(r.head.clone());
        }
    }
    for lit in [
        "occurs(putdown(rob1,white_block,green_can),3)",
        "occurs(pickup(rob1,pitcher),4)",
        &on(4),
        &on(5),
        &above(4),
        &above(5),
        &below(5),
        &touch(5),
        "h(in_hand(rob1,pitcher),5)",
        "-occurs(pickup(rob1,green_can),5)",
        "h(small_base(white_block),4)",
        "h(stable(white_block),4)",
    ] {
        let lit = lit.replace("h(", "holds(");
        model.insert(t(&lit));
    }
    ModelOracle { rules, model }
}

/// The execution example of docs/domain.md 6.8 in small: the rules the paper's questions touch at
/// steps 0 to 5 (observation of the stack at step 0, E7 and E2 grounded at step 0, E10 for the
/// mug at step 3), on top of [`example3`]. Plan: the paper's six actions.
pub fn paper() -> (ModelOracle, Vec<(u32, Symbol)>) {
    let mut o = example3();
    let on0 = "h(relation(on,green_can,white_block),0)";
    let above0 = "h(relation(above,green_can,white_block),0)";
    let below0 = "h(relation(below,white_block,green_can),0)";
    let obs0 = "obs(relation(on,green_can,white_block),true,0)";
    let more = vec![
        rule("fact", Fact, obs0),
        rule("initial state", History, &format!("{on0} :- {obs0}")),
        rule("SR1b", StateConstraint, &format!("{above0} :- {on0}")),
        rule("SR3", StateConstraint, &format!("{below0} :- {above0}, complement(above,below)")),
        rule("SR3", StateConstraint, &format!("{above0} :- {below0}, complement(below,above)")),
        rule("fact", Fact, "action(pickup(rob1,white_block))"),
        rule("fact", Fact, "action(putdown(rob1,green_can,table))"),
        rule("fact", Fact, "action(putdown(rob1,white_block,mug))"),
        rule("fact", Fact, "has_surface(mug,irregular)"),
        rule("E7", Executability, &format!("-occurs(pickup(rob1,white_block),0) :- action(pickup(rob1,white_block)), {below0}")),
        rule("action CWA", ClosedWorld, "-occurs(pickup(rob1,white_block),0) :- action(pickup(rob1,white_block)), not occurs(pickup(rob1,white_block),0)"),
        rule("D0", History, "-h(in_hand(rob1,green_can),0) :- not h(in_hand(rob1,green_can),0)"),
        rule("E2", Executability, "-occurs(putdown(rob1,green_can,table),0) :- action(putdown(rob1,green_can,table)), -h(in_hand(rob1,green_can),0)"),
        rule("C3", CausalLaw, "h(in_hand(rob1,green_can),1) :- occurs(pickup(rob1,green_can),0)"),
        rule("history", History, "occurs(pickup(rob1,green_can),0) :- hpd(pickup(rob1,green_can),0)"),
        rule("fact", Fact, "hpd(pickup(rob1,green_can),0)"),
        rule("E10", Executability, "-occurs(putdown(rob1,white_block,mug),3) :- action(putdown(rob1,white_block,mug)), has_surface(mug,irregular)"),
        rule("action CWA", ClosedWorld, "-occurs(putdown(rob1,white_block,mug),3) :- action(putdown(rob1,white_block,mug)), not occurs(putdown(rob1,white_block,mug),3)"),
        rule("fact", Fact, "action(pickup(rob1,pig))"),
        rule("action CWA", ClosedWorld, "-occurs(pickup(rob1,pig),2) :- action(pickup(rob1,pig)), not occurs(pickup(rob1,pig),2)"),
    ];
    o.rules.extend(more);
    for lit in [
        obs0,
        on0,
        above0,
        below0,
        "action(pickup(rob1,white_block))",
        "action(putdown(rob1,green_can,table))",
        "action(putdown(rob1,white_block,mug))",
        "action(pickup(rob1,pig))",
        "has_surface(mug,irregular)",
        "-occurs(pickup(rob1,white_block),0)",
        "-h(in_hand(rob1,green_can),0)",
        "-occurs(putdown(rob1,green_can,table),0)",
        "h(in_hand(rob1,green_can),1)",
        "occurs(pickup(rob1,green_can),0)",
        "hpd(pickup(rob1,green_can),0)",
        "-occurs(putdown(rob1,white_block,mug),3)",
        "-occurs(pickup(rob1,pig),2)",
    ] {
        o.model.insert(t(&lit.replace("h(", "holds(")));
    }
    let plan = [
        (0, "pickup(rob1,green_can)"),
        (1, "putdown(rob1,green_can,table)"),
        (2, "pickup(rob1,white_block)"),
        (3, "putdown(rob1,white_block,green_can)"),
        (4, "pickup(rob1,pitcher)"),
        (5, "putdown(rob1,pitcher,red_block)"),
    ]
    .iter()
    .map(|(i, a)| (*i, t(a)))
    .collect();
    (o, plan)
}

/// The set of terms, for models.
pub fn terms(lits: &[&str]) -> HashSet<Symbol> {
    lits.iter().map(|s| t(s)).collect()
}

//! Literal verbalization and the answer templates of docs/domain.md 6.7 over the built-in lexicon:
//! every literal kind in each tense, merging, the plan and the paper's answers (docs/domain.md 6.8)
//! from their literals.

use lucent::control::Symbol;
use lucent::explain::lexicon::Lexicon;
use lucent::explain::verbalize::{Tense, Verbalizer};

fn t(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

#[test]
fn literals_in_each_tense() {
    let lex = Lexicon::ra();
    let v = Verbalizer::new(&lex);
    let mut out = String::new();
    for lit in [
        "holds(relation(on,green_can,white_block),0)",
        "holds(relation(above,green_can,white_block),0)",
        "holds(relation(below,white_block,green_can),0)",
        "holds(relation(front,pitcher,mug),1)",
        "holds(relation(behind,mug,pitcher),1)",
        "holds(relation(left,red_block,mug),1)",
        "holds(relation(right,mug,red_block),1)",
        "holds(relation(touch,green_can,white_block),0)",
        "-holds(relation(on,green_can,white_block),1)",
        "holds(in_hand(rob1,pitcher),4)",
        "-holds(in_hand(rob1,white_block),2)",
        "has_surface(mug,irregular)",
        "has_size(green_can_small,small)",
        "holds(tower_height(white_block,3),4)",
        "holds(small_base(white_block),3)",
        "holds(irreg_below(pitcher),2)",
        "-holds(stable(white_block),3)",
        "holds(stable(white_block),3)",
        "holds(occluded(mug),0)",
        "-holds(occluded(mug),0)",
        "holds(absent(duck),0)",
        "-holds(absent(duck),0)",
        "holds(partially_occluded(mug,pitcher),0)",
        "occurs(pickup(rob1,green_can),0)",
        "-occurs(putdown(rob1,white_block,mug),3)",
        "holds(scene_stable,2)",
    ] {
        let l = t(lit);
        out.push_str(&format!(
            "{lit}\n  past: {}\n  present: {}\n  future: {}\n  bare: {}\n",
            v.clause(&l, Tense::Past),
            v.clause(&l, Tense::Present),
            v.clause(&l, Tense::Future),
            v.bare(&l)
        ));
    }
    insta::assert_snapshot!(out);
}

#[test]
fn constants_in_words() {
    let lex = Lexicon::ra();
    let v = Verbalizer::new(&lex);
    let words: Vec<String> = [
        "green_can",
        "red_cube_large",
        "white_can_small",
        "table",
        "pitcher",
        "ob1",
    ]
    .iter()
    .map(|c| v.object(&t(c)))
    .collect();
    assert_eq!(
        words,
        [
            "the green can",
            "the red cube",
            "the white can",
            "the table",
            "the pitcher",
            "the ob1"
        ]
    );
}

#[test]
fn merging_literals_with_the_same_predicate_and_first_argument() {
    let lex = Lexicon::ra();
    let v = Verbalizer::new(&lex);
    let lits: Vec<Symbol> = [
        "holds(relation(below,red_block,white_block),0)",
        "holds(relation(below,red_block,green_can),0)",
        "holds(relation(on,pitcher,table),0)",
        "holds(relation(below,red_block,pitcher),1)",
        "holds(relation(below,white_block,green_can),0)",
        "has_size(ob2,small)",
        "has_size(ob3,small)",
        "holds(relation(on,mug,table),0)",
        "holds(relation(on,mug,table),0)",
    ]
    .iter()
    .map(|s| t(s))
    .collect();
    insta::assert_snapshot!(v.clauses(&lits, Tense::Past).join("\n"));
    let two = [
        t("holds(relation(below,red_block,white_block),0)"),
        t("holds(relation(below,red_block,green_can),0)"),
    ];
    assert_eq!(
        v.join(&two, Tense::Past),
        "the red block was below the white block and the green can"
    );
}

/// The paper's answers (docs/domain.md 6.8) said from the literals the questions select.
#[test]
fn the_papers_answers() {
    let lex = Lexicon::ra();
    let v = Verbalizer::new(&lex);
    let plan: Vec<(u32, Symbol)> = [
        (0, "pickup(rob1,green_can)"),
        (1, "putdown(rob1,green_can,table)"),
        (2, "pickup(rob1,white_block)"),
        (3, "putdown(rob1,white_block,green_can)"),
        (4, "pickup(rob1,pitcher)"),
        (5, "putdown(rob1,pitcher,red_block)"),
    ]
    .iter()
    .rev()
    .map(|(i, a)| (*i, t(a)))
    .collect();
    let mut out = String::new();
    out.push_str(&v.plan(&plan, true));
    out.push('\n');
    out.push_str(&v.plan(&plan[..2], false));
    out.push('\n');
    out.push_str(&v.why_action(
        &t("pickup(rob1,white_block)"),
        &t("holds(relation(below,white_block,green_can),0)"),
        Tense::Past,
    ));
    out.push('\n');
    out.push_str(&v.why_action(
        &t("putdown(rob1,ball,orange_block)"),
        &t("holds(relation(on,blue_block,orange_block),0)"),
        Tense::Past,
    ));
    out.push('\n');
    out.push_str(&v.why_not(&[t("has_surface(mug,irregular)")], Tense::Past));
    out.push('\n');
    out.push_str(&v.belief_observed(&t("holds(relation(on,green_can,white_block),0)"), 0));
    out.push('\n');
    out.push_str(&v.why_not_observed(&t("holds(relation(on,green_can,white_block),0)"), 0));
    out.push('\n');
    out.push_str(&v.why_not(
        &[t("holds(relation(on,white_block,green_can),5)")],
        Tense::Past,
    ));
    out.push('\n');
    out.push_str(&v.why_not(
        &[
            t("holds(relation(on,white_block,green_can),5)"),
            t("holds(in_hand(rob1,pitcher),5)"),
        ],
        Tense::Past,
    ));
    out.push('\n');
    out.push_str(&v.belief_action(&t("putdown(rob1,white_block,green_can)"), 3));
    out.push('\n');
    out.push_str(&v.belief_frontier(
        &[
            t("holds(relation(below,ob2,ob1),0)"),
            t("has_size(ob2,small)"),
            t("has_size(ob1,large)"),
        ],
        Tense::Past,
    ));
    out.push('\n');
    out.push_str(&v.belief_static());
    out.push('\n');
    out.push_str(&v.belief_assumed(
        &t("holds(stable(white_block),3)"),
        &t("-holds(stable(white_block),3)"),
        Tense::Past,
    ));
    out.push('\n');
    out.push_str(&v.not_believed(&t("holds(relation(on,mug,red_block),2)"), 2, Tense::Past));
    out.push('\n');
    out.push_str(&v.why_not_unrelated(&t("pig")));
    out.push('\n');
    out.push_str(&v.why_not_not_planned());
    out.push('\n');
    out.push_str(&v.did_it(&t("pickup(rob1,white_block)"), 2));
    out.push('\n');
    out.push_str(&v.why_goal(&[t("holds(relation(on,pitcher,red_block),6)")]));
    out.push('\n');
    let mut initial = v;
    initial.initial_state_wording = true;
    out.push_str(&initial.belief_observed(&t("holds(relation(on,green_can,white_block),0)"), 0));
    insta::assert_snapshot!(out);
}

//! Property tests of the parser and printer: random programs generated from the grammar
//! (`grammar/asp.ebnf`) parse without errors and round-trip through the printer; random token
//! soup never breaks the parse invariants (no panic, valid spans) nor the round trip.

use proptest::prelude::*;

use lucent::base::FileId;
use lucent::syntax::ast::Dialect;
use lucent::syntax::fuzzing::{check_parse_invariants, check_round_trip};
use lucent::syntax::parse;

/// A small deterministic generator of grammatical clingo programs.
struct Gen {
    /// xorshift state.
    state: u64,
}

impl Gen {
    fn next(&mut self) -> u64 {
        let mut x = self.state;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.state = x;
        x
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len() as u64) as usize]
    }

    fn term(&mut self, depth: u32) -> String {
        if depth == 0 {
            return self
                .pick(&[
                    "1",
                    "0",
                    "42",
                    "a",
                    "b_c",
                    "X",
                    "Y'",
                    "_",
                    "\"s\\\"t\"",
                    "#inf",
                    "#sup",
                ])
                .to_string();
        }
        match self.below(10) {
            0 => format!("{}({})", self.pick(&["f", "g"]), self.terms(depth - 1)),
            1 => format!(
                "{} {} {}",
                self.term(depth - 1),
                self.pick(&["+", "-", "*", "/", "\\", "**", "&", "?", "^", ".."]),
                self.term(depth - 1)
            ),
            2 => format!("-{}", self.term(depth - 1)),
            3 => format!("~{}", self.term(depth - 1)),
            4 => format!("|{}|", self.term(depth - 1)),
            5 => format!("({})", self.term(depth - 1)),
            6 => format!("({}, {})", self.term(depth - 1), self.term(depth - 1)),
            7 => format!("({};{})", self.term(depth - 1), self.term(depth - 1)),
            8 => format!("({},)", self.term(depth - 1)),
            _ => self.term(0),
        }
    }

    fn terms(&mut self, depth: u32) -> String {
        let n = 1 + self.below(3);
        let parts: Vec<String> = (0..n).map(|_| self.term(depth)).collect();
        if self.below(5) == 0 {
            format!("{};{}", parts.join(","), self.term(depth))
        } else {
            parts.join(",")
        }
    }

    /// Terms separated by commas, without pools (aggregate tuples).
    fn tuple(&mut self, depth: u32) -> String {
        let n = 1 + self.below(3);
        (0..n)
            .map(|_| self.term(depth))
            .collect::<Vec<_>>()
            .join(",")
    }

    fn atom(&mut self) -> String {
        let neg = if self.below(4) == 0 { "-" } else { "" };
        let name = self.pick(&["p", "q", "r_1", "prefer"]);
        match self.below(3) {
            0 => format!("{neg}{name}"),
            _ => format!("{neg}{name}({})", self.terms(2)),
        }
    }

    fn cmp(&mut self) -> &'static str {
        self.pick(&["=", "==", "!=", "<>", "<", "<=", ">", ">="])
    }

    fn literal(&mut self, chains: bool) -> String {
        let sign = self.pick(&["", "", "not ", "not not "]);
        match self.below(6) {
            0 => format!("{sign}{} {} {}", self.term(1), self.cmp(), self.term(1)),
            1 if chains && sign.is_empty() => format!(
                "{} {} {} {} {}",
                self.term(1),
                self.cmp(),
                self.term(1),
                self.cmp(),
                self.term(1)
            ),
            2 => format!("{sign}{}", self.pick(&["#true", "#false"])),
            _ => format!("{sign}{}", self.atom()),
        }
    }

    fn condition(&mut self) -> String {
        let n = self.below(3);
        (0..n)
            .map(|_| self.literal(true))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn function(&mut self) -> &'static str {
        self.pick(&["#count", "#sum", "#sum+", "#min", "#max"])
    }

    fn guard_left(&mut self) -> String {
        match self.below(3) {
            0 => String::new(),
            1 => format!("{} ", self.term(1)),
            _ => format!("{} {} ", self.term(1), self.cmp()),
        }
    }

    fn guard_right(&mut self) -> String {
        match self.below(3) {
            0 => String::new(),
            1 => format!(" {}", self.term(1)),
            _ => format!(" {} {}", self.cmp(), self.term(1)),
        }
    }

    fn body_literal(&mut self) -> String {
        match self.below(6) {
            0 => {
                let sign = self.pick(&["", "not "]);
                let n = self.below(3);
                let els: Vec<String> = (0..n)
                    .map(|_| {
                        let c = self.condition();
                        format!("{} : {c}", self.tuple(1))
                    })
                    .collect();
                format!(
                    "{sign}{}{}{{ {} }}{}",
                    self.guard_left(),
                    self.function(),
                    els.join("; "),
                    self.guard_right()
                )
            }
            1 => {
                let c = self.condition();
                format!("{} : {c}", self.literal(false))
            }
            _ => self.literal(true),
        }
    }

    fn body(&mut self) -> String {
        let n = 1 + self.below(3);
        (0..n)
            .map(|_| self.body_literal())
            .collect::<Vec<_>>()
            .join("; ")
    }

    fn head(&mut self) -> String {
        match self.below(5) {
            0 => {
                let n = self.below(3);
                let els: Vec<String> = (0..n)
                    .map(|_| {
                        let c = self.condition();
                        format!("{} : {c}", self.literal(false))
                    })
                    .collect();
                format!(
                    "{}{{ {} }}{}",
                    self.guard_left(),
                    els.join("; "),
                    self.guard_right()
                )
            }
            1 => {
                let n = self.below(3);
                let els: Vec<String> = (0..n)
                    .map(|_| {
                        let c = self.condition();
                        format!("{} : {} : {c}", self.tuple(1), self.literal(false))
                    })
                    .collect();
                format!(
                    "{}{}{{ {} }}{}",
                    self.guard_left(),
                    self.function(),
                    els.join("; "),
                    self.guard_right()
                )
            }
            _ => {
                let n = 1 + self.below(3);
                (0..n)
                    .map(|_| self.atom())
                    .collect::<Vec<_>>()
                    .join(self.pick(&[" | ", "; ", ", "]))
            }
        }
    }

    fn statement(&mut self) -> String {
        match self.below(12) {
            0 => format!(":- {}.", self.body()),
            1 => format!("{} :+ {}.", self.atom(), self.body()),
            2 => format!("{} : {} :+ {}.", self.atom(), self.atom(), self.body()),
            3 => format!(
                ":~ {}. [{}@{}, {}]",
                self.body(),
                self.term(1),
                self.term(0),
                self.term(1)
            ),
            4 => format!(
                "#minimize {{ {}@{}, {} : {} }}.",
                self.term(1),
                self.term(0),
                self.term(1),
                self.condition()
            ),
            5 => format!("#show {} : {}.", self.term(1), self.body()),
            6 => format!("#const c = {}.", self.term(2)),
            7 => format!(
                "#external {} : {}. [{}]",
                self.atom(),
                self.body(),
                self.pick(&["true", "false", "free"])
            ),
            8 => format!("{}.", self.head()),
            _ => format!("{} :- {}.", self.head(), self.body()),
        }
    }
}

impl Gen {
    fn sort_primary(&mut self, depth: u32) -> String {
        match self.below(if depth == 0 { 4 } else { 7 }) {
            0 => format!("{{{}}}", self.tuple(1)),
            1 => format!(
                "{}..{}",
                self.pick(&["0", "1", "n", "-1"]),
                self.pick(&["3", "n", "(n + 1)"])
            ),
            2 => format!("#{}", self.pick(&["s", "t", "step"])),
            3 => format!(
                "[{}][1..{}]",
                self.pick(&["a", "b"]),
                self.pick(&["2", "n"])
            ),
            4 => format!("({})", self.sort_expr(depth - 1)),
            5 => "rec(#s(X), #t(Y)) : X != Y".to_string(),
            _ => format!("rec(#s, {})", self.sort_primary(depth - 1)),
        }
    }

    fn sort_expr(&mut self, depth: u32) -> String {
        let n = 1 + self.below(3);
        let mut out = self.sort_primary(depth);
        for _ in 1..n {
            let op = self.pick(&[" + ", " - ", " * "]);
            let rhs = self.sort_primary(depth);
            // A record with a condition can only end an expression.
            if out.contains(" : ") {
                break;
            }
            out = format!("{out}{op}{rhs}");
        }
        out
    }

    fn sparc_program(&mut self) -> String {
        let mut out = String::from("#const n = 3.\nsorts\n#s = {a, b}.\n#t = 1..n.\n");
        for i in 0..1 + self.below(4) {
            out.push_str(&format!("#u{i} = {}.\n", self.sort_expr(2)));
        }
        out.push_str("predicates\np(#s, #t).\nq().\nrules\n");
        for _ in 0..1 + self.below(4) {
            let body = self.body();
            out.push_str(&format!("{} :- {body}, #s(X).\n", self.atom()));
        }
        out.push_str("display\np.\n-q.\n#s(X).\n");
        out
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn generated_programs_parse_and_round_trip(seed in 1u64.., n in 1usize..12) {
        let mut g = Gen { state: seed };
        let program: String = (0..n).map(|_| g.statement() + "\n").collect();
        let parsed = parse(FileId(0), &program, Dialect::Clingo);
        prop_assert!(parsed.diagnostics.is_empty(), "{program}\n{:?}", parsed.diagnostics);
        check_round_trip(&program, Dialect::Clingo).map_err(TestCaseError::fail)?;
        check_parse_invariants(&program).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn generated_sparc_programs_parse_and_round_trip(seed in 1u64..) {
        let mut g = Gen { state: seed };
        let program = g.sparc_program();
        let parsed = parse(FileId(0), &program, Dialect::Sparc);
        prop_assert!(parsed.diagnostics.is_empty(), "{program}\n{:?}", parsed.diagnostics);
        check_round_trip(&program, Dialect::Sparc).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn token_soup_keeps_invariants(tokens in prop::collection::vec(prop::sample::select(vec![
        "p", "q(", "X", "_", "1", "\"s\"", "#count", "#sum+", "#show", "#const", "#script (python)",
        "#end.", "@f", "not", "-", "|", "(", ")", "{", "}", "[", "]", ",", ";", ":", ":-", ":+",
        ":~", ".", "..", "=", "<", "!=", "+", "*", "**", "/", "\\", "%", "%*", "*%", "\n", "sorts",
        "predicates", "rules", "display", "#s", "#s(X)", "=", "#true", "@", "^", "?", "~",
    ]), 0..60)) {
        let text = tokens.join(" ");
        check_parse_invariants(&text).map_err(TestCaseError::fail)?;
        check_round_trip(&text, Dialect::Clingo).map_err(TestCaseError::fail)?;
        check_round_trip(&text, Dialect::Sparc).map_err(TestCaseError::fail)?;
    }
}

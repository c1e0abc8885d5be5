//! The flat store of a ground program's rules ([`Rules`]): every rule's heads in one array,
//! normal bodies in a second, weight bodies in a third, and one record of three ends per rule,
//! so a program of millions of small rules costs no allocation per rule.
//!
//! Invariants: see [`Rules`]; equal rule sequences have equal stores, and a rule reads back
//! (as a [`RuleRef`]) exactly as it was pushed.

use super::{Atom, BodyRef, HeadKind, Lit, Rule, RuleRef, Weight};

/// Where one rule of a [`Rules`] store ends in each of the store's arrays.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Ends {
    /// End in `heads`, with `CHOICE` set for a choice rule.
    head: usize,
    /// End in `lits` (normal bodies).
    lit: usize,
    /// End in `wlits` (weight bodies).
    wlit: usize,
}

/// The flag in `Ends::head` that marks a choice rule.
const CHOICE: usize = 1 << (usize::BITS - 1);

/// The rules of a ground program, stored flat: the heads of all rules one after another in one
/// array, normal bodies in a second and weight bodies in a third, plus one record of three
/// ends per rule. A rule costs 24 bytes plus 4 per head atom and body literal (16 per weight
/// literal), without an allocation of its own: a `Vec<Rule>` costs 64 bytes per rule plus a
/// heap block per non-empty head and body, several times more for the millions of small
/// constraints some programs ground to.
///
/// Invariants: `ends` is non-decreasing in each component (with `CHOICE` masked off); rule
/// `i` spans from the ends of rule `i - 1` (0 for the first) to its own; a weight body starts
/// with one entry `(0, lower)` holding its bound (no literal is 0), so a rule has a weight body
/// exactly when its `wlits` range is not empty, and then its `lits` range is empty. Equal rule
/// sequences have equal stores.
#[derive(Clone, Default, PartialEq, Eq)]
pub struct Rules {
    heads: Vec<Atom>,
    lits: Vec<Lit>,
    wlits: Vec<(Lit, Weight)>,
    ends: Vec<Ends>,
}

impl Rules {
    /// No rules.
    pub fn new() -> Rules {
        Rules::default()
    }

    /// The number of rules.
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    /// Whether there are no rules.
    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    fn last_ends(&self) -> Ends {
        self.ends.last().map_or(Ends::default(), |e| Ends {
            head: e.head & !CHOICE,
            ..*e
        })
    }

    /// Makes room for `rules` more rules with `heads` head atoms and `lits` body literals in
    /// all, so that a store whose size is known roughly does not grow step by step.
    pub fn reserve(&mut self, rules: usize, heads: usize, lits: usize) {
        self.ends.reserve(rules);
        self.heads.reserve(heads);
        self.lits.reserve(lits);
    }

    /// Makes room for as many more rules, head atoms and literals as `other` holds (for a
    /// store that is written from `other`, such as the simplified program from the ground one).
    pub fn reserve_like(&mut self, other: &Rules) {
        self.reserve(other.ends.len(), other.heads.len(), other.lits.len());
        self.wlits.reserve(other.wlits.len());
    }

    /// Appends a rule.
    pub fn push_parts(&mut self, head_kind: HeadKind, head: &[Atom], body: BodyRef<'_>) {
        self.heads.extend_from_slice(head);
        match body {
            BodyRef::Normal(lits) => self.lits.extend_from_slice(lits),
            BodyRef::Weight { lower, lits } => {
                self.wlits.push((0, lower));
                self.wlits.extend_from_slice(lits);
            }
        }
        let choice = if head_kind == HeadKind::Choice {
            CHOICE
        } else {
            0
        };
        self.ends.push(Ends {
            head: self.heads.len() | choice,
            lit: self.lits.len(),
            wlit: self.wlits.len(),
        });
    }

    /// Appends a rule given as a view.
    pub fn push_ref(&mut self, rule: RuleRef<'_>) {
        self.push_parts(rule.head_kind, rule.head, rule.body);
    }

    /// Appends an owned rule (its vectors are copied in and dropped).
    pub fn push(&mut self, rule: Rule) {
        self.push_ref(rule.as_ref());
    }

    /// Rule `i` (panics when `i >= len()`, as slice indexing does).
    #[inline]
    pub fn get(&self, i: usize) -> RuleRef<'_> {
        let start = if i == 0 {
            Ends::default()
        } else {
            let e = self.ends[i - 1];
            Ends {
                head: e.head & !CHOICE,
                ..e
            }
        };
        self.view(start, self.ends[i])
    }

    #[inline]
    fn view(&self, start: Ends, end: Ends) -> RuleRef<'_> {
        let head_kind = if end.head & CHOICE != 0 {
            HeadKind::Choice
        } else {
            HeadKind::Disjunction
        };
        let body = if end.wlit > start.wlit {
            let w = &self.wlits[start.wlit..end.wlit];
            BodyRef::Weight {
                lower: w[0].1,
                lits: &w[1..],
            }
        } else {
            BodyRef::Normal(&self.lits[start.lit..end.lit])
        };
        RuleRef {
            head_kind,
            head: &self.heads[start.head..end.head & !CHOICE],
            body,
        }
    }

    /// The rules in order.
    #[inline]
    pub fn iter(&self) -> RulesIter<'_> {
        RulesIter {
            rules: self,
            next: 0,
            start: Ends::default(),
        }
    }

    /// Owned copies of the rules.
    pub fn to_vec(&self) -> Vec<Rule> {
        self.iter().map(RuleRef::to_rule).collect()
    }

    /// Keeps the first `n` rules.
    pub fn truncate(&mut self, n: usize) {
        if n >= self.len() {
            return;
        }
        self.ends.truncate(n);
        let e = self.last_ends();
        self.heads.truncate(e.head);
        self.lits.truncate(e.lit);
        self.wlits.truncate(e.wlit);
    }

    /// The largest atom in any head or body literal (0 without rules): one pass over the
    /// flat arrays, not a view per rule.
    pub fn max_atom(&self) -> Atom {
        let heads = self.heads.iter().copied().max().unwrap_or(0);
        let lits = self
            .lits
            .iter()
            .map(|l| l.unsigned_abs())
            .max()
            .unwrap_or(0);
        // The `(0, lower)` entries count as atom 0.
        let wlits = self
            .wlits
            .iter()
            .map(|(l, _)| l.unsigned_abs())
            .max()
            .unwrap_or(0);
        heads.max(lits).max(wlits)
    }

    /// Releases spare capacity.
    pub fn shrink_to_fit(&mut self) {
        self.heads.shrink_to_fit();
        self.lits.shrink_to_fit();
        self.wlits.shrink_to_fit();
        self.ends.shrink_to_fit();
    }

    /// Renumbers every atom of every rule by `f`; a body literal keeps its sign.
    pub fn map_atoms(&mut self, f: &mut dyn FnMut(Atom) -> Atom) {
        self.for_each_head_atom(&mut |a| *a = f(*a));
        self.for_each_body_lit(&mut |l| {
            let m = f(l.unsigned_abs()) as Lit;
            *l = if *l < 0 { -m } else { m };
        });
    }

    /// Calls `f` on every body literal (weights kept), in place.
    pub(super) fn for_each_body_lit(&mut self, f: &mut dyn FnMut(&mut Lit)) {
        self.lits.iter_mut().for_each(&mut *f);
        // The `(0, lower)` entries are bounds, not literals.
        self.wlits
            .iter_mut()
            .filter(|(l, _)| *l != 0)
            .for_each(|(l, _)| f(l));
    }

    /// Calls `f` on every head atom, in place.
    pub(super) fn for_each_head_atom(&mut self, f: &mut dyn FnMut(&mut Atom)) {
        self.heads.iter_mut().for_each(f);
    }
}

impl std::fmt::Debug for Rules {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl PartialEq<Vec<Rule>> for Rules {
    fn eq(&self, other: &Vec<Rule>) -> bool {
        self.len() == other.len() && self.iter().zip(other).all(|(a, b)| a == b.as_ref())
    }
}

impl From<Vec<Rule>> for Rules {
    fn from(rules: Vec<Rule>) -> Rules {
        rules.iter().map(Rule::as_ref).collect()
    }
}

impl<'a> FromIterator<RuleRef<'a>> for Rules {
    fn from_iter<I: IntoIterator<Item = RuleRef<'a>>>(iter: I) -> Rules {
        let mut rules = Rules::new();
        rules.extend(iter);
        rules
    }
}

impl<'a> Extend<RuleRef<'a>> for Rules {
    fn extend<I: IntoIterator<Item = RuleRef<'a>>>(&mut self, iter: I) {
        for r in iter {
            self.push_ref(r);
        }
    }
}

impl Extend<Rule> for Rules {
    fn extend<I: IntoIterator<Item = Rule>>(&mut self, iter: I) {
        for r in iter {
            self.push(r);
        }
    }
}

impl<'a> Extend<&'a Rule> for Rules {
    fn extend<I: IntoIterator<Item = &'a Rule>>(&mut self, iter: I) {
        for r in iter {
            self.push_ref(r.as_ref());
        }
    }
}

/// The rules of a [`Rules`] store in order.
pub struct RulesIter<'a> {
    rules: &'a Rules,
    next: usize,
    start: Ends,
}

impl<'a> Iterator for RulesIter<'a> {
    type Item = RuleRef<'a>;

    #[inline]
    fn next(&mut self) -> Option<RuleRef<'a>> {
        let end = *self.rules.ends.get(self.next)?;
        let r = self.rules.view(self.start, end);
        self.next += 1;
        self.start = Ends {
            head: end.head & !CHOICE,
            ..end
        };
        Some(r)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.rules.len() - self.next;
        (n, Some(n))
    }
}

impl ExactSizeIterator for RulesIter<'_> {}

impl<'a> IntoIterator for &'a Rules {
    type Item = RuleRef<'a>;
    type IntoIter = RulesIter<'a>;

    fn into_iter(self) -> RulesIter<'a> {
        self.iter()
    }
}

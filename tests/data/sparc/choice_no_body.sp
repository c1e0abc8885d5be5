% A choice rule without a body: every variable of its element is local, so 1{p(X)}1. chooses
% exactly one p(X) with X in p's sort.
%
% Expected, derived by hand: three answer sets, one atom each. (Typing X in the body instead
% would give one rule 1{p(x)}1 per element x and the single answer set {p(a), p(b), p(c)}.)
%% answer: p(a)
%% answer: p(b)
%% answer: p(c)
sorts
#s = {a, b, c}.
predicates
p(#s).
rules
1{p(X)}1.

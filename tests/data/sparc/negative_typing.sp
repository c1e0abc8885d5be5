% A rule stands for its instances whose atoms are all atoms of the program, default-negated
% ones included: `not p(z)` is no literal of a program where z is outside p's sort.
%
% Expected, derived by hand: p(x) is a fact. q(X) :- #b(X), not p(X). has the instance X = y
% (p(y) is an atom of the program, and false, so q(y) holds) but none for X = z (z is not in
% #a, so p(z) is no atom of the program): q(z) is false.
%% answer: p(x) q(y)
sorts
#a = {x, y}.
#b = {y, z}.
predicates
p(#a).
q(#b).
rules
p(x).
q(X) :- #b(X), not p(X).

% Intervals in facts (SPARC rules are ASP rules): s(1..4). is the four facts s(1), ..., s(4);
% every value must belong to the argument's sort (see errors/interval_outside_sort.sp).
%
% Expected, derived by hand: s(1) s(2) s(3) s(4), pair(1,a) pair(2,a) pair(1,b) pair(2,b).
%% answer: s(1) s(2) s(3) s(4) pair(1,a) pair(2,a) pair(1,b) pair(2,b)
sorts
#n = 1..4.
#l = {a, b}.
predicates
s(#n).
pair(#n, #l).
rules
s(1..4).
pair(1..2, a).
pair(1..2, b).

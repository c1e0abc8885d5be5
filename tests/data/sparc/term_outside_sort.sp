% A head term whose form no element of the sort has (#s has no g(...)): SPARC accepts the
% rule with a warning, and the rule never applies (its typing literal cannot hold).
% Expected, derived by hand: q(a) only.
%% answer: q(a)
sorts
#s = {a, f(a)}.
predicates
p(#s).
q(#s).
rules
q(a).
p(g(X)) :- q(X).

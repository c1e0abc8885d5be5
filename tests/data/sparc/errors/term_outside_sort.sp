% A term whose form no element of the sort has: #s has no g(...).
sorts
#s = {a, f(a)}.
predicates
p(#s).
q(#s).
rules
q(a).
p(g(X)) :- q(X).

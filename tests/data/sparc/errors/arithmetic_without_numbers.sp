% Arithmetic in an argument whose sort has no numbers.
sorts
#s = {a, b}.
predicates
p(#s).
rules
p(a).
p(X + 1) :- p(X).

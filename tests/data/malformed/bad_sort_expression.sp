sorts
#a = {x, y}.
#b = #a + .
#c = 1..3.
predicates
p(#a).
rules
p(x).

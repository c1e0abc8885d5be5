sorts
#s = {a}.
predicates
p(s).
rules
p(a).

% A predicate declared twice (SPARC manual, predicate declaration errors).
sorts
#s = {a}.
predicates
p(#s).
p(#s, #s).
rules
p(a).

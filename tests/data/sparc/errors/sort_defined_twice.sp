% A sort defined twice (SPARC manual, sort definition errors).
sorts
#s = {a}.
#s = {b}.
predicates
p(#s).
rules
p(a).

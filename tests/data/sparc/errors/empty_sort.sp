% A sort denoting no element (SPARC manual, sort definition errors).
sorts
#s1 = {a, b, c}.
#s = #s1 - {a, b, c}.
predicates
p(#s1).
rules
p(a).

% A numeric range with an undefined constant (SPARC manual, sort definition errors).
#const n1 = 5.
sorts
#s = n1..n2.

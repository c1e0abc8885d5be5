% A variable naming two arguments of a record (SPARC manual, sort definition errors).
sorts
#s = {a}.
#f = f(#s(X), #s(X)) : X != X.

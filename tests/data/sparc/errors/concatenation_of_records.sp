% A concatenation of a sort with records (SPARC manual: concatenations take basic sorts).
sorts
#s = {f(a)}.
#c = [a][#s].

% A numeric range whose first end is greater than its second (SPARC manual).
sorts
#s = 4..3.
predicates
p(#s).
rules
p(X) :- #s(X).

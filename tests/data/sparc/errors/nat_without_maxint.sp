% #nat without #maxint: the built-in sort exists only with #maxint = N.
sorts
#s = {a}.
predicates
p(#nat).
rules

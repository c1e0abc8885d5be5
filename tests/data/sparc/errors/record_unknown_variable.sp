% A record condition naming a variable the record does not have.
sorts
#s = 1..2.
#f = f(#s(X), #s(Y)) : X < Z.

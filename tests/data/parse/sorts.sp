% A small SPARC program: every section, every kind of sort expression.
#const steps = 3.
#const top = 2.

sorts
#blocks = [block][1..3].
#towers = [t][a, b] + {ground}.
#place = #blocks + #towers.
#small = {b1, b2, f(c)}.
#only = #place - #towers.
#common = #place * #blocks.
#step = 0..steps.
#height = 1..top.
#grouped = (#blocks + #towers) * #place.
#action = move(#blocks, #place) + wait(#step).
#distinct = pair(#blocks(X), #blocks(Y)) : X != Y.
#fluent = on(#blocks, #place).

predicates
holds(#fluent, #step).
occurs(#action, #step).
goal(#step).
success().

rules
holds(on(B, P), I+1) :- occurs(move(B, P), I), #step(I).
-holds(F, I) :- #fluent(F), #step(I), not holds(F, I).
success :- goal(I).
:- not success.
occurs(A, I) | -occurs(A, I) :- #action(A), #step(I), not goal(I).
holds(on(B, ground), 0) :+ #blocks(B).
goal(I) :- holds(on(block1, block2), I).

display
occurs.
-holds(F, I).
#blocks(B).

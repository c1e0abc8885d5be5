% Record sorts with conditions (SPARC manual, "set of records"): f(#s(X), #s(Y)) : c is every
% f(x, y) with x, y in #s for which c holds; conditions join comparisons with `and`, `or` and
% `not(...)`, and a record with a condition may stand anywhere in a sort expression.
%
% Expected, derived by hand with #s = {1, 2, 3}:
% - #lt: X < Y gives f(1,2), f(1,3), f(2,3).
% - #mix: z, then g(X, Y) with X = Y or not(X <= 2) (that is, X = 3): g(1,1), g(2,2), g(3,3),
%   g(3,1), g(3,2); then w (the `+ {w}` after the condition belongs to the sort expression).
% - #both: X != Y and Y > 1: h(1,2), h(1,3), h(2,3), h(3,2).
% - #nest: a record with a condition as the argument of another record: k(f(1,2), a),
%   k(f(1,3), a), k(f(2,3), a) (the `,` before a ends the inner record: no variable follows);
%   the rule for nest/1 has the instances Y = 2, 3 (Y = 1 gives k(f(1,1), a), outside #nest).
%% answer: lt(f(1,2)) lt(f(1,3)) lt(f(2,3)) mix(z) mix(g(1,1)) mix(g(2,2)) mix(g(3,3)) mix(g(3,1)) mix(g(3,2)) mix(w) both(h(1,2)) both(h(1,3)) both(h(2,3)) both(h(3,2)) nest(k(f(1,2),a)) nest(k(f(1,3),a))
sorts
#s = 1..3.
#lt = f(#s(X), #s(Y)) : X < Y.
#mix = {z} + g(#s(X), #s(Y)) : X = Y or not(X <= 2) + {w}.
#both = h(#s(X), #s(Y)) : X != Y and Y > 1.
#nest = k(f(#s(X), #s(Y)) : X < Y, {a}).
predicates
lt(#lt).
mix(#mix).
both(#both).
nest(#nest).
rules
lt(X) :- #lt(X).
mix(X) :- #mix(X).
both(X) :- #both(X).
nest(k(f(1, Y), a)) :- #s(Y).

% Sort names that are clingo directives in gringo's language: a SPARC sort may be called
% #program, #show or #external, and is then a sort everywhere in the program (definitions,
% declarations, rule bodies, display).
%
% Expected, derived by hand: #program = {a, b}, #show = {a, b, c}, #external = {b, c}.
% p(a), p(b) and q(a), q(b), q(c) hold; r(X) needs X in #external and q(X): r(b), r(c).
% Display shows r and the sort #program.
%% answer: r(b) r(c) #program(a) #program(b)
sorts
#program = {a, b}.
#show = #program + {c}.
#external = #show - {a}.
predicates
p(#program).
q(#show).
r(#external).
rules
p(X) :- #program(X).
q(X) :- #show(X).
r(X) :- #external(X), q(X).
display
r.
#program.

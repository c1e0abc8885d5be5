% #nat without #maxint: SPARC always has the built-in sort #nat = 0..maxint, and its maximal
% integer is 1000000 when the program sets no #maxint (iensen/sparc, sorts/BuiltIn.java). So a
% program may declare arguments of sort #nat and build sorts from it without any directive.
%
% Expected, derived by hand:
% - age(tom, 30) is a fact: 30 is in #nat.
% - next(P, A + 1) :- age(P, A). gives next(tom, 31).
% - scaled(P, N) :- age(P, A), N = A * 30000. N = 900000 is in #nat: scaled(tom, 900000).
% - huge(P, N) :- age(P, A), N = A * 40000. N = 1200000 is above 1000000: no instance.
% - #small = #nat * {2, 7, 2000000} keeps 2 and 7 (2000000 is outside #nat); pick(X) holds
%   for each of them.
%% answer: age(tom,30) next(tom,31) scaled(tom,900000) pick(2) pick(7)
sorts
#person = {tom}.
#small = #nat * {2, 7, 2000000}.
predicates
age(#person, #nat).
next(#person, #nat).
scaled(#person, #nat).
huge(#person, #nat).
pick(#small).
rules
age(tom, 30).
next(P, A + 1) :- age(P, A).
scaled(P, N) :- age(P, A), N = A * 30000.
huge(P, N) :- age(P, A), N = A * 40000.
pick(X) :- #small(X).

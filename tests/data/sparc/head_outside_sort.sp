% A rule head whose term lies outside its sort for every value of its variable: #pair has only
% f(1, ...) records, so p(f(2,X)) can never be typed. SPARC accepts the program and warns that
% the rule has no well-typed instance (its test suite: "Rule p(f(2,X)). ... is an empty rule");
% Lucent warns at the term, file:line:col, and the rule never applies.
%
% Expected, derived by hand: #pair = {f(1,1), f(1,2)}. p(f(2,X)) has no instance. The rule
% -p(X) :- not p(X). types X by #pair, and nothing derives p, so -p(f(1,1)) and -p(f(1,2)).
%% answer: -p(f(1,1)) -p(f(1,2))
%% warning: head_outside_sort.sp:17:3-9: info: 'f(2,X)' does not belong to sort #pair
sorts
#one = {1}.
#two = 1..2.
#pair = f(#one, #two).
predicates
p(#pair).
rules
p(f(2,X)).
-p(X) :- not p(X).

% #maxint and #nat (SPARC manual, "Directives"): #maxint = 4 makes the built-in sort #nat the
% integers 0..4, and a variable that only arithmetic mentions ranges over #nat.
%
% Expected, derived by hand: p(1), p(2), p(3) are facts.
% - sq(X * X) :- p(X). gives 1 and 4; 9 is not in #nat (9 > 4), so sq(9) has no instance.
% - sum(X + Y) :- p(X), p(Y). gives 2, 3, 4; 5 and 6 are outside #nat.
% - even(X) :- p(X), X = Z + Z. Z occurs only in arithmetic, so it ranges over 0..4: X = 2
%   (Z = 1) is the only p-value that is a double.
% - big :- W * W = 16. W ranges over 0..4: W = 4 makes it hold.
% - small :- W * W = 25. would need W = 5, outside #nat: no instance, small stays false.
%% answer: p(1) p(2) p(3) sq(1) sq(4) sum(2) sum(3) sum(4) even(2) big
#maxint = 4.
sorts
#n = 1..3.
predicates
p(#n).
sq(#nat).
sum(#nat).
even(#n).
big().
small().
rules
p(1). p(2). p(3).
sq(X * X) :- p(X).
sum(X + Y) :- p(X), p(Y).
even(X) :- p(X), X = Z + Z.
big :- W * W = 16.
small :- W * W = 25.

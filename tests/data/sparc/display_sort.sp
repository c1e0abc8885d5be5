% The display section (SPARC manual, "Display"): a literal shows the literals unifiable with it,
% `#t.` shows the atoms of the sort #t, and nothing else is shown.
%
% Expected, derived by hand: the rules derive -r (from #t(a)), q(a) (from -r), q(g(a)),
% -q(b), -q(g(b)) and s(a) (from #t(b)). Shown: -r (display -r), q(a) and q(g(a)) (display
% q(X)), -q(g(b)) (display -q(g(X)); -q(b) does not unify with it), and every element of #t.
% s(a) is not shown: no display item unifies with it.
%% answer: -r q(a) q(g(a)) -q(g(b)) #t(a) #t(b) #t(c) #t(g(a)) #t(g(b))
sorts
#t = {a, b, c, g(a), g(b)}.
predicates
q(#t).
r().
s(#t).
rules
s(a) :- #t(b).
-r :- #t(a).
q(a) :- -r.
-q(b).
q(g(a)).
-q(g(b)).
display
-r.
-q(g(X)).
q(X).
#t.

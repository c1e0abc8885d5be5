% A choice element's local variable ranges over the sort of its argument position:
% in 1{has(X, C)}1 :- #region(X). C occurs only in the element, so it is typed inside it
% (1{has(X, C) : #color(C)}1), and each region gets exactly one color.
%
% Expected, derived by hand: r1 and r2 each get one of red, green; the constraint forbids the
% same color for both, leaving two answer sets. (Typing C in the rule body instead would make
% one choice rule per color, force all four has/2 atoms and make the program unsatisfiable.)
%% answer: has(r1,red) has(r2,green)
%% answer: has(r1,green) has(r2,red)
sorts
#region = {r1, r2}.
#color = {red, green}.
predicates
has(#region, #color).
rules
1{has(X, C)}1 :- #region(X).
:- has(r1, C), has(r2, C).

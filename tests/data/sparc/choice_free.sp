% The same choice without the constraint: every region picks one of its two colors
% independently, 2 x 2 = 4 answer sets.
%% answer: has(r1,red) has(r2,red)
%% answer: has(r1,red) has(r2,green)
%% answer: has(r1,green) has(r2,red)
%% answer: has(r1,green) has(r2,green)
sorts
#region = {r1, r2}.
#color = {red, green}.
predicates
has(#region, #color).
rules
1{has(X, C)}1 :- #region(X).

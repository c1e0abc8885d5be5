% Without #maxint, a variable that occurs only inside an arithmetic argument of a head atom
% ranges over that argument's sort. Expected, derived by hand: X and Y range over 1..9;
% ((X-1)/3)*3 is 0, 3 or 6 and (Y+2)/3 is 1, 2 or 3, so the sums are 1..9, all in #num.
%% answer: p(1) p(2) p(3) p(4) p(5) p(6) p(7) p(8) p(9)
sorts
#num = 1..9.
predicates
p(#num).
rules
p(((X-1)/3)*3+((Y+2)/3)).

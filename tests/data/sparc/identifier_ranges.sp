% Identifier ranges (SPARC manual, "identifier range"): id1..id2 is every identifier s with
% id1 <= s <= id2 and |id1| <= |s| <= |id2|, over lower-case letters (SPARC's own test suite:
% [ab..cd] has 55 members). They may stand alone or inside a concatenation.
%
% Expected, derived by hand:
% - #short = a..e: a, b, c, d, e.
% - #code = [ab..ad][1..2]: ab1, ab2, ac1, ac2, ad1, ad2.
% - #two = ay..bb has only identifiers of length 2: ay, az (first letter a, second at least y),
%   then ba, bb: 4 in all.
% - #wide = ab..cd: ab..az (25), ba..bz (26), ca..cd (4): 55.
%% answer: short(a) short(b) short(c) short(d) short(e) code(ab1) code(ab2) code(ac1) code(ac2) code(ad1) code(ad2) count(4) two(ay) two(bb) wide(55)
#maxint = 100.
sorts
#short = a..e.
#code = [ab..ad][1..2].
#two = ay..bb.
#wide = [ab..cd].
predicates
short(#short).
code(#code).
count(#nat).
two(#two).
wide(#nat).
rules
short(X) :- #short(X).
code(X) :- #code(X).
count(N) :- N = #count{X : #two(X)}.
wide(N) :- N = #count{X : #wide(X)}.
two(ay). two(bb).

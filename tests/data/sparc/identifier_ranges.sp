% Identifier ranges (SPARC manual, "identifier range"): id1..id2 is every identifier s with
% id1 <= s <= id2 and |id1| <= |s| <= |id2|, characters compared by code over letters, digits
% and `_` (SPARC's alphabet). They may stand alone or inside a concatenation.
%
% Expected, derived by hand:
% - #short = a..e: a, b, c, d, e.
% - #code = [ab..ad][1..2]: ab1, ab2, ac1, ac2, ad1, ad2.
% - #two = ay..bb has only identifiers of length 2: ay, az (first letter a, second at least y),
%   then b followed by a digit (10), an upper-case letter (26), `_`, a or b: 41 in all.
%% answer: short(a) short(b) short(c) short(d) short(e) code(ab1) code(ab2) code(ac1) code(ac2) code(ad1) code(ad2) count(41) two(ay) two(bZ) two(b_) two(bb)
#maxint = 100.
sorts
#short = a..e.
#code = [ab..ad][1..2].
#two = ay..bb.
predicates
short(#short).
code(#code).
count(#nat).
two(#two).
rules
short(X) :- #short(X).
code(X) :- #code(X).
count(N) :- N = #count{X : #two(X)}.
two(ay). two(bZ). two(b_). two(bb).

% A labelled CR rule with an empty head, `label: :+ body.` (SPARC manual, CR-rules). Applied,
% it is the constraint `:- q(d).`; it can only remove answer sets, so a minimal abductive
% support never applies it, while `add_d` is needed for consistency.
%
% Expected, derived by hand: the regular rules alone are inconsistent (:- not q(d). with no way
% to derive q(d)); applying add_d (p(d) :+.) gives p(d), hence q(d), and the constraint holds.
% Applying r1 as well would kill that answer set. p(c), q(c) hold throughout.
%% answer: p(c) q(c) p(d) q(d)
sorts
#s = {c, d}.
predicates
p(#s).
q(#s).
rules
p(c).
q(X) :- p(X).
:- not q(d).
add_d: p(d) :+ .
r1: :+ q(d).

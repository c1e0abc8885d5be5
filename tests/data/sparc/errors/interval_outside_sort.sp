% An interval in a fact reaching outside the sort: 0 is not in #n.
sorts
#n = 1..4.
predicates
s(#n).
rules
s(0..2).

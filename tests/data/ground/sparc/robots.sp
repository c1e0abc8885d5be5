% A small sorted program: sorts of every kind, typed predicates, a CR rule, a display section.
#const n = 2.
sorts
#robot = [r][1..n].
#room = {kitchen, hall, lab}.
#dark = {lab}.
#lit = #room - #dark.
#step = 0..n.
#move = go(#robot, #room).
#thing = #robot + #room.
predicates
at(#robot, #room, #step).
occurs(#move, #step).
visited(#robot, #room).
busy(#robot).
rules
at(r1, kitchen, 0).
at(r2, hall, 0).
at(R, L, I+1) :- occurs(go(R, L), I).
-at(R, L2, I) :- at(R, L1, I), L1 != L2.
at(R, L, I+1) :- at(R, L, I), not -at(R, L, I+1).
occurs(go(R, L), I) | -occurs(go(R, L), I) :- #lit(L), I < n.
:- occurs(go(R, L1), I), occurs(go(R, L2), I), L1 != L2.
:- occurs(go(R1, L), I), occurs(go(R2, L), I), R1 != R2.
visited(R, L) :- at(R, L, I).
:- not visited(r1, hall).
busy(R) :+ #robot(R).
:- not busy(r2), visited(r2, kitchen).
display
visited.
busy.

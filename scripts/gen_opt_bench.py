#!/usr/bin/env python3
"""Writes the optimization benchmark rows of scripts/bench_opt.sh into benches/data/opt/:
travelling-salesman tours over 10-16 cities (sparse random graphs with Euclidean costs),
0/1 knapsack, and a small timetabling problem with weighted soft constraints on two priority
levels. Every file is encoding plus instance, generated from a fixed seed, so re-running this
script rewrites the same bytes. Usage: python3 scripts/gen_opt_bench.py"""
import math
import os
import random

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benches", "data", "opt")

TSP = """% Travelling salesman: a Hamiltonian cycle of least total cost.
{ cycle(X,Y) : cost(X,Y,_) } = 1 :- node(X).
{ cycle(X,Y) : cost(X,Y,_) } = 1 :- node(Y).
reached(Y) :- cycle(1,Y).
reached(Y) :- cycle(X,Y), reached(X).
:- node(Y), not reached(Y).
#minimize { C,X,Y : cycle(X,Y), cost(X,Y,C) }.
"""

KNAPSACK = """% 0/1 knapsack: the most valuable load within the capacity.
{ take(I) : item(I,_,_) }.
:- #sum { W,I : take(I), item(I,W,_) } > C, capacity(C).
#maximize { V,I : take(I), item(I,_,V) }.
"""

TIMETABLE = """% Timetabling: each event gets one slot and one room; a teacher teaches one event per
% slot, a room holds one event per slot and must be large enough. Soft: a teacher's unwanted
% slots (priority 2, weight = how strongly), a class's events spread over days (priority 1).
{ at(E,S,R) : slot(S), room(R,C), C >= N } = 1 :- event(E,_,_,N).
:- teaches(T,E1), teaches(T,E2), E1 < E2, at(E1,S,_), at(E2,S,_).
:- room(R,_), slot(S), #count { E : at(E,S,R) } > 1.
:- class(K,E1), class(K,E2), E1 < E2, at(E1,S,_), at(E2,S,_).
teaches(T,E) :- event(E,T,_,_).
class(K,E) :- event(E,_,K,_).
busy(T,S) :- teaches(T,E), at(E,S,_).
:~ busy(T,S), unwanted(T,S,W). [W@2,T,S]
day_of(E,D) :- at(E,S,_), day(S,D).
:~ class(K,E1), class(K,E2), E1 < E2, day_of(E1,D), day_of(E2,D), weight(K,W). [W@1,K,E1,E2]
"""


def tsp(n, rng):
    pts = [(rng.randint(0, 100), rng.randint(0, 100)) for _ in range(n)]
    arcs = set()
    tour = list(range(n))
    rng.shuffle(tour)
    for i in range(n):
        arcs.add((tour[i], tour[(i + 1) % n]))
    for i in range(n):
        near = sorted((j for j in range(n) if j != i), key=lambda j: math.dist(pts[i], pts[j]))
        for j in near[:5]:
            arcs.add((i, j))
            arcs.add((j, i))
    facts = [f"node(1..{n})."]
    for (i, j) in sorted(arcs):
        facts.append(f"cost({i + 1},{j + 1},{int(math.dist(pts[i], pts[j])) + 1}).")
    return TSP + "\n".join(facts) + "\n"


def knapsack(n, rng):
    items = [(rng.randint(5, 40), rng.randint(5, 60)) for _ in range(n)]
    cap = sum(w for w, _ in items) // 3
    facts = [f"item({i + 1},{w},{v})." for i, (w, v) in enumerate(items)]
    facts.append(f"capacity({cap}).")
    return KNAPSACK + "\n".join(facts) + "\n"


def timetable(events, rng):
    slots, days, teachers, classes = 10, 5, max(3, events // 4), max(2, events // 5)
    facts = [f"slot(1..{slots})."]
    facts += [f"day({s},{(s - 1) // (slots // days) + 1})." for s in range(1, slots + 1)]
    facts += [f"room({r},{c})." for r, c in enumerate([20, 30, 40], start=1)]
    for e in range(1, events + 1):
        facts.append(f"event({e},t{rng.randint(1, teachers)},k{rng.randint(1, classes)},"
                     f"{rng.choice([15, 20, 25, 35])}).")
    for t in range(1, teachers + 1):
        for s in rng.sample(range(1, slots + 1), 4):
            facts.append(f"unwanted(t{t},{s},{rng.randint(1, 5)}).")
    facts += [f"weight(k{k},{rng.randint(1, 3)})." for k in range(1, classes + 1)]
    return TIMETABLE + "\n".join(facts) + "\n"


def main():
    os.makedirs(OUT, exist_ok=True)
    rows = {}
    for n in range(10, 17):
        rows[f"tsp_{n:02}.lp"] = tsp(n, random.Random(1000 + n))
    for n in (20, 25, 30):
        rows[f"knapsack_{n}.lp"] = knapsack(n, random.Random(2000 + n))
    for n in (12, 16, 20):
        rows[f"timetable_{n}.lp"] = timetable(n, random.Random(3000 + n))
    for name, text in rows.items():
        with open(os.path.join(OUT, name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()

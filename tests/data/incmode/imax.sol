Step: 1
Step: 2
Step: 3
UNSAT

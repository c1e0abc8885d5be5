Step: 1

a(0)
Step: 2
a(0) a(1) seen(1)
Step: 3
a(0) a(1) a(2) seen(1) seen(2)
SAT

Step: 1
Step: 2
Step: 3
Step: 4
inc(1,1) inc(2,2) inc(3,2)
inc(1,2) inc(2,1) inc(3,2)
inc(1,2) inc(2,2) inc(3,1)
Step: 5
inc(1,0) inc(2,1) inc(3,2) inc(4,2)
inc(1,0) inc(2,2) inc(3,1) inc(4,2)
inc(1,0) inc(2,2) inc(3,2) inc(4,1)
inc(1,1) inc(2,0) inc(3,2) inc(4,2)
inc(1,1) inc(2,1) inc(3,1) inc(4,2)
inc(1,1) inc(2,1) inc(3,2) inc(4,1)
inc(1,1) inc(2,2) inc(3,0) inc(4,2)
inc(1,1) inc(2,2) inc(3,1) inc(4,1)
inc(1,1) inc(2,2) inc(3,2) inc(4,0)
inc(1,2) inc(2,0) inc(3,1) inc(4,2)
inc(1,2) inc(2,0) inc(3,2) inc(4,1)
inc(1,2) inc(2,1) inc(3,0) inc(4,2)
inc(1,2) inc(2,1) inc(3,1) inc(4,1)
inc(1,2) inc(2,1) inc(3,2) inc(4,0)
inc(1,2) inc(2,2) inc(3,0) inc(4,1)
inc(1,2) inc(2,2) inc(3,1) inc(4,0)
SAT

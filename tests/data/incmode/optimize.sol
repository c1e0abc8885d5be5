Step: 1
Step: 2
pick(1,1)
Step: 3
pick(1,1) pick(2,1)
OPTIMUM FOUND

Step: 1
Step: 2
Step: 3
Step: 4
move(1,2,1) move(2,3,2) move(3,4,3)
move(1,5,1) move(3,4,3) move(5,3,2)
SAT

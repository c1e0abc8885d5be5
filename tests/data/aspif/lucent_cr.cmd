hand-written: what Lucent's grounder writes for a program with CR rules r1 and r2(1,"a b")

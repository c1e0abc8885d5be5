gringo --output=intermediate disjunction.lp > disjunction.aspif

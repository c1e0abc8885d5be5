gringo --output=intermediate disjunction.lp > disjunction.aspif
clasp -n 0 --opt-mode=ignore disjunction.aspif > disjunction.out, then the lines after Answer: sorted (LC_ALL=C sort) > disjunction.models

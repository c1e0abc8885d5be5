gringo --output=intermediate weights.lp > weights.aspif
clasp -n 0 --opt-mode=ignore weights.aspif > weights.out, then the lines after Answer: sorted (LC_ALL=C sort) > weights.models

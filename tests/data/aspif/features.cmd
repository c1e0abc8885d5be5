gringo --output=intermediate features.lp > features.aspif
clasp -n 0 --opt-mode=ignore features.aspif > features.out, then the lines after Answer: sorted (LC_ALL=C sort) > features.models

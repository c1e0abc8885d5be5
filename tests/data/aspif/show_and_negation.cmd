gringo --output=intermediate show_and_negation.lp > show_and_negation.aspif
clasp -n 0 --opt-mode=ignore show_and_negation.aspif > show_and_negation.out, then the lines after Answer: sorted (LC_ALL=C sort) > show_and_negation.models

gringo --output=intermediate show_and_negation.lp > show_and_negation.aspif

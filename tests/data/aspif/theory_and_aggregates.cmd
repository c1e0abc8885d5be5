gringo --output=intermediate theory_and_aggregates.lp > theory_and_aggregates.aspif

gringo --output=intermediate weights.lp > weights.aspif

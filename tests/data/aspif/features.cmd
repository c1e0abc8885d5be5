gringo --output=intermediate features.lp > features.aspif

gringo --output=intermediate unicode_strings.lp > unicode_strings.aspif

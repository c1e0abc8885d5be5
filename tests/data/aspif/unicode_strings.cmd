gringo --output=intermediate unicode_strings.lp > unicode_strings.aspif
clasp -n 0 --opt-mode=ignore unicode_strings.aspif > unicode_strings.out, then the lines after Answer: sorted (LC_ALL=C sort) > unicode_strings.models

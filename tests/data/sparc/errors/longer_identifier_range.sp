% An identifier range whose first end is longer than its second (SPARC manual): ab comes
% before b, but no identifier is at least 2 and at most 1 characters long.
sorts
#s = ab..b.

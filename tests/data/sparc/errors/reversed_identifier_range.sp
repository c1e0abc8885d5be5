% An identifier range whose first end comes after its second (SPARC manual).
sorts
#s = zbc..cbz.

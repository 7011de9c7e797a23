#version 3.7;
#include "math.inc"
#debug concat(str(0, 0, 0), ": even ", str(even(0), 0, 0), " odd ", str(odd(0), 0, 0), "\n")
#debug concat(str(1, 0, 0), ": even ", str(even(1), 0, 0), " odd ", str(odd(1), 0, 0), "\n")
#debug concat(str(2, 0, 0), ": even ", str(even(2), 0, 0), " odd ", str(odd(2), 0, 0), "\n")
#debug concat(str(3, 0, 0), ": even ", str(even(3), 0, 0), " odd ", str(odd(3), 0, 0), "\n")
#debug concat(str(-1, 0, 0), ": even ", str(even(-1), 0, 0), " odd ", str(odd(-1), 0, 0), "\n")
#debug concat(str(-2, 0, 0), ": even ", str(even(-2), 0, 0), " odd ", str(odd(-2), 0, 0), "\n")
#debug concat(str(2.5, 0, 0), ": even ", str(even(2.5), 0, 0), " odd ", str(odd(2.5), 0, 0), "\n")

#version 3.7;
#include "math.inc"
#debug concat("f_sqr(7) = ", str(f_sqr(7), 0, 3), "\n")
#debug concat("f_sqr(-1.5) = ", str(f_sqr(-1.5), 0, 3), "\n")

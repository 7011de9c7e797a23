#version 3.7;
#include "math.inc"
#debug concat("max3(1, 5, 3) = ", str(max3(1, 5, 3), 0, 3), "\n")
#debug concat("min3(4, -2, 9) = ", str(min3(4, -2, 9), 0, 3), "\n")

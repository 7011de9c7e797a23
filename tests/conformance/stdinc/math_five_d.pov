#version 3.7;
#include "math.inc"
#debug concat("VLength5D(<1, 2, 3, 4, 5>) = ", str(VLength5D(<1, 2, 3, 4, 5>), 0, 9), "\n")
#debug concat("VDot5D(<1, 2, 3, 4, 5>, <1, 1, 1, 1, 1>) = ", str(VDot5D(<1, 2, 3, 4, 5>, <1, 1, 1, 1, 1>), 0, 3), "\n")

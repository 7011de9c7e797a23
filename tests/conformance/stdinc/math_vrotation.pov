#version 3.7;
#include "math.inc"
#debug concat("VRotationD(x, y, z) = ", str(VRotationD(x, y, z), 0, 9), "\n")
#debug concat("VRotation(x, <1, 1, 0>, z) = ", str(VRotation(x, <1, 1, 0>, z), 0, 9), "\n")

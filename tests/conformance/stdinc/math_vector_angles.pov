#version 3.7;
#include "math.inc"
#debug concat("VAngle(x, y) = ", str(VAngle(x, y), 0, 9), "\n")
#debug concat("VAngleD(x, <1, 1, 0>) = ", str(VAngleD(x, <1, 1, 0>), 0, 9), "\n")
#debug concat("VCos_Angle(x, <1, 1, 0>) = ", str(VCos_Angle(x, <1, 1, 0>), 0, 9), "\n")

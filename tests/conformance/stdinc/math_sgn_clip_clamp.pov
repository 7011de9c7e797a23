#version 3.7;
#include "math.inc"
#debug concat("sgn(-3) = ", str(sgn(-3), 0, 6), "\n")
#debug concat("sgn(0) = ", str(sgn(0), 0, 6), "\n")
#debug concat("sgn(2) = ", str(sgn(2), 0, 6), "\n")
#debug concat("clip(5, 0, 1) = ", str(clip(5, 0, 1), 0, 6), "\n")
#debug concat("clip(-5, 0, 1) = ", str(clip(-5, 0, 1), 0, 6), "\n")
#debug concat("clip(0.5, 0, 1) = ", str(clip(0.5, 0, 1), 0, 6), "\n")
#debug concat("clamp(5.5, 0, 2) = ", str(clamp(5.5, 0, 2), 0, 6), "\n")
#debug concat("clamp(-0.5, 0, 2) = ", str(clamp(-0.5, 0, 2), 0, 6), "\n")

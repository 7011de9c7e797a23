#version 3.7;
#include "math.inc"
#debug concat("Interpolate(0.25, 0, 1, 10, 20, 0) = ", str(Interpolate(0.25, 0, 1, 10, 20, 0), 0, 9), "\n")
#debug concat("Interpolate(0.25, 0, 1, 10, 20, 1) = ", str(Interpolate(0.25, 0, 1, 10, 20, 1), 0, 9), "\n")
#debug concat("Interpolate(0.25, 0, 1, 10, 20, 2) = ", str(Interpolate(0.25, 0, 1, 10, 20, 2), 0, 9), "\n")
#debug concat("Interpolate(0.25, 0, 1, 10, 20, 0.5) = ", str(Interpolate(0.25, 0, 1, 10, 20, 0.5), 0, 9), "\n")

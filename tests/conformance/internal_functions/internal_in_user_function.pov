#version 3.7;
#include "functions.inc"
#declare F = function { f_sphere(x, y, z, 1) - f_noise3d(x * 2, y * 2, z * 2) * 0.1 }
#debug concat("F(0.3, 0.4, 0.5) = ", str(F(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("F(1, 1, 1) = ", str(F(1, 1, 1), 0, 9), "\n")

#version 3.7;
#include "functions.inc"
#debug concat("0.3, 0.4, 0.5 | 1 = ", str(f_sphere(0.3, 0.4, 0.5, 1), 0, 9), "\n")
#debug concat("-0.7, 0.2, 1.1 | 1 = ", str(f_sphere(-0.7, 0.2, 1.1, 1), 0, 9), "\n")
#debug concat("1.5, -0.6, -0.25 | 1 = ", str(f_sphere(1.5, -0.6, -0.25, 1), 0, 9), "\n")

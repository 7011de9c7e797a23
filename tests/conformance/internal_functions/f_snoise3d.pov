#version 3.7;
#include "functions.inc"
#debug concat("f_snoise3d(0.3, 0.4, 0.5) = ", str(f_snoise3d(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_snoise3d(-0.7, 0.2, 1.1) = ", str(f_snoise3d(-0.7, 0.2, 1.1), 0, 9), "\n")
#debug concat("f_snoise3d(1.5, -0.6, -0.25) = ", str(f_snoise3d(1.5, -0.6, -0.25), 0, 9), "\n")

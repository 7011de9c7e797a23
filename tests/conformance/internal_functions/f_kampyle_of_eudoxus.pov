#version 3.7;
#include "functions.inc"
#debug concat("0.3, 0.4, 0.5 | 1, 0.5, 0.8 = ", str(f_kampyle_of_eudoxus(0.3, 0.4, 0.5, 1, 0.5, 0.8), 0, 9), "\n")
#debug concat("-0.7, 0.2, 1.1 | 1, 0.5, 0.8 = ", str(f_kampyle_of_eudoxus(-0.7, 0.2, 1.1, 1, 0.5, 0.8), 0, 9), "\n")
#debug concat("1.5, -0.6, -0.25 | 1, 0.5, 0.8 = ", str(f_kampyle_of_eudoxus(1.5, -0.6, -0.25, 1, 0.5, 0.8), 0, 9), "\n")

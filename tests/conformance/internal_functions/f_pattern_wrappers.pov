#version 3.7;
#include "functions.inc"
#debug concat("f_bozo(0.3, 0.4, 0.5) = ", str(f_bozo(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_bumps(0.3, 0.4, 0.5) = ", str(f_bumps(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_dents(0.3, 0.4, 0.5) = ", str(f_dents(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_granite(0.3, 0.4, 0.5) = ", str(f_granite(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_wrinkles(0.3, 0.4, 0.5) = ", str(f_wrinkles(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_agate(0.3, 0.4, 0.5) = ", str(f_agate(0.3, 0.4, 0.5), 0, 9), "\n")
#debug concat("f_spotted(0.3, 0.4, 0.5) = ", str(f_spotted(0.3, 0.4, 0.5), 0, 9), "\n")

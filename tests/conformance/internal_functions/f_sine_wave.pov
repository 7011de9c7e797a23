#version 3.7;
#include "functions.inc"
#debug concat("f_sine_wave(0.3, 2, 0.5) = ", str(f_sine_wave(0.3, 2, 0.5), 0, 9), "\n")

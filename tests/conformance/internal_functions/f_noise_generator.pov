#version 3.7;
#include "functions.inc"
#debug concat("0.3, 0.4, 0.5 | 1 = ", str(f_noise_generator(0.3, 0.4, 0.5, 1), 0, 9), "\n")
#debug concat("-0.7, 0.2, 1.1 | 1 = ", str(f_noise_generator(-0.7, 0.2, 1.1, 1), 0, 9), "\n")
#debug concat("1.5, -0.6, -0.25 | 1 = ", str(f_noise_generator(1.5, -0.6, -0.25, 1), 0, 9), "\n")
#debug concat("0.3, 0.4, 0.5 | 2 = ", str(f_noise_generator(0.3, 0.4, 0.5, 2), 0, 9), "\n")
#debug concat("-0.7, 0.2, 1.1 | 2 = ", str(f_noise_generator(-0.7, 0.2, 1.1, 2), 0, 9), "\n")
#debug concat("1.5, -0.6, -0.25 | 2 = ", str(f_noise_generator(1.5, -0.6, -0.25, 2), 0, 9), "\n")
#debug concat("0.3, 0.4, 0.5 | 3 = ", str(f_noise_generator(0.3, 0.4, 0.5, 3), 0, 9), "\n")
#debug concat("-0.7, 0.2, 1.1 | 3 = ", str(f_noise_generator(-0.7, 0.2, 1.1, 3), 0, 9), "\n")
#debug concat("1.5, -0.6, -0.25 | 3 = ", str(f_noise_generator(1.5, -0.6, -0.25, 3), 0, 9), "\n")

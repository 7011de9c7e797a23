#version 3.7;
#include "rand.inc"
#declare R = seed(8);
#debug concat("Rand_Normal(0, 1, R) = ", str(Rand_Normal(0, 1, R), 0, 9), "\n")
#debug concat("Rand_Normal(10, 2, R) = ", str(Rand_Normal(10, 2, R), 0, 9), "\n")

#version 3.7;
#include "rand.inc"
#declare R = seed(8);
#debug concat("RRand(-5, 5, R) = ", str(RRand(-5, 5, R), 0, 12), "\n")
#debug concat("RRand(-5, 5, R) = ", str(RRand(-5, 5, R), 0, 12), "\n")
#debug concat("RRand(-5, 5, R) = ", str(RRand(-5, 5, R), 0, 12), "\n")

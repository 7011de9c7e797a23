#version 3.7;
#include "rand.inc"
#declare R = seed(8);
#debug concat("SRand(R) = ", str(SRand(R), 0, 12), "\n")
#debug concat("SRand(R) = ", str(SRand(R), 0, 12), "\n")
#debug concat("SRand(R) = ", str(SRand(R), 0, 12), "\n")

#version 3.7;
#include "math.inc"
#declare A = array[5] {1, 2, 3, 4, 10};
#declare M = Mean(A);
#debug concat("M = ", str(M, 0, 9), "\n")
#debug concat("Std_Dev(A, M) = ", str(Std_Dev(A, M), 0, 9), "\n")

#version 3.7;
#include "arrays.inc"
#declare A = array[2] {1, 2};
Resize_Array(A, 5)
#debug concat("dimension_size(A, 1) = ", str(dimension_size(A, 1), 0, 0), "\n")
#debug concat("A[1] = ", str(A[1], 0, 0), "\n")

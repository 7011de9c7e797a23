#version 3.7;
#include "math.inc"
#debug concat("adj_range(0.5, 10, 20) = ", str(adj_range(0.5, 10, 20), 0, 6), "\n")
#debug concat("adj_range2(15, 10, 20, 0, 1) = ", str(adj_range2(15, 10, 20, 0, 1), 0, 6), "\n")

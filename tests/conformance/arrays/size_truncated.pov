#version 3.7;
#declare A = array[3.9];
#debug concat("dimension_size(A, 1) = ", str(dimension_size(A, 1), 0, 0), "\n")

#version 3.7;
#declare B = array[6][10];
#debug concat("dimension_size(B, 1) = ", str(dimension_size(B, 1), 0, 0), "\n")
#debug concat("dimension_size(B, 2) = ", str(dimension_size(B, 2), 0, 0), "\n")

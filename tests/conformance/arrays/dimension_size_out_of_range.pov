#version 3.7;
#declare B = array[6][10];
#debug concat("dimension_size(B, 3) = ", str(dimension_size(B, 3), 0, 0), "\n")
#debug concat("dimension_size(B, 0) = ", str(dimension_size(B, 0), 0, 0), "\n")

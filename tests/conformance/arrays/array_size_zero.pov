#version 3.7;
#debug "before\n"
#declare A = array[0];
#debug concat("dimensions(A) = ", str(dimensions(A), 0, 0), "\n")

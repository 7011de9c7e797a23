#version 3.7;
#declare A = array[3] {1, 2, 3};
#debug "before\n"
#debug concat("A[-1] = ", str(A[-1], 0, 0), "\n")

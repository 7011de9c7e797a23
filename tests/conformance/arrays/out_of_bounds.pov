#version 3.7;
#declare A = array[3] {1, 2, 3};
#debug "before\n"
#debug concat("A[3] = ", str(A[3], 0, 0), "\n")

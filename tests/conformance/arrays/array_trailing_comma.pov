#version 3.7;
#debug "before\n"
#declare A = array[2] {1, 2,};
#debug concat("A[1] = ", str(A[1], 0, 0), "\n")

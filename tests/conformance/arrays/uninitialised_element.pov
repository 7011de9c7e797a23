#version 3.7;
#declare A = array[3];
#declare A[0] = 1;
#debug "before\n"
#debug concat("A[1] = ", str(A[1], 0, 0), "\n")

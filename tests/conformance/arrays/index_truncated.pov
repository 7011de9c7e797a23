#version 3.7;
#declare A = array[3] {10, 20, 30};
#debug concat("A[1.9] = ", str(A[1.9], 0, 0), "\n")
#debug concat("A[0.2] = ", str(A[0.2], 0, 0), "\n")

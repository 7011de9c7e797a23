#version 3.7;
#declare A = array[1] {5};
#declare A[0] = A[0] + 1;
#debug concat("A[0] = ", str(A[0], 0, 0), "\n")

#version 3.7;
#declare A = array[2] {1, 2};
#declare B = A;
#declare B[0] = 99;
#debug concat("A[0] = ", str(A[0], 0, 0), "\n")
#debug concat("B[0] = ", str(B[0], 0, 0), "\n")

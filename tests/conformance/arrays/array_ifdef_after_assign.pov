#version 3.7;
#declare A = array[2];
#declare A[1] = 1;
#debug concat("defined(A[1]) = ", str(defined(A[1]), 0, 0), "\n")
#debug concat("defined(A[0]) = ", str(defined(A[0]), 0, 0), "\n")

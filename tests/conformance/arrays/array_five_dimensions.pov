#version 3.7;
#declare A = array[1][2][1][2][1];
#declare A[0][1][0][1][0] = 5;
#debug concat("A[0][1][0][1][0] = ", str(A[0][1][0][1][0], 0, 0), "\n")
#debug concat("dimensions(A) = ", str(dimensions(A), 0, 0), "\n")

#version 3.7;
#declare A = array[3];
#declare A[0] = 10;
#declare A[1] = 20;
#declare A[2] = 30;
#debug concat("A[0] + A[1] + A[2] = ", str(A[0] + A[1] + A[2], 0, 0), "\n")

#version 3.7;
#declare A = array[5] {0, 10, 20, 30, 40};
#declare I = 1;
#debug concat("A[I * 2 + 1] = ", str(A[I * 2 + 1], 0, 0), "\n")

#version 3.7;
#declare A = 1;
#declare A = A + 1;
#declare A = A * 10;
#debug concat("A = ", str(A, 0, 0), "\n")

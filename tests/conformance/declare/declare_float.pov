#version 3.7;
#declare A = 1.5;
#debug concat("A = ", str(A, 0, 2), "\n")

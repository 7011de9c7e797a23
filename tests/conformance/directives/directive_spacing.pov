#version 3.7;
#   declare A = 1;
#declare	B = 2;
#debug concat("A + B = ", str(A + B, 0, 0), "\n")

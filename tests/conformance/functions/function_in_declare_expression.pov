#version 3.7;
#declare F = function { x * y }
#declare A = F(3, 4, 0) + 1;
#debug concat("A = ", str(A, 0, 1), "\n")

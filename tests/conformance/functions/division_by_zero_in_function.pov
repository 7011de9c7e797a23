#version 3.7;
#declare F = function { 1 / x }
#debug concat("F(0, 0, 0) = ", str(F(0, 0, 0), 0, 3), "\n")
#debug concat("F(4, 0, 0) = ", str(F(4, 0, 0), 0, 3), "\n")

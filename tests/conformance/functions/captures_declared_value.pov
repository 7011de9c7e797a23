#version 3.7;
#declare K = 5;
#declare F = function { x * K }
#declare K = 100;
#debug concat("F(2, 0, 0) = ", str(F(2, 0, 0), 0, 1), "\n")

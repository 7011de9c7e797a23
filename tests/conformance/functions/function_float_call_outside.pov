#version 3.7;
#declare F = function { x }
#debug concat("F(1, 2, 3) + F(4, 5, 6) = ", str(F(1, 2, 3) + F(4, 5, 6), 0, 3), "\n")

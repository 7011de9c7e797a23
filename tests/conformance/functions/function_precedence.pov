#version 3.7;
#declare F = function { x + y * z - x / y }
#debug concat("F(2, 4, 3) = ", str(F(2, 4, 3), 0, 6), "\n")

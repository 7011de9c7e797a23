#version 3.7;
#declare F = function { x + y * z }
#debug concat("F(1, 2, 3) = ", str(F(1, 2, 3), 0, 6), "\n")
#debug concat("F(-1, 0.5, 4) = ", str(F(-1, 0.5, 4), 0, 6), "\n")

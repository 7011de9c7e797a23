#version 3.7;
#declare F = function { select(x, -1, 0, 1) }
#debug concat("F(-2, 0, 0) = ", str(F(-2, 0, 0), 0, 0), "\n")
#debug concat("F(0, 0, 0) = ", str(F(0, 0, 0), 0, 0), "\n")
#debug concat("F(3, 0, 0) = ", str(F(3, 0, 0), 0, 0), "\n")

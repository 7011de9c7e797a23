#version 3.7;
#declare F = function { ((x + 1) * (y - 1)) / (z + 2) }
#debug concat("F(1, 3, 0) = ", str(F(1, 3, 0), 0, 6), "\n")

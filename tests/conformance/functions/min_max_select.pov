#version 3.7;
#declare F = function { min(x, y, z) + max(x, y) * 10 + select(z, 100, 200) }
#debug concat("F(1, 2, 3) = ", str(F(1, 2, 3), 0, 3), "\n")
#debug concat("F(5, -2, -1) = ", str(F(5, -2, -1), 0, 3), "\n")

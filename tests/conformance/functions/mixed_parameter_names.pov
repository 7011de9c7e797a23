#version 3.7;
#declare F = function(k1, k2, z, y) { x + y * z + k1 * y + k2 }
#debug concat("F(1, 2, 3, 4) = ", str(F(1, 2, 3, 4), 0, 6), "\n")

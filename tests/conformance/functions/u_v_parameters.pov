#version 3.7;
#declare F = function(u, v) { x + y * v }
#debug concat("F(2, 3) = ", str(F(2, 3), 0, 6), "\n")

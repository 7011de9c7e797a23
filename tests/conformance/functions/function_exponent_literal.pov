#version 3.7;
#declare F = function { x * 1e-3 + 2.5e2 }
#debug concat("F(1000, 0, 0) = ", str(F(1000, 0, 0), 0, 6), "\n")

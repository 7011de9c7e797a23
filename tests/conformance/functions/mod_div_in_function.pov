#version 3.7;
#declare F = function { mod(x, y) * 10 }
#debug concat("F(-7, 3, 0) = ", str(F(-7, 3, 0), 0, 3), "\n")
#debug concat("F(7.5, 2, 0) = ", str(F(7.5, 2, 0), 0, 3), "\n")

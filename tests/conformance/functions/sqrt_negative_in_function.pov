#version 3.7;
#declare F = function { sqrt(x) }
#debug concat("F(-4, 0, 0) = ", str(F(-4, 0, 0), 0, 3), "\n")

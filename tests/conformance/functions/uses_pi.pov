#version 3.7;
#declare F = function { x * pi }
#debug concat("F(1, 0, 0) = ", str(F(1, 0, 0), 0, 9), "\n")

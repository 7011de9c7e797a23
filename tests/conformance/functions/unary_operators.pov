#version 3.7;
#declare F = function { -x + +z - -y }
#debug concat("F(1, 2, 5) = ", str(F(1, 2, 5), 0, 3), "\n")

#version 3.7;
#declare F = function { pattern { spherical } }
#debug concat("F(0, 0, 0) = ", str(F(0, 0, 0), 0, 6), "\n")
#debug concat("F(0.5, 0, 0) = ", str(F(0.5, 0, 0), 0, 6), "\n")
#debug concat("F(0.6, 0.8, 0) = ", str(F(0.6, 0.8, 0), 0, 6), "\n")
#debug concat("F(2, 0, 0) = ", str(F(2, 0, 0), 0, 6), "\n")

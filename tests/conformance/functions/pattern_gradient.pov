#version 3.7;
#declare F = function { pattern { gradient x } }
#debug concat("F(0.25, 0, 0) = ", str(F(0.25, 0, 0), 0, 6), "\n")
#debug concat("F(1.75, 0, 0) = ", str(F(1.75, 0, 0), 0, 6), "\n")
#debug concat("F(-0.25, 0, 0) = ", str(F(-0.25, 0, 0), 0, 6), "\n")

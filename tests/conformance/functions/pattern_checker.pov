#version 3.7;
#declare F = function { pattern { checker } }
#debug concat("F(0.5, 0.5, 0.5) = ", str(F(0.5, 0.5, 0.5), 0, 3), "\n")
#debug concat("F(1.5, 0.5, 0.5) = ", str(F(1.5, 0.5, 0.5), 0, 3), "\n")
#debug concat("F(1.5, 1.5, 0.5) = ", str(F(1.5, 1.5, 0.5), 0, 3), "\n")
#debug concat("F(-0.5, 0.5, 0.5) = ", str(F(-0.5, 0.5, 0.5), 0, 3), "\n")

#version 3.7;
#declare F = function { pattern { checker scale 2 } }
#debug concat("F(1.5, 0.5, 0.5) = ", str(F(1.5, 0.5, 0.5), 0, 3), "\n")
#debug concat("F(2.5, 0.5, 0.5) = ", str(F(2.5, 0.5, 0.5), 0, 3), "\n")

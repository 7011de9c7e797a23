#version 3.7;
#declare F = function { pattern { bozo } }
#debug concat("F(0.1, 0.2, 0.3) = ", str(F(0.1, 0.2, 0.3), 0, 9), "\n")
#debug concat("F(1.5, -2.5, 3.25) = ", str(F(1.5, -2.5, 3.25), 0, 9), "\n")
#debug concat("F(10, 20, 30) = ", str(F(10, 20, 30), 0, 9), "\n")

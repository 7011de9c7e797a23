#version 3.7;
#declare F = function { (x > 0 ? x : -x * 10) }
#debug concat("F(3, 0, 0) = ", str(F(3, 0, 0), 0, 1), "\n")
#debug concat("F(-3, 0, 0) = ", str(F(-3, 0, 0), 0, 1), "\n")

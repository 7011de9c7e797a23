#version 3.7;
#declare F = function { floor(x) * 100 + ceil(x) * 10 + int(x) }
#debug concat("F(2.5, 0, 0) = ", str(F(2.5, 0, 0), 0, 1), "\n")
#debug concat("F(-2.5, 0, 0) = ", str(F(-2.5, 0, 0), 0, 1), "\n")

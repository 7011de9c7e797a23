#version 3.7;
#declare F = function { atan2(x, y) + asin(z) + acos(z) + tan(x) + degrees(pi) + radians(180) }
#debug concat("F(1, 1, 0.5) = ", str(F(1, 1, 0.5), 0, 9), "\n")

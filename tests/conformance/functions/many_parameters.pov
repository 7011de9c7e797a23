#version 3.7;
#declare F = function(a, b, c, d, e, f) { a + 2*b + 3*c + 4*d + 5*e + 6*f }
#debug concat("F(1, 1, 1, 1, 1, 1) = ", str(F(1, 1, 1, 1, 1, 1), 0, 3), "\n")
#debug concat("F(1, 2, 3, 4, 5, 6) = ", str(F(1, 2, 3, 4, 5, 6), 0, 3), "\n")

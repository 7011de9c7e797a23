#version 3.7;
#declare G = function(a) { a * 2 }
#declare F = function { G(x) + G(y) }
#debug concat("F(1, 3, 0) = ", str(F(1, 3, 0), 0, 1), "\n")

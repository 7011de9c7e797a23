#version 3.7;
#declare F = function(a, b) { a * 10 + b }
#debug concat("F(3, 4) = ", str(F(3, 4), 0, 6), "\n")

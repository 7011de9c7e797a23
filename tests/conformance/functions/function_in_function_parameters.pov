#version 3.7;
#declare F = function(a) { a * a }
#declare G = function(a, b) { F(a) + F(b) }
#debug concat("G(3, 4) = ", str(G(3, 4), 0, 3), "\n")

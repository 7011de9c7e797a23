#version 3.7;
#declare S = function { sum(i, 0.5, 3, i) }
#debug concat("S(0, 0, 0) = ", str(S(0, 0, 0), 0, 3), "\n")

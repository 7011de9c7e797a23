#version 3.7;
#declare S = function(n) { sum(i, 1, n, i) }
#debug concat("S(10) = ", str(S(10), 0, 3), "\n")
#debug concat("S(0) = ", str(S(0), 0, 3), "\n")

#version 3.7;
#declare S = function(n) { sum(i, 1, n, sum(j, 1, i, j)) }
#debug concat("S(4) = ", str(S(4), 0, 3), "\n")

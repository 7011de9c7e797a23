#version 3.7;
#declare V = <7, 8>;
#debug concat("V.u = ", str(V.u, 0, 1), "\n")
#debug concat("V.v = ", str(V.v, 0, 1), "\n")
#debug concat("V.x = ", str(V.x, 0, 1), "\n")
#debug concat("V.y = ", str(V.y, 0, 1), "\n")

#version 3.7;
#declare V = <1, 2, 3>;
#debug concat("V.x = ", str(V.x, 0, 1), "\n")
#debug concat("V.y = ", str(V.y, 0, 1), "\n")
#debug concat("V.z = ", str(V.z, 0, 1), "\n")

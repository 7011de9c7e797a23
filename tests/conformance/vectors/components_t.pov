#version 3.7;
#declare V = <1, 2, 3, 4>;
#debug concat("V.t = ", str(V.t, 0, 1), "\n")
#debug concat("V.z = ", str(V.z, 0, 1), "\n")

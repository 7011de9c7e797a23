#version 3.7;
#declare V = <0.1, 0.2, 0.3>;
#debug concat("V.x = ", str(V.x, 0, 20), "\n")
#debug concat("V.y = ", str(V.y, 0, 20), "\n")
#debug concat("V.z = ", str(V.z, 0, 20), "\n")

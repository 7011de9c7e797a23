#version 3.7;
#declare V = <0.1, 0.2, 0.3>;
#debug concat("V.red = ", str(V.red, 0, 2), "\n")
#debug concat("V.blue = ", str(V.blue, 0, 2), "\n")

#version 3.7;
#declare V = <1, 0.5, 0.2>;
#debug concat("V.gray = ", str(V.gray, 0, 9), "\n")

#version 3.7;
#declare V = <1.25, -2.5, 3>;
#debug concat("str(V.y, 0, 2) = [", str(V.y, 0, 2), "]\n")

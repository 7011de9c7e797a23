#version 3.7;
#declare V = <1,2,3>;
#declare V = 5;
#debug concat("V = ", str(V, 0, 1), "\n")

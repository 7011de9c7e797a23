#version 3.7;
#debug "before\n"
#declare V = <1, 2, 3>;
#debug concat("V.t = ", str(V.t, 0, 1), "\n")

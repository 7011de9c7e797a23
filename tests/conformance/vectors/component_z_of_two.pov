#version 3.7;
#debug "before\n"
#declare V = <1, 2>;
#debug concat("V.z = ", str(V.z, 0, 1), "\n")

#version 3.7;
#debug "before\n"
#declare F = <1,2,3>;
#debug concat("F = ", str(F, 0, 1), "\n")

#version 3.7;
#declare S = sphere { 0, 1 }
#debug "before\n"
#debug concat("S = ", str(S, 0, 0), "\n")

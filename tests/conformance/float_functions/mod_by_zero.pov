#version 3.7;
#debug "before\n"
#debug concat("mod(1,0) = ", str(mod(1,0), 0, 3), "\n")
#debug "after\n"

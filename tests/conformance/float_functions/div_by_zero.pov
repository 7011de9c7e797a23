#version 3.7;
#debug "before\n"
#debug concat("div(1,0) = ", str(div(1,0), 0, 3), "\n")
#debug "after\n"

#version 3.7;
#debug "before\n"
#debug concat("atan2(0,0) = ", str(atan2(0,0), 0, 6), "\n")

#version 3.7;
#debug "before\n"
#debug concat("pow(0,0) = ", str(pow(0,0), 0, 6), "\n")

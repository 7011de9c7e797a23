#version 3.7;
#debug "before\n"
#debug concat("rand(0) = ", str(rand(0), 0, 6), "\n")

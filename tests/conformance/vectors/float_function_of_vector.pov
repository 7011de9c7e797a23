#version 3.7;
#debug "before\n"
#debug concat("abs(<1,2,3>) = ", str(abs(<1,2,3>), 0, 1), "\n")

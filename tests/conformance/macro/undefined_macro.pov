#version 3.7;
#debug "before\n"
#debug concat("Nope(1) = ", str(Nope(1), 0, 0), "\n")

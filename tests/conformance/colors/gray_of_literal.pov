#version 3.7;
#debug "before\n"
#debug concat("(rgb 1).gray = ", str((rgb 1).gray, 0, 9), "\n")

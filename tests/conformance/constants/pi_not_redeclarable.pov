#version 3.7;
#debug "before\n"
#declare pi = 3;
#debug concat("pi = ", str(pi, 0, 9), "\n")

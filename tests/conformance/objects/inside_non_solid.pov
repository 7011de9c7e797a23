#version 3.7;
#declare D = disc { 0, y, 1 }
#debug "before\n"
#debug concat("inside(D, <0, 0, 0>) = ", str(inside(D, <0, 0, 0>), 0, 0), "\n")

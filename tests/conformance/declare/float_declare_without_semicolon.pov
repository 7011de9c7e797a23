#version 3.7;
#debug "before\n"
#declare A = 1
#declare B = 2;
#debug concat("A = ", str(A, 0, 0), "\n")

#version 3.7;
#debug concat("vstr(7, 1, \", \", 0, 1) = [", vstr(7, 1, ", ", 0, 1), "]\n")
#debug concat("vstr(0, <1,2>, \", \", 0, 1) = [", vstr(0, <1,2>, ", ", 0, 1), "]\n")

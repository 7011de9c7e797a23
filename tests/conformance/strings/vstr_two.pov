#version 3.7;
#debug concat("vstr(2, <1, 2>, \", \", 0, 1) = [", vstr(2, <1, 2>, ", ", 0, 1), "]\n")

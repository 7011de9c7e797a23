#version 3.7;
#debug concat("vstr(3, <1, 2>, \", \", 0, 1) = [", vstr(3, <1, 2>, ", ", 0, 1), "]\n")
#debug concat("vstr(5, <1, 2, 3>, \", \", 0, 1) = [", vstr(5, <1, 2, 3>, ", ", 0, 1), "]\n")

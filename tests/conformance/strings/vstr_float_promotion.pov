#version 3.7;
#debug concat("vstr(1, 1, \", \", 0, 1) = [", vstr(1, 1, ", ", 0, 1), "]\n")
#debug concat("vstr(2, 1, \", \", 0, 1) = [", vstr(2, 1, ", ", 0, 1), "]\n")
#debug concat("vstr(5, 1, \", \", 0, 1) = [", vstr(5, 1, ", ", 0, 1), "]\n")

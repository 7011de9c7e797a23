#version 3.7;
#declare E = 1;
#local E = E + 1;
#debug concat("E = ", str(E, 0, 0), "\n")

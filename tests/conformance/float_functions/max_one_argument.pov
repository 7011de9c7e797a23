#version 3.7;
#debug concat("max(-4) = ", str(max(-4), 0, 3), "\n")

#version 3.7;
#debug concat("min(3) = ", str(min(3), 0, 3), "\n")

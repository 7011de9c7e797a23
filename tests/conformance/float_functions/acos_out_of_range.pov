#version 3.7;
#debug concat("acos(1.5) = ", str(acos(1.5), 0, 6), "\n")

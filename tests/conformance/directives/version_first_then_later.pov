#declare A = 1;
#version 3.6;
#debug concat("version = ", str(version, 0, 2), "\n")

#version 3.0 + 0.7;
#debug concat("version = ", str(version, 0, 2), "\n")

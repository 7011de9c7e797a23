#version 3.7;
#debug concat("n=", str(1e3, 0, 0), "\n")

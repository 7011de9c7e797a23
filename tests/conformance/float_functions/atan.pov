#version 3.7;
#debug concat("atan(1) = ", str(atan(1), 0, 9), "\n")
#debug concat("atan(-1) = ", str(atan(-1), 0, 9), "\n")
#debug concat("atan(0) = ", str(atan(0), 0, 9), "\n")
#debug concat("atan(1e6) = ", str(atan(1e6), 0, 9), "\n")

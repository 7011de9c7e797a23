#version 3.7;
#debug concat("sinh(0) = ", str(sinh(0), 0, 9), "\n")
#debug concat("sinh(1) = ", str(sinh(1), 0, 9), "\n")
#debug concat("sinh(-2) = ", str(sinh(-2), 0, 9), "\n")

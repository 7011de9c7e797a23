#version 3.7;
#debug concat("degrees(pi) = ", str(degrees(pi), 0, 9), "\n")
#debug concat("degrees(1) = ", str(degrees(1), 0, 9), "\n")
#debug concat("degrees(-pi/4) = ", str(degrees(-pi/4), 0, 9), "\n")

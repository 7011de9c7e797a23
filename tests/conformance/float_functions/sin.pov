#version 3.7;
#debug concat("sin(0) = ", str(sin(0), 0, 9), "\n")
#debug concat("sin(pi/2) = ", str(sin(pi/2), 0, 9), "\n")
#debug concat("sin(pi/6) = ", str(sin(pi/6), 0, 9), "\n")
#debug concat("sin(-2) = ", str(sin(-2), 0, 9), "\n")
#debug concat("sin(100) = ", str(sin(100), 0, 9), "\n")

#version 3.7;
#debug concat("cos(0) = ", str(cos(0), 0, 9), "\n")
#debug concat("cos(pi) = ", str(cos(pi), 0, 9), "\n")
#debug concat("cos(pi/3) = ", str(cos(pi/3), 0, 9), "\n")
#debug concat("cos(-2) = ", str(cos(-2), 0, 9), "\n")
#debug concat("cos(100) = ", str(cos(100), 0, 9), "\n")

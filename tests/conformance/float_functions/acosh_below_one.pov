#version 3.7;
#debug concat("acosh(0.5) = ", str(acosh(0.5), 0, 6), "\n")

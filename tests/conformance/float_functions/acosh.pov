#version 3.7;
#debug concat("acosh(1) = ", str(acosh(1), 0, 9), "\n")
#debug concat("acosh(2) = ", str(acosh(2), 0, 9), "\n")
#debug concat("acosh(10) = ", str(acosh(10), 0, 9), "\n")

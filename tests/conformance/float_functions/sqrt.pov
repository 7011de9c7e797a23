#version 3.7;
#debug concat("sqrt(4) = ", str(sqrt(4), 0, 9), "\n")
#debug concat("sqrt(2) = ", str(sqrt(2), 0, 9), "\n")
#debug concat("sqrt(0) = ", str(sqrt(0), 0, 9), "\n")
#debug concat("sqrt(1e-10) = ", str(sqrt(1e-10), 0, 9), "\n")

#version 3.7;
#debug concat("exp(0) = ", str(exp(0), 0, 9), "\n")
#debug concat("exp(1) = ", str(exp(1), 0, 9), "\n")
#debug concat("exp(-1) = ", str(exp(-1), 0, 9), "\n")
#debug concat("exp(10) = ", str(exp(10), 0, 9), "\n")

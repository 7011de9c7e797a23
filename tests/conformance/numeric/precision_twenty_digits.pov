#version 3.7;
#debug concat("pi = ", str(pi, 0, 20), "\n")
#debug concat("exp(1) = ", str(exp(1), 0, 20), "\n")
#debug concat("sqrt(2) = ", str(sqrt(2), 0, 20), "\n")
#debug concat("1e10/7 = ", str(1e10/7, 0, 20), "\n")

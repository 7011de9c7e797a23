#version 3.7;
#debug concat("abs(-3.5) = ", str(abs(-3.5), 0, 9), "\n")
#debug concat("abs(2) = ", str(abs(2), 0, 9), "\n")
#debug concat("abs(-0) = ", str(abs(-0), 0, 9), "\n")
#debug concat("abs(-1e-12) = ", str(abs(-1e-12), 0, 9), "\n")

#version 3.7;
#debug concat("ln(1) = ", str(ln(1), 0, 9), "\n")
#debug concat("ln(exp(2)) = ", str(ln(exp(2)), 0, 9), "\n")
#debug concat("ln(10) = ", str(ln(10), 0, 9), "\n")
#debug concat("ln(0.5) = ", str(ln(0.5), 0, 9), "\n")

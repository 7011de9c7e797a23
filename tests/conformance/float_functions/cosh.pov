#version 3.7;
#debug concat("cosh(0) = ", str(cosh(0), 0, 9), "\n")
#debug concat("cosh(1) = ", str(cosh(1), 0, 9), "\n")
#debug concat("cosh(-2) = ", str(cosh(-2), 0, 9), "\n")

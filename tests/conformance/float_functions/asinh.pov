#version 3.7;
#debug concat("asinh(0) = ", str(asinh(0), 0, 9), "\n")
#debug concat("asinh(1) = ", str(asinh(1), 0, 9), "\n")
#debug concat("asinh(-2.5) = ", str(asinh(-2.5), 0, 9), "\n")

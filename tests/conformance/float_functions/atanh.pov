#version 3.7;
#debug concat("atanh(0) = ", str(atanh(0), 0, 9), "\n")
#debug concat("atanh(0.5) = ", str(atanh(0.5), 0, 9), "\n")
#debug concat("atanh(-0.9) = ", str(atanh(-0.9), 0, 9), "\n")

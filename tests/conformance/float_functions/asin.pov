#version 3.7;
#debug concat("asin(0.5) = ", str(asin(0.5), 0, 9), "\n")
#debug concat("asin(-1) = ", str(asin(-1), 0, 9), "\n")
#debug concat("asin(0) = ", str(asin(0), 0, 9), "\n")
#debug concat("asin(1) = ", str(asin(1), 0, 9), "\n")

#version 3.7;
#debug concat("asin(-2) = ", str(asin(-2), 0, 6), "\n")

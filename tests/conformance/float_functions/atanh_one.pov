#version 3.7;
#debug concat("atanh(1) = ", str(atanh(1), 0, 6), "\n")

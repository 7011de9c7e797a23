#version 3.7;
#debug concat("bitwise_or(12,10) = ", str(bitwise_or(12,10), 0, 0), "\n")
#debug concat("bitwise_or(1,2,4,8) = ", str(bitwise_or(1,2,4,8), 0, 0), "\n")
#debug concat("bitwise_or(0,0) = ", str(bitwise_or(0,0), 0, 0), "\n")
